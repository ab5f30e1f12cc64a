// select_variant: exact match, Unity's closest match and its tie-breaking,
// strict mode, and the keywords that are reported and ignored.
#include <gtest/gtest.h>

#include <algorithm>
#include <algorithm>
#include <sstream>

#include "facet/variants.h"
#include "unit/variants/pragma_lines.h"

namespace facet::variants {
namespace {

using pragma_lines::Lines;
using Keywords = std::vector<std::string>;

using pragma_lines::program_of;
using pragma_lines::space_of;

// The key whose keywords are `keywords` (one per set, "" for the off state).
VariantKey key_of(const KeywordSpace& space, const Keywords& per_set) {
  VariantKey key;
  for (size_t s = 0; s < space.sets.size(); ++s) {
    const auto& keywords = space.sets[s].keywords;
    auto it = std::find(keywords.begin(), keywords.end(), per_set.at(s));
    EXPECT_NE(it, keywords.end()) << per_set[s];
    key.choice.push_back(uint32_t(it - keywords.begin()));
  }
  return key;
}

// ---- table: which variant a keyword combination selects --------------------

struct SelectCase {
  const char* name;
  Lines space;
  Keywords material;
  Keywords global;
  Keywords expected;  // the chosen keyword of each set, "" for off
  bool exact;
};

class VariantsSelectTableTest : public ::testing::TestWithParam<SelectCase> {};

TEST_P(VariantsSelectTableTest, PicksTheExpectedVariant) {
  const SelectCase& c = GetParam();
  KeywordSpace space = space_of(c.space);
  Diagnostics diags;
  auto selection = select_variant(space, c.material, c.global, {}, diags);
  ASSERT_TRUE(selection.has_value());
  EXPECT_EQ(all_keywords(space, selection->key), all_keywords(space, key_of(space, c.expected)));
  EXPECT_EQ(selection->key, key_of(space, c.expected));
  EXPECT_EQ(selection->exact, c.exact);
  EXPECT_EQ(diags.size(), 0u);
}

// fwdbase's three reachable keywords as a plain product; selection among
// Unity's listed shortcut combinations is tested in shortcut_sets_test.cpp.
const Lines kForward = {"multi_compile DIRECTIONAL", "multi_compile _ LIGHTPROBE_SH", "multi_compile _ SHADOWS_SCREEN", "multi_compile_fog", "shader_feature_local _ _NORMALMAP",
                        "shader_feature _ _ALPHATEST_ON _ALPHABLEND_ON"};

INSTANTIATE_TEST_SUITE_P(
    Cases, VariantsSelectTableTest,
    ::testing::Values(
        SelectCase{"NothingEnabledUsesFirstEntries", kForward, {}, {}, {"DIRECTIONAL", "", "", "", "", ""}, true},
        SelectCase{"MaterialAndGlobalUnite",
                   kForward,
                   {"_NORMALMAP"},
                   {"SHADOWS_SCREEN", "FOG_EXP2"},
                   {"DIRECTIONAL", "", "SHADOWS_SCREEN", "FOG_EXP2", "_NORMALMAP", ""},
                   true},
        SelectCase{"FirstEntryOfSetWithoutOffState", {"multi_compile A B", "multi_compile _ C"}, {"C"}, {}, {"A", "C"},
                   true},
        SelectCase{"OffStateInTheMiddleMatchesNothingEnabled", {"multi_compile A _ B"}, {}, {}, {""}, true},
        // Two keywords of one set: no exact variant; closest shares one, ties
        // go to the first declared.
        SelectCase{"ConflictTiesToFirstDeclared", {"multi_compile _ A B", "multi_compile _ C"}, {"B", "A", "C"}, {},
                   {"A", "C"}, false},
        // A skipped keyword has no variant; the set falls back to its first
        // remaining entry.
        SelectCase{"SkippedKeywordFallsBack", {"multi_compile _ A B", "skip_variants A"}, {"A"}, {}, {""}, false},
        SelectCase{"SkippedFirstEntryIsPassedOver", {"multi_compile A B C", "skip_variants A"}, {}, {}, {"B"}, true}),
    [](const ::testing::TestParamInfo<SelectCase>& info) { return std::string(info.param.name); });

// A set whose keywords are all skipped has only kOffChoice, which key_of()
// cannot name, so this case is checked directly.
TEST(VariantsSelectOffTest, WholeSetSkippedSelectsOffChoice) {
  KeywordSpace space = space_of({"multi_compile A", "multi_compile _ C", "skip_variants A"});
  Diagnostics diags;
  auto enabled_c = select_variant(space, {"C"}, {}, {.strict = true}, diags);
  ASSERT_TRUE(enabled_c.has_value());
  EXPECT_TRUE(enabled_c->exact);
  EXPECT_EQ(enabled_c->key.choice, (std::vector<uint32_t>{kOffChoice, 1}));
  auto enabled_a = select_variant(space, {"A"}, {}, {}, diags);
  ASSERT_TRUE(enabled_a.has_value());
  EXPECT_FALSE(enabled_a->exact);
  EXPECT_EQ(enabled_a->key.choice, (std::vector<uint32_t>{kOffChoice, 0}));
}

// ---- closest match over an explicit list of compiled variants --------------

class VariantsSelectTest : public ::testing::Test {
 protected:
  KeywordSpace space = space_of({"shader_feature _ A", "shader_feature _ B", "shader_feature _ C"});
  Diagnostics diags;

  Selection select(const Keywords& material, const std::vector<VariantKey>& available, bool strict = false) {
    auto selection = select_variant(space, material, {}, {.strict = strict, .available = &available}, diags);
    EXPECT_TRUE(selection.has_value());
    return selection ? *selection : Selection{};
  }
  VariantKey key(const Keywords& per_set) { return key_of(space, per_set); }
};

TEST_F(VariantsSelectTest, ExactMatchInTheList) {
  std::vector<VariantKey> available = {key({"", "", ""}), key({"A", "B", ""})};
  Selection s = select({"B", "A"}, available);
  EXPECT_TRUE(s.exact);
  EXPECT_EQ(s.key, key({"A", "B", ""}));
}

TEST_F(VariantsSelectTest, ClosestMatchHasTheMostSharedKeywords) {
  std::vector<VariantKey> available = {key({"", "", ""}), key({"A", "", ""}), key({"A", "B", ""}),
                                       key({"", "", "C"})};
  Selection s = select({"A", "B", "C"}, available);
  EXPECT_FALSE(s.exact);
  EXPECT_EQ(s.key, key({"A", "B", ""}));
}

TEST_F(VariantsSelectTest, ClosestMatchTiesGoToTheFirstDeclared) {
  // {B} and {A} each share one keyword: the smallest key wins (the one that
  // comes first in enumerate()'s order), whatever the list's order.
  std::vector<VariantKey> available = {key({"", "B", ""}), key({"A", "", ""})};
  EXPECT_EQ(select({"A", "B"}, available).key, key({"", "B", ""}));
  std::reverse(available.begin(), available.end());
  EXPECT_EQ(select({"A", "B"}, available).key, key({"", "B", ""}));
  // No shared keyword at all: still the smallest key.
  EXPECT_EQ(select({"C"}, available).key, key({"", "B", ""}));
}

TEST_F(VariantsSelectTest, EmptyListIsAnError) {
  auto selection = select_variant(space, {"A"}, {}, {.available = nullptr}, diags);
  EXPECT_TRUE(selection.has_value());
  std::vector<VariantKey> none;
  auto failed = select_variant(space, {"A"}, {}, {.available = &none}, diags);
  EXPECT_FALSE(failed.has_value());
  EXPECT_EQ(diags.all().back().message, "the pass has no variants to select from");
}

// ---- strict mode -----------------------------------------------------------

TEST_F(VariantsSelectTest, StrictModeNamesTheMissingKeywordSet) {
  std::vector<VariantKey> available = {key({"", "", ""}), key({"A", "", ""})};
  auto selection = select_variant(space, {"C"}, {"A"}, {.strict = true, .available = &available}, diags);
  ASSERT_FALSE(selection.has_value());
  ASSERT_EQ(diags.size(), 1u);
  EXPECT_EQ(diags.all()[0].id, DiagId::variants_no_exact_match);
  EXPECT_EQ(diags.all()[0].severity, Severity::error);
  EXPECT_EQ(diags.all()[0].message, "strict variant matching: no variant has exactly the keywords 'A C'");
  EXPECT_EQ(selection.error().reason, "no variant matches the enabled keywords exactly");
}

TEST_F(VariantsSelectTest, StrictModeExplainsConflictsAndSkips) {
  KeywordSpace conflicted = space_of({"multi_compile _ X Y", "multi_compile _ Z", "skip_variants Z"});
  auto selection = select_variant(conflicted, {"Y", "X", "Z"}, {}, {.strict = true}, diags);
  ASSERT_FALSE(selection.has_value());
  const Diagnostic& d = diags.all().back();
  EXPECT_EQ(d.message, "strict variant matching: no variant has exactly the keywords 'X Y Z'");
  ASSERT_EQ(d.notes.size(), 2u);
  EXPECT_EQ(d.notes[0].span, conflicted.sets[0].span);
  EXPECT_EQ(d.notes[0].message, "more than one keyword of this set is enabled; a variant has at most one");
  EXPECT_EQ(d.notes[1].message, "'Z' is listed in skip_variants");
}

TEST_F(VariantsSelectTest, StrictModeAcceptsAnExactMatch) {
  auto selection = select_variant(space, {"B"}, {}, {.strict = true}, diags);
  ASSERT_TRUE(selection.has_value());
  EXPECT_TRUE(selection->exact);
  EXPECT_EQ(selection->key, key({"", "B", ""}));
  EXPECT_EQ(diags.size(), 0u);
}

// ---- reported keywords -----------------------------------------------------

TEST(VariantsSelectReportTest, UnknownKeywordsAreIgnoredAndReported) {
  KeywordSpace space = space_of({"multi_compile _ A"});
  Diagnostics diags;
  auto s = select_variant(space, {"NOPE", "A", "NOPE"}, {"GLOBAL_NOPE"}, {.strict = true}, diags);
  ASSERT_TRUE(s.has_value());
  EXPECT_TRUE(s->exact);
  EXPECT_EQ(s->unknown_keywords, (Keywords{"NOPE", "GLOBAL_NOPE"}));
}

TEST(VariantsSelectReportTest, GlobalKeywordsCannotEnableLocalOnes) {
  KeywordSpace space = space_of({"multi_compile_local _ L", "multi_compile _ G"});
  Diagnostics diags;
  auto s = select_variant(space, {}, {"L", "G"}, {}, diags);
  ASSERT_TRUE(s.has_value());
  EXPECT_EQ(all_keywords(space, s->key), (Keywords{"G"}));
  EXPECT_EQ(s->ignored_global_keywords, (Keywords{"L"}));
  // The same keyword from the material counts.
  auto m = select_variant(space, {"L"}, {"L"}, {}, diags);
  EXPECT_EQ(all_keywords(space, m->key), (Keywords{"L"}));
  EXPECT_TRUE(m->ignored_global_keywords.empty());
}

TEST(VariantsSelectReportTest, DynamicBranchKeywordsBecomeUniformBools) {
  KeywordSpace space = space_of({"dynamic_branch DB1 DB2", "multi_compile _ A"});
  Diagnostics diags;
  auto s = select_variant(space, {"DB2", "A"}, {"DB1"}, {.strict = true}, diags);
  ASSERT_TRUE(s.has_value());
  EXPECT_TRUE(s->exact);
  EXPECT_EQ(s->dynamic_branches_on, (Keywords{"DB2", "DB1"}));
  EXPECT_TRUE(s->unknown_keywords.empty());
}

}  // namespace
}  // namespace facet::variants
