// Stripping: keyword_rule pragmas, strip filters and implied keywords.
#include <gtest/gtest.h>

#include <sstream>

#include "facet/variants.h"
#include "unit/variants/pragma_lines.h"

namespace facet::variants {
namespace {

using pragma_lines::program_of;

KeywordSpace space_of(const std::vector<std::string>& lines, Diagnostics&) { return pragma_lines::space_of(lines); }

const std::vector<std::string> kPragmas = {"multi_compile _ A", "multi_compile _ B", "multi_compile _ C"};

// Which of the 8 variants of A x B x C survive.
std::vector<std::string> survivors(const KeywordSpace& space, const StripFilter& filter = {},
                                   const std::string& pass = "FORWARD", size_t index = 0) {
  Diagnostics diags;
  auto keys = enumerate(space, {}, diags);
  std::vector<std::string> out;
  for (const VariantKey& key : *keys) {
    std::vector<std::string> kw = all_keywords(space, key);
    if (strip_reason(space, kw, filter, pass, index)) continue;
    std::string name;
    for (const std::string& k : kw) name += k;
    out.push_back(name.empty() ? "-" : name);
  }
  return out;
}

TEST(VariantsStripTest, KeywordRulesParseAndStrip) {
  Diagnostics diags;
  auto lines = kPragmas;
  lines.push_back("keyword_rule requires A B");
  EXPECT_EQ(survivors(space_of(lines, diags)), (std::vector<std::string>{"-", "C", "B", "BC", "AB", "ABC"}));
  lines.back() = "keyword_rule excludes A B C";
  EXPECT_EQ(survivors(space_of(lines, diags)), (std::vector<std::string>{"-", "C", "B", "BC", "A"}));
  lines.back() = "keyword_rule implies C A";
  KeywordSpace implies = space_of(lines, diags);
  EXPECT_EQ(survivors(implies), (std::vector<std::string>{"-", "B", "A", "AC", "AB", "ABC"}));
  EXPECT_EQ(apply_implications(implies, {"C"}), (KeywordList{"C", "A"}));
  auto pick = select_variant(implies, {"C"}, {}, {}, diags);
  ASSERT_TRUE(pick);
  EXPECT_TRUE(pick->exact) << "C implies A, and the A C variant exists";
  EXPECT_EQ(all_keywords(implies, pick->key), (std::vector<std::string>{"A", "C"}));
}

TEST(VariantsStripTest, BadKeywordRulesAreErrors) {
  for (const std::string bad : {"keyword_rule requires A", "keyword_rule needs A B", "keyword_rule requires A 9x",
                                "keyword_rule excludes A NOT_DECLARED"}) {
    Diagnostics diags;
    auto lines = kPragmas;
    lines.push_back(bad);
    EXPECT_FALSE(build_keyword_space(program_of(lines), diags)) << bad;
    ASSERT_GE(diags.size(), 1u) << bad;
    EXPECT_EQ(diags.all()[0].id, DiagId::pragma_bad_keyword_rule) << bad;
  }
}

TEST(VariantsStripTest, FilterDenyAllowAlwaysOnOff) {
  Diagnostics diags;
  KeywordSpace space = space_of(kPragmas, diags);
  StripFilter deny{{{.kind = StripKind::deny, .keywords = {"A", "B"}}}};
  EXPECT_EQ(survivors(space, deny), (std::vector<std::string>{"-", "C", "B", "BC", "A", "AC"}));
  StripFilter with_allow = deny;
  with_allow.rules.push_back({.kind = StripKind::allow, .keywords = {"A", "B", "C"}});
  EXPECT_EQ(survivors(space, with_allow), (std::vector<std::string>{"-", "C", "B", "BC", "A", "AC", "ABC"}));
  StripFilter on{{{.kind = StripKind::always_on, .keywords = {"C"}}}};
  EXPECT_EQ(survivors(space, on), (std::vector<std::string>{"C", "BC", "AC", "ABC"}));
  StripFilter off{{{.kind = StripKind::always_off, .keywords = {"A", "B"}}}};
  EXPECT_EQ(survivors(space, off), (std::vector<std::string>{"-", "C"}));
}

TEST(VariantsStripTest, FilterRulesCanNameOnePass) {
  Diagnostics diags;
  KeywordSpace space = space_of(kPragmas, diags);
  StripFilter by_name{{{.kind = StripKind::always_off, .keywords = {"A"}, .pass = "forward"}}};
  EXPECT_EQ(survivors(space, by_name, "FORWARD", 0).size(), 4u);
  EXPECT_EQ(survivors(space, by_name, "SHADOW", 1).size(), 8u);
  StripFilter by_index{{{.kind = StripKind::always_off, .keywords = {"A"}, .pass = "1"}}};
  EXPECT_EQ(survivors(space, by_index, "FORWARD", 0).size(), 8u);
  EXPECT_EQ(survivors(space, by_index, "SHADOW", 1).size(), 4u);
}

}  // namespace
}  // namespace facet::variants
