// A Backend scans each included text once for all its programs: the cache
// gives back the same scan for the same text, a new one for any other, and
// the scan says what the uncached checks say.
#include <gtest/gtest.h>

#include <string>
#include <thread>
#include <vector>

#include "include_scan.h"

namespace facet::backend {
namespace {

TEST(IncludeScanCacheTest, TheSameTextIsScannedOnceAndAnotherTextAgain) {
  IncludeScanCache cache;
  auto first = cache.scan("#define A 1\nfloat f() { return A; }\n");
  auto again = cache.scan("#define A 1\nfloat f() { return A; }\n");
  auto other = cache.scan("#define A 2\nfloat f() { return A; }\n");
  EXPECT_EQ(first.get(), again.get());
  EXPECT_NE(first.get(), other.get());
  EXPECT_EQ(cache.size(), 2u);
  EXPECT_EQ(other->text, "#define A 2\nfloat f() { return A; }\n");
}

TEST(IncludeScanCacheTest, AScanHasTheTokensAndHazardOfTheUncachedChecks) {
  IncludeScanCache cache;
  const std::string text = "#define TWICE(x) x + x\nfloat g = TWICE(1);\n";
  auto scanned = cache.scan(text);
  MacroBudget::TokenLines direct = MacroBudget::tokenize(text);
  ASSERT_EQ(scanned->lines.tokens.size(), direct.tokens.size());
  for (size_t i = 0; i < direct.tokens.size(); ++i) {
    EXPECT_EQ(scanned->lines.tokens[i].text, direct.tokens[i].text);
    EXPECT_EQ(scanned->lines.tokens[i].offset, direct.tokens[i].offset);
  }
  EXPECT_EQ(scanned->lines.starts, direct.starts);
  EXPECT_FALSE(scanned->hazard);

  const std::string deep = "float h = " + std::string(100000, '!') + "1;\n";
  auto hazardous = cache.scan(deep);
  ASSERT_TRUE(hazardous->hazard);
  EXPECT_EQ(hazardous->hazard->offset, find_recursion_hazard(deep)->offset);
  EXPECT_EQ(cache.scan(deep)->hazard->message, hazardous->hazard->message);
}

// The budget reads a cached scan as it reads the text: a macro bomb split
// over two "files" is refused the same way either way.
TEST(IncludeScanCacheTest, TheMacroBudgetGivesTheSameVerdictOnACachedScan) {
  std::string bomb = "#define M0 x\n";
  for (int i = 1; i <= 40; ++i) bomb += "#define M" + std::to_string(i) + " M" + std::to_string(i - 1) + " M" +
                                         std::to_string(i - 1) + "\n";
  IncludeScanCache cache;
  MacroBudget direct(uint64_t(64) << 20), cached(uint64_t(64) << 20);
  auto direct_excess = direct.add_text(bomb);
  auto cached_excess = cached.add_lines(cache.scan(bomb)->lines);
  ASSERT_TRUE(direct_excess);
  ASSERT_TRUE(cached_excess);
  EXPECT_EQ(cached_excess->offset, direct_excess->offset);
  EXPECT_EQ(cached_excess->message, direct_excess->message);
}

TEST(IncludeScanCacheTest, ThreadsScanningOneTextShareOneScan) {
  IncludeScanCache cache;
  const std::string text(200000, 'a');
  std::vector<std::shared_ptr<const ScannedText>> keep(8);
  std::vector<std::thread> threads;
  for (size_t t = 0; t < keep.size(); ++t) {
    threads.emplace_back([&, t] { keep[t] = cache.scan(text); });
  }
  for (std::thread& t : threads) t.join();
  EXPECT_EQ(cache.size(), 1u);
  for (size_t t = 1; t < keep.size(); ++t) EXPECT_EQ(keep[t]->text, keep[0]->text);
  EXPECT_EQ(cache.scan(text).get(), cache.scan(text).get());
}

}  // namespace
}  // namespace facet::backend
