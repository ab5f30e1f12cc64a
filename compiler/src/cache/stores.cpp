// The local + remote pair: entries and include manifests are looked up in
// the folder, then on the server, and each is checked against the key it
// was looked up under before it is used or copied into the folder.
#include <fmt/format.h>

#include "facet/cache.h"

namespace facet::cache {
namespace {

std::string entry_problem(const std::string& location, const std::string& why) {
  return fmt::format("corrupt cache entry '{}': {}; it was not used (the program is compiled instead)", location, why);
}

std::string manifest_problem(const std::string& location, const std::string& why) {
  return fmt::format("corrupt include manifest '{}': {}; it was not used (the program is preprocessed instead)",
                     location, why);
}

// Decodes what one store found; a hit, or nothing with a problem recorded.
std::optional<CacheEntry> checked_entry(const StoredBytes& stored, const std::string& key, uint64_t token_hash,
                                        EntryLookup& out) {
  if (!stored.problem.empty()) out.problems.push_back(entry_problem(stored.location, stored.problem));
  if (!stored.bytes) return std::nullopt;
  auto entry = decode_entry(*stored.bytes, key);
  if (!entry) {
    out.problems.push_back(entry_problem(stored.location, entry.error().reason));
    return std::nullopt;
  }
  if (entry->token_hash != token_hash) {
    out.other_program = true;
    out.problems.push_back(entry_problem(
        stored.location,
        fmt::format("it holds another program (tokens {:016x}, not {:016x})", entry->token_hash, token_hash)));
    return std::nullopt;
  }
  return std::move(*entry);
}

std::optional<IncludeManifest> checked_manifest(const StoredBytes& stored, const std::string& key,
                                                ManifestLookup& out) {
  if (!stored.problem.empty()) out.problems.push_back(manifest_problem(stored.location, stored.problem));
  if (!stored.bytes) return std::nullopt;
  auto manifest = decode_manifest(*stored.bytes, key);
  if (!manifest) {
    out.problems.push_back(manifest_problem(stored.location, manifest.error().reason));
    return std::nullopt;
  }
  out.location = stored.location;
  return std::move(*manifest);
}

}  // namespace

EntryLookup CacheStores::load_entry(const std::string& key, uint64_t token_hash) const {
  EntryLookup out;
  if (local) {
    out.entry = checked_entry(local->load_bytes(key), key, token_hash, out);
    if (out.entry) return out;
  }
  if (!remote) return out;
  StoredBytes stored = remote->load_bytes(key);
  out.entry = checked_entry(stored, key, token_hash, out);
  if (out.entry) {
    out.remote = true;
    if (local) (void)local->store_bytes(key, *stored.bytes);  // checked: safe to keep
  }
  return out;
}

void CacheStores::store_entry(const std::string& key, const CacheEntry& entry) const {
  std::string bytes = encode_entry(key, entry);
  if (local) (void)local->store_bytes(key, bytes);
  if (remote) (void)remote->store_bytes(key, bytes);
}

ManifestLookup CacheStores::load_manifest(const std::string& key) const {
  ManifestLookup out;
  if (local) {
    out.manifest = checked_manifest(local->load_bytes(key), key, out);
    if (out.manifest) return out;
  }
  if (!remote) return out;
  StoredBytes stored = remote->load_bytes(key);
  out.manifest = checked_manifest(stored, key, out);
  if (out.manifest && local) (void)local->store_bytes(key, *stored.bytes);
  return out;
}

void CacheStores::store_manifest(const std::string& key, const IncludeManifest& manifest) const {
  std::string bytes = encode_manifest(key, manifest);
  if (local) (void)local->store_bytes(key, bytes);
  if (remote) (void)remote->store_bytes(key, bytes);
}

}  // namespace facet::cache
