// build_keyword_space: every pragma rule of docs/variants.md.
#include <gtest/gtest.h>

#include <sstream>

#include "facet/variants.h"

namespace facet::variants {
namespace {

using Keywords = std::vector<std::string>;
using Lines = std::vector<std::string_view>;

// A program whose pragmas are the given lines ("multi_compile A B"); each
// pragma's span is its line's byte range in file 0.
ir::Program program_of(const Lines& lines) {
  ir::Program program;
  uint32_t offset = 0;
  for (std::string_view line : lines) {
    std::istringstream words{std::string(line)};
    ir::Pragma pragma;
    words >> pragma.name;
    for (std::string arg; words >> arg;) pragma.args.push_back(arg);
    pragma.span = SourceSpan{0, offset, offset + uint32_t(line.size())};
    offset += uint32_t(line.size()) + 1;
    program.pragmas.push_back(std::move(pragma));
  }
  return program;
}

SourceSpan line_span(const Lines& lines, size_t index) {
  uint32_t offset = 0;
  size_t i = 0;
  for (std::string_view line : lines) {
    if (i++ == index) return SourceSpan{0, offset, offset + uint32_t(line.size())};
    offset += uint32_t(line.size()) + 1;
  }
  return {};
}

class VariantsBuildTest : public ::testing::Test {
 protected:
  // Builds and expects success.
  KeywordSpace build(const Lines& lines) {
    auto space = build_keyword_space(program_of(lines), diags);
    EXPECT_TRUE(space.has_value()) << dump_messages();
    return space ? *space : KeywordSpace{};
  }
  // Builds and expects failure.
  void build_fails(const Lines& lines) {
    auto space = build_keyword_space(program_of(lines), diags);
    EXPECT_FALSE(space.has_value());
    EXPECT_TRUE(diags.has_errors());
  }
  std::string dump_messages() const {
    std::string text;
    for (const Diagnostic& d : diags.all()) text += std::string(diag_name(d.id)) + ": " + d.message + "\n";
    return text;
  }
  size_t count(DiagId id) const {
    size_t n = 0;
    for (const Diagnostic& d : diags.all()) n += d.id == id ? 1 : 0;
    return n;
  }
  const Diagnostic& first(DiagId id) const {
    for (const Diagnostic& d : diags.all()) {
      if (d.id == id) return d;
    }
    ADD_FAILURE() << "no diagnostic " << diag_name(id) << "\n" << dump_messages();
    static const Diagnostic none;
    return none;
  }

  Diagnostics diags;
};

TEST_F(VariantsBuildTest, AnyAllUnderscoreNameIsTheEmptyKeyword) {
  KeywordSpace space = build({"multi_compile _ A", "multi_compile __ B", "multi_compile ___ C"});
  ASSERT_EQ(space.sets.size(), 3u);
  EXPECT_EQ(space.sets[0].keywords, (Keywords{"", "A"}));
  EXPECT_EQ(space.sets[1].keywords, (Keywords{"", "B"}));
  EXPECT_EQ(space.sets[2].keywords, (Keywords{"", "C"}));
  EXPECT_EQ(diags.size(), 0u);
}

TEST_F(VariantsBuildTest, SingleShaderFeatureGetsAnImplicitOffState) {
  KeywordSpace space = build({"shader_feature A", "shader_feature_local B"});
  EXPECT_EQ(space.sets[0].keywords, (Keywords{"", "A"}));
  EXPECT_EQ(space.sets[1].keywords, (Keywords{"", "B"}));
}

TEST_F(VariantsBuildTest, SingleMultiCompileHasNoOffState) {
  KeywordSpace space = build({"multi_compile A"});
  EXPECT_EQ(space.sets[0].keywords, (Keywords{"A"}));
}

TEST_F(VariantsBuildTest, OffStateStaysWhereItWasWritten) {
  KeywordSpace space = build({"shader_feature A _", "multi_compile A2 _ B2"});
  EXPECT_EQ(space.sets[0].keywords, (Keywords{"A", ""}));
  EXPECT_EQ(space.sets[1].keywords, (Keywords{"A2", "", "B2"}));
}

TEST_F(VariantsBuildTest, DuplicateInOneSetWarnsAndIsDropped) {
  KeywordSpace space = build({"multi_compile A B A", "shader_feature _ __ C"});
  EXPECT_EQ(space.sets[0].keywords, (Keywords{"A", "B"}));
  EXPECT_EQ(space.sets[1].keywords, (Keywords{"", "C"}));
  EXPECT_EQ(count(DiagId::pragma_duplicate_keyword), 2u);
  EXPECT_EQ(first(DiagId::pragma_duplicate_keyword).severity, Severity::warning);
  EXPECT_EQ(first(DiagId::pragma_duplicate_keyword).message,
            "duplicate keyword 'A' in '#pragma multi_compile'; the repeat is ignored");
}

TEST_F(VariantsBuildTest, DuplicateLoneShaderFeatureStillGetsOffState) {
  KeywordSpace space = build({"shader_feature A A"});
  EXPECT_EQ(space.sets[0].keywords, (Keywords{"", "A"}));
}

TEST_F(VariantsBuildTest, AKeywordInTwoSetsJoinsThemInOneCombinationGroup) {
  KeywordSpace space = build({"multi_compile _ A B", "shader_feature C A"});
  EXPECT_EQ(count(DiagId::pragma_keyword_in_two_sets), 0u);
  ASSERT_EQ(space.sets.size(), 2u);
  EXPECT_EQ(space.sets[1].keywords, (Keywords{"C", "A"}));
  ASSERT_EQ(space.combinations.size(), 1u);
  EXPECT_EQ(space.combinations[0].sets, (std::vector<size_t>{0, 1}));
  // {_, A, B} x {C, A}: (_,A) and (A,A) are one variant, A; five in all.
  EXPECT_EQ(space.combinations[0].choices.size(), 5u);
}

TEST_F(VariantsBuildTest, KeywordInASetAndADynamicBranchIsAnError) {
  build_fails({"dynamic_branch A", "multi_compile _ A"});
  EXPECT_EQ(count(DiagId::pragma_keyword_in_two_sets), 1u);
}

// Unity compiles a repeated keyword set once: a surface shader's own
// '#pragma multi_compile_fog' next to the one its lowering adds.
TEST_F(VariantsBuildTest, ARepeatedKeywordSetCountsOnceWithANoteAtTheFirst) {
  Lines lines = {"multi_compile_fog", "multi_compile _ B", "multi_compile_fog"};
  KeywordSpace space = build(lines);
  ASSERT_EQ(space.sets.size(), 2u);
  EXPECT_EQ(space.sets[0].keywords, (Keywords{"", "FOG_LINEAR", "FOG_EXP", "FOG_EXP2"}));
  const Diagnostic& d = first(DiagId::pragma_repeated_keyword_set);
  EXPECT_EQ(d.severity, Severity::note);
  EXPECT_EQ(d.span, line_span(lines, 2));
  ASSERT_EQ(d.notes.size(), 1u);
  EXPECT_EQ(d.notes[0].span, line_span(lines, 0));
}

TEST_F(VariantsBuildTest, TheSameKeywordsInAnotherOrderAreARepeatToo) {
  KeywordSpace space = build({"multi_compile _ A B", "multi_compile B _ A"});
  EXPECT_EQ(space.sets.size(), 1u);
  EXPECT_EQ(count(DiagId::pragma_repeated_keyword_set), 1u);
}

TEST_F(VariantsBuildTest, SetsSharingAKeywordWithTooManyCombinationsAreAnError) {
  std::string a = "multi_compile", b = "multi_compile";
  for (int i = 0; i < 1100; ++i) a += " A" + std::to_string(i);
  for (int i = 0; i < 1000; ++i) b += " B" + std::to_string(i);
  b += " A0";
  build_fails({a, b});
  EXPECT_EQ(count(DiagId::pragma_keyword_in_two_sets), 1u);
  EXPECT_NE(first(DiagId::pragma_keyword_in_two_sets).message.find("too many to combine"), std::string::npos);
}

TEST_F(VariantsBuildTest, AnOverlappingButDifferentSetCombinesWithTheShortcut) {
  KeywordSpace space = build({"multi_compile_fog", "multi_compile _ FOG_LINEAR"});
  EXPECT_EQ(count(DiagId::pragma_keyword_in_two_sets), 0u);
  // The fog set {_, LINEAR, EXP, EXP2} and {_, LINEAR}: LINEAR with EXP or EXP2 is a variant too.
  EXPECT_EQ(count_variants(space).full, BigCount(6));
}

struct DirectiveCase {
  const char* pragma;
  KeywordDirective directive;
  bool local;
  StageMask stages;
};

class VariantsDirectiveTest : public VariantsBuildTest, public ::testing::WithParamInterface<DirectiveCase> {};

TEST_P(VariantsDirectiveTest, ParsesDirectiveLocalAndStage) {
  const DirectiveCase& c = GetParam();
  std::string line = std::string(c.pragma) + " _ KW";
  KeywordSpace space = build({line});
  ASSERT_EQ(space.sets.size(), 1u);
  EXPECT_EQ(space.sets[0].directive, c.directive);
  EXPECT_EQ(space.sets[0].local, c.local);
  EXPECT_EQ(space.sets[0].stages, c.stages);
  EXPECT_EQ(space.sets[0].pragma, c.pragma);
}

constexpr auto mc = KeywordDirective::multi_compile;
constexpr auto sf = KeywordDirective::shader_feature;

INSTANTIATE_TEST_SUITE_P(
    Spellings, VariantsDirectiveTest,
    ::testing::Values(DirectiveCase{"multi_compile", mc, false, kAllStages},
                      DirectiveCase{"multi_compile_local", mc, true, kAllStages},
                      DirectiveCase{"shader_feature", sf, false, kAllStages},
                      DirectiveCase{"shader_feature_local", sf, true, kAllStages},
                      DirectiveCase{"multi_compile_vertex", mc, false, stage_bit(Stage::vertex)},
                      DirectiveCase{"multi_compile_local_fragment", mc, true, stage_bit(Stage::fragment)},
                      DirectiveCase{"shader_feature_geometry", sf, false, stage_bit(Stage::geometry)},
                      DirectiveCase{"shader_feature_local_hull", sf, true, stage_bit(Stage::hull)},
                      DirectiveCase{"shader_feature_local_domain", sf, true, stage_bit(Stage::domain)},
                      DirectiveCase{"shader_feature_local_fragment", sf, true, stage_bit(Stage::fragment)}));

TEST_F(VariantsBuildTest, DynamicBranchIsRecordedWithoutVariants) {
  KeywordSpace space = build({"dynamic_branch _ A", "dynamic_branch_local_fragment B C", "multi_compile _ D"});
  EXPECT_EQ(space.dynamic_branch_keywords, (Keywords{"A", "B", "C"}));
  ASSERT_EQ(space.sets.size(), 1u);
  EXPECT_EQ(space.sets[0].keywords, (Keywords{"", "D"}));
}

struct ShortcutCase {
  const char* pragma;
  std::vector<Keywords> sets;
};

class VariantsShortcutTest : public VariantsBuildTest, public ::testing::WithParamInterface<ShortcutCase> {};

TEST_P(VariantsShortcutTest, ExpandsToTheFixedSets) {
  const ShortcutCase& c = GetParam();
  KeywordSpace space = build({c.pragma});
  std::vector<Keywords> sets;
  for (const KeywordSet& set : space.sets) {
    sets.push_back(set.keywords);
    EXPECT_EQ(set.directive, KeywordDirective::multi_compile);
    EXPECT_FALSE(set.local);
    // Unity's fragment programs never see VERTEXLIGHT_ON.
    bool vertex_light = set.keywords.back() == "VERTEXLIGHT_ON";
    EXPECT_EQ(set.stages, vertex_light ? stage_bit(Stage::vertex) : kAllStages);
    EXPECT_EQ(set.pragma, std::string(c.pragma).substr(0, std::string(c.pragma).find(' ')));
  }
  EXPECT_EQ(sets, c.sets);
  EXPECT_EQ(diags.size(), 0u) << dump_messages();
}

const Keywords kLights = {"POINT", "DIRECTIONAL", "SPOT", "POINT_COOKIE", "DIRECTIONAL_COOKIE"};
const std::vector<Keywords> kFullShadowSets = {kLights,
                                               {"", "SHADOWS_DEPTH", "SHADOWS_SCREEN", "SHADOWS_CUBE"},
                                               {"", "SHADOWS_SOFT"},
                                               {"", "SHADOWS_SHADOWMASK"},
                                               {"", "LIGHTMAP_SHADOW_MIXING"}};

INSTANTIATE_TEST_SUITE_P(
    Shortcuts, VariantsShortcutTest,
    ::testing::Values(
        ShortcutCase{"multi_compile_fwdbase",
                     {{"DIRECTIONAL"}, {"", "LIGHTMAP_ON"}, {"", "DIRLIGHTMAP_COMBINED"}, {"", "DYNAMICLIGHTMAP_ON"},
                      {"", "SHADOWS_SCREEN"}, {"", "SHADOWS_SHADOWMASK"}, {"", "LIGHTMAP_SHADOW_MIXING"},
                      {"", "LIGHTPROBE_SH"}, {"", "VERTEXLIGHT_ON"}}},
        ShortcutCase{"multi_compile_fwdadd", {kLights}},
        ShortcutCase{"multi_compile_fwdadd_fullshadows", kFullShadowSets},
        ShortcutCase{"multi_compile_shadowcaster", {{"SHADOWS_DEPTH", "SHADOWS_CUBE"}}},
        ShortcutCase{"multi_compile_fwdbasealpha",
                     {{"DIRECTIONAL"}, {"", "LIGHTMAP_ON"}, {"", "DIRLIGHTMAP_COMBINED"}, {"", "DYNAMICLIGHTMAP_ON"},
                      {"", "LIGHTMAP_SHADOW_MIXING"}, {"", "LIGHTPROBE_SH"}, {"", "VERTEXLIGHT_ON"}}},
        ShortcutCase{"multi_compile_lightpass", kFullShadowSets},
        ShortcutCase{"multi_compile_shadowcollector", {{"", "SHADOWS_SPLIT_SPHERES"}, {"", "SHADOWS_SINGLE_CASCADE"}}},
        ShortcutCase{"multi_compile_prepassfinal",
                     {{"", "LIGHTMAP_ON"}, {"", "DIRLIGHTMAP_COMBINED"}, {"", "DYNAMICLIGHTMAP_ON"}, {"", "UNITY_HDR_ON"},
                      {"", "SHADOWS_SHADOWMASK"}, {"", "LIGHTPROBE_SH"}}},
        ShortcutCase{"multi_compile_fog", {{"", "FOG_LINEAR", "FOG_EXP", "FOG_EXP2"}}},
        ShortcutCase{"multi_compile_instancing", {{"", "INSTANCING_ON"}}},
        ShortcutCase{"multi_compile_particles", {{"", "SOFTPARTICLES_ON"}}},
        // Modifiers remove the listed combinations holding their keywords;
        // keywords left in none leave their sets, and an emptied set disappears.
        ShortcutCase{"multi_compile_fwdbase noshadow",
                     {{"DIRECTIONAL"}, {"", "LIGHTMAP_ON"}, {"", "DIRLIGHTMAP_COMBINED"}, {"", "DYNAMICLIGHTMAP_ON"},
                      {"", "LIGHTMAP_SHADOW_MIXING"}, {"", "LIGHTPROBE_SH"}, {"", "VERTEXLIGHT_ON"}}},
        ShortcutCase{"multi_compile_fwdadd_fullshadows noshadow", {kLights}},
        ShortcutCase{"multi_compile_shadowcaster noshadow", {}},
        ShortcutCase{"multi_compile_lightpass noshadow", {kLights}},
        ShortcutCase{"multi_compile_fwdbase nolightmap nodynlightmap nodirlightmap noshadowmask novertexlight nolppv",
                     {{"DIRECTIONAL"}, {"", "SHADOWS_SCREEN"}, {"", "LIGHTMAP_SHADOW_MIXING"}, {"", "LIGHTPROBE_SH"}}}));

TEST_F(VariantsBuildTest, UnknownModifierWarnsNamingTheKnownOnes) {
  KeywordSpace space = build({"multi_compile_fog nofoo"});
  EXPECT_EQ(space.sets.size(), 1u);
  const Diagnostic& d = first(DiagId::pragma_unknown_shortcut_modifier);
  EXPECT_EQ(d.severity, Severity::warning);
  EXPECT_EQ(d.message,
            "unknown modifier 'nofoo' for 'multi_compile_fog' is ignored; known modifiers are noshadow, "
            "nolightmap, nodynlightmap, nodirlightmap, noshadowmask, novertexlight, nolppv");
}

TEST_F(VariantsBuildTest, UnknownShortcutIsALocatedWarningNamingTheKnownOnesAndAddsNothing) {
  Lines lines = {"multi_compile _ A", "multi_compile_fwdbasealfa"};
  KeywordSpace space = build(lines);
  ASSERT_EQ(space.sets.size(), 1u) << "only 'multi_compile _ A'";
  EXPECT_EQ(space.sets[0].keywords, (Keywords{"", "A"}));
  const Diagnostic& d = first(DiagId::pragma_unknown_shortcut);
  EXPECT_EQ(d.severity, Severity::warning);
  EXPECT_EQ(d.span, line_span(lines, 1));
  EXPECT_EQ(d.message,
            "unknown keyword shortcut 'multi_compile_fwdbasealfa' adds no keywords; the known shortcuts are "
            "multi_compile_fwdbase, "
            "multi_compile_fwdadd, multi_compile_fwdadd_fullshadows, multi_compile_shadowcaster, "
            "multi_compile_fwdbasealpha, multi_compile_lightpass, multi_compile_shadowcollector, "
            "multi_compile_prepassfinal, multi_compile_fog, multi_compile_instancing, multi_compile_particles");
}

TEST_F(VariantsBuildTest, MisspeltShortcutOrSuffixSuggestsTheClosest) {
  build({"multi_compile_fwdbas", "multi_compile_fragmnet _ A"});
  ASSERT_EQ(count(DiagId::pragma_unknown_shortcut), 2u);
  std::vector<std::string> notes;
  for (const Diagnostic& d : diags.all()) notes.push_back(d.notes.empty() ? "" : d.notes[0].message);
  EXPECT_EQ(notes, (Keywords{"did you mean 'multi_compile_fwdbase'?", "did you mean 'multi_compile_fragment'?"}));
}

TEST_F(VariantsBuildTest, UnknownShaderFeatureSpellingIsAnError) {
  build_fails({"shader_feature_vertx _ A"});
  const Diagnostic& d = first(DiagId::pragma_unknown_keyword_directive);
  ASSERT_EQ(d.notes.size(), 1u);
  EXPECT_EQ(d.notes[0].message, "did you mean 'shader_feature_vertex'?");
}

struct BadPragmaCase {
  const char* line;
  const char* message;
};

class VariantsBadPragmaTest : public VariantsBuildTest, public ::testing::WithParamInterface<BadPragmaCase> {};

TEST_P(VariantsBadPragmaTest, IsALocatedError) {
  Lines lines = {"multi_compile _ OK", GetParam().line};
  build_fails(lines);
  const Diagnostic& d = first(DiagId::pragma_bad_keyword_set);
  EXPECT_EQ(d.severity, Severity::error);
  EXPECT_EQ(d.span, line_span(lines, 1));
  EXPECT_EQ(d.message, GetParam().message);
}

INSTANTIATE_TEST_SUITE_P(
    Cases, VariantsBadPragmaTest,
    ::testing::Values(
        BadPragmaCase{"multi_compile", "'#pragma multi_compile' declares no keywords"},
        BadPragmaCase{"shader_feature_local", "'#pragma shader_feature_local' declares no keywords"},
        BadPragmaCase{"skip_variants", "'#pragma skip_variants' declares no keywords"},
        BadPragmaCase{"multi_compile _ FOO-BAR",
                      "invalid keyword name 'FOO-BAR' in '#pragma multi_compile'; a keyword is an identifier of "
                      "letters, digits and '_'"},
        BadPragmaCase{"shader_feature 1ST",
                      "invalid keyword name '1ST' in '#pragma shader_feature'; a keyword is an identifier of "
                      "letters, digits and '_'"}));

TEST_F(VariantsBuildTest, EveryBadPragmaIsReported) {
  build_fails({"multi_compile", "shader_feature A.B", "multi_compile_nope", "shader_feature_vertx _ B"});
  EXPECT_EQ(diags.error_count(), 3u);
  EXPECT_EQ(count(DiagId::pragma_unknown_shortcut), 1u) << "a warning, reported with the errors";
}

TEST_F(VariantsBuildTest, OnlyUnderscoresWarnsAndAddsNothing) {
  KeywordSpace space = build({"multi_compile _", "shader_feature __"});
  EXPECT_TRUE(space.sets.empty());
  EXPECT_EQ(count(DiagId::pragma_empty_keyword_set), 2u);
}

TEST_F(VariantsBuildTest, TrailingCommentIsNotAKeyword) {
  KeywordSpace space = build({"shader_feature _EMISSION // glow"});
  EXPECT_EQ(space.sets[0].keywords, (Keywords{"", "_EMISSION"}));
}

TEST_F(VariantsBuildTest, OtherPragmasAreIgnored) {
  KeywordSpace space =
      build({"vertex vert", "fragment frag", "target 3.0", "multi_compiles X", "surface surf Lambert"});
  EXPECT_TRUE(space.sets.empty());
  EXPECT_EQ(diags.size(), 0u);
}

TEST_F(VariantsBuildTest, SkipVariantsAreCollectedOnce) {
  KeywordSpace space = build({"skip_variants B", "multi_compile _ A B", "skip_variants A B _"});
  EXPECT_EQ(space.skip_variants, (Keywords{"B", "A"}));
  EXPECT_EQ(diags.size(), 0u) << dump_messages();
}

TEST_F(VariantsBuildTest, SkipVariantsOfAnUndeclaredKeywordWarns) {
  Lines lines = {"multi_compile _ A", "skip_variants NOPE", "dynamic_branch DYN", "skip_variants DYN"};
  KeywordSpace space = build(lines);
  ASSERT_EQ(count(DiagId::pragma_unused_skip_variant), 2u);
  const Diagnostic& d = first(DiagId::pragma_unused_skip_variant);
  EXPECT_EQ(d.span, line_span(lines, 1));
  EXPECT_EQ(d.message, "skip_variants keyword 'NOPE' is not declared by any keyword pragma of this program");
  EXPECT_EQ(diags.all().back().message,
            "skip_variants keyword 'DYN' is a dynamic_branch keyword, which has no variants to skip");
}

TEST_F(VariantsBuildTest, KnownShortcutsAreListedInDocumentedOrder) {
  EXPECT_EQ(known_shortcuts(),
            (Keywords{"multi_compile_fwdbase", "multi_compile_fwdadd", "multi_compile_fwdadd_fullshadows",
                      "multi_compile_shadowcaster", "multi_compile_fwdbasealpha", "multi_compile_lightpass",
                      "multi_compile_shadowcollector", "multi_compile_prepassfinal", "multi_compile_fog",
                      "multi_compile_instancing", "multi_compile_particles"}));
}

}  // namespace
}  // namespace facet::variants
