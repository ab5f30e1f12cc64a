// The local directory backend: <dir>/<first two key chars>/<key>, and the
// bounded file reads that it and the include manifests' checks share.
#include <fcntl.h>
#include <fmt/format.h>
#include <sys/stat.h>
#include <unistd.h>
#include <xxhash.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "facet/cache.h"
#include "facet/support/atomic_file.h"

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

std::string_view kind_of(mode_t mode) {
  if (S_ISDIR(mode)) return "a directory";
  if (S_ISFIFO(mode)) return "a FIFO";
  if (S_ISCHR(mode) || S_ISBLK(mode)) return "a device";
  if (S_ISSOCK(mode)) return "a socket";
  return "a special file";
}

// Why a file cannot be read as a cache file, or "" when it can.
std::string refusal(const struct stat& st, uint64_t max_bytes) {
  if (!S_ISREG(st.st_mode)) return std::string(kind_of(st.st_mode)) + ", not a regular file";
  if (uint64_t(st.st_size) > max_bytes) {
    return fmt::format("{} bytes, over the limit of {} bytes", uint64_t(st.st_size), max_bytes);
  }
  return "";
}

// Closes a descriptor on every way out.
struct Fd {
  int fd = -1;
  ~Fd() {
    if (fd >= 0) ::close(fd);
  }
};

// The whole of a regular file of at most `max_bytes`. A missing file leaves
// both fields empty. The file is checked before it is opened (a symlink is
// followed only to a regular file), opened without blocking (a FIFO that
// appeared in between opens at once) and checked again on the open file,
// and never more than `max_bytes` + 1 bytes are read (a file that grows
// while it is read is refused).
StoredBytes read_regular_file(const std::string& path, uint64_t max_bytes) {
  StoredBytes out{.location = path};
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0) {
    if (errno != ENOENT && errno != ENOTDIR) out.problem = std::strerror(errno);
    return out;
  }
  if (out.problem = refusal(st, max_bytes); !out.problem.empty()) return out;
  Fd file{::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC)};
  if (file.fd < 0) {
    if (errno != ENOENT) out.problem = std::strerror(errno);
    return out;
  }
  if (::fstat(file.fd, &st) != 0) {
    out.problem = std::strerror(errno);
    return out;
  }
  if (out.problem = refusal(st, max_bytes); !out.problem.empty()) return out;
  std::string bytes(size_t(st.st_size) + 1, '\0');
  size_t got = 0;
  while (got < bytes.size()) {
    ssize_t n = ::read(file.fd, bytes.data() + got, bytes.size() - got);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) {
      out.problem = std::strerror(errno);
      return out;
    }
    if (n == 0) break;
    got += size_t(n);
  }
  if (got > max_bytes || got > size_t(st.st_size)) {
    out.problem = fmt::format("it grew while it was read (over {} bytes)", size_t(st.st_size));
    return out;
  }
  bytes.resize(got);
  out.bytes = std::move(bytes);
  return out;
}

}  // namespace

FileHash hash_file(const std::string& path) {
  StoredBytes read = read_regular_file(path, kMaxHashedFileBytes);
  FileHash out{.problem = std::move(read.problem)};
  if (read.bytes) out.hash = XXH3_64bits(read.bytes->data(), read.bytes->size());
  return out;
}

std::string LocalCache::path_of(const std::string& key) const {
  return (fs::path(dir_) / key.substr(0, 2) / key).string();
}

StoredBytes LocalCache::load_bytes(const std::string& key) const {
  if (!valid_key(key)) return {};
  return read_regular_file(path_of(key), kMaxEntryBytes);
}

LoadResult LocalCache::load(const std::string& key) const {
  StoredBytes stored = load_bytes(key);
  LoadResult result{.problem = stored.problem};
  if (!stored.bytes) return result;
  auto entry = decode_entry(*stored.bytes, key);
  if (entry) {
    result.entry = std::move(*entry);
  } else {
    result.problem = entry.error().reason;
  }
  return result;
}

bool LocalCache::store(const std::string& key, const CacheEntry& entry) const {
  return store_bytes(key, encode_entry(key, entry));
}

bool LocalCache::store_bytes(const std::string& key, std::string_view bytes) const {
  if (!valid_key(key) || bytes.size() > kMaxEntryBytes) return false;  // it could never be read back
  std::error_code ec;
  fs::path target = path_of(key);
  fs::create_directories(target.parent_path(), ec);
  if (ec) return false;
  // Atomic: readers see the old entry or the new one. A directory (or
  // anything else) in the entry's place makes the rename fail: no store.
  // What stands in an entry's place (a FIFO, a device) is replaced, as a corrupt entry is.
  return bool(support::write_file_atomically(target.string(), bytes, support::SpecialTarget::replace));
}

}  // namespace facet::cache
