#include "facet/bigcount.h"

#include <gtest/gtest.h>

#include <sstream>

namespace facet {
namespace {

struct PowCase {
  uint64_t base;
  uint32_t exponent;
  const char* expected;
};

class BigCountPowTest : public ::testing::TestWithParam<PowCase> {};

TEST_P(BigCountPowTest, PrintsExactly) {
  const PowCase& c = GetParam();
  EXPECT_EQ(BigCount::pow(c.base, c.exponent).to_string(), c.expected);
}

INSTANTIATE_TEST_SUITE_P(Powers, BigCountPowTest,
                         ::testing::Values(PowCase{2, 0, "1"}, PowCase{0, 0, "1"}, PowCase{0, 5, "0"},
                                           PowCase{2, 32, "4294967296"}, PowCase{2, 64, "18446744073709551616"},
                                           PowCase{2, 70, "1180591620717411303424"},
                                           PowCase{3, 41, "36472996377170786403"},
                                           PowCase{7, 23, "27368747340080916343"},
                                           PowCase{2, 128, "340282366920938463463374607431768211456"},
                                           PowCase{10, 30, "1000000000000000000000000000000"}));

TEST(BigCountTest, ZeroAndSmallValues) {
  EXPECT_EQ(BigCount().to_string(), "0");
  EXPECT_TRUE(BigCount().is_zero());
  EXPECT_EQ(BigCount(16).to_string(), "16");
  // Chunks of nine digits must keep their inner zeros.
  EXPECT_EQ(BigCount(1000000000ull).to_string(), "1000000000");
  EXPECT_EQ(BigCount(1000000007000000001ull).to_string(), "1000000007000000001");
}

TEST(BigCountTest, RepeatedSmallMultiplicationMatchesPow) {
  BigCount n = 1;
  for (int i = 0; i < 70; ++i) n *= 2;
  EXPECT_EQ(n, BigCount::pow(2, 70));
  EXPECT_EQ(n.to_string(), "1180591620717411303424");
}

TEST(BigCountTest, AdditionCarriesAcrossLimbs) {
  BigCount max64 = UINT64_MAX;
  EXPECT_EQ((max64 + 1).to_string(), "18446744073709551616");
  EXPECT_EQ((max64 + max64).to_string(), "36893488147419103230");
  EXPECT_EQ((BigCount() + BigCount()).to_string(), "0");
}

TEST(BigCountTest, MultiplicationOfLargeValues) {
  BigCount a = BigCount::pow(2, 64);
  EXPECT_EQ(a * a, BigCount::pow(2, 128));
  EXPECT_EQ((a * BigCount()).to_string(), "0");
  // (2^64 - 1)^2 = 2^128 - 2^65 + 1: every limb product carries.
  EXPECT_EQ((BigCount(UINT64_MAX) * BigCount(UINT64_MAX)).to_string(),
            "340282366920938463426481119284349108225");
}

TEST(BigCountTest, ComparesByValue) {
  EXPECT_LT(BigCount(5), BigCount(6));
  EXPECT_GT(BigCount::pow(2, 64), BigCount(UINT64_MAX));
  EXPECT_LT(BigCount::pow(2, 64), BigCount::pow(2, 65));
  EXPECT_EQ(BigCount(7), BigCount(7));
  EXPECT_TRUE(BigCount::pow(2, 70) > BigCount(65536));
}

TEST(BigCountTest, ToU64OnlyWhenItFits) {
  EXPECT_EQ(BigCount(UINT64_MAX).to_u64(), UINT64_MAX);
  EXPECT_EQ(BigCount().to_u64(), 0u);
  EXPECT_FALSE(BigCount::pow(2, 64).to_u64().has_value());
}

TEST(BigCountTest, SubtractionBorrowsAcrossLimbsAndSaturatesAtZero) {
  // 2^65 - 1 = 36893488147419103231: a borrow through two zero limbs.
  EXPECT_EQ((BigCount::pow(2, 65) - 1).to_string(), "36893488147419103231");
  EXPECT_EQ((BigCount::pow(2, 65) - BigCount::pow(2, 64)).to_string(), "18446744073709551616");
  EXPECT_EQ(BigCount(3) * BigCount::pow(2, 64) - BigCount(3) * BigCount::pow(2, 63),
            BigCount(3) * BigCount::pow(2, 63));
  EXPECT_TRUE((BigCount(5) - BigCount(7)).is_zero()) << "counts never go negative";
  EXPECT_TRUE((BigCount::pow(2, 70) - BigCount::pow(2, 70)).is_zero());
}

TEST(BigCountTest, ToDoubleIsTheNearestDouble) {
  EXPECT_EQ(BigCount(0).to_double(), 0.0);
  EXPECT_EQ(BigCount(12345).to_double(), 12345.0);
  EXPECT_EQ(BigCount::pow(2, 65).to_double(), 36893488147419103232.0);
  EXPECT_DOUBLE_EQ(BigCount::pow(3, 41).to_double(), 36472996377170786403.0);
}

TEST(BigCountTest, StreamsAsDecimal) {
  std::ostringstream out;
  out << BigCount::pow(3, 41);
  EXPECT_EQ(out.str(), "36472996377170786403");
}

}  // namespace
}  // namespace facet
