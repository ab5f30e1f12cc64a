// Unity's keyword shortcuts with Unity's exact keyword combinations: counts,
// the listed combinations, modifiers removing whole combinations, stage
// views, what facet builds (reachable) and selection among the listed ones.
#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <sstream>

#include "facet/variants.h"

namespace facet::variants {
namespace {

using Keywords = std::vector<std::string>;

KeywordSpace space_of(std::string_view pragma_line) {
  ir::Program program;
  std::istringstream words{std::string(pragma_line)};
  ir::Pragma pragma;
  words >> pragma.name;
  for (std::string arg; words >> arg;) pragma.args.push_back(arg);
  pragma.span = SourceSpan{0, 0, uint32_t(pragma_line.size())};
  program.pragmas.push_back(pragma);
  Diagnostics diags;
  auto space = build_keyword_space(program, diags);
  EXPECT_TRUE(space.has_value());
  EXPECT_FALSE(diags.has_errors());
  return space ? *space : KeywordSpace{};
}

// Every variant's enabled keywords, sorted within a variant as Unity prints them.
std::set<Keywords> variants_of(const KeywordSpace& space, const EnumerateOptions& options = {}) {
  Diagnostics diags;
  auto keys = enumerate(space, options, diags);
  EXPECT_TRUE(keys.has_value());
  std::set<Keywords> out;
  if (!keys) return out;
  for (const VariantKey& key : *keys) {
    Keywords k = all_keywords(space, key);
    std::sort(k.begin(), k.end());
    out.insert(k);
  }
  return out;
}

struct CountCase {
  const char* pragma;
  uint64_t pass, vertex, fragment, reachable;
};

class ShortcutCountTest : public testing::TestWithParam<CountCase> {};

TEST_P(ShortcutCountTest, CountsUnitysCombinations) {
  const CountCase& c = GetParam();
  KeywordSpace space = space_of(c.pragma);
  EXPECT_EQ(count_variants(space).full, BigCount(c.pass));
  EXPECT_EQ(count_variants(space).after_skip, BigCount(c.pass));
  EXPECT_EQ(count_variants(space, {.stage = Stage::vertex}).full, BigCount(c.vertex));
  EXPECT_EQ(count_variants(space, {.stage = Stage::fragment}).full, BigCount(c.fragment));
  EXPECT_EQ(count_variants(space).reachable, BigCount(c.reachable));
  // Enumeration agrees with the count, and every variant is distinct.
  EXPECT_EQ(variants_of(space).size(), c.pass);
  EXPECT_EQ(variants_of(space, {.drop_unreachable = true}).size(), c.reachable);
}

// Unity's figures: fwdbase 83 (its fragment table has 63 rows; facet counts
// the 69 distinct fragment programs of the 83 variants, VERTEXLIGHT_ON being
// vertex-only; so for the fragment column of every fwdbase row), the
// modifiers' 20, 35, 52, 50, 46 and 63, fwdbasealpha 19, fwdadd 5, fwdadd_fullshadows and lightpass
// 47, shadowcaster 2, shadowcollector 4, prepassfinal 38, fog 4, particles 2,
// instancing 2.
INSTANTIATE_TEST_SUITE_P(
    Shortcuts, ShortcutCountTest,
    testing::Values(CountCase{"multi_compile_fwdbase", 83, 83, 69, 8},
                    CountCase{"multi_compile_fwdbasealpha", 19, 19, 16, 3},
                    CountCase{"multi_compile_fwdadd", 5, 5, 5, 5},
                    CountCase{"multi_compile_fwdadd_fullshadows", 47, 47, 47, 13},
                    CountCase{"multi_compile_lightpass", 47, 47, 47, 13},
                    CountCase{"multi_compile_shadowcaster", 2, 2, 2, 2},
                    CountCase{"multi_compile_shadowcollector", 4, 4, 4, 4},
                    CountCase{"multi_compile_prepassfinal", 38, 38, 38, 4},
                    CountCase{"multi_compile_fog", 4, 4, 4, 4},
                    CountCase{"multi_compile_particles", 2, 2, 2, 2},
                    CountCase{"multi_compile_instancing", 2, 2, 2, 2},
                    // Modifiers remove whole combinations (Unity's rule).
                    CountCase{"multi_compile_fwdbase noshadow", 20, 20, 16, 4},
                    CountCase{"multi_compile_fwdbase nolightmap", 35, 35, 21, 8},
                    CountCase{"multi_compile_fwdbase nodirlightmap", 52, 52, 40, 8},
                    CountCase{"multi_compile_fwdbase nodynlightmap", 50, 50, 43, 8},
                    CountCase{"multi_compile_fwdbase noshadowmask", 46, 46, 36, 8},
                    CountCase{"multi_compile_fwdbase novertexlight", 63, 63, 63, 4},
                    CountCase{"multi_compile_fwdbase novertexlight noshadowmask nodynlightmap nodirlightmap "
                              "nolightmap noshadow",
                              2, 2, 2, 2},
                    CountCase{"multi_compile_fwdadd_fullshadows noshadow", 5, 5, 5, 5}),
    [](const testing::TestParamInfo<CountCase>& info) {
      std::string name = info.param.pragma;
      std::replace(name.begin(), name.end(), ' ', '_');
      return name.substr(0, 60) + "_" + std::to_string(info.index);
    });

TEST(ShortcutSetsTest, ForwardBaseListsUnitysCombinationsAndNoOthers) {
  std::set<Keywords> all = variants_of(space_of("multi_compile_fwdbase"));
  for (const Keywords& k : all) EXPECT_TRUE(std::count(k.begin(), k.end(), "DIRECTIONAL") == 1);
  auto has = [&](Keywords k) {
    std::sort(k.begin(), k.end());
    return all.count(k) == 1;
  };
  EXPECT_TRUE(has({"DIRECTIONAL"}));
  EXPECT_TRUE(has({"DIRECTIONAL", "LIGHTPROBE_SH", "SHADOWS_SCREEN"}));
  EXPECT_TRUE(has({"DIRECTIONAL", "LIGHTMAP_ON", "LIGHTPROBE_SH"}));
  EXPECT_TRUE(has({"DIRECTIONAL", "DIRLIGHTMAP_COMBINED", "DYNAMICLIGHTMAP_ON", "LIGHTMAP_ON",
                   "LIGHTMAP_SHADOW_MIXING", "SHADOWS_SCREEN", "SHADOWS_SHADOWMASK"}));
  EXPECT_TRUE(has({"DIRECTIONAL", "LIGHTMAP_SHADOW_MIXING", "SHADOWS_SCREEN", "VERTEXLIGHT_ON"}));
  // Combinations Unity's list does not have.
  EXPECT_FALSE(has({"DIRECTIONAL", "DYNAMICLIGHTMAP_ON", "LIGHTPROBE_SH"}));
  EXPECT_FALSE(has({"DIRECTIONAL", "LIGHTMAP_ON", "VERTEXLIGHT_ON"}));
  EXPECT_FALSE(has({"DIRECTIONAL", "SHADOWS_SHADOWMASK"}));
  EXPECT_FALSE(has({"DIRECTIONAL", "DIRLIGHTMAP_COMBINED"}));
  EXPECT_FALSE(has({"DIRECTIONAL", "LIGHTMAP_SHADOW_MIXING", "SHADOWS_SCREEN"}));
}

TEST(ShortcutSetsTest, FullShadowsPairsEachShadowKindWithItsLights) {
  std::set<Keywords> all = variants_of(space_of("multi_compile_fwdadd_fullshadows"));
  for (const Keywords& k : all) {
    bool soft = std::count(k.begin(), k.end(), "SHADOWS_SOFT");
    bool depth = std::count(k.begin(), k.end(), "SHADOWS_DEPTH");
    bool cube = std::count(k.begin(), k.end(), "SHADOWS_CUBE");
    bool screen = std::count(k.begin(), k.end(), "SHADOWS_SCREEN");
    if (soft) {
      EXPECT_TRUE(depth || cube) << ::testing::PrintToString(k);
    }
    if (depth) {
      EXPECT_TRUE(std::count(k.begin(), k.end(), "SPOT")) << ::testing::PrintToString(k);
    }
    if (screen) {
      EXPECT_TRUE(std::count(k.begin(), k.end(), "DIRECTIONAL") || std::count(k.begin(), k.end(), "DIRECTIONAL_COOKIE"));
    }
  }
  EXPECT_EQ(all.count(Keywords{"SHADOWS_DEPTH", "SHADOWS_SOFT", "SPOT"}), 1u);
  EXPECT_EQ(all.count(Keywords{"DIRECTIONAL", "SHADOWS_SCREEN", "SHADOWS_SOFT"}), 0u);
}

TEST(ShortcutSetsTest, PrepassFinalAndShadowCollectorHaveAnAllOffVariant) {
  EXPECT_EQ(variants_of(space_of("multi_compile_prepassfinal")).count(Keywords{}), 1u);
  std::set<Keywords> collector = variants_of(space_of("multi_compile_shadowcollector"));
  EXPECT_EQ(collector, (std::set<Keywords>{{}, {"SHADOWS_SPLIT_SPHERES"}, {"SHADOWS_SINGLE_CASCADE"},
                                           {"SHADOWS_SINGLE_CASCADE", "SHADOWS_SPLIT_SPHERES"}}));
}

TEST(ShortcutSetsTest, VertexLightsApplyToTheVertexStageOnly) {
  KeywordSpace space = space_of("multi_compile_fwdbase");
  for (const KeywordSet& set : space.sets) {
    bool vertex_light = std::count(set.keywords.begin(), set.keywords.end(), "VERTEXLIGHT_ON");
    EXPECT_EQ(set.stages, vertex_light ? stage_bit(Stage::vertex) : kAllStages);
  }
}

TEST(ShortcutSetsTest, UnreachableKeywordsAreTheBakedLighting) {
  EXPECT_EQ(space_of("multi_compile_fwdbase").unreachable_keywords,
            (Keywords{"LIGHTMAP_ON", "DIRLIGHTMAP_COMBINED", "DYNAMICLIGHTMAP_ON", "SHADOWS_SHADOWMASK",
                      "LIGHTMAP_SHADOW_MIXING"}));
  EXPECT_TRUE(space_of("multi_compile_fog").unreachable_keywords.empty());
  // What facet builds of fwdbase: the eight its renderer draws with, vertex lights or not.
  EXPECT_EQ(variants_of(space_of("multi_compile_fwdbase"), {.drop_unreachable = true}),
            (std::set<Keywords>{{"DIRECTIONAL"},
                                {"DIRECTIONAL", "LIGHTPROBE_SH"},
                                {"DIRECTIONAL", "SHADOWS_SCREEN"},
                                {"DIRECTIONAL", "LIGHTPROBE_SH", "SHADOWS_SCREEN"},
                                {"DIRECTIONAL", "VERTEXLIGHT_ON"},
                                {"DIRECTIONAL", "LIGHTPROBE_SH", "VERTEXLIGHT_ON"},
                                {"DIRECTIONAL", "SHADOWS_SCREEN", "VERTEXLIGHT_ON"},
                                {"DIRECTIONAL", "LIGHTPROBE_SH", "SHADOWS_SCREEN", "VERTEXLIGHT_ON"}}));
}

TEST(ShortcutSetsTest, SelectionPicksAListedCombination) {
  KeywordSpace space = space_of("multi_compile_fwdbase");
  Diagnostics diags;
  // Listed: an exact match.
  auto exact = select_variant(space, {"LIGHTPROBE_SH", "SHADOWS_SCREEN"}, {"DIRECTIONAL"}, {}, diags);
  ASSERT_TRUE(exact.has_value());
  EXPECT_TRUE(exact->exact);
  // Not listed (no DYNAMICLIGHTMAP_ON with LIGHTPROBE_SH): the closest listed one.
  auto closest = select_variant(space, {"DYNAMICLIGHTMAP_ON", "LIGHTPROBE_SH"}, {}, {}, diags);
  ASSERT_TRUE(closest.has_value());
  EXPECT_FALSE(closest->exact);
  Keywords k = all_keywords(space, closest->key);
  std::sort(k.begin(), k.end());
  EXPECT_TRUE(variants_of(space).count(k)) << ::testing::PrintToString(k);
  // Strict: an error naming the combination.
  auto strict = select_variant(space, {"DYNAMICLIGHTMAP_ON", "LIGHTPROBE_SH"}, {}, {.strict = true}, diags);
  EXPECT_FALSE(strict.has_value());
  EXPECT_TRUE(diags.has_errors());
}

TEST(ShortcutSetsTest, ShortcutCombinesFreelyWithOtherSets) {
  ir::Program program;
  for (const char* line : {"multi_compile_fwdbase", "multi_compile_fog"}) {
    ir::Pragma pragma;
    pragma.name = line;
    program.pragmas.push_back(pragma);
  }
  Diagnostics diags;
  auto space = build_keyword_space(program, diags);
  ASSERT_TRUE(space.has_value());
  EXPECT_EQ(count_variants(*space).full, BigCount(83 * 4));
  EXPECT_EQ(count_variants(*space).reachable, BigCount(8 * 4));
}

}  // namespace
}  // namespace facet::variants

namespace facet::variants {
namespace {

// Unity's SpeedTree shaders declare LOD_FADE_CROSSFADE for the vertex and
// for the fragment stage: the keyword is on in both stages or in neither.
TEST(SharedStageKeywordTest, SetsOfDifferentStagesMayShareAKeyword) {
  ir::Program program;
  for (std::vector<std::string> words : {std::vector<std::string>{"multi_compile_vertex", "__", "LOD_FADE_PERCENTAGE",
                                                                  "LOD_FADE_CROSSFADE"},
                                         std::vector<std::string>{"multi_compile_fragment", "__", "LOD_FADE_CROSSFADE"}}) {
    ir::Pragma pragma;
    pragma.name = words[0];
    pragma.args.assign(words.begin() + 1, words.end());
    program.pragmas.push_back(pragma);
  }
  Diagnostics diags;
  auto space = build_keyword_space(program, diags);
  ASSERT_TRUE(space.has_value());
  EXPECT_FALSE(diags.has_errors());
  // Variants: none, PERCENTAGE, CROSSFADE (in both stages).
  EXPECT_EQ(count_variants(*space).full, BigCount(3));
  EXPECT_EQ(count_variants(*space, {.stage = Stage::vertex}).full, BigCount(3));
  EXPECT_EQ(count_variants(*space, {.stage = Stage::fragment}).full, BigCount(2));
  std::set<Keywords> all = variants_of(*space);
  EXPECT_EQ(all, (std::set<Keywords>{{}, {"LOD_FADE_PERCENTAGE"}, {"LOD_FADE_CROSSFADE"}}));
  auto pick = select_variant(*space, {"LOD_FADE_CROSSFADE"}, {}, {.strict = true}, diags);
  ASSERT_TRUE(pick.has_value());
  EXPECT_EQ(stage_keywords(*space, pick->key, Stage::fragment), (Keywords{"LOD_FADE_CROSSFADE"}));
  EXPECT_EQ(stage_keywords(*space, pick->key, Stage::vertex), (Keywords{"LOD_FADE_CROSSFADE"}));
}

KeywordSpace space_of_lines(const std::vector<std::string>& lines, Diagnostics& diags) {
  ir::Program program;
  for (const std::string& line : lines) {
    std::istringstream words(line);
    ir::Pragma pragma;
    words >> pragma.name;
    for (std::string arg; words >> arg;) pragma.args.push_back(arg);
    program.pragmas.push_back(pragma);
  }
  auto space = build_keyword_space(program, diags);
  EXPECT_TRUE(space.has_value());
  return space ? *space : KeywordSpace{};
}

// Unity's rule for a keyword two pragmas of one stage declare: a variant
// enables the union of its sets' choices, and equal unions are one variant.
TEST(SharedStageKeywordTest, SetsOfOneStageSharingAKeywordGiveEachUnionOnce) {
  Diagnostics diags;
  KeywordSpace space = space_of_lines({"multi_compile _ A B", "shader_feature C A"}, diags);
  EXPECT_FALSE(diags.has_errors());
  // {_,A,B} x {C,A} (two keywords: no off state): 6 choices, 5 distinct unions.
  EXPECT_EQ(variants_of(space), (std::set<Keywords>{{"A"}, {"C"}, {"A", "C"}, {"B", "C"}, {"A", "B"}}));
  EXPECT_EQ(count_variants(space).full, BigCount(5));
  EXPECT_EQ(count_variants(space, {.stage = Stage::fragment}).full, BigCount(5));
}

TEST(SharedStageKeywordTest, AVertexSetAndAnAllStageSetSharingAKeywordEnableItInEveryStage) {
  Diagnostics diags;
  KeywordSpace space = space_of_lines({"multi_compile_vertex _ A", "multi_compile _ A"}, diags);
  EXPECT_FALSE(diags.has_errors());
  EXPECT_EQ(variants_of(space), (std::set<Keywords>{{}, {"A"}}));
  EXPECT_EQ(count_variants(space).full, BigCount(2));
  Diagnostics pick_diags;
  auto pick = select_variant(space, {"A"}, {}, {.strict = true}, pick_diags);
  ASSERT_TRUE(pick.has_value());
  EXPECT_EQ(stage_keywords(space, pick->key, Stage::vertex), (Keywords{"A"}));
  EXPECT_EQ(stage_keywords(space, pick->key, Stage::fragment), (Keywords{"A"}));
}

// VRChat-style shaders declare VERTEXLIGHT_ON next to multi_compile_fwdbase,
// before or after it: the shortcut's combinations stay, and every one of
// them can also have the vertex lights on, in both stages.
TEST(SharedStageKeywordTest, VertexLightsDeclaredBesideForwardBaseJoinItsCombinations) {
  for (bool before : {true, false}) {
    Diagnostics diags;
    std::vector<std::string> lines = {"multi_compile_fwdbase", "multi_compile _ VERTEXLIGHT_ON"};
    if (before) std::swap(lines[0], lines[1]);
    KeywordSpace space = space_of_lines(lines, diags);
    EXPECT_FALSE(diags.has_errors()) << before;
    std::set<Keywords> fwdbase = variants_of(space_of("multi_compile_fwdbase"));
    std::set<Keywords> expected;
    for (Keywords k : fwdbase) {
      expected.insert(k);
      if (std::find(k.begin(), k.end(), "VERTEXLIGHT_ON") == k.end()) k.push_back("VERTEXLIGHT_ON");
      std::sort(k.begin(), k.end());
      expected.insert(k);
    }
    EXPECT_EQ(variants_of(space), expected) << before;
    EXPECT_EQ(count_variants(space).full, BigCount(expected.size())) << before;
    Diagnostics pick_diags;
    auto pick = select_variant(space, {"DIRECTIONAL", "VERTEXLIGHT_ON"}, {}, {.strict = true}, pick_diags);
    ASSERT_TRUE(pick.has_value()) << before;
    Keywords fragment = stage_keywords(space, pick->key, Stage::fragment);
    EXPECT_NE(std::find(fragment.begin(), fragment.end(), "VERTEXLIGHT_ON"), fragment.end()) << before;
  }
}

}  // namespace
}  // namespace facet::variants
