// dump_keyword_space: the text of `facetc --dump=variants` / --list-variants,
// compared whole so that a format change shows in review.
#include <gtest/gtest.h>

#include <sstream>

#include "facet/variants.h"
#include "unit/variants/pragma_lines.h"

namespace facet::variants {
namespace {

using pragma_lines::Lines;

using pragma_lines::program_of;
using pragma_lines::space_of;

const Lines kForward = {"multi_compile DIRECTIONAL", "multi_compile _ LIGHTPROBE_SH", "multi_compile _ SHADOWS_SCREEN", "multi_compile_fog", "shader_feature_local_fragment _NORMALMAP",
                        "dynamic_branch _USE_X", "skip_variants SHADOWS_SCREEN FOG_EXP"};

TEST(VariantsDumpTest, SetsCountsAndVariants) {
  DumpOptions options{.stages = stage_bit(Stage::vertex) | stage_bit(Stage::fragment), .list_variants = true};
  EXPECT_EQ(dump_keyword_space(space_of(kForward), options),
            "keyword sets: 5\n"
            "  #0  multi_compile                  DIRECTIONAL\n"
            "  #1  multi_compile                  _ LIGHTPROBE_SH\n"
            "  #2  multi_compile                  _ SHADOWS_SCREEN\n"
            "  #3  multi_compile_fog              _ FOG_LINEAR FOG_EXP FOG_EXP2\n"
            "  #4  shader_feature_local_fragment  _ _NORMALMAP\n"
            "dynamic_branch: _USE_X\n"
            "skip_variants: SHADOWS_SCREEN FOG_EXP\n"
            "variant counts:\n"
            "            full  after skip_variants\n"
            "  pass        32  12\n"
            "  vertex      16  6\n"
            "  fragment    32  12\n"
            "variants: 12\n"
            "   0  DIRECTIONAL\n"
            "   1  DIRECTIONAL _NORMALMAP\n"
            "   2  DIRECTIONAL FOG_LINEAR\n"
            "   3  DIRECTIONAL FOG_LINEAR _NORMALMAP\n"
            "   4  DIRECTIONAL FOG_EXP2\n"
            "   5  DIRECTIONAL FOG_EXP2 _NORMALMAP\n"
            "   6  DIRECTIONAL LIGHTPROBE_SH\n"
            "   7  DIRECTIONAL LIGHTPROBE_SH _NORMALMAP\n"
            "   8  DIRECTIONAL LIGHTPROBE_SH FOG_LINEAR\n"
            "   9  DIRECTIONAL LIGHTPROBE_SH FOG_LINEAR _NORMALMAP\n"
            "  10  DIRECTIONAL LIGHTPROBE_SH FOG_EXP2\n"
            "  11  DIRECTIONAL LIGHTPROBE_SH FOG_EXP2 _NORMALMAP\n");
}

TEST(VariantsDumpTest, EmptySpace) {
  EXPECT_EQ(dump_keyword_space({}, {.stages = stage_bit(Stage::fragment), .list_variants = true}),
            "keyword sets: 0\n"
            "dynamic_branch: (none)\n"
            "skip_variants: (none)\n"
            "variant counts:\n"
            "            full  after skip_variants\n"
            "  pass         1  1\n"
            "  fragment     1  1\n"
            "variants: 1\n"
            "  0  (no keywords)\n");
}

TEST(VariantsDumpTest, HugeSpacePrintsItsExactCountInsteadOfAList) {
  Lines lines;
  for (int i = 0; i < 70; ++i) lines.push_back("shader_feature_vertex K" + std::to_string(i));
  DumpOptions options{.stages = stage_bit(Stage::vertex) | stage_bit(Stage::fragment), .list_variants = true};
  std::string text = dump_keyword_space(space_of(lines), options);
  std::string tail = text.substr(text.find("variant counts:"));
  EXPECT_EQ(tail,
            "variant counts:\n"
            "                              full  after skip_variants\n"
            "  pass      1180591620717411303424  1180591620717411303424\n"
            "  vertex    1180591620717411303424  1180591620717411303424\n"
            "  fragment                       1  1\n"
            "variants: 1180591620717411303424 (not listed: more than 4096)\n");
}

TEST(VariantsDumpTest, HandMadeSetsSpellTheirDirective) {
  KeywordSpace space;
  space.sets.push_back(KeywordSet{KeywordDirective::shader_feature, true, stage_bit(Stage::hull), {"", "H"}, "", {}});
  EXPECT_EQ(dump_keyword_space(space, {.counts = false}),
            "keyword sets: 1\n"
            "  #0  shader_feature_local_hull  _ H\n"
            "dynamic_branch: (none)\n"
            "skip_variants: (none)\n");
}

}  // namespace
}  // namespace facet::variants
