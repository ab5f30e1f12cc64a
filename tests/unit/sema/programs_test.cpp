// Program blocks: pragma scanning, entry points, targets, include scopes,
// surface programs and GLSL stage sections.
#include <gtest/gtest.h>

#include <memory>

#include "facet/sema.h"
#include "lower.h"
#include "sema_test_util.h"

namespace facet::sema {
namespace {

using test_util::Analyzed;
using test_util::analyze_text;

std::string cg_pass(std::string_view body) {
  return "Shader \"T\" { SubShader { Pass {\nCGPROGRAM\n" + std::string(body) + "\nENDCG\n} } }";
}

// --- the directive scanner ------------------------------------------------------

std::vector<Directive> scan(std::string text) {
  return scan_directives(ir::SourceChunk{text, SourceSpan{0, 100, uint32_t(100 + text.size())}, 1});
}

TEST(SemaDirectivesTest, FindsDirectivesAndSplitsWords) {
  auto d = scan("int a;\n  #  pragma  vertex   vert\t\n#ifdef FOO\n#if defined(VERTEX)\n");
  ASSERT_EQ(d.size(), 3u);
  EXPECT_EQ(d[0].name, "pragma");
  EXPECT_EQ(d[0].words, (std::vector<std::string>{"vertex", "vert"}));
  EXPECT_EQ(d[0].span.begin, 100u + 9u);  // the '#'
  EXPECT_EQ(d[0].span.end, 100u + 33u);   // after "vert"
  EXPECT_EQ(d[1].name, "ifdef");
  EXPECT_EQ(d[2].name, "if");
  EXPECT_EQ(d[2].rest, "defined(VERTEX)");
}

TEST(SemaDirectivesTest, JoinsContinuationLines) {
  auto d = scan("#pragma multi_compile A \\\n  B \\  \n C\nint x;");
  ASSERT_EQ(d.size(), 1u);
  EXPECT_EQ(d[0].words, (std::vector<std::string>{"multi_compile", "A", "B", "C"}));
}

TEST(SemaDirectivesTest, SkipsComments) {
  auto d = scan(
      "// #pragma vertex a\n"
      "/* #pragma vertex b\n"
      "#pragma vertex c */ #pragma fragment d\n"
      "#pragma target 3.0 // trailing\n"
      "#pragma /* inline */ geometry g\n"
      "// comment that continues \\\n"
      "#pragma vertex e\n");
  ASSERT_EQ(d.size(), 3u);
  EXPECT_EQ(d[0].words, (std::vector<std::string>{"fragment", "d"}));
  EXPECT_EQ(d[1].words, (std::vector<std::string>{"target", "3.0"}));
  EXPECT_EQ(d[2].words, (std::vector<std::string>{"geometry", "g"}));
}

TEST(SemaDirectivesTest, UnterminatedCommentAndEmptyText) {
  EXPECT_TRUE(scan("/* #pragma vertex v").empty());
  EXPECT_TRUE(scan("").empty());
  EXPECT_EQ(scan("#").at(0).name, "");
  EXPECT_TRUE(scan("\\").empty());
}

// --- pragmas into the IR -------------------------------------------------------

TEST(SemaProgramsTest, EntryPointsAndPragmaSpans) {
  auto a = analyze_text(cg_pass(
      "#pragma vertex vert\n#pragma fragment frag\n#pragma multi_compile_fog\n#pragma shader_feature _ A B"));
  ASSERT_TRUE(a->ir) << render_text(a->diags, a->sources);
  const ir::Program& p = a->program();
  EXPECT_EQ(p.language, ir::ProgramLanguage::cg);
  EXPECT_EQ(p.entry_points[size_t(Stage::vertex)], "vert");
  EXPECT_EQ(p.entry_points[size_t(Stage::fragment)], "frag");
  EXPECT_FALSE(p.has_stage(Stage::geometry));
  EXPECT_EQ(p.shader_target, 25);
  ASSERT_EQ(p.pragmas.size(), 4u);
  EXPECT_EQ(p.pragmas[3].name, "shader_feature");
  EXPECT_EQ(p.pragmas[3].args, (std::vector<std::string>{"_", "A", "B"}));
  // Spans point at the pragma in the .shader file.
  EXPECT_EQ(a->at(p.pragmas[1].span).line, 4u);
  EXPECT_EQ(a->at(p.pragmas[1].span).column, 1u);
  const std::string& text = a->sources.text(a->file);
  EXPECT_EQ(text.substr(p.pragmas[1].span.begin, p.pragmas[1].span.end - p.pragmas[1].span.begin),
            "#pragma fragment frag");
  EXPECT_EQ(p.body.first_line, 2u);
}

TEST(SemaProgramsTest, UnknownPragmaWarnsWithTheClosestKnownOne) {
  auto a = analyze_text(cg_pass("#pragma vertex vert\n#pragma fragmnet frag\n#pragma fragment frag"));
  ASSERT_TRUE(a->ir) << render_text(a->diags, a->sources);
  const Diagnostic* d = a->find(DiagId::sema_unknown_pragma);
  ASSERT_NE(d, nullptr);
  EXPECT_EQ(d->severity, Severity::warning);
  EXPECT_EQ(d->message, "unknown pragma 'fragmnet' is ignored");
  EXPECT_EQ(a->at(d->span).line, 4u);
  EXPECT_EQ(a->at(d->span).column, 1u);
  ASSERT_EQ(d->notes.size(), 1u);
  EXPECT_EQ(d->notes[0].message, "did you mean 'fragment'?");
}

TEST(SemaProgramsTest, UnitysOtherPragmasAreNotWarnedAbout) {
  auto a = analyze_text(cg_pass("#pragma vertex v\n#pragma fragment f\n#pragma fragmentoption ARB_precision_hint_fastest\n"
                                "#pragma only_renderers d3d11 vulkan\n#pragma enable_d3d11_debug_symbols\n"
                                "#pragma multi_compile_fog\n#pragma warning (disable : 3205)"));
  ASSERT_TRUE(a->ir) << render_text(a->diags, a->sources);
  EXPECT_EQ(a->find(DiagId::sema_unknown_pragma), nullptr);
}

// A typo in '#pragma fragment' leaves a vertex-only program: a located
// error at the program, never a pass that fails later in the renderer.
TEST(SemaProgramsTest, AVertexFunctionWithoutAFragmentFunctionIsAnError) {
  auto a = analyze_text(cg_pass("#pragma vertex vert\n#pragma fragmnet frag"));
  EXPECT_FALSE(a->ir);
  const Diagnostic* d = a->find(DiagId::sema_missing_stage);
  ASSERT_NE(d, nullptr);
  EXPECT_EQ(d->message, "this program has a vertex function but no fragment function");
  EXPECT_EQ(a->at(d->span).line, 2u);
  EXPECT_EQ(a->at(d->span).column, 1u);
  ASSERT_EQ(d->notes.size(), 1u);
  EXPECT_EQ(a->at(d->notes[0].span).line, 3u);
  EXPECT_EQ(d->notes[0].message, "add '#pragma fragment <function>' next to this one");
}

TEST(SemaProgramsTest, AFragmentFunctionWithoutAVertexFunctionIsAnError) {
  auto a = analyze_text(cg_pass("#pragma fragment frag"));
  EXPECT_FALSE(a->ir);
  const Diagnostic* d = a->find(DiagId::sema_missing_stage);
  ASSERT_NE(d, nullptr);
  EXPECT_EQ(d->message, "this program has a fragment function but no vertex function");
}

struct TargetCase {
  const char* pragmas;
  int target;
};

class SemaShaderTargetTest : public testing::TestWithParam<TargetCase> {};

TEST_P(SemaShaderTargetTest, Maps) {
  auto a = analyze_text(cg_pass(GetParam().pragmas));
  ASSERT_TRUE(a->ir) << render_text(a->diags, a->sources);
  EXPECT_EQ(a->program().shader_target, GetParam().target);
}

INSTANTIATE_TEST_SUITE_P(Targets, SemaShaderTargetTest,
                         testing::Values(TargetCase{"", 25}, TargetCase{"#pragma target 3.0", 30},
                                         TargetCase{"#pragma target 4.5", 45}, TargetCase{"#pragma target 2.0", 20},
                                         TargetCase{"#pragma target 5.0", 50}, TargetCase{"#pragma target 3", 30},
                                         TargetCase{"#pragma target 3.0\n#pragma target 3.5", 35},
                                         TargetCase{"#pragma geometry g", 40},
                                         TargetCase{"#pragma target 3.0\n#pragma hull h\n#pragma domain d", 46},
                                         TargetCase{"#pragma target 5.0\n#pragma geometry g", 50},
                                         TargetCase{"#pragma target es3.0", 35},
                                         TargetCase{"#pragma target gl4.1", 40}));

TEST(SemaProgramsTest, BadTargetListsValidOnes) {
  auto a = analyze_text(cg_pass("#pragma target three"));
  EXPECT_FALSE(a->ir);
  const Diagnostic* d = a->find(DiagId::sema_bad_shader_target);
  ASSERT_NE(d, nullptr);
  EXPECT_EQ(d->message, "invalid shader target 'three'");
  EXPECT_EQ(d->notes.at(0).message, "valid targets are 2.0, 2.5, 3.0, 3.5, 4.0, 4.5, 4.6, 5.0");
  EXPECT_EQ(a->at(d->span).line, 3u);
  for (const char* bad : {"9.7", "1", "3.7", "30"}) {
    auto b = analyze_text(cg_pass(std::string("#pragma target ") + bad));
    EXPECT_FALSE(b->ir) << bad;
    EXPECT_NE(b->find(DiagId::sema_bad_shader_target), nullptr) << bad;
  }
}

TEST(SemaProgramsTest, ConflictingEntryPointIsAnError) {
  auto a = analyze_text(cg_pass("#pragma vertex a\n#pragma vertex a\n#pragma vertex b\n#pragma fragment f"));
  EXPECT_FALSE(a->ir);
  const Diagnostic* d = a->find(DiagId::sema_duplicate_entry_point);
  ASSERT_NE(d, nullptr);
  EXPECT_EQ(d->message, "the vertex function is already 'a'");
  EXPECT_EQ(a->at(d->span).line, 5u);
  EXPECT_EQ(a->at(d->notes.at(0).span).line, 4u);
  EXPECT_EQ(a->diags.error_count(), 1u);
}

TEST(SemaProgramsTest, MissingPragmaArgument) {
  auto a = analyze_text(cg_pass("#pragma fragment"));
  EXPECT_FALSE(a->ir);
  EXPECT_NE(a->find(DiagId::sema_missing_pragma_argument), nullptr);
}

TEST(SemaProgramsTest, IncludesInScopeMatchTheLanguage) {
  auto a = analyze_text(R"(Shader "T" {
    CGINCLUDE
    #pragma target 3.0
    ENDCG
    HLSLINCLUDE
    #define H 1
    ENDHLSL
    SubShader {
      CGINCLUDE
      #pragma vertex vert
      ENDCG
      Pass { CGPROGRAM
        #pragma fragment frag
        ENDCG }
      Pass { HLSLPROGRAM
        ENDHLSL }
    }
    SubShader { Pass { CGPROGRAM ENDCG } }
  })");
  ASSERT_TRUE(a->ir) << render_text(a->diags, a->sources);
  const ir::Program& cg = a->program(0);
  ASSERT_EQ(cg.includes.size(), 2u);
  EXPECT_EQ(cg.includes[0].first_line, 2u);  // Shader scope first
  EXPECT_EQ(cg.includes[1].first_line, 9u);
  EXPECT_EQ(cg.shader_target, 30);
  EXPECT_EQ(cg.entry_points[size_t(Stage::vertex)], "vert");
  ASSERT_EQ(cg.pragmas.size(), 3u);
  EXPECT_EQ(cg.pragmas[2].name, "fragment");
  const ir::Program& hlsl = a->program(1);
  ASSERT_EQ(hlsl.includes.size(), 1u);
  EXPECT_EQ(hlsl.includes[0].text, "\n    #define H 1\n    ");
  EXPECT_EQ(a->ir->subshaders[1].passes[0].program->includes.size(), 1u);
}

TEST(SemaProgramsTest, ProgramInSubShaderIsTheSurfaceProgram) {
  auto a = analyze_text(R"(Shader "T" { SubShader { Tags { "RenderType"="Opaque" }
    CGPROGRAM
    #pragma surface surf Standard fullforwardshadows vertex:vert
    #pragma target 3.0
    ENDCG } FallBack "Diffuse" })");
  ASSERT_TRUE(a->ir) << render_text(a->diags, a->sources);
  const ir::SubShader& sub = a->ir->subshaders[0];
  ASSERT_EQ(sub.surface_programs.size(), 1u);
  const ir::Program& surface = sub.surface_programs[0].program;
  EXPECT_TRUE(surface.is_surface());
  EXPECT_EQ(surface.surface_function, "surf");
  EXPECT_EQ(surface.pragmas[0].args,
            (std::vector<std::string>{"surf", "Standard", "fullforwardshadows", "vertex:vert"}));
  EXPECT_TRUE(sub.passes.empty());
}

TEST(SemaProgramsTest, SurfacePragmaInsideAPassIsAnError) {
  auto a = analyze_text(cg_pass("#pragma surface surf Lambert"));
  EXPECT_FALSE(a->ir);
  const Diagnostic* d = a->find(DiagId::sema_surface_in_pass);
  ASSERT_NE(d, nullptr);
  EXPECT_EQ(a->at(d->span).line, 3u);
}

TEST(SemaProgramsTest, ProgramOutsidePassNeedsSurfacePragma) {
  auto a = analyze_text("Shader \"T\" { SubShader {\n  CGPROGRAM\n#pragma vertex v\nENDCG } }");
  EXPECT_FALSE(a->ir);
  const Diagnostic* d = a->find(DiagId::sema_program_outside_pass);
  ASSERT_NE(d, nullptr);
  EXPECT_EQ(a->at(d->span).line, 2u);
  EXPECT_EQ(a->at(d->span).column, 3u);
}

TEST(SemaProgramsTest, SeveralSurfaceProgramsAreKeptWithTheirPlaceAmongThePasses) {
  auto a = analyze_text(
      "Shader \"T\" { SubShader {\nCGPROGRAM\n#pragma surface a Lambert\nENDCG\n"
      "Pass { ColorMask 0 }\n"
      "CGPROGRAM\n#pragma surface b Lambert\nENDCG\nPass { ZWrite Off } } }");
  ASSERT_TRUE(a->ir) << render_text(a->diags, a->sources);
  const ir::SubShader& sub = a->ir->subshaders[0];
  ASSERT_EQ(sub.surface_programs.size(), 2u);
  EXPECT_EQ(sub.surface_programs[0].program.surface_function, "a");
  EXPECT_EQ(sub.surface_programs[0].before_pass, 0u);
  EXPECT_EQ(sub.surface_programs[1].program.surface_function, "b");
  EXPECT_EQ(sub.surface_programs[1].before_pass, 1u);
}

TEST(SemaProgramsTest, IncludesCopiedIntoManyPassesAreBounded) {
  std::string shader = "Shader \"T\" {\nCGINCLUDE\n" + std::string(1000, 'x') + "\nENDCG\nSubShader {\n";
  for (int i = 0; i < 100; ++i) shader += "Pass { CGPROGRAM ENDCG }\n";
  shader += "} }";
  auto a = analyze_text(shader, {.max_program_bytes = 50'000});
  EXPECT_FALSE(a->ir);
  EXPECT_EQ(a->diags.error_count(), 1u);
  const Diagnostic* d = a->find(DiagId::sema_programs_too_large);
  ASSERT_NE(d, nullptr);
  EXPECT_EQ(a->at(d->span).line, 55u);  // the 50th pass (line 6 + 49) passes 50,000 bytes
}

struct GlslCase {
  const char* name;
  const char* body;
  bool vertex, fragment, geometry;
};

class SemaGlslStagesTest : public testing::TestWithParam<GlslCase> {};

TEST_P(SemaGlslStagesTest, FindsSections) {
  const GlslCase& c = GetParam();
  auto a = analyze_text("Shader \"T\" { SubShader { Pass {\nGLSLPROGRAM\n" + std::string(c.body) + "\nENDGLSL\n} } }");
  ASSERT_TRUE(a->ir) << render_text(a->diags, a->sources);
  const ir::Program& p = a->program();
  EXPECT_EQ(p.language, ir::ProgramLanguage::glsl);
  EXPECT_EQ(p.entry_points[size_t(Stage::vertex)], c.vertex ? "main" : "");
  EXPECT_EQ(p.entry_points[size_t(Stage::fragment)], c.fragment ? "main" : "");
  EXPECT_EQ(p.entry_points[size_t(Stage::geometry)], c.geometry ? "main" : "");
}

INSTANTIATE_TEST_SUITE_P(
    Sections, SemaGlslStagesTest,
    testing::Values(GlslCase{"ifdef", "#ifdef VERTEX\n#endif\n#ifdef FRAGMENT\n#endif", true, true, false},
                    GlslCase{"if_defined", "#if defined(VERTEX)\n#elif defined (FRAGMENT)\n#endif", true, true, false},
                    GlslCase{"defined_no_parens", "#if defined GEOMETRY || defined(VERTEX)\n#endif", true, false, true},
                    GlslCase{"vertex_only", "#ifdef VERTEX\n#endif", true, false, false},
                    GlslCase{"longer_name", "#ifdef VERTEX_COLOR\n#endif\n#if defined(FRAGMENTS)\n#endif", false,
                             false, false},
                    GlslCase{"commented", "// #ifdef VERTEX\n/* #ifdef FRAGMENT */", false, false, false}),
    [](const testing::TestParamInfo<GlslCase>& info) { return std::string(info.param.name); });

}  // namespace
}  // namespace facet::sema
