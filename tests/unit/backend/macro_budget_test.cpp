// The macro budget's estimate across #define and #undef: an #undef that
// runs whenever its text is read drops the name's definitions, one inside
// an #if (which may not run) keeps them.
#include <gtest/gtest.h>

#include <string>

#include "macro_budget.h"

namespace facet::backend {
namespace {

std::string macro_of(size_t tokens) {
  std::string body;
  for (size_t i = 0; i < tokens; ++i) body += " token";
  return "#define BIG" + body + "\n";
}

// `#define M i` / `#undef M` repeated kept every definition, and each new one
// was compared with all of them: an #undef outside every #if forgets them.
TEST(MacroBudgetTest, AnUndefOutsideEveryIfForgetsTheDefinitions) {
  MacroBudget budget(uint64_t(1) << 20);
  ASSERT_FALSE(budget.add_text(macro_of(1000) + "#undef BIG\nBIG\n"));
  EXPECT_LT(budget.estimated_bytes(), 100u);
}

TEST(MacroBudgetTest, AnUndefInsideAnIfMayNotRunAndKeepsThem) {
  MacroBudget budget(uint64_t(1) << 20);
  ASSERT_FALSE(budget.add_text(macro_of(1000) + "#if SOMETHING\n#undef BIG\n#endif\nBIG\n"));
  EXPECT_GT(budget.estimated_bytes(), 5000u);
}

TEST(MacroBudgetTest, AMacroDefinedAgainAfterItsUndefIsMeasuredAgain) {
  MacroBudget budget(uint64_t(1) << 20);
  ASSERT_FALSE(budget.add_text("#define SMALL x\n#define USES SMALL\n#undef SMALL\n" + macro_of(1000) +
                               "#define SMALL BIG\nUSES\n"));
  EXPECT_GT(budget.estimated_bytes(), 5000u);
}

}  // namespace
}  // namespace facet::backend
