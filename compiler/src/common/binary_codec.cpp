#include "facet/support/binary_codec.h"

#include <bit>
#include <cstdint>
#include <string>

#include "facet/result.h"

namespace facet::codec {

uint32_t StringTable::intern(std::string_view s) {
  auto it = index_.find(s);
  if (it != index_.end()) return it->second;
  if (strings_.size() >= UINT32_MAX) FACET_ICE("package string table overflow");
  uint32_t index = uint32_t(strings_.size());
  strings_.emplace_back(s);
  index_.emplace(std::string(s), index);
  return index;
}

void put_u32(std::vector<uint8_t>& out, size_t at, uint32_t v) {
  for (int i = 0; i < 4; ++i) out[at + size_t(i)] = uint8_t(v >> (8 * i));
}

void put_u64(std::vector<uint8_t>& out, size_t at, uint64_t v) {
  for (int i = 0; i < 8; ++i) out[at + size_t(i)] = uint8_t(v >> (8 * i));
}

uint32_t get_u32(std::span<const uint8_t> in, size_t at) {
  uint32_t v = 0;
  for (int i = 3; i >= 0; --i) v = (v << 8) | in[at + size_t(i)];
  return v;
}

uint64_t get_u64(std::span<const uint8_t> in, size_t at) {
  uint64_t v = 0;
  for (int i = 7; i >= 0; --i) v = (v << 8) | in[at + size_t(i)];
  return v;
}

void Encoder::u32(uint32_t v) {
  const uint8_t le[4] = {uint8_t(v), uint8_t(v >> 8), uint8_t(v >> 16), uint8_t(v >> 24)};
  bytes_.insert(bytes_.end(), le, le + 4);
}

void Encoder::u64(uint64_t v) {
  u32(uint32_t(v));
  u32(uint32_t(v >> 32));
}

void Encoder::f32(float v) { u32(std::bit_cast<uint32_t>(v)); }

void Encoder::count(size_t n) {
  if (n > UINT32_MAX) FACET_ICE("package element count exceeds 32 bits");
  u32(uint32_t(n));
}

void Encoder::strs(const std::vector<std::string>& v) {
  count(v.size());
  for (const std::string& s : v) str(s);
}

void Encoder::u32s(const std::vector<uint32_t>& v) {
  count(v.size());
  if constexpr (std::endian::native == std::endian::little) {
    const auto* first = reinterpret_cast<const uint8_t*>(v.data());
    bytes_.insert(bytes_.end(), first, first + v.size() * 4);
  } else {
    for (uint32_t x : v) u32(x);
  }
}

void DecodeContext::fail(uint64_t offset, std::string_view what) {
  if (failed) return;
  failed = true;
  if (diags) {
    diags->add(DiagId::package_corrupt, SourceSpan{},
               "corrupt package: " + std::string(what) + " at byte offset " + std::to_string(offset));
  }
}

bool Decoder::take(size_t n) {
  if (!ok()) return false;
  if (n > remaining()) {
    fail("unexpected end of section (" + std::to_string(n) + " bytes needed, " +
         std::to_string(remaining()) + " left)");
    return false;
  }
  return true;
}

uint8_t Decoder::u8() {
  if (!take(1)) return 0;
  return data_[pos_++];
}

uint32_t Decoder::u32() {
  if (!take(4)) return 0;
  uint32_t v = get_u32(data_, pos_);
  pos_ += 4;
  return v;
}

uint64_t Decoder::u64() {
  if (!take(8)) return 0;
  uint64_t v = get_u64(data_, pos_);
  pos_ += 8;
  return v;
}

float Decoder::f32() { return std::bit_cast<float>(u32()); }

bool Decoder::boolean(std::string_view what) {
  uint64_t at = offset();
  uint8_t v = u8();
  if (v > 1) fail_at(at, "invalid " + std::string(what) + " " + std::to_string(v) + " (expected 0 or 1)");
  return v == 1;
}

uint8_t Decoder::enum_byte(uint8_t max, std::string_view what) {
  uint64_t at = offset();
  uint8_t v = u8();
  if (v > max) {
    fail_at(at, "invalid " + std::string(what) + " " + std::to_string(v) + " (at most " + std::to_string(max) + ")");
    return 0;
  }
  return v;
}

uint32_t Decoder::count(size_t min_element_size, std::string_view what) {
  uint64_t at = offset();
  uint32_t n = u32();
  if (!ok()) return 0;
  if (uint64_t(n) * min_element_size > remaining()) {
    fail_at(at, std::string(what) + " count " + std::to_string(n) + " exceeds the " + std::to_string(remaining()) +
                    " bytes left in the section");
    return 0;
  }
  return n;
}

std::string Decoder::str() {
  uint64_t at = offset();
  uint32_t index = u32();
  if (!ok()) return {};
  if (index >= ctx_->strings.size()) {
    fail_at(at, "string index " + std::to_string(index) + " out of range (table has " +
                    std::to_string(ctx_->strings.size()) + " strings)");
    return {};
  }
  const std::string& s = ctx_->strings[index];
  if (s.size() > ctx_->string_budget) {
    fail_at(at, "strings expand past the decoding limit (64 x file size + 1 MiB, at most 1 GiB)");
    return {};
  }
  ctx_->string_budget -= s.size();
  return s;
}

std::vector<std::string> Decoder::strs(std::string_view what) {
  uint32_t n = count(4, what);
  std::vector<std::string> out;
  out.reserve(n);
  for (uint32_t i = 0; i < n && ok(); ++i) out.push_back(str());
  return out;
}

std::vector<uint32_t> Decoder::u32s(std::string_view what) {
  uint32_t n = count(4, what);
  std::vector<uint32_t> out;
  out.reserve(n);
  for (uint32_t i = 0; i < n && ok(); ++i) out.push_back(u32());
  return out;
}

std::string Decoder::inline_string() {
  uint64_t at = offset();
  uint32_t n = u32();
  if (!ok()) return {};
  if (n > remaining()) {
    fail_at(at, "string length " + std::to_string(n) + " exceeds the " + std::to_string(remaining()) +
                    " bytes left in the section");
    return {};
  }
  if (n == 0) return {};
  std::string s(reinterpret_cast<const char*>(data_.data() + pos_), n);
  pos_ += n;
  return s;
}

bool Decoder::charge(uint64_t bytes, std::string_view what) {
  if (!ok()) return false;
  if (bytes > ctx_->string_budget) {
    fail(std::string(what) + " expand past the decoding limit (64 x file size + 1 MiB, at most 1 GiB)");
    return false;
  }
  ctx_->string_budget -= bytes;
  return true;
}

void Decoder::expect_end(std::string_view section) {
  if (ok() && remaining() != 0) {
    fail(std::to_string(remaining()) + " unused bytes at the end of section '" + std::string(section) + "'");
  }
}

}  // namespace facet::codec
