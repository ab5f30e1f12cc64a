// A little-endian byte codec shared by the package format and the compile
// cache: an Encoder that interns strings into a StringTable, and a bounded
// Decoder that never reads past its span, never allocates more than the
// input can justify, and records the first error with its byte offset.
// StageReflection has one binary form here, used by both.
#pragma once

#include <cstdint>
#include <functional>
#include <span>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "facet/diagnostics.h"
#include "facet/reflection.h"
#include "facet/stage.h"

namespace facet::codec {

// Nested BlockMember structs deeper than this are rejected (stack safety).
inline constexpr uint32_t kMaxMemberDepth = 32;
// Largest valid value of each enum stored as a byte.
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
  struct Hash {
    using is_transparent = void;
    size_t operator()(std::string_view s) const { return std::hash<std::string_view>{}(s); }
  };
  // Lookup only; the numbering comes from strings_, so iteration order never matters.
  std::unordered_map<std::string, uint32_t, Hash, std::equal_to<>> index_;
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
  // Takes `bytes` from the string budget (data that expands through
  // references); false and an error naming `what` when it runs out.
  bool charge(uint64_t bytes, std::string_view what);
  // Errors unless every byte was consumed.
  void expect_end(std::string_view section);

 private:
  bool take(size_t n);

  std::span<const uint8_t> data_;
  uint64_t base_ = 0;
  size_t pos_ = 0;
  DecodeContext* ctx_;
};

// ---- StageReflection -------------------------------------------------------

// Every field, in declaration order.
void encode_reflection(Encoder& e, const StageReflection& r);
StageReflection decode_reflection(Decoder& d);
// The smallest encoded StageReflection, which bounds a count of them.
inline constexpr size_t kReflectionMinSize = 1 + 4 + 6 * 4;
// An upper bound of the memory a decoded StageReflection holds beyond its
// encoded bytes' string references: what a copy of it costs the budget.
uint64_t reflection_weight(const StageReflection& r);

}  // namespace facet::codec
