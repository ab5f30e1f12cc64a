// A content-addressed store of compiled stage programs, so that a rebuild
// compiles only what changed.
//
// The key of a program hashes everything its SPIR-V and reflection depend
// on: facet's build id, the back-end options, stage, language and entry
// point, the shader's properties, and the program's preprocessed tokens
// (which hold every transitively included file and the variant's keywords).
// A local directory backend stores one file per key, written to a temporary
// file and renamed, so concurrent builders and a build killed mid-write
// never expose a partial entry. Each entry carries the key it was stored
// under, its program's token hash and a checksum over all of it, so an
// entry that was altered, truncated, renamed or swapped with another is
// reported as corrupt and recompiled, never used.
//
//   cache::CacheStores stores{.local = cache::LocalCache("/tmp/facet-cache")};
//   cache::EntryLookup found = stores.load_entry(key, token_hash);
//   for (const std::string& p : found.problems) warn(p);
//   if (found.entry) use(*found.entry);
//   else stores.store_entry(key, compiled);
#pragma once

#include <atomic>
#include <cstdint>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "facet/compiled_variant.h"
#include "facet/reflection.h"
#include "facet/result.h"

namespace facet::cache {

// The largest entry or include manifest a store reads or writes (64 MiB; a
// stage program's SPIR-V with debug info is a few MiB). Anything larger
// under a key is corrupt, and is never read past this size.
inline constexpr uint64_t kMaxEntryBytes = uint64_t(64) << 20;
// The largest file an include manifest's check hashes: the compiler's
// limit for a source file (64 MiB). A listed file over it, or one that is
// not a regular file, makes the manifest stale.
inline constexpr uint64_t kMaxHashedFileBytes = uint64_t(64) << 20;

// What one compiled stage program leaves behind: the compiled variant and
// the hash of the tokens it was compiled from.
struct CacheEntry : CompiledVariant {
  // XXH3 of the program's preprocessed tokens, so that an include manifest
  // naming this entry for another program is caught.
  uint64_t token_hash = 0;
};

// facet's build id: a hash of the compiler's own sources, made at build time.
std::string_view build_id();

// Bytes of an entry stored under `key` (format in docs/cache.md): the key
// itself, the entry and a trailing checksum over both.
std::string encode_entry(const std::string& key, const CacheEntry& entry);
// Fails (with the reason) when the bytes are truncated, altered, of another
// format version, or were encoded for another key.
Result<CacheEntry> decode_entry(std::string_view bytes, const std::string& key);

// The include manifest of a program (ccache's "direct mode"): which files its
// preprocessing read, with their content hashes, and the keys that
// preprocessing gave. When every file still hashes the same, the program's
// tokens are known without running the preprocessor.
struct IncludeManifest {
  std::string entry_key;  // the CacheEntry key
  uint64_t token_hash = 0;
  std::vector<std::pair<std::string, uint64_t>> files;  // path, XXH3 of the content
};
// Like entries, a manifest carries the key it is stored under.
std::string encode_manifest(const std::string& key, const IncludeManifest& manifest);
Result<IncludeManifest> decode_manifest(std::string_view bytes, const std::string& key);

// The XXH3 of a file an include manifest lists. Never blocks and never reads
// more than kMaxHashedFileBytes: a FIFO, device, directory or oversized file
// is refused with `problem` set. A missing file has neither (the manifest is
// simply stale).
struct FileHash {
  std::optional<uint64_t> hash;
  std::string problem;
};
FileHash hash_file(const std::string& path);

// What a backend found under a key: nothing (a miss), the bytes, or
// something it refused to use (`problem` says why: not a regular file,
// larger than kMaxEntryBytes, a blob that does not hash to its name).
struct StoredBytes {
  std::optional<std::string> bytes;
  std::string problem;
  std::string location;  // the entry's file, or its key on the server, for messages
};

struct LoadResult {
  std::optional<CacheEntry> entry;  // set on a hit
  std::string problem;              // set when an entry existed but failed its checks
  bool corrupt() const { return !problem.empty(); }
};

class LocalCache {
 public:
  explicit LocalCache(std::string dir) : dir_(std::move(dir)) {}
  const std::string& dir() const { return dir_; }

  // A missing key is a miss; an unreadable or corrupt entry is a miss with
  // `problem` set (the next store replaces it).
  LoadResult load(const std::string& key) const;
  // Writes atomically (temporary file + rename). false when the folder is
  // not writable; a cache that cannot store never fails a build.
  bool store(const std::string& key, const CacheEntry& entry) const;
  // Raw bytes under `key`, read only from a regular file of at most
  // kMaxEntryBytes and without blocking (a FIFO or device is refused).
  StoredBytes load_bytes(const std::string& key) const;
  // Same atomic write; refuses bytes over kMaxEntryBytes.
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
// since the action-cache values are not Bazel ActionResults. A server that
// is down, slow or answering errors is a miss; a body whose SHA-256 is not
// its name, or one over kMaxEntryBytes, is a miss with `problem` set. A
// cache never fails a build.
//
//   cache::HttpCache remote("http://cache.example:8080");
// What a Compiler has learnt of cache servers, shared by all its builds
// (facetc's many shaders, a renderer's compiles): a server found not
// answering is asked nothing more. Thread-safe.
class RemoteServers {
 public:
  // The flag of `url`, the same object for every call with that URL.
  std::shared_ptr<std::atomic<bool>> down_flag(const std::string& url);

 private:
  std::mutex mutex_;
  std::map<std::string, std::shared_ptr<std::atomic<bool>>> down_;
};

class HttpCache {
 public:
  // `down`: a flag shared with other HttpCaches of the same server
  // (RemoteServers::down_flag); null: one of its own.
  explicit HttpCache(std::string base_url, long timeout_ms = 10000, std::shared_ptr<std::atomic<bool>> down = nullptr);
  const std::string& url() const { return base_url_; }

  StoredBytes load_bytes(const std::string& key) const;
  bool store_bytes(const std::string& key, std::string_view bytes) const;
  // Whether a request found the server not answering (no connection, or no
  // answer within the timeout): from then on, for this object, its copies
  // and every HttpCache sharing its flag, every load is a miss and every
  // store is skipped at once, so a server that accepts connections and
  // never answers costs one timeout, not one a program.
  bool down() const;

 private:
  std::string base_url_;  // without a trailing '/'
  long timeout_ms_;
  std::shared_ptr<std::atomic<bool>> down_;
};

// Lower-case hex SHA-256 (the bazel-remote digest).
std::string sha256_hex(std::string_view bytes);

// An entry looked up in every store.
struct EntryLookup {
  std::optional<CacheEntry> entry;  // a hit
  bool remote = false;              // the hit came from the server
  // One line per entry that was found but not used, naming it and why.
  std::vector<std::string> problems;
  // An entry under the key held another program's tokens: the key itself
  // is wrong (it came from a rewritten include manifest).
  bool other_program = false;
};

struct ManifestLookup {
  std::optional<IncludeManifest> manifest;
  std::string location;               // of the manifest that was read, for messages
  std::vector<std::string> problems;  // as in EntryLookup
};

// The caches a build uses: the local folder first, then the server; a
// remote hit is checked, then written to the local folder; a store goes to
// both.
struct CacheStores {
  std::optional<LocalCache> local;
  std::optional<HttpCache> remote;

  bool any() const { return local || remote; }
  // The entry under `key`, which must be bound to `key` and hold the program
  // whose tokens hash to `token_hash`.
  EntryLookup load_entry(const std::string& key, uint64_t token_hash) const;
  void store_entry(const std::string& key, const CacheEntry& entry) const;
  ManifestLookup load_manifest(const std::string& key) const;
  void store_manifest(const std::string& key, const IncludeManifest& manifest) const;
};

}  // namespace facet::cache
