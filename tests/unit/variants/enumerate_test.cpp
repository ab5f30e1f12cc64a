// enumerate: exhaustive invariants over small spaces (Filament's
// test_variants.cpp style), plus order, projections and the cap.
#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <sstream>

#include "facet/variants.h"
#include "unit/variants/pragma_lines.h"

namespace facet::variants {
namespace {

using pragma_lines::Lines;
using Keywords = std::vector<std::string>;

using pragma_lines::program_of;
using pragma_lines::space_of;

std::vector<VariantKey> keys_of(const KeywordSpace& space, const EnumerateOptions& options) {
  Diagnostics diags;
  auto keys = enumerate(space, options, diags);
  EXPECT_TRUE(keys.has_value());
  return keys ? *keys : std::vector<VariantKey>{};
}

std::vector<Keywords> keyword_lists(const KeywordSpace& space, const std::vector<VariantKey>& keys) {
  std::vector<Keywords> lists;
  for (const VariantKey& key : keys) lists.push_back(all_keywords(space, key));
  return lists;
}

// ---- exhaustive checks over small spaces ----------------------------------

struct SmallSpace {
  const char* name;
  Lines lines;
};

class VariantsEnumerateExhaustiveTest : public ::testing::TestWithParam<SmallSpace> {
 protected:
  KeywordSpace space = space_of(GetParam().lines);
};

TEST_P(VariantsEnumerateExhaustiveTest, FullSpaceIsDistinctSortedAndCountedExactly) {
  std::vector<VariantKey> keys = keys_of(space, {.apply_skip_variants = false});
  EXPECT_EQ(BigCount(keys.size()), count_variants(space).full);
  EXPECT_TRUE(std::is_sorted(keys.begin(), keys.end()));
  EXPECT_EQ(std::adjacent_find(keys.begin(), keys.end()), keys.end()) << "duplicate key";
  for (const VariantKey& key : keys) {
    ASSERT_EQ(key.choice.size(), space.sets.size());
    for (size_t s = 0; s < space.sets.size(); ++s) EXPECT_LT(key.choice[s], space.sets[s].keywords.size());
  }
}

TEST_P(VariantsEnumerateExhaustiveTest, SkipVariantsRemovesExactlyTheSkippedKeywords) {
  std::vector<VariantKey> keys = keys_of(space, {});
  EXPECT_EQ(BigCount(keys.size()), count_variants(space).after_skip);
  EXPECT_TRUE(std::is_sorted(keys.begin(), keys.end()));
  EXPECT_EQ(std::adjacent_find(keys.begin(), keys.end()), keys.end());
  for (const Keywords& keywords : keyword_lists(space, keys)) {
    for (const std::string& skipped : space.skip_variants) {
      EXPECT_EQ(std::count(keywords.begin(), keywords.end(), skipped), 0) << skipped;
    }
  }
}

TEST_P(VariantsEnumerateExhaustiveTest, StageViewIsTheDistinctProjections) {
  std::vector<VariantKey> pass = keys_of(space, {});
  for (int s = 0; s < kStageCount; ++s) {
    Stage stage = Stage(s);
    std::set<VariantKey> projections;
    for (const VariantKey& key : pass) projections.insert(project(space, key, stage));
    std::vector<VariantKey> keys = keys_of(space, {.stage = stage});
    EXPECT_EQ(keys, std::vector<VariantKey>(projections.begin(), projections.end())) << stage_name(stage);
    EXPECT_EQ(BigCount(keys.size()), count_variants(space, {.stage = stage}).after_skip) << stage_name(stage);
    for (const VariantKey& key : keys) EXPECT_EQ(all_keywords(space, key), stage_keywords(space, key, stage));
  }
}

TEST_P(VariantsEnumerateExhaustiveTest, MaterialFilterMatchesItsCount) {
  // Every keyword of the space, one material each, plus the empty material.
  std::vector<KeywordList> materials = {{}};
  for (const KeywordSet& set : space.sets) {
    for (const std::string& keyword : set.keywords) {
      if (!keyword.empty()) materials.push_back({keyword});
    }
  }
  for (std::optional<Stage> stage : {std::optional<Stage>(), std::optional<Stage>(Stage::fragment)}) {
    std::vector<VariantKey> keys = keys_of(space, {.stage = stage, .materials = materials});
    EXPECT_EQ(BigCount(keys.size()), count_variants(space, {.stage = stage, .materials = materials}).after_materials);
    EXPECT_TRUE(std::is_sorted(keys.begin(), keys.end()));
    EXPECT_EQ(std::adjacent_find(keys.begin(), keys.end()), keys.end());
    std::vector<VariantKey> unfiltered = keys_of(space, {.stage = stage});
    for (const VariantKey& key : keys) {
      EXPECT_TRUE(std::binary_search(unfiltered.begin(), unfiltered.end(), key)) << "filter added a variant";
    }
  }
}

TEST_P(VariantsEnumerateExhaustiveTest, SelectingAVariantsOwnKeywordsReturnsIt) {
  std::vector<VariantKey> keys = keys_of(space, {});
  for (const SelectOptions& options : {SelectOptions{.strict = true}, SelectOptions{.available = &keys}}) {
    for (const VariantKey& key : keys) {
      Diagnostics diags;
      auto selection = select_variant(space, all_keywords(space, key), {}, options, diags);
      ASSERT_TRUE(selection.has_value());
      EXPECT_TRUE(selection->exact);
      EXPECT_EQ(selection->key, key);
    }
  }
}

TEST_P(VariantsEnumerateExhaustiveTest, ClosestMatchInSpaceEqualsScanOfEveryVariant) {
  // For every subset of the space's keywords (the spaces here have few).
  std::vector<std::string> universe;
  for (const KeywordSet& set : space.sets) {
    for (const std::string& keyword : set.keywords) {
      if (!keyword.empty()) universe.push_back(keyword);
    }
  }
  ASSERT_LE(universe.size(), 12u);
  std::vector<VariantKey> keys = keys_of(space, {});
  for (uint32_t mask = 0; mask < (1u << universe.size()); ++mask) {
    KeywordList enabled;
    for (size_t i = 0; i < universe.size(); ++i) {
      if (mask & (1u << i)) enabled.push_back(universe[i]);
    }
    Diagnostics diags;
    auto analytic = select_variant(space, enabled, {}, {}, diags);
    auto scanned = select_variant(space, enabled, {}, {.available = &keys}, diags);
    ASSERT_TRUE(analytic.has_value() && scanned.has_value());
    EXPECT_EQ(analytic->key, scanned->key) << "mask " << mask;
    EXPECT_EQ(analytic->exact, scanned->exact) << "mask " << mask;
  }
}

INSTANTIATE_TEST_SUITE_P(
    Spaces, VariantsEnumerateExhaustiveTest,
    ::testing::Values(
        SmallSpace{"Empty", {}},
        SmallSpace{"FwdbaseFog", {"multi_compile_fwdbase", "multi_compile_fog"}},
        SmallSpace{"StagesAndSkip",
                   {"multi_compile A B C", "shader_feature_local_fragment _ D", "multi_compile_vertex _ E F",
                    "skip_variants B"}},
        SmallSpace{"WholeSetSkipped",
                   {"multi_compile A", "shader_feature X", "multi_compile P Q", "skip_variants A P Q"}},
        SmallSpace{"OffStateInTheMiddle", {"multi_compile A _ B", "shader_feature_vertex C _", "skip_variants A"}},
        SmallSpace{"HullAndFeatures",
                   {"shader_feature_local _ A B C", "multi_compile_fragment _ D", "multi_compile_hull _ E",
                    "shader_feature F", "skip_variants C E"}}),
    [](const ::testing::TestParamInfo<SmallSpace>& info) { return std::string(info.param.name); });

// ---- order, views, cap -----------------------------------------------------

TEST(VariantsEnumerateTest, FirstSetVariesSlowest) {
  KeywordSpace space = space_of({"multi_compile _ A", "multi_compile X Y Z"});
  std::vector<Keywords> expected = {{"X"}, {"Y"}, {"Z"}, {"A", "X"}, {"A", "Y"}, {"A", "Z"}};
  EXPECT_EQ(keyword_lists(space, keys_of(space, {})), expected);
}

TEST(VariantsEnumerateTest, WholeSetSkippedKeepsItsOffState) {
  KeywordSpace space = space_of({"multi_compile A", "shader_feature X", "skip_variants A"});
  std::vector<VariantKey> keys = keys_of(space, {});
  ASSERT_EQ(keys.size(), 2u);
  EXPECT_EQ(keys[0].choice, (std::vector<uint32_t>{kOffChoice, 0}));
  EXPECT_EQ(keys[1].choice, (std::vector<uint32_t>{kOffChoice, 1}));
  EXPECT_EQ(keyword_lists(space, keys), (std::vector<Keywords>{{}, {"X"}}));
  // Without skip_variants the lone keyword is always on.
  EXPECT_EQ(keyword_lists(space, keys_of(space, {.apply_skip_variants = false})),
            (std::vector<Keywords>{{"A"}, {"A", "X"}}));
  KeywordSpace skipped = space_of({"multi_compile A", "skip_variants A"});
  std::vector<VariantKey> only = keys_of(skipped, {});
  ASSERT_EQ(only.size(), 1u);
  EXPECT_EQ(only[0].choice, (std::vector<uint32_t>{kOffChoice}));
  EXPECT_TRUE(all_keywords(skipped, only[0]).empty());
}

TEST(VariantsEnumerateTest, StageProjectionPinsOtherStagesSets) {
  KeywordSpace space = space_of({"multi_compile_vertex _ V", "multi_compile_fragment _ F"});
  std::vector<VariantKey> vertex = keys_of(space, {.stage = Stage::vertex});
  ASSERT_EQ(vertex.size(), 2u);
  EXPECT_EQ(vertex[0].choice, (std::vector<uint32_t>{0, kOffChoice}));
  EXPECT_EQ(vertex[1].choice, (std::vector<uint32_t>{1, kOffChoice}));
  EXPECT_EQ(keys_of(space, {.stage = Stage::geometry}).size(), 1u);
}

TEST(VariantsEnumerateTest, MaterialFilterKeepsUsedShaderFeatureCombinations) {
  KeywordSpace space = space_of({"shader_feature _ A", "multi_compile _ M", "shader_feature _ B"});
  std::vector<KeywordList> materials = {{"B"}, {"A", "B"}};
  std::vector<Keywords> expected = {{"B"}, {"M", "B"}, {"A", "B"}, {"A", "M", "B"}};
  EXPECT_EQ(keyword_lists(space, keys_of(space, {.materials = materials})), expected);
}

TEST(VariantsEnumerateTest, CapIsAClearErrorWithTheExactCount) {
  Lines lines;
  for (int i = 0; i < 70; ++i) lines.push_back("multi_compile _ K" + std::to_string(i));
  KeywordSpace space = space_of(lines);
  Diagnostics diags;
  auto keys = enumerate(space, {}, diags);
  ASSERT_FALSE(keys.has_value());
  ASSERT_EQ(diags.size(), 1u);
  const Diagnostic& d = diags.all()[0];
  EXPECT_EQ(d.id, DiagId::variants_too_many);
  EXPECT_EQ(d.span, space.sets[0].span);
  EXPECT_EQ(d.message,
            "the keyword space has 1180591620717411303424 variants (pass, after skip_variants), more than the "
            "enumeration limit of 65536");
  EXPECT_EQ(keys.error().reason, "too many variants to enumerate: 1180591620717411303424");
}

TEST(VariantsEnumerateTest, CapIsInclusive) {
  KeywordSpace space = space_of({"multi_compile _ A", "multi_compile _ B"});
  Diagnostics diags;
  EXPECT_TRUE(enumerate(space, {.max_variants = 4}, diags).has_value());
  EXPECT_FALSE(enumerate(space, {.max_variants = 3}, diags).has_value());
  EXPECT_EQ(diags.all().back().message,
            "the keyword space has 4 variants (pass, after skip_variants), more than the enumeration limit of 3");
  EXPECT_TRUE(enumerate(space, {.stage = Stage::vertex, .max_variants = 4}, diags).has_value());
}

}  // namespace
}  // namespace facet::variants
