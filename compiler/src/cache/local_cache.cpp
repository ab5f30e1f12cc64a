// The local directory backend: <dir>/<first two key chars>/<key>.
#include <unistd.h>

#include <atomic>
#include <filesystem>
#include <fstream>
#include <thread>

#include "facet/cache.h"

namespace facet::cache {
namespace fs = std::filesystem;

namespace {

// A key is lower-case hex; anything else could escape the folder.
bool valid_key(const std::string& key) {
  if (key.size() < 8 || key.size() > 128) return false;
  for (char c : key) {
    if (!((c >= '0' && c <= '9') || (c >= 'a' && c <= 'f'))) return false;
  }
  return true;
}

}  // namespace

std::string LocalCache::path_of(const std::string& key) const {
  return (fs::path(dir_) / key.substr(0, 2) / key).string();
}

std::optional<std::string> LocalCache::load_bytes(const std::string& key) const {
  if (!valid_key(key)) return std::nullopt;
  // One read into a string of the file's size: entries are read by the
  // thousand on a warm build, where a stream copy costs more than the I/O.
  std::ifstream in(path_of(key), std::ios::binary | std::ios::ate);
  if (!in) return std::nullopt;
  std::streamoff size = in.tellg();
  if (size < 0) return std::nullopt;
  std::string bytes(size_t(size), '\0');
  in.seekg(0);
  if (!in.read(bytes.data(), size)) return std::nullopt;
  return bytes;
}

LoadResult LocalCache::load(const std::string& key) const {
  std::optional<std::string> bytes = load_bytes(key);
  if (!bytes) return {};
  LoadResult result;
  result.entry = decode_entry(*bytes);
  result.corrupt = !result.entry;
  return result;
}

bool LocalCache::store(const std::string& key, const CacheEntry& entry) const {
  return store_bytes(key, encode_entry(entry));
}

bool LocalCache::store_bytes(const std::string& key, std::string_view bytes) const {
  if (!valid_key(key)) return false;
  std::error_code ec;
  fs::path target = path_of(key);
  fs::create_directories(target.parent_path(), ec);
  if (ec) return false;
  // Unique per process, thread and call: concurrent writers never share a temp file.
  static std::atomic<uint64_t> counter{0};
  fs::path temp = target;
  temp += ".tmp." + std::to_string(::getpid()) + "." +
          std::to_string(std::hash<std::thread::id>{}(std::this_thread::get_id())) + "." +
          std::to_string(counter++);
  {
    std::ofstream out(temp, std::ios::binary | std::ios::trunc);
    out.write(bytes.data(), std::streamsize(bytes.size()));
    out.flush();
    if (!out) {
      out.close();
      fs::remove(temp, ec);
      return false;
    }
  }
  fs::rename(temp, target, ec);  // atomic: readers see the old entry or the new one
  if (ec) {
    fs::remove(temp, ec);
    return false;
  }
  return true;
}

}  // namespace facet::cache
