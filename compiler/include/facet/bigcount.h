// BigCount: an exact unsigned integer for variant counts. Unity's variant
// spaces routinely pass 2^64 (70 two-state sets is 2^70), and a count that
// silently wraps or rounds to a double is wrong exactly when it matters.
//
//   BigCount n = 1;
//   for (int i = 0; i < 70; ++i) n *= 2;
//   n.to_string();  // "1180591620717411303424"
#pragma once

#include <compare>
#include <cstdint>
#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

namespace facet {

// Arbitrary-precision unsigned integer supporting what counting needs:
// construction from uint64_t, +, saturating -, *, comparison and decimal printing.
// Invariant: limbs_ is little-endian base 2^32 with no most-significant zero
// limbs, so zero is the empty vector and equal values have equal limbs.
class BigCount {
 public:
  BigCount() = default;
  BigCount(uint64_t value);  // NOLINT: implicit so that counts read like numbers

  // base^exponent, exactly.
  static BigCount pow(uint64_t base, uint32_t exponent);

  BigCount& operator+=(const BigCount& other);
  BigCount& operator*=(const BigCount& other);
  // Saturating: a - b is 0 when b >= a (counts never go negative).
  BigCount& operator-=(const BigCount& other);
  friend BigCount operator+(BigCount a, const BigCount& b) { return a += b; }
  friend BigCount operator*(BigCount a, const BigCount& b) { return a *= b; }
  friend BigCount operator-(BigCount a, const BigCount& b) { return a -= b; }

  bool operator==(const BigCount&) const = default;
  std::strong_ordering operator<=>(const BigCount& other) const;

  bool is_zero() const { return limbs_.empty(); }
  // The value when it fits in 64 bits.
  std::optional<uint64_t> to_u64() const;
  // The nearest double (for estimates that multiply a count by seconds).
  double to_double() const;
  // Decimal digits, no separators: "0", "16", "1180591620717411303424".
  std::string to_string() const;

 private:
  void trim();
  std::vector<uint32_t> limbs_;
};

// Prints to_string(); lets GoogleTest show values in failure messages.
std::ostream& operator<<(std::ostream& out, const BigCount& value);

}  // namespace facet
