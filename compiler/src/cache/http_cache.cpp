// The bazel-remote HTTP backend (libcurl).
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

// A response body of at most `limit` bytes; past it the transfer stops and
// `too_large` is set.
struct Download {
  std::string body;
  uint64_t limit = 0;
  bool too_large = false;
};

size_t append_body(char* data, size_t size, size_t count, void* user) {
  auto* down = static_cast<Download*>(user);
  if (down->body.size() + size * count > down->limit) {
    down->too_large = true;
    return 0;  // curl ends the transfer with a write error
  }
  down->body.append(data, size * count);
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

// The server did not answer (no connection, or none within the timeout), as
// opposed to answering "no".
// (A server that drops a connection mid-transfer, e.g. refusing a large
// upload, answered: it is not given up on.)
bool unanswered(CURLcode rc) {
  return rc == CURLE_OPERATION_TIMEDOUT || rc == CURLE_COULDNT_CONNECT || rc == CURLE_COULDNT_RESOLVE_HOST ||
         rc == CURLE_COULDNT_RESOLVE_PROXY;
}

// GET: the body on 200, else nullopt; `too_large` when a 200's body was
// longer than `limit`; `server_down` when the server did not answer.
std::optional<std::string> http_get(const std::string& url, long timeout_ms, uint64_t limit, bool& too_large,
                                    bool& server_down) {
  init_curl_once();
  CURL* curl = curl_easy_init();
  if (!curl) return std::nullopt;
  Download down{.limit = limit};
  curl_easy_setopt(curl, CURLOPT_URL, url.c_str());
  curl_easy_setopt(curl, CURLOPT_WRITEFUNCTION, append_body);
  curl_easy_setopt(curl, CURLOPT_WRITEDATA, &down);
  // Refused before the body when the server states its length.
  curl_easy_setopt(curl, CURLOPT_MAXFILESIZE_LARGE, curl_off_t(limit));
  curl_easy_setopt(curl, CURLOPT_TIMEOUT_MS, timeout_ms);
  curl_easy_setopt(curl, CURLOPT_NOSIGNAL, 1L);
  CURLcode rc = curl_easy_perform(curl);
  long status = 0;
  curl_easy_getinfo(curl, CURLINFO_RESPONSE_CODE, &status);
  curl_easy_cleanup(curl);
  // Only a 200's body is a value: a miss's error page (nginx sends 153 bytes
  // of HTML with its 404) may be longer than a value may be, and is a miss.
  too_large = status == 200 && (down.too_large || rc == CURLE_FILESIZE_EXCEEDED);
  if (unanswered(rc)) server_down = true;
  if (rc != CURLE_OK || status != 200) return std::nullopt;
  return std::move(down.body);
}

bool http_put(const std::string& url, std::string_view bytes, long timeout_ms, bool& server_down) {
  init_curl_once();
  CURL* curl = curl_easy_init();
  if (!curl) return false;
  Upload up{bytes};
  Download ignored{.limit = 1 << 20};
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
  if (unanswered(rc)) server_down = true;
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

std::shared_ptr<std::atomic<bool>> RemoteServers::down_flag(const std::string& url) {
  std::lock_guard lock(mutex_);
  std::shared_ptr<std::atomic<bool>>& flag = down_[url];
  if (!flag) flag = std::make_shared<std::atomic<bool>>(false);
  return flag;
}

HttpCache::HttpCache(std::string base_url, long timeout_ms, std::shared_ptr<std::atomic<bool>> down)
    : base_url_(std::move(base_url)),
      timeout_ms_(timeout_ms),
      down_(down ? std::move(down) : std::make_shared<std::atomic<bool>>(false)) {
  while (!base_url_.empty() && base_url_.back() == '/') base_url_.pop_back();
}

bool HttpCache::down() const { return down_->load(); }

StoredBytes HttpCache::load_bytes(const std::string& key) const {
  const std::string ac = base_url_ + "/ac/" + sha256_hex(key);
  StoredBytes out{.location = fmt::format("{} (remote {})", key, ac)};
  if (down()) return out;  // a miss: the server did not answer before
  bool too_large = false, server_down = false;
  auto digest = http_get(ac, timeout_ms_, 64, too_large, server_down);
  if (server_down) down_->store(true);
  if (!digest && !too_large) return out;  // a miss, or the server is down
  if (!digest || !is_hex64(*digest)) {
    out.problem = "the action-cache value is not a digest";
    return out;
  }
  auto bytes = http_get(base_url_ + "/cas/" + *digest, timeout_ms_, kMaxEntryBytes, too_large, server_down);
  if (server_down) down_->store(true);
  if (!bytes) {
    if (too_large) out.problem = fmt::format("its blob is over the limit of {} bytes", kMaxEntryBytes);
    return out;
  }
  if (sha256_hex(*bytes) != *digest) {  // content-addressed: check the name
    out.problem = "its blob does not hash to its name";
    return out;
  }
  out.bytes = std::move(bytes);
  return out;
}

bool HttpCache::store_bytes(const std::string& key, std::string_view bytes) const {
  if (bytes.size() > kMaxEntryBytes || down()) return false;  // no reader would take it; no server answers
  std::string digest = sha256_hex(bytes);
  // The blob first, so that an action-cache entry never names a missing blob.
  bool server_down = false;
  bool stored = http_put(base_url_ + "/cas/" + digest, bytes, timeout_ms_, server_down) &&
                http_put(base_url_ + "/ac/" + sha256_hex(key), digest, timeout_ms_, server_down);
  if (server_down) down_->store(true);
  return stored;
}

}  // namespace facet::cache
