// The bazel-remote HTTP backend (libcurl), and the local + remote pair.
#include <curl/curl.h>
#include <fmt/format.h>
#include <openssl/sha.h>

#include <algorithm>
#include <mutex>

#include "facet/cache.h"

namespace facet::cache {
namespace {

// curl_global_init is not thread-safe; it runs once, on first use.
void init_curl_once() {
  static std::once_flag once;
  std::call_once(once, [] { curl_global_init(CURL_GLOBAL_DEFAULT); });
}

size_t append_body(char* data, size_t size, size_t count, void* user) {
  auto* body = static_cast<std::string*>(user);
  if (body->size() + size * count > (size_t(1) << 30)) return 0;  // refuse absurd bodies
  body->append(data, size * count);
  return size * count;
}

struct Upload {
  std::string_view bytes;
  size_t offset = 0;
};

size_t read_body(char* buffer, size_t size, size_t count, void* user) {
  auto* up = static_cast<Upload*>(user);
  size_t n = std::min(size * count, up->bytes.size() - up->offset);
  std::copy_n(up->bytes.data() + up->offset, n, buffer);
  up->offset += n;
  return n;
}

// GET: the body on 200, else nullopt.
std::optional<std::string> http_get(const std::string& url, long timeout_ms) {
  init_curl_once();
  CURL* curl = curl_easy_init();
  if (!curl) return std::nullopt;
  std::string body;
  curl_easy_setopt(curl, CURLOPT_URL, url.c_str());
  curl_easy_setopt(curl, CURLOPT_WRITEFUNCTION, append_body);
  curl_easy_setopt(curl, CURLOPT_WRITEDATA, &body);
  curl_easy_setopt(curl, CURLOPT_TIMEOUT_MS, timeout_ms);
  curl_easy_setopt(curl, CURLOPT_NOSIGNAL, 1L);
  CURLcode rc = curl_easy_perform(curl);
  long status = 0;
  curl_easy_getinfo(curl, CURLINFO_RESPONSE_CODE, &status);
  curl_easy_cleanup(curl);
  if (rc != CURLE_OK || status != 200) return std::nullopt;
  return body;
}

bool http_put(const std::string& url, std::string_view bytes, long timeout_ms) {
  init_curl_once();
  CURL* curl = curl_easy_init();
  if (!curl) return false;
  Upload up{bytes};
  std::string ignored;
  curl_easy_setopt(curl, CURLOPT_URL, url.c_str());
  curl_easy_setopt(curl, CURLOPT_UPLOAD, 1L);
  curl_easy_setopt(curl, CURLOPT_READFUNCTION, read_body);
  curl_easy_setopt(curl, CURLOPT_READDATA, &up);
  curl_easy_setopt(curl, CURLOPT_INFILESIZE_LARGE, curl_off_t(bytes.size()));
  curl_easy_setopt(curl, CURLOPT_WRITEFUNCTION, append_body);
  curl_easy_setopt(curl, CURLOPT_WRITEDATA, &ignored);
  curl_easy_setopt(curl, CURLOPT_TIMEOUT_MS, timeout_ms);
  curl_easy_setopt(curl, CURLOPT_NOSIGNAL, 1L);
  CURLcode rc = curl_easy_perform(curl);
  long status = 0;
  curl_easy_getinfo(curl, CURLINFO_RESPONSE_CODE, &status);
  curl_easy_cleanup(curl);
  return rc == CURLE_OK && status >= 200 && status < 300;
}

bool is_hex64(std::string_view s) {
  return s.size() == 64 && std::all_of(s.begin(), s.end(), [](char c) {
           return (c >= '0' && c <= '9') || (c >= 'a' && c <= 'f');
         });
}

}  // namespace

std::string sha256_hex(std::string_view bytes) {
  unsigned char digest[SHA256_DIGEST_LENGTH];
  SHA256(reinterpret_cast<const unsigned char*>(bytes.data()), bytes.size(), digest);
  std::string hex;
  for (unsigned char b : digest) hex += fmt::format("{:02x}", b);
  return hex;
}

HttpCache::HttpCache(std::string base_url, long timeout_ms) : base_url_(std::move(base_url)), timeout_ms_(timeout_ms) {
  while (!base_url_.empty() && base_url_.back() == '/') base_url_.pop_back();
}

std::optional<std::string> HttpCache::load_bytes(const std::string& key) const {
  auto digest = http_get(base_url_ + "/ac/" + sha256_hex(key), timeout_ms_);
  if (!digest || !is_hex64(*digest)) return std::nullopt;
  auto bytes = http_get(base_url_ + "/cas/" + *digest, timeout_ms_);
  if (!bytes || sha256_hex(*bytes) != *digest) return std::nullopt;  // content-addressed: check the name
  return bytes;
}

bool HttpCache::store_bytes(const std::string& key, std::string_view bytes) const {
  std::string digest = sha256_hex(bytes);
  // The blob first, so that an action-cache entry never names a missing blob.
  return http_put(base_url_ + "/cas/" + digest, bytes, timeout_ms_) &&
         http_put(base_url_ + "/ac/" + sha256_hex(key), digest, timeout_ms_);
}

std::optional<std::string> CacheStores::load_bytes(const std::string& key, bool* remote_hit) const {
  if (remote_hit) *remote_hit = false;
  if (local) {
    if (auto bytes = local->load_bytes(key)) return bytes;
  }
  if (!remote) return std::nullopt;
  auto bytes = remote->load_bytes(key);
  if (bytes) {
    if (remote_hit) *remote_hit = true;
    if (local) (void)local->store_bytes(key, *bytes);
  }
  return bytes;
}

void CacheStores::store_bytes(const std::string& key, std::string_view bytes) const {
  if (local) (void)local->store_bytes(key, bytes);
  if (remote) (void)remote->store_bytes(key, bytes);
}

}  // namespace facet::cache
