// A content-addressed store of compiled stage programs, so that a rebuild
// compiles only what changed.
//
// The key of a program hashes everything its SPIR-V and reflection depend
// on: facet's build id, the back-end options, stage, language and entry
// point, the shader's properties, and the program's preprocessed tokens
// (which hold every transitively included file and the variant's keywords).
// A local directory backend stores one file per key, written to a temporary
// file and renamed, so concurrent builders and a build killed mid-write
// never expose a partial entry; each entry carries a checksum, and an entry
// that fails it is reported as corrupt and recompiled, never used.
//
//   cache::LocalCache store("/tmp/facet-cache");
//   if (auto hit = store.load(key)) use(*hit->entry);
//   else store.store(key, compiled);
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "facet/reflection.h"

namespace facet::cache {

// What one compiled stage program leaves behind.
struct CacheEntry {
  std::vector<uint32_t> spirv;
  StageReflection reflection;
  std::vector<std::string> included_files;  // sorted
};

// facet's build id: a hash of the compiler's own sources, made at build time.
std::string_view build_id();

// Bytes of an entry (format in docs/cache.md), with a trailing checksum.
std::string encode_entry(const CacheEntry& entry);
// nullopt when the bytes are truncated, corrupt or of another format version.
std::optional<CacheEntry> decode_entry(std::string_view bytes);

// The include manifest of a program (ccache's "direct mode"): which files its
// preprocessing read, with their content hashes, and the keys that
// preprocessing gave. When every file still hashes the same, the program's
// tokens are known without running the preprocessor.
struct IncludeManifest {
  std::string entry_key;  // the CacheEntry key
  uint64_t token_hash = 0;
  std::vector<std::pair<std::string, uint64_t>> files;  // path, XXH3 of the content
};
std::string encode_manifest(const IncludeManifest& manifest);
std::optional<IncludeManifest> decode_manifest(std::string_view bytes);

struct LoadResult {
  std::optional<CacheEntry> entry;  // set on a hit
  bool corrupt = false;             // an entry existed but failed its checks
};

class LocalCache {
 public:
  explicit LocalCache(std::string dir) : dir_(std::move(dir)) {}
  const std::string& dir() const { return dir_; }

  // A missing key is a miss; an unreadable or corrupt entry is a miss with
  // `corrupt` set (the next store replaces it).
  LoadResult load(const std::string& key) const;
  // Writes atomically (temporary file + rename). false when the folder is
  // not writable; a cache that cannot store never fails a build.
  bool store(const std::string& key, const CacheEntry& entry) const;
  // Raw bytes under `key` (the driver's include manifests, which carry their
  // own checksum); same atomic write. nullopt: absent or unreadable.
  std::optional<std::string> load_bytes(const std::string& key) const;
  bool store_bytes(const std::string& key, std::string_view bytes) const;
  // The entry file of `key` (for tests and tools).
  std::string path_of(const std::string& key) const;

 private:
  std::string dir_;
};

// A shared cache server speaking the bazel-remote HTTP layout
// (github.com/buchgr/bazel-remote): the entry bytes are stored under
// /cas/<sha256 of the bytes>, and /ac/<sha256 of the facet key> holds that
// digest as 64 hex digits. bazel-remote needs --disable_http_ac_validation,
// since the action-cache values are not Bazel ActionResults. Every failure
// (server down, 404, timeout, a body whose SHA-256 is not its name) is a
// miss; a cache never fails a build.
//
//   cache::HttpCache remote("http://cache.example:8080");
class HttpCache {
 public:
  explicit HttpCache(std::string base_url, long timeout_ms = 10000);
  const std::string& url() const { return base_url_; }

  std::optional<std::string> load_bytes(const std::string& key) const;
  bool store_bytes(const std::string& key, std::string_view bytes) const;

 private:
  std::string base_url_;  // without a trailing '/'
  long timeout_ms_;
};

// Lower-case hex SHA-256 (the bazel-remote digest).
std::string sha256_hex(std::string_view bytes);

// The caches a build uses: the local folder first, then the server; a
// remote hit is written to the local folder, a store goes to both.
struct CacheStores {
  std::optional<LocalCache> local;
  std::optional<HttpCache> remote;

  bool any() const { return local || remote; }
  // `remote_hit` tells whether the bytes came from the server.
  std::optional<std::string> load_bytes(const std::string& key, bool* remote_hit = nullptr) const;
  void store_bytes(const std::string& key, std::string_view bytes) const;
};

}  // namespace facet::cache
