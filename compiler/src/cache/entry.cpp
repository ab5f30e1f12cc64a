// The cache entry format: little-endian, length-prefixed, checksummed.
//   "FACETCACHE" u16 version
//   u64 n, n bytes: the key the entry is stored under
//   u64 XXH3 of the program's preprocessed tokens
//   u64 n, n x u32 SPIR-V words
//   u64 n, n bytes of reflection: u32 string count, count x (u32 n, n bytes),
//                                 then the StageReflection (common/binary_codec.h)
//   u64 count, count x (u64 n, n bytes) included file paths
//   u64 XXH64 of every byte before it
#include <fmt/format.h>
#include <xxhash.h>

#include <cstring>
#include <optional>
#include <span>

#include "facet/cache.h"
#include "facet/support/binary_codec.h"
#include "facet_build_id.h"

namespace facet::cache {
namespace {

constexpr std::string_view kMagic = "FACETCACHE";
// 3: the key and the token hash (an entry is bound to its key); 2: binary
// reflection (1 was JSON).
constexpr uint16_t kVersion = 3;
constexpr uint64_t kChecksumSeed = 0x66616365745f6361ull;  // "facet_ca"

// Reflection strings expand through references; their decoded bytes are
// bounded like a package's (64 x the encoded size + 1 MiB), but at most
// 256 MiB, since entries themselves are at most kMaxEntryBytes.
uint64_t reflection_string_budget(uint64_t encoded_bytes) {
  constexpr uint64_t kMax = uint64_t(256) << 20;
  uint64_t budget = 64 * encoded_bytes + (uint64_t(1) << 20);
  return budget < kMax ? budget : kMax;
}

std::string fmt_hex(uint64_t v) { return fmt::format("{:016x}", v); }

std::optional<uint64_t> parse_hex(std::string_view s) {
  if (s.size() != 16) return std::nullopt;
  uint64_t v = 0;
  for (char c : s) {
    int d = c >= '0' && c <= '9' ? c - '0' : c >= 'a' && c <= 'f' ? c - 'a' + 10 : -1;
    if (d < 0) return std::nullopt;
    v = v << 4 | uint64_t(d);
  }
  return v;
}

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
    if (n > 0) std::memcpy(out.data(), bytes_.data() + pos_, n * 4);  // an empty vector's data() may be null
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
  ctx.string_budget = reflection_string_budget(bytes.size());
  codec::Decoder in(data, 0, ctx);
  uint32_t n = in.count(4, "string");
  for (uint32_t i = 0; i < n && in.ok(); ++i) ctx.strings.push_back(in.inline_string());
  StageReflection reflection = codec::decode_reflection(in);
  in.expect_end("reflection");
  if (!in.ok()) return std::nullopt;
  return reflection;
}

// The checked part of an entry: magic, version and checksum. The body
// (without the checksum) on success.
Result<std::string_view> checked_body(std::string_view bytes) {
  const size_t header = kMagic.size() + 2;
  if (bytes.size() < header + 8 || bytes.substr(0, kMagic.size()) != kMagic) return failure("not a facet cache entry");
  uint16_t version = uint16_t(uint8_t(bytes[kMagic.size()]) | uint8_t(bytes[kMagic.size() + 1]) << 8);
  if (version != kVersion) return failure(fmt::format("format version {}, not {}", version, kVersion));
  std::string_view body = bytes.substr(0, bytes.size() - 8);
  Reader tail(bytes.substr(bytes.size() - 8));
  uint64_t checksum = 0;
  if (!tail.u64(checksum) || checksum != XXH64(body.data(), body.size(), kChecksumSeed)) {
    return failure("truncated or altered (its checksum does not match)");
  }
  return body;
}

}  // namespace

std::string encode_entry(const std::string& key, const CacheEntry& entry) {
  std::string out(kMagic);
  out += char(kVersion & 0xff);
  out += char(kVersion >> 8);
  put_bytes(out, key);
  put_u64(out, entry.token_hash);
  put_u64(out, entry.spirv.size());
  out.append(reinterpret_cast<const char*>(entry.spirv.data()), entry.spirv.size() * 4);
  put_bytes(out, encode_reflection_bytes(entry.reflection));
  put_u64(out, entry.included_files.size());
  for (const std::string& path : entry.included_files) put_bytes(out, path);
  put_u64(out, XXH64(out.data(), out.size(), kChecksumSeed));
  return out;
}

Result<CacheEntry> decode_entry(std::string_view bytes, const std::string& key) {
  auto body = checked_body(bytes);
  if (!body) return failure(body.error().reason);
  Reader in(*body);
  CacheEntry entry;
  std::string stored_key, reflection;
  uint64_t files = 0;
  if (!in.skip(kMagic.size() + 2) || !in.bytes(stored_key)) return failure("truncated");
  // The key binding: a copied, renamed or swapped entry carries its own key.
  if (stored_key != key) return failure(fmt::format("it was stored under another key ({})", stored_key));
  if (!in.u64(entry.token_hash) || !in.words(entry.spirv) || !in.bytes(reflection) || !in.u64(files) ||
      files > body->size()) {
    return failure("malformed");
  }
  for (uint64_t i = 0; i < files; ++i) {
    std::string path;
    if (!in.bytes(path)) return failure("malformed");
    entry.included_files.push_back(std::move(path));
  }
  if (!in.at_end()) return failure("malformed (bytes after its end)");
  auto parsed = decode_reflection_bytes(reflection);
  if (!parsed) return failure("malformed reflection");
  entry.reflection = std::move(*parsed);
  return entry;
}

std::string_view build_id() { return FACET_BUILD_ID; }

namespace {
constexpr std::string_view kManifestMagic = "FACETMANIFEST2\n";  // 2: the "for" line
}  // namespace

// Text lines: magic, "for <manifest key>", "key <entry key>", "<token hash>",
// "file <hex> <path>"..., then "check <hex>" = XXH64 of everything before it.
std::string encode_manifest(const std::string& key, const IncludeManifest& manifest) {
  std::string out(kManifestMagic);
  out += "for " + key + "\n";
  out += "key " + manifest.entry_key + "\n";
  out += fmt_hex(manifest.token_hash) + "\n";
  for (const auto& [path, hash] : manifest.files) out += "file " + fmt_hex(hash) + " " + path + "\n";
  out += "check " + fmt_hex(XXH64(out.data(), out.size(), kChecksumSeed)) + "\n";
  return out;
}

namespace {

// One line of a manifest's body after the magic; false when malformed.
bool read_manifest_line(std::string_view line, int line_no, std::string& bound_key, IncludeManifest& m) {
  if (line_no == 0) {
    if (!line.starts_with("for ")) return false;
    bound_key = std::string(line.substr(4));
  } else if (line_no == 1) {
    if (!line.starts_with("key ")) return false;
    m.entry_key = std::string(line.substr(4));
  } else if (line_no == 2) {
    auto h = parse_hex(line);
    if (!h) return false;
    m.token_hash = *h;
  } else {
    if (!line.starts_with("file ") || line.size() < 22 || line[21] != ' ') return false;
    auto h = parse_hex(line.substr(5, 16));
    if (!h) return false;
    m.files.emplace_back(std::string(line.substr(22)), *h);
  }
  return true;
}

}  // namespace

Result<IncludeManifest> decode_manifest(std::string_view bytes, const std::string& key) {
  size_t check = bytes.rfind("check ");
  if (!bytes.starts_with(kManifestMagic) || check == std::string_view::npos || !bytes.ends_with("\n")) {
    return failure("not a facet include manifest of this version");
  }
  std::string_view body = bytes.substr(0, check);
  auto stated = parse_hex(bytes.substr(check + 6, bytes.size() - check - 7));
  if (!stated || *stated != XXH64(body.data(), body.size(), kChecksumSeed)) {
    return failure("truncated or altered (its checksum does not match)");
  }
  IncludeManifest m;
  std::string bound_key;
  size_t pos = kManifestMagic.size();
  int line_no = 0;
  while (pos < body.size()) {
    size_t eol = body.find('\n', pos);
    if (eol == std::string_view::npos) return failure("malformed");
    if (!read_manifest_line(body.substr(pos, eol - pos), line_no++, bound_key, m)) return failure("malformed");
    pos = eol + 1;
  }
  if (line_no < 3) return failure("malformed");
  if (bound_key != key) return failure(fmt::format("it was stored under another key ({})", bound_key));
  return m;
}

}  // namespace facet::cache
