// End-to-end compiles through glslang, spirv-opt, spirv-val and SPIRV-Cross.
#include <gtest/gtest.h>

#include <map>

#include "glslang_frontend.h"
#include "backend_test_util.h"

namespace facet::backend {
namespace {

using testing::load_shader;
using testing::TestShader;

class BackendCompileTest : public ::testing::Test {
 protected:
  Result<CompiledVariant> compile(TestShader& t, Stage stage, const std::vector<std::string>& keywords = {},
                                const BackendOptions& options = {}) {
    return backend_.compile(t.shader, t.program, stage, keywords, options, t.sources, diags_);
  }
  std::string diagnostics(const TestShader& t) const { return render_text(diags_, t.sources); }

  Backend backend_;
  Diagnostics diags_;
};

TEST_F(BackendCompileTest, UnlitCgShaderCompilesBothStages) {
  TestShader t = load_shader("unlit.shader");
  for (Stage stage : {Stage::vertex, Stage::fragment}) {
    auto compiled = compile(t, stage);
    ASSERT_TRUE(compiled) << diagnostics(t);
    EXPECT_EQ(compiled->stage(), stage);
    EXPECT_GT(compiled->spirv.size(), 5u);
    EXPECT_EQ(compiled->spirv[0], 0x07230203u);  // SPIR-V magic
    EXPECT_TRUE(validate(compiled->spirv, TargetEnv::vulkan1_1, diags_)) << diagnostics(t);
  }
  EXPECT_FALSE(diags_.has_errors()) << diagnostics(t);
}

TEST_F(BackendCompileTest, IncludedFilesAreRecordedAndAddedToTheSourceMap) {
  TestShader t = load_shader("unlit.shader");
  auto compiled = compile(t, Stage::vertex);
  ASSERT_TRUE(compiled) << diagnostics(t);
  auto has = [&](const std::string& name) {
    return std::any_of(compiled->included_files.begin(), compiled->included_files.end(),
                       [&](const std::string& p) { return p.ends_with("/" + name); });
  };
  EXPECT_TRUE(has("UnityCG.cginc"));
  EXPECT_TRUE(has("HLSLSupport.cginc"));           // implicit in CGPROGRAM
  EXPECT_TRUE(has("UnityShaderVariables.cginc"));  // implicit in CGPROGRAM
  EXPECT_TRUE(std::is_sorted(compiled->included_files.begin(), compiled->included_files.end()));
  for (const std::string& path : compiled->included_files) EXPECT_TRUE(t.sources.find(path)) << path;
}

TEST_F(BackendCompileTest, FogKeywordsEachCompile) {
  TestShader t = load_shader("unlit.shader");
  for (const char* keyword : {"FOG_LINEAR", "FOG_EXP", "FOG_EXP2"}) {
    for (Stage stage : {Stage::vertex, Stage::fragment}) {
      auto compiled = compile(t, stage, {keyword});
      ASSERT_TRUE(compiled) << keyword << "\n" << diagnostics(t);
    }
  }
}

struct CrossCase {
  CrossTarget target;
  const char* marker;  // text the output must contain
};

class BackendCrossCompileTest : public BackendCompileTest, public ::testing::WithParamInterface<CrossCase> {};

TEST_P(BackendCrossCompileTest, UnlitShaderTranslates) {
  TestShader t = load_shader("unlit.shader");
  for (Stage stage : {Stage::vertex, Stage::fragment}) {
    auto compiled = compile(t, stage, {"FOG_EXP2"});
    ASSERT_TRUE(compiled) << diagnostics(t);
    auto text = cross_compile(compiled->spirv, stage, GetParam().target, diags_);
    ASSERT_TRUE(text) << diagnostics(t);
    EXPECT_NE(text->find(GetParam().marker), std::string::npos) << *text;
    EXPECT_EQ(text->find('$'), std::string::npos) << "identifiers must be valid\n" << *text;
    if (GetParam().target != CrossTarget::msl) {
      EXPECT_EQ(glsl_errors(*text, stage), "") << *text;
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Targets, BackendCrossCompileTest,
                         ::testing::Values(CrossCase{CrossTarget::glsl450, "#version 450"},
                                           CrossCase{CrossTarget::essl300, "#version 300 es"},
                                           CrossCase{CrossTarget::msl, "#include <metal_stdlib>"}),
                         [](const auto& info) {
                           switch (info.param.target) {
                             case CrossTarget::glsl450: return std::string("glsl450");
                             case CrossTarget::essl300: return std::string("essl300");
                             case CrossTarget::msl: return std::string("msl");
                           }
                           return std::string("unknown");
                         });

TEST_F(BackendCompileTest, FogDistanceReachesTheInterpolator) {
  TestShader t = load_shader("unlit.shader");
  auto compiled = compile(t, Stage::vertex, {"FOG_LINEAR"});
  ASSERT_TRUE(compiled) << diagnostics(t);
  std::string text = disassemble(compiled->spirv);
  EXPECT_NE(text.find("OpStore %_entryPointOutput_fogCoord"), std::string::npos) << text;
}

TEST_F(BackendCompileTest, OpenGlOutputHasOneBindingNamespacePerKind) {
  TestShader t = load_shader("dx9.shader");
  auto compiled = compile(t, Stage::fragment);
  ASSERT_TRUE(compiled) << diagnostics(t);
  auto glsl = cross_compile(compiled->spirv, Stage::fragment, CrossTarget::glsl450, diags_);
  ASSERT_TRUE(glsl) << diagnostics(t);
  // Blocks of sets 0, 1 and 2 are numbered 0, 1, 2 for OpenGL; textures apart.
  EXPECT_NE(glsl->find("layout(binding = 0, std140) uniform FacetPerFrame"), std::string::npos) << *glsl;
  EXPECT_NE(glsl->find("layout(binding = 1, std140) uniform FacetPerLight"), std::string::npos) << *glsl;
  EXPECT_NE(glsl->find("layout(binding = 0) uniform sampler2D _MainTex"), std::string::npos) << *glsl;
  EXPECT_NE(glsl->find("layout(binding = 1) uniform samplerCube _Cube"), std::string::npos) << *glsl;
}

TEST_F(BackendCompileTest, EsslHasNoGeometryStage) {
  TestShader t = load_shader("unlit.shader");
  auto compiled = compile(t, Stage::vertex);
  ASSERT_TRUE(compiled);
  EXPECT_FALSE(cross_compile(compiled->spirv, Stage::geometry, CrossTarget::essl300, diags_));
  ASSERT_EQ(diags_.size(), 1u);
  EXPECT_EQ(diags_.all()[0].id, DiagId::backend_cross_compile_failed);
}

class BackendOptLevelTest : public BackendCompileTest, public ::testing::WithParamInterface<OptLevel> {};

TEST_P(BackendOptLevelTest, EveryLevelGivesValidSpirv) {
  TestShader t = load_shader("dx9.shader");
  BackendOptions options;
  options.opt = GetParam();
  for (Stage stage : {Stage::vertex, Stage::fragment}) {
    auto compiled = compile(t, stage, {}, options);
    ASSERT_TRUE(compiled) << diagnostics(t);
    EXPECT_TRUE(validate(compiled->spirv, options.target, diags_)) << diagnostics(t);
  }
}

INSTANTIATE_TEST_SUITE_P(Levels, BackendOptLevelTest,
                         ::testing::Values(OptLevel::none, OptLevel::size, OptLevel::performance));

TEST_F(BackendCompileTest, OptimisedModuleIsSmallerThanUnoptimised) {
  TestShader t = load_shader("dx9.shader");
  BackendOptions o0, o;
  o0.opt = OptLevel::none;
  o.opt = OptLevel::performance;
  auto unoptimised = compile(t, Stage::fragment, {}, o0);
  auto optimised = compile(t, Stage::fragment, {}, o);
  ASSERT_TRUE(unoptimised && optimised) << diagnostics(t);
  EXPECT_LT(optimised->spirv.size(), unoptimised->spirv.size());
}

TEST_F(BackendCompileTest, DebugInfoKeepsSourceLines) {
  TestShader t = load_shader("unlit.shader");
  BackendOptions options;
  options.debug_info = true;
  options.opt = OptLevel::none;
  auto compiled = compile(t, Stage::fragment, {}, options);
  ASSERT_TRUE(compiled) << diagnostics(t);
  std::string text = disassemble(compiled->spirv);
  EXPECT_NE(text.find("OpLine"), std::string::npos) << text;
  EXPECT_NE(text.find("unlit.shader"), std::string::npos);
}

TEST_F(BackendCompileTest, Dx9StyleCodeCompiles) {
  // sampler2D, tex2D, texCUBElod, float4 -> float3 truncation, fixed4,
  // 1.0f literals, inline, ternary on vectors, scalar broadcast.
  TestShader t = load_shader("dx9.shader");
  for (Stage stage : {Stage::vertex, Stage::fragment}) {
    auto compiled = compile(t, stage);
    ASSERT_TRUE(compiled) << diagnostics(t);
    if (stage == Stage::fragment) {
      // A DX9 "COLOR" output is render target 0.
      ASSERT_EQ(compiled->reflection.outputs.size(), 1u);
      EXPECT_EQ(compiled->reflection.outputs[0].semantic, "COLOR");
      EXPECT_EQ(compiled->reflection.outputs[0].location, 0u);
    }
  }
  EXPECT_FALSE(diags_.has_errors()) << diagnostics(t);
}

// glslang makes "float f : VFACE" a varying no vertex stage writes, and a
// "uint f : SV_IsFrontFace" built-in invalid SPIR-V: both read FrontFacing.
TEST_F(BackendCompileTest, FrontFacingParametersOfAnyTypeReadTheBuiltIn) {
  for (const char* parameter : {"float facing : VFACE", "uint facing : SV_IsFrontFace", "half facing : VFACE",
                                "bool facing : SV_IsFrontFace"}) {
    TestShader t = testing::make_shader("facing.shader", std::string(R"(Shader "T" { SubShader { Pass { Cull Off
      CGPROGRAM
      #pragma vertex vert
      #pragma fragment frag
      float4 vert(float4 v : POSITION) : SV_POSITION { return v; }
      float4 frag(float4 p : SV_POSITION, )") + parameter + R"() : SV_Target { return facing > 0 ? 1 : 0; }
      ENDCG } } })");
    diags_ = {};
    auto compiled = compile(t, Stage::fragment);
    ASSERT_TRUE(compiled) << parameter << "\n" << diagnostics(t);
    std::string text = disassemble(compiled->spirv);
    EXPECT_NE(text.find("BuiltIn FrontFacing"), std::string::npos) << parameter << "\n" << text;
    EXPECT_TRUE(compiled->reflection.inputs.empty()) << parameter;  // no varying left behind
  }
}

// ForwardAdd/ForwardBase light keywords with Lighting.cginc and AutoLight.cginc.
class BackendLightKeywordTest : public BackendCompileTest,
                                public ::testing::WithParamInterface<std::vector<std::string>> {};

TEST_P(BackendLightKeywordTest, ForwardLitShaderCompiles) {
  TestShader t = load_shader("forward_lit.shader");
  for (const char* fragment : {"frag_add", "frag_base"}) {
    t.program.entry_points[size_t(Stage::fragment)] = fragment;
    for (Stage stage : {Stage::vertex, Stage::fragment}) {
      auto compiled = compile(t, stage, GetParam());
      ASSERT_TRUE(compiled) << fragment << "\n" << diagnostics(t);
    }
  }
  EXPECT_EQ(diags_.size(), 0u) << diagnostics(t);
}

INSTANTIATE_TEST_SUITE_P(
    Keywords, BackendLightKeywordTest,
    ::testing::Values(std::vector<std::string>{"DIRECTIONAL"}, std::vector<std::string>{"POINT", "FOG_LINEAR"},
                      std::vector<std::string>{"SPOT", "FOG_EXP2"}, std::vector<std::string>{"POINT_COOKIE"},
                      std::vector<std::string>{"DIRECTIONAL_COOKIE", "SHADOWS_SCREEN"},
                      std::vector<std::string>{"DIRECTIONAL", "LIGHTPROBE_SH", "SHADOWS_SCREEN"}));

TEST_F(BackendCompileTest, LightKeywordsChangeTheInterface) {
  TestShader t = load_shader("forward_lit.shader");
  auto point = compile(t, Stage::vertex, {"POINT"});
  auto directional = compile(t, Stage::vertex, {"DIRECTIONAL"});
  ASSERT_TRUE(point && directional) << diagnostics(t);
  auto has_light_coord = [](const CompiledVariant& c) {
    return std::any_of(c.reflection.outputs.begin(), c.reflection.outputs.end(),
                       [](const StageVariable& v) { return v.semantic == "TEXCOORD3"; });
  };
  EXPECT_TRUE(has_light_coord(*point));
  EXPECT_FALSE(has_light_coord(*directional));
}

TEST_F(BackendCompileTest, OverlappingSemanticsWarnAndKeepSequentialLocations) {
  TestShader t = testing::make_shader("/virtual/o.shader",
                                      "Shader \"O\" { SubShader { Pass {\n"
                                      "CGPROGRAM\n"
                                      "#pragma vertex vert\n"
                                      "#pragma fragment frag\n"
                                      "struct v2f { float4 pos : SV_POSITION; float3x3 m : TEXCOORD1; float k : TEXCOORD2; };\n"
                                      "v2f vert(float4 p : POSITION) { v2f o; o.pos = p; o.m = (float3x3)0; o.k = 1; return o; }\n"
                                      "fixed4 frag(v2f i) : SV_Target { return i.m[0].x + i.k; }\n"
                                      "ENDCG\n} } }\n");
  auto compiled = compile(t, Stage::vertex);
  ASSERT_TRUE(compiled) << diagnostics(t);
  ASSERT_EQ(diags_.size(), 1u) << diagnostics(t);
  EXPECT_EQ(diags_.all()[0].id, DiagId::backend_semantic_overlap);
  EXPECT_NE(diags_.all()[0].message.find("'TEXCOORD2'"), std::string::npos) << diagnostics(t);
  EXPECT_EQ(t.sources.line_column(t.shader.file, diags_.all()[0].span.begin).line, 3u);  // the #pragma vertex
}

TEST_F(BackendCompileTest, CustomSemanticsFollowTheFixedSlotsAlphabetically) {
  TestShader t = testing::make_shader("/virtual/c.shader",
                                      "Shader \"C\" { SubShader { Pass {\n"
                                      "CGPROGRAM\n"
                                      "#pragma vertex vert\n"
                                      "#pragma fragment frag\n"
                                      "struct v2f { float4 pos : SV_POSITION; float4 extra : EXTRA; float3x3 basis : BASIS; };\n"
                                      "v2f vert(float4 p : POSITION, float4 w : WIND) { v2f o; o.pos = p; o.extra = w;\n"
                                      "  o.basis = float3x3(w.xyz, w.yzx, w.zxy); return o; }\n"
                                      "fixed4 frag(v2f i) : SV_Target { return i.extra + i.basis[2].x; }\n"
                                      "ENDCG\n} } }\n");
  auto vs = compile(t, Stage::vertex);
  auto fs = compile(t, Stage::fragment);
  ASSERT_TRUE(vs && fs) << diagnostics(t);
  EXPECT_EQ(diags_.size(), 0u) << diagnostics(t);
  std::map<std::string, uint32_t> out, in;
  for (const StageVariable& v : vs->reflection.outputs) out[v.semantic] = v.location;
  for (const StageVariable& v : fs->reflection.inputs) in[v.semantic] = v.location;
  EXPECT_EQ(out, (std::map<std::string, uint32_t>{{"BASIS", 23}, {"EXTRA", 26}}));
  EXPECT_EQ(out, in);
  ASSERT_EQ(vs->reflection.inputs.size(), 2u);
  EXPECT_EQ(vs->reflection.inputs[1].semantic, "WIND");
  EXPECT_EQ(vs->reflection.inputs[1].location, 16u);
}

TEST_F(BackendCompileTest, RepeatedCompilesDoNotGrowTheSourceMap) {
  TestShader t = load_shader("unlit.shader");
  ASSERT_TRUE(compile(t, Stage::vertex));
  size_t files = t.sources.file_count();
  ASSERT_TRUE(compile(t, Stage::fragment, {"FOG_EXP"}));
  EXPECT_EQ(t.sources.file_count(), files);
}

TEST_F(BackendCompileTest, HlslProgramHasNoImplicitIncludes) {
  TestShader t = testing::make_shader("/virtual/h.shader",
                                      "Shader \"H\" { SubShader { Pass {\n"
                                      "HLSLPROGRAM\n"
                                      "#pragma vertex vert\n"
                                      "#pragma fragment frag\n"
                                      "float4 vert(float4 p : POSITION) : SV_POSITION { return p; }\n"
                                      "float4 frag() : SV_Target { return fixed4(1, 0, 0, 1); }\n"
                                      "ENDHLSL\n} } }\n");
  auto source = backend_.source_text(t.shader, t.program, {.stage = Stage::fragment, .preprocess = false}, {},
                                     t.sources, diags_);
  ASSERT_TRUE(source);
  const std::string* text = &source->text;
  EXPECT_EQ(text->find("HLSLSupport.cginc"), std::string::npos) << *text;
  // `fixed4` comes from HLSLSupport.cginc, which HLSLPROGRAM does not include.
  EXPECT_FALSE(compile(t, Stage::fragment));
  EXPECT_NE(diagnostics(t).find("'fixed4'"), std::string::npos) << diagnostics(t);
}

TEST_F(BackendCompileTest, GlslProgramCompilesEachSection) {
  TestShader t = load_shader("glsl.shader");
  for (Stage stage : {Stage::vertex, Stage::fragment}) {
    auto compiled = compile(t, stage);
    ASSERT_TRUE(compiled) << diagnostics(t);
    EXPECT_EQ(compiled->reflection.entry_point, "main");
    if (stage == Stage::fragment) {
      // Loose uniforms form "$Globals" here too, at the same place as for HLSL.
      ASSERT_EQ(compiled->reflection.uniform_blocks.size(), 1u);
      EXPECT_EQ(compiled->reflection.uniform_blocks[0].name, kGlobalsBlock);
      EXPECT_EQ(compiled->reflection.uniform_blocks[0].set, kMaterialSet);
      EXPECT_EQ(compiled->reflection.uniform_blocks[0].binding, 0u);
      ASSERT_EQ(compiled->reflection.resources.size(), 1u);
      EXPECT_EQ(compiled->reflection.resources[0].binding, 1u);
    }
    auto glsl = cross_compile(compiled->spirv, stage, CrossTarget::glsl450, diags_);
    ASSERT_TRUE(glsl) << diagnostics(t);
  }
}

TEST_F(BackendCompileTest, GeometryStageMatchesItsNeighbours) {
  TestShader t = load_shader("geometry.shader");
  auto vs = compile(t, Stage::vertex);
  auto gs = compile(t, Stage::geometry);
  auto fs = compile(t, Stage::fragment);
  ASSERT_TRUE(vs && gs && fs) << diagnostics(t);
  auto locations = [](const std::vector<StageVariable>& vars) {
    std::map<std::string, uint32_t> out;
    for (const StageVariable& v : vars) out[v.semantic] = v.location;
    return out;
  };
  EXPECT_EQ(locations(vs->reflection.outputs), locations(gs->reflection.inputs));
  EXPECT_EQ(locations(gs->reflection.outputs), locations(fs->reflection.inputs));
  EXPECT_EQ(gs->reflection.inputs[0].array_size, 3u);  // one element per triangle vertex
  EXPECT_TRUE(cross_compile(gs->spirv, Stage::geometry, CrossTarget::glsl450, diags_)) << diagnostics(t);
  EXPECT_FALSE(diags_.has_errors()) << diagnostics(t);
}

TEST_F(BackendCompileTest, MissingStageIsAnError) {
  TestShader t = load_shader("unlit.shader");
  EXPECT_FALSE(compile(t, Stage::geometry));
  ASSERT_EQ(diags_.size(), 1u);
  EXPECT_EQ(diags_.all()[0].id, DiagId::backend_no_entry_point);
}

TEST_F(BackendCompileTest, Vulkan12AndOpenGlTargetsValidate) {
  TestShader t = load_shader("unlit.shader");
  for (TargetEnv target : {TargetEnv::vulkan1_2, TargetEnv::opengl4_5}) {
    BackendOptions options;
    options.target = target;
    auto compiled = compile(t, Stage::fragment, {}, options);
    ASSERT_TRUE(compiled) << diagnostics(t);
  }
}

TEST_F(BackendCompileTest, ResolverServesIncludesFromMemory) {
  TestShader t = testing::make_shader("/virtual/r.shader",
                                      "Shader \"R\" { SubShader { Pass {\n"
                                      "CGPROGRAM\n"
                                      "#pragma vertex vert\n"
                                      "#pragma fragment frag\n"
                                      "#include \"mine.cginc\"\n"
                                      "float4 vert(float4 p : POSITION) : SV_POSITION { return UnityObjectToClipPos(p); }\n"
                                      "fixed4 frag() : SV_Target { return MyColor(); }\n"
                                      "ENDCG\n} } }\n");
  BackendOptions options;
  std::vector<std::string> asked;
  options.resolver = [&](const std::string& requested, const std::string& includer) -> std::optional<IncludedFile> {
    asked.push_back(requested + " from " + includer);
    if (requested == "mine.cginc") return IncludedFile{"/mem/mine.cginc", "#include \"UnityCG.cginc\"\nfixed4 MyColor() { return 1; }\n"};
    return std::nullopt;  // UnityCG.cginc falls through to the stdlib folder
  };
  auto compiled = compile(t, Stage::fragment, {}, options);
  ASSERT_TRUE(compiled) << diagnostics(t);
  EXPECT_TRUE(std::find(asked.begin(), asked.end(), "mine.cginc from /virtual/r.shader") != asked.end());
  // The resolver sees includes of included files with the resolved includer.
  EXPECT_TRUE(std::find(asked.begin(), asked.end(), "UnityCG.cginc from /mem/mine.cginc") != asked.end());
  EXPECT_TRUE(std::find(compiled->included_files.begin(), compiled->included_files.end(), "/mem/mine.cginc") !=
              compiled->included_files.end());
}

TEST_F(BackendCompileTest, SourceTextHasPreludeDefinesAndLineMarkers) {
  TestShader t = load_shader("unlit.shader");
  BackendOptions options;
  options.defines = {{"MY_DEFINE", "3"}, {"FLAG", ""}};
  auto source = backend_.source_text(t.shader, t.program,
                                     {.stage = Stage::fragment, .keywords = {"FOG_LINEAR"}, .preprocess = false},
                                     options, t.sources, diags_);
  ASSERT_TRUE(source);
  const std::string* text = &source->text;
  for (const char* expected : {"#define SHADER_STAGE_FRAGMENT 1", "#define SHADER_TARGET 25",
                               "#define SHADER_API_VULKAN 1", "#define FOG_LINEAR 1", "#define MY_DEFINE 3",
                               "#define FLAG 1", "#include <HLSLSupport.cginc>", "#line 14 \""}) {
    EXPECT_NE(text->find(expected), std::string::npos) << expected << "\n" << *text;
  }
  auto preprocessed_source = backend_.source_text(t.shader, t.program,
                                                  {.stage = Stage::fragment, .keywords = {"FOG_LINEAR"}}, options,
                                                  t.sources, diags_);
  ASSERT_TRUE(preprocessed_source) << diagnostics(t);
  const std::string* preprocessed = &preprocessed_source->text;
  EXPECT_FALSE(preprocessed_source->included_files.empty()) << "the preprocessed text lists the files it read";
  EXPECT_NE(preprocessed->find("fogCoord"), std::string::npos);
  EXPECT_EQ(preprocessed->find("UNITY_FOG_COORDS"), std::string::npos);
}

}  // namespace
}  // namespace facet::backend
