// count_variants: Unity's ladder (full, after skip_variants, after material
// usage) with hand-computed, exact numbers.
#include <gtest/gtest.h>

#include <sstream>

#include "facet/variants.h"
#include "unit/variants/pragma_lines.h"

namespace facet::variants {
namespace {

using pragma_lines::Lines;

using pragma_lines::program_of;
using pragma_lines::space_of;

// `n` pragmas "<directive> K<i>..." with `states` entries each.
Lines many_sets(const std::string& directive, int n, int states) {
  Lines lines;
  for (int i = 0; i < n; ++i) {
    std::string line = directive + " _";
    for (int k = 1; k < states; ++k) line += " K" + std::to_string(i) + "_" + std::to_string(k);
    lines.push_back(line);
  }
  return lines;
}

struct CountCase {
  const char* name;
  Lines lines;
  std::optional<Stage> stage;
  const char* full;
  const char* after_skip;
};

class VariantsCountTest : public ::testing::TestWithParam<CountCase> {};

TEST_P(VariantsCountTest, MatchesHandComputedCounts) {
  const CountCase& c = GetParam();
  VariantCounts counts = count_variants(space_of(c.lines), {.stage = c.stage});
  EXPECT_EQ(counts.full.to_string(), c.full);
  EXPECT_EQ(counts.after_skip.to_string(), c.after_skip);
  EXPECT_EQ(counts.after_materials, counts.after_skip);  // no material filter given
}

const auto kVertex = std::optional<Stage>(Stage::vertex);
const auto kFragment = std::optional<Stage>(Stage::fragment);
const auto kGeometry = std::optional<Stage>(Stage::geometry);

INSTANTIATE_TEST_SUITE_P(
    Ladder, VariantsCountTest,
    ::testing::Values(
        CountCase{"NoPragmas", {}, std::nullopt, "1", "1"},
        // Unity's listed combinations: fwdbase 83, fwdadd_fullshadows 47.
        CountCase{"FwdbaseAndFog", {"multi_compile_fwdbase", "multi_compile_fog"}, std::nullopt, "332", "332"},
        CountCase{"FwdaddFullshadows", {"multi_compile_fwdadd_fullshadows"}, std::nullopt, "47", "47"},
        CountCase{"Shadowcaster", {"multi_compile_shadowcaster"}, std::nullopt, "2", "2"},
        CountCase{"LoneMultiCompile", {"multi_compile A"}, std::nullopt, "1", "1"},
        CountCase{"LoneShaderFeature", {"shader_feature A"}, std::nullopt, "2", "2"},
        CountCase{"DynamicBranchAddsNothing", {"dynamic_branch A B", "multi_compile _ C"}, std::nullopt, "2", "2"},
        CountCase{"TwoStateSets70", many_sets("shader_feature", 70, 2), std::nullopt, "1180591620717411303424",
                  "1180591620717411303424"},
        CountCase{"ThreeStateSets41", many_sets("multi_compile", 41, 3), std::nullopt, "36472996377170786403",
                  "36472996377170786403"},
        // Stage suffixes: a stage counts only the sets applying to it.
        CountCase{"SuffixPass", {"multi_compile_vertex _ A B", "multi_compile_fragment _ C", "multi_compile _ D"},
                  std::nullopt, "12", "12"},
        CountCase{"SuffixVertex", {"multi_compile_vertex _ A B", "multi_compile_fragment _ C", "multi_compile _ D"},
                  kVertex, "6", "6"},
        CountCase{"SuffixFragment", {"multi_compile_vertex _ A B", "multi_compile_fragment _ C", "multi_compile _ D"},
                  kFragment, "4", "4"},
        CountCase{"SuffixGeometry", {"multi_compile_vertex _ A B", "multi_compile_fragment _ C", "multi_compile _ D"},
                  kGeometry, "2", "2"},
        CountCase{"FragmentOnlyFeatureVertex", {"multi_compile _ A", "shader_feature_local_fragment B"}, kVertex, "2",
                  "2"},
        // skip_variants removes keywords from their sets.
        CountCase{"SkipOne", {"multi_compile _ A B", "skip_variants A"}, std::nullopt, "3", "2"},
        CountCase{"SkipTheOnlyKeywordKeepsOffState", {"shader_feature A", "skip_variants A"}, std::nullopt, "2", "1"},
        CountCase{"SkipLoneMultiCompileKeepsOffState", {"multi_compile A", "multi_compile _ B", "skip_variants A"},
                  std::nullopt, "2", "2"},
        CountCase{"SkipWholeSet", {"multi_compile A B", "multi_compile _ C", "skip_variants A B"}, std::nullopt, "4",
                  "2"},
        // Skipping removes the listed combinations that hold the keywords.
        CountCase{"SkipShadows", {"multi_compile_fwdadd_fullshadows", "skip_variants SHADOWS_SOFT SHADOWS_CUBE"},
                  std::nullopt, "47", "27"},
        CountCase{"SkipInOtherStage", {"multi_compile_fragment _ A", "multi_compile _ B", "skip_variants A"}, kVertex,
                  "2", "2"},
        CountCase{"SkipBeyond2To64", [] {
                    Lines lines = many_sets("multi_compile", 70, 2);
                    lines.push_back("skip_variants K0_1 K1_1");
                    return lines;
                  }(),
                  std::nullopt, "1180591620717411303424", "295147905179352825856"}),
    [](const ::testing::TestParamInfo<CountCase>& info) { return std::string(info.param.name); });

class VariantsMaterialCountTest : public ::testing::Test {
 protected:
  VariantCounts count(const Lines& lines, std::vector<KeywordList> materials, std::optional<Stage> stage = {}) {
    return count_variants(space_of(lines), {.stage = stage, .materials = std::move(materials)});
  }
};

TEST_F(VariantsMaterialCountTest, ShaderFeatureKeepsOnlyUsedCombinations) {
  Lines lines = {"shader_feature _ A", "shader_feature _ B", "multi_compile_fog"};
  VariantCounts c = count(lines, {{"A"}, {"B"}, {"A", "B"}, {}, {"A"}});
  EXPECT_EQ(c.full, BigCount(16));
  EXPECT_EQ(c.after_materials, BigCount(16));  // all 4 combinations used, fog untouched
  EXPECT_EQ(count(lines, {{"A"}, {"A", "UNKNOWN"}}).after_materials, BigCount(4));
  EXPECT_EQ(count(lines, {{"A"}, {"B"}}).after_materials, BigCount(8));
}

TEST_F(VariantsMaterialCountTest, CombinationsAreJointNotPerSet) {
  // Materials {A} and {B} use (A,_) and (_,B), not the 4 per-set products.
  EXPECT_EQ(count({"shader_feature _ A", "shader_feature _ B"}, {{"A"}, {"B"}}).after_materials, BigCount(2));
}

TEST_F(VariantsMaterialCountTest, NoMaterialsLeaveNoShaderFeatureVariants) {
  EXPECT_EQ(count({"shader_feature _ A", "multi_compile _ B"}, {}).after_materials, BigCount(0));
  // Without shader_feature sets the filter changes nothing.
  EXPECT_EQ(count({"multi_compile _ A", "multi_compile _ B"}, {}).after_materials, BigCount(4));
}

TEST_F(VariantsMaterialCountTest, MaterialUsingASkippedKeywordGetsNoVariant) {
  Lines lines = {"shader_feature _ A B", "skip_variants A"};
  VariantCounts c = count(lines, {{"A"}, {"B"}, {}});
  EXPECT_EQ(c.full, BigCount(3));
  EXPECT_EQ(c.after_skip, BigCount(2));
  EXPECT_EQ(c.after_materials, BigCount(2));  // {B} and {}; {A} is dropped
  EXPECT_EQ(count(lines, {{"A"}}).after_materials, BigCount(0));
}

TEST_F(VariantsMaterialCountTest, NothingEnabledUsesTheFirstEntry) {
  // No off state: a material without A or B uses A; with both, the first declared.
  EXPECT_EQ(count({"shader_feature A B"}, {{}, {"A"}, {"A", "B"}}).after_materials, BigCount(1));
  EXPECT_EQ(count({"shader_feature A B"}, {{}, {"B"}}).after_materials, BigCount(2));
}

TEST_F(VariantsMaterialCountTest, StageViewProjectsMaterialCombinations) {
  Lines lines = {"shader_feature_fragment _ A", "shader_feature_vertex _ B", "multi_compile _ C"};
  std::vector<KeywordList> materials = {{"A"}, {"A", "B"}};
  EXPECT_EQ(count(lines, materials).after_materials, BigCount(4));
  EXPECT_EQ(count(lines, materials, Stage::vertex).after_materials, BigCount(4));
  EXPECT_EQ(count(lines, materials, Stage::fragment).after_materials, BigCount(2));
}

TEST_F(VariantsMaterialCountTest, LadderNeverGrows) {
  Lines lines = {"multi_compile_fwdbase", "shader_feature_local _ _NORMALMAP", "shader_feature _ _EMISSION",
                 "skip_variants SHADOWS_SCREEN"};
  VariantCounts c = count(lines, {{"_NORMALMAP"}});
  // fwdbase: 83 listed, 33 of them without SHADOWS_SCREEN; x 4 features.
  EXPECT_EQ(c.full, BigCount(332));
  EXPECT_EQ(c.after_skip, BigCount(132));
  EXPECT_EQ(c.after_materials, BigCount(33));
  // Without the keywords facet's renderer never enables: DIRECTIONAL ± LIGHTPROBE_SH ± VERTEXLIGHT_ON.
  EXPECT_EQ(c.reachable, BigCount(4));
  EXPECT_LE(c.reachable, c.after_materials);
  EXPECT_LE(c.after_materials, c.after_skip);
  EXPECT_LE(c.after_skip, c.full);
}

}  // namespace
}  // namespace facet::variants
