// The macro budget across repeated definitions: a definition given again is
// known by its hash, and the number of different definitions of one name is
// bounded, since every use weighs each of them.
#include <gtest/gtest.h>

#include <string>

#include "macro_budget.h"

namespace facet::backend {
namespace {

std::string define_undef_pairs(size_t count, bool distinct) {
  std::string text;
  for (size_t i = 0; i < count; ++i) text += "#define M " + std::to_string(distinct ? i : 7) + "\n#undef M\n";
  return text;
}

// 40,000 `#define M i` / `#undef M` pairs compared each definition with all
// the earlier ones (minutes); the same definition repeated is one.
TEST(MacroBudgetTest, ARepeatedDefinitionIsKnownAndCountedOnce) {
  MacroBudget budget(uint64_t(1) << 20);
  EXPECT_FALSE(budget.add_text(define_undef_pairs(100000, false) + "M M M\n"));
  EXPECT_LT(budget.estimated_bytes(), 100u);
}

TEST(MacroBudgetTest, MoreThanItsLimitOfDifferentDefinitionsIsRefusedAtTheDefine) {
  MacroBudget budget(uint64_t(1) << 20);
  std::string text = define_undef_pairs(kMaxDefinitions, true);
  const size_t last = text.size();
  text += "#define M past\n";
  std::optional<MacroExcess> excess = budget.add_text(text);
  ASSERT_TRUE(excess);
  EXPECT_EQ(excess->offset, last + std::string("#define ").size());
  EXPECT_EQ(excess->message,
            "macro 'M' has more than 1024 different definitions in one program (every one is "
            "weighed at each use, as an #if may pick any)");
}

// An #undef is not trusted: the budget reads a file before the files it
// includes, so a definition undone after an #include still counts for it.
TEST(MacroBudgetTest, AnUndefDoesNotHideADefinitionFromLaterTexts) {
  MacroBudget budget(uint64_t(1) << 20);
  std::string big = "#define BIG";
  for (int i = 0; i < 1000; ++i) big += " token";
  ASSERT_FALSE(budget.add_text(big + "\n#include \"uses.cginc\"\n#undef BIG\n"));
  ASSERT_FALSE(budget.add_text("BIG\n"));  // uses.cginc, read after its includer
  EXPECT_GT(budget.estimated_bytes(), 5000u);
}

}  // namespace
}  // namespace facet::backend
