// Byte-level encoding of .facetpkg (docs/package-format.md): the layout
// constants, a little-endian Encoder that interns strings, and a bounded
// Decoder that never reads past its span, never allocates more than the
// input can justify, and records the first error with its byte offset.
#pragma once

#include <array>
#include <cstdint>
#include <map>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "facet/diagnostics.h"
#include "facet/ir.h"
#include "facet/package.h"
#include "facet/reflection.h"
#include "facet/variants.h"

namespace facet::package::codec {

// ---- Layout ---------------------------------------------------------------

inline constexpr std::array<uint8_t, 8> kMagic = {'F', 'A', 'C', 'E', 'T', 'P', 'K', 'G'};
// magic[8] version:u32 flags:u32 total_size:u64 checksum:u64
inline constexpr size_t kHeaderSize = 32;
inline constexpr size_t kVersionOffset = 8;
inline constexpr size_t kFlagsOffset = 12;
inline constexpr size_t kTotalSizeOffset = 16;
inline constexpr size_t kChecksumOffset = 24;
// The section table starts at kHeaderSize: count:u32 reserved:u32, then
// `count` entries of id:u32 reserved:u32 offset:u64 length:u64.
inline constexpr size_t kSectionTableHeaderSize = 8;
inline constexpr size_t kSectionEntrySize = 24;
inline constexpr size_t kSectionAlign = 8;
// Seed of the xxHash64 checksum over bytes [kHeaderSize, total_size).
inline constexpr uint64_t kChecksumSeed = 0;

// In file order; every section is present exactly once, in this order.
enum class SectionId : uint32_t { strings = 1, shader, properties, passes, keywords, variants, blobs };
inline constexpr uint32_t kSectionCount = 7;
std::string_view section_name(SectionId id);

// Nested BlockMember structs deeper than this are rejected (stack safety).
inline constexpr uint32_t kMaxMemberDepth = 32;
// Strings expand through references; decoded string bytes are limited to
// min(kStringBudgetFactor * file size + kStringBudgetBase, kStringBudgetMax).
inline constexpr uint64_t kStringBudgetFactor = 64;
inline constexpr uint64_t kStringBudgetBase = uint64_t(1) << 20;
inline constexpr uint64_t kStringBudgetMax = uint64_t(1) << 30;
inline uint64_t string_budget(uint64_t file_size) {
  uint64_t budget = kStringBudgetFactor * file_size + kStringBudgetBase;
  return budget < kStringBudgetMax ? budget : kStringBudgetMax;
}

// Largest valid value of each enum stored as a byte.
inline constexpr uint8_t kMaxPropertyType = uint8_t(ir::PropertyType::cube_array);
inline constexpr uint8_t kMaxKeywordDirective = 2;  // dynamic_branch
inline constexpr uint8_t kMaxStage = uint8_t(Stage::domain);
inline constexpr uint8_t kMaxResourceKind = uint8_t(ResourceKind::uniform_texel_buffer);

inline constexpr size_t align_up(size_t n, size_t a) { return (n + a - 1) / a * a; }

// ---- Encoding -------------------------------------------------------------

// Deduplicated strings, numbered in order of first use (deterministic).
class StringTable {
 public:
  uint32_t intern(std::string_view s);
  const std::vector<std::string>& strings() const { return strings_; }

 private:
  std::map<std::string, uint32_t, std::less<>> index_;
  std::vector<std::string> strings_;
};

// Appends little-endian values to a byte buffer. Strings are written as
// indices into the StringTable.
class Encoder {
 public:
  explicit Encoder(StringTable& strings) : strings_(&strings) {}

  void u8(uint8_t v) { bytes_.push_back(v); }
  void boolean(bool v) { u8(v ? 1 : 0); }
  void u32(uint32_t v);
  void i32(int32_t v) { u32(uint32_t(v)); }
  void u64(uint64_t v);
  void f32(float v);
  // A count of following elements; FACET_ICE past UINT32_MAX.
  void count(size_t n);
  void str(std::string_view s) { u32(strings_->intern(s)); }
  void strs(const std::vector<std::string>& v);
  void u32s(const std::vector<uint32_t>& v);

  std::vector<uint8_t>& bytes() { return bytes_; }

 private:
  StringTable* strings_;
  std::vector<uint8_t> bytes_;
};

// Little-endian helpers for the header, outside any Encoder.
void put_u32(std::vector<uint8_t>& out, size_t at, uint32_t v);
void put_u64(std::vector<uint8_t>& out, size_t at, uint64_t v);
uint32_t get_u32(std::span<const uint8_t> in, size_t at);
uint64_t get_u64(std::span<const uint8_t> in, size_t at);

// ---- Decoding -------------------------------------------------------------

// Shared by every Decoder of one read: the string table, the string budget
// and the first error.
struct DecodeContext {
  Diagnostics* diags = nullptr;
  std::vector<std::string> strings;
  uint64_t string_budget = 0;
  bool failed = false;

  // Reports "corrupt package: <what> at byte offset N" once; later errors
  // are consequences of the first and are dropped.
  void fail(uint64_t offset, std::string_view what);
};

// Reads from one section. After the first error every read returns a zero
// value and ok() is false; callers stop their loops on !ok().
class Decoder {
 public:
  Decoder(std::span<const uint8_t> data, uint64_t base_offset, DecodeContext& ctx)
      : data_(data), base_(base_offset), ctx_(&ctx) {}

  bool ok() const { return !ctx_->failed; }
  uint64_t offset() const { return base_ + pos_; }
  size_t remaining() const { return data_.size() - pos_; }
  void fail(std::string_view what) { fail_at(offset(), what); }
  void fail_at(uint64_t offset, std::string_view what) { ctx_->fail(offset, what); }

  uint8_t u8();
  uint32_t u32();
  int32_t i32() { return int32_t(u32()); }
  uint64_t u64();
  float f32();
  // 0 or 1; anything else is an error naming `what`.
  bool boolean(std::string_view what);
  // A byte that must be <= max.
  uint8_t enum_byte(uint8_t max, std::string_view what);
  // An element count; rejected when `count * min_element_size` exceeds the
  // bytes left, so a corrupt count never drives a large allocation.
  uint32_t count(size_t min_element_size, std::string_view what);
  // A string-table reference.
  std::string str();
  std::vector<std::string> strs(std::string_view what);
  std::vector<uint32_t> u32s(std::string_view what);
  // A string stored inline (the string table itself): length:u32 + bytes.
  std::string inline_string();
  // Errors unless every byte was consumed.
  void expect_end(std::string_view section);

 private:
  bool take(size_t n);

  std::span<const uint8_t> data_;
  uint64_t base_ = 0;
  size_t pos_ = 0;
  DecodeContext* ctx_;
};

// ---- Shared pieces --------------------------------------------------------

void encode_reflection(Encoder& e, const StageReflection& r);
StageReflection decode_reflection(Decoder& d);

// Invariant checks shared by read_package and validate_package: "" when
// fine, otherwise what is wrong. `previous` is the variant before `v` in its
// pass (nullptr for the first).
std::string check_variant(const variants::KeywordSpace& space, const PackageVariant& v,
                          const PackageVariant* previous, size_t blob_count);

}  // namespace facet::package::codec
