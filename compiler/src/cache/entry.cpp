// The cache entry format: little-endian, length-prefixed, checksummed.
//   "FACETCACHE" u16 version
//   u64 n, n x u32 SPIR-V words
//   u64 n, n bytes of reflection: u32 string count, count x (u32 n, n bytes),
//                                 then the StageReflection (common/binary_codec.h)
//   u64 count, count x (u64 n, n bytes) included file paths
//   u64 XXH64 of every byte before it
#include <xxhash.h>

#include <cstring>
#include <optional>
#include <span>

#include "facet/cache.h"
#include "common/binary_codec.h"
#include "facet_build_id.h"

namespace facet::cache {
namespace {

constexpr std::string_view kMagic = "FACETCACHE";
constexpr uint16_t kVersion = 2;  // 2: binary reflection (1 was JSON)
constexpr uint64_t kChecksumSeed = 0x66616365745f6361ull;  // "facet_ca"

}  // namespace

static std::string fmt_hex(uint64_t v) {
  static const char digits[] = "0123456789abcdef";
  std::string out(16, '0');
  for (int i = 15; i >= 0; --i, v >>= 4) out[size_t(i)] = digits[v & 0xf];
  return out;
}

static std::optional<uint64_t> parse_hex(std::string_view s) {
  if (s.size() != 16) return std::nullopt;
  uint64_t v = 0;
  for (char c : s) {
    int d = c >= '0' && c <= '9' ? c - '0' : c >= 'a' && c <= 'f' ? c - 'a' + 10 : -1;
    if (d < 0) return std::nullopt;
    v = v << 4 | uint64_t(d);
  }
  return v;
}

namespace {

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

// The string table first, so that the decoder resolves references as it goes.
std::string encode_reflection_bytes(const StageReflection& reflection) {
  codec::StringTable strings;
  codec::Encoder body(strings);
  codec::encode_reflection(body, reflection);
  codec::Encoder head(strings);
  head.count(strings.strings().size());
  for (const std::string& s : strings.strings()) {
    head.u32(uint32_t(s.size()));
    head.bytes().insert(head.bytes().end(), s.begin(), s.end());
  }
  std::string out(head.bytes().begin(), head.bytes().end());
  out.append(body.bytes().begin(), body.bytes().end());
  return out;
}

std::optional<StageReflection> decode_reflection_bytes(std::string_view bytes) {
  std::span<const uint8_t> data(reinterpret_cast<const uint8_t*>(bytes.data()), bytes.size());
  codec::DecodeContext ctx;
  ctx.string_budget = UINT64_MAX;  // strings are stored inline, so they are bounded by the entry
  codec::Decoder in(data, 0, ctx);
  uint32_t n = in.count(4, "string");
  for (uint32_t i = 0; i < n && in.ok(); ++i) ctx.strings.push_back(in.inline_string());
  StageReflection reflection = codec::decode_reflection(in);
  in.expect_end("reflection");
  if (!in.ok()) return std::nullopt;
  return reflection;
}

}  // namespace

std::string encode_entry(const CacheEntry& entry) {
  std::string out(kMagic);
  out += char(kVersion & 0xff);
  out += char(kVersion >> 8);
  put_u64(out, entry.spirv.size());
  out.append(reinterpret_cast<const char*>(entry.spirv.data()), entry.spirv.size() * 4);
  put_bytes(out, encode_reflection_bytes(entry.reflection));
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
  auto parsed = decode_reflection_bytes(reflection);
  if (!parsed) return std::nullopt;
  entry.reflection = std::move(*parsed);
  return entry;
}

std::string_view build_id() { return FACET_BUILD_ID; }

}  // namespace facet::cache

namespace facet::cache {
namespace {
constexpr std::string_view kManifestMagic = "FACETMANIFEST1\n";
}  // namespace

// Text lines: magic, "key <hex>", "tokens <hex>", "file <hex> <path>"...,
// then "check <hex>" = XXH64 of everything before it.
std::string encode_manifest(const IncludeManifest& manifest) {
  std::string out(kManifestMagic);
  out += "key " + manifest.entry_key + "\n";
  out += fmt_hex(manifest.token_hash) + "\n";
  for (const auto& [path, hash] : manifest.files) out += "file " + fmt_hex(hash) + " " + path + "\n";
  out += "check " + fmt_hex(XXH64(out.data(), out.size(), kChecksumSeed)) + "\n";
  return out;
}

std::optional<IncludeManifest> decode_manifest(std::string_view bytes) {
  size_t check = bytes.rfind("check ");
  if (!bytes.starts_with(kManifestMagic) || check == std::string_view::npos || !bytes.ends_with("\n")) {
    return std::nullopt;
  }
  std::string_view body = bytes.substr(0, check);
  auto stated = parse_hex(bytes.substr(check + 6, bytes.size() - check - 7));
  if (!stated || *stated != XXH64(body.data(), body.size(), kChecksumSeed)) return std::nullopt;
  IncludeManifest m;
  size_t pos = kManifestMagic.size();
  int line_no = 0;
  while (pos < body.size()) {
    size_t eol = body.find('\n', pos);
    if (eol == std::string_view::npos) return std::nullopt;
    std::string_view line = body.substr(pos, eol - pos);
    pos = eol + 1;
    if (line_no == 0) {
      if (!line.starts_with("key ")) return std::nullopt;
      m.entry_key = std::string(line.substr(4));
    } else if (line_no == 1) {
      auto h = parse_hex(line);
      if (!h) return std::nullopt;
      m.token_hash = *h;
    } else {
      if (!line.starts_with("file ") || line.size() < 22 || line[21] != ' ') return std::nullopt;
      auto h = parse_hex(line.substr(5, 16));
      if (!h) return std::nullopt;
      m.files.emplace_back(std::string(line.substr(22)), *h);
    }
    ++line_no;
  }
  if (line_no < 2) return std::nullopt;
  return m;
}

}  // namespace facet::cache
