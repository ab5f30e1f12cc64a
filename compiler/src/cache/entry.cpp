// The cache entry format: little-endian, length-prefixed, checksummed.
//   "FACETCACHE" u16 version
//   u64 n, n x u32 SPIR-V words
//   u64 n, n bytes of reflection JSON
//   u64 count, count x (u64 n, n bytes) included file paths
//   u64 XXH64 of every byte before it
#include <xxhash.h>

#include <cstring>

#include "facet/cache.h"
#include "facet/reflection_json.h"
#include "facet_build_id.h"

namespace facet::cache {
namespace {

constexpr std::string_view kMagic = "FACETCACHE";
constexpr uint16_t kVersion = 1;
constexpr uint64_t kChecksumSeed = 0x66616365745f6361ull;  // "facet_ca"

void put_u64(std::string& out, uint64_t v) {
  for (int i = 0; i < 8; ++i) out += char((v >> (8 * i)) & 0xff);
}

void put_bytes(std::string& out, std::string_view bytes) {
  put_u64(out, bytes.size());
  out.append(bytes);
}

// Reads from a byte range, failing (not crashing) past its end.
class Reader {
 public:
  explicit Reader(std::string_view bytes) : bytes_(bytes) {}
  bool u64(uint64_t& v) {
    if (bytes_.size() - pos_ < 8) return false;
    v = 0;
    for (int i = 0; i < 8; ++i) v |= uint64_t(uint8_t(bytes_[pos_ + i])) << (8 * i);
    pos_ += 8;
    return true;
  }
  bool bytes(std::string& out) {
    uint64_t n = 0;
    if (!u64(n) || n > bytes_.size() - pos_) return false;
    out.assign(bytes_.substr(pos_, n));
    pos_ += n;
    return true;
  }
  bool words(std::vector<uint32_t>& out) {
    uint64_t n = 0;
    if (!u64(n) || n > (bytes_.size() - pos_) / 4) return false;
    out.resize(n);
    std::memcpy(out.data(), bytes_.data() + pos_, n * 4);
    pos_ += n * 4;
    return true;
  }
  bool skip(size_t n) {
    if (bytes_.size() - pos_ < n) return false;
    pos_ += n;
    return true;
  }
  bool at_end() const { return pos_ == bytes_.size(); }

 private:
  std::string_view bytes_;
  size_t pos_ = 0;
};

}  // namespace

std::string encode_entry(const CacheEntry& entry) {
  std::string out(kMagic);
  out += char(kVersion & 0xff);
  out += char(kVersion >> 8);
  put_u64(out, entry.spirv.size());
  out.append(reinterpret_cast<const char*>(entry.spirv.data()), entry.spirv.size() * 4);
  put_bytes(out, reflection_to_json_text(entry.reflection, -1));
  put_u64(out, entry.included_files.size());
  for (const std::string& path : entry.included_files) put_bytes(out, path);
  put_u64(out, XXH64(out.data(), out.size(), kChecksumSeed));
  return out;
}

std::optional<CacheEntry> decode_entry(std::string_view bytes) {
  const size_t header = kMagic.size() + 2;
  if (bytes.size() < header + 8 || bytes.substr(0, kMagic.size()) != kMagic) return std::nullopt;
  if (uint8_t(bytes[kMagic.size()]) != (kVersion & 0xff) || uint8_t(bytes[kMagic.size() + 1]) != (kVersion >> 8)) {
    return std::nullopt;
  }
  std::string_view body = bytes.substr(0, bytes.size() - 8);
  Reader tail(bytes.substr(bytes.size() - 8));
  uint64_t checksum = 0;
  if (!tail.u64(checksum) || checksum != XXH64(body.data(), body.size(), kChecksumSeed)) return std::nullopt;

  Reader in(body);
  CacheEntry entry;
  std::string reflection;
  uint64_t files = 0;
  if (!in.skip(header) || !in.words(entry.spirv) || !in.bytes(reflection) || !in.u64(files)) return std::nullopt;
  if (files > body.size()) return std::nullopt;
  for (uint64_t i = 0; i < files; ++i) {
    std::string path;
    if (!in.bytes(path)) return std::nullopt;
    entry.included_files.push_back(std::move(path));
  }
  if (!in.at_end()) return std::nullopt;
  auto parsed = reflection_from_json_text(reflection);
  if (!parsed) return std::nullopt;
  entry.reflection = std::move(*parsed);
  return entry;
}

std::string_view build_id() { return FACET_BUILD_ID; }

}  // namespace facet::cache
