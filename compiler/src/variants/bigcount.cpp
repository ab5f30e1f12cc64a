#include "facet/bigcount.h"

#include <ostream>

namespace facet {

BigCount::BigCount(uint64_t value) {
  while (value != 0) {
    limbs_.push_back(uint32_t(value));
    value >>= 32;
  }
}

BigCount BigCount::pow(uint64_t base, uint32_t exponent) {
  // Square-and-multiply: 3^41 and 2^70 need a handful of multiplications.
  BigCount result = 1;
  BigCount factor = base;
  while (exponent != 0) {
    if (exponent & 1u) result *= factor;
    exponent >>= 1;
    if (exponent != 0) factor *= factor;
  }
  return result;
}

void BigCount::trim() {
  while (!limbs_.empty() && limbs_.back() == 0) limbs_.pop_back();
}

BigCount& BigCount::operator+=(const BigCount& other) {
  if (limbs_.size() < other.limbs_.size()) limbs_.resize(other.limbs_.size(), 0);
  uint64_t carry = 0;
  for (size_t i = 0; i < limbs_.size(); ++i) {
    uint64_t sum = uint64_t(limbs_[i]) + carry + (i < other.limbs_.size() ? other.limbs_[i] : 0);
    limbs_[i] = uint32_t(sum);
    carry = sum >> 32;
  }
  if (carry != 0) limbs_.push_back(uint32_t(carry));
  return *this;
}

BigCount& BigCount::operator-=(const BigCount& other) {
  if (*this <= other) {
    limbs_.clear();
    return *this;
  }
  int64_t borrow = 0;
  for (size_t i = 0; i < limbs_.size(); ++i) {
    int64_t cell = int64_t(limbs_[i]) - borrow - (i < other.limbs_.size() ? int64_t(other.limbs_[i]) : 0);
    borrow = cell < 0;
    limbs_[i] = uint32_t(cell + (borrow << 32));
  }
  trim();
  return *this;
}

double BigCount::to_double() const {
  double value = 0;
  for (size_t i = limbs_.size(); i-- > 0;) value = value * 4294967296.0 + double(limbs_[i]);
  return value;
}

BigCount& BigCount::operator*=(const BigCount& other) {
  if (is_zero() || other.is_zero()) {
    limbs_.clear();
    return *this;
  }
  // Schoolbook multiplication; operands here have a few limbs at most.
  std::vector<uint32_t> product(limbs_.size() + other.limbs_.size(), 0);
  for (size_t i = 0; i < limbs_.size(); ++i) {
    uint64_t carry = 0;
    for (size_t j = 0; j < other.limbs_.size(); ++j) {
      uint64_t cell = uint64_t(limbs_[i]) * other.limbs_[j] + product[i + j] + carry;
      product[i + j] = uint32_t(cell);
      carry = cell >> 32;
    }
    for (size_t k = i + other.limbs_.size(); carry != 0; ++k) {
      uint64_t cell = uint64_t(product[k]) + carry;
      product[k] = uint32_t(cell);
      carry = cell >> 32;
    }
  }
  limbs_ = std::move(product);
  trim();
  return *this;
}

std::strong_ordering BigCount::operator<=>(const BigCount& other) const {
  // Trimmed limbs: more limbs means larger; otherwise compare from the top.
  if (limbs_.size() != other.limbs_.size()) return limbs_.size() <=> other.limbs_.size();
  for (size_t i = limbs_.size(); i-- > 0;) {
    if (limbs_[i] != other.limbs_[i]) return limbs_[i] <=> other.limbs_[i];
  }
  return std::strong_ordering::equal;
}

std::optional<uint64_t> BigCount::to_u64() const {
  if (limbs_.size() > 2) return std::nullopt;
  uint64_t value = 0;
  for (size_t i = limbs_.size(); i-- > 0;) value = (value << 32) | limbs_[i];
  return value;
}

std::string BigCount::to_string() const {
  if (is_zero()) return "0";
  // Repeated division by 10^9 yields nine decimal digits per step.
  constexpr uint32_t kChunk = 1000000000u;
  std::vector<uint32_t> rest = limbs_;
  std::vector<uint32_t> chunks;  // least significant first
  while (!rest.empty()) {
    uint64_t remainder = 0;
    for (size_t i = rest.size(); i-- > 0;) {
      uint64_t current = (remainder << 32) | rest[i];
      rest[i] = uint32_t(current / kChunk);
      remainder = current % kChunk;
    }
    chunks.push_back(uint32_t(remainder));
    while (!rest.empty() && rest.back() == 0) rest.pop_back();
  }
  std::string text = std::to_string(chunks.back());
  for (size_t i = chunks.size() - 1; i-- > 0;) {
    std::string digits = std::to_string(chunks[i]);
    text.append(9 - digits.size(), '0');
    text += digits;
  }
  return text;
}

std::ostream& operator<<(std::ostream& out, const BigCount& value) { return out << value.to_string(); }

}  // namespace facet
