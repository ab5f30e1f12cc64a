// Surface-shader lowering: which passes and keywords each example surface
// shader produces, what the AST analysis finds, and the errors for bad
// directives and functions.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "facet/compiler.h"

namespace facet {
namespace {

std::string example(const std::string& name) { return std::string(FACET_SOURCE_DIR) + "/examples/shaders/" + name; }

struct Loaded {
  SourceMap sources;
  Diagnostics diags;
  std::optional<ir::Shader> shader;
};

std::unique_ptr<Loaded> load(const Compiler& compiler, const std::string& path) {
  auto out = std::make_unique<Loaded>();
  auto shader = compiler.load(path, out->sources, out->diags);
  if (shader) out->shader = std::move(*shader);
  return out;
}

std::unique_ptr<Loaded> load_text(const Compiler& compiler, const std::string& text) {
  auto out = std::make_unique<Loaded>();
  auto shader = compiler.load_source("surface_test.shader", text, out->sources, out->diags);
  if (shader) out->shader = std::move(*shader);
  return out;
}

// "FORWARD:ForwardBase[multi_compile_fwdbase,multi_compile_fog,...]" per pass.
std::vector<std::string> pass_summary(const Compiler& compiler, const ir::Shader& shader) {
  Diagnostics diags;
  auto passes = compiler.select_passes(shader, {}, diags);
  std::vector<std::string> out;
  if (!passes) return out;
  for (const SelectedPass& p : *passes) {
    std::string line = p.ir.name + ":" + p.ir.tag("LightMode") + "[";
    std::vector<std::string> pragmas;
    for (const variants::KeywordSet& set : p.keywords.sets) {
      if (pragmas.empty() || pragmas.back() != set.pragma) pragmas.push_back(set.pragma);
    }
    for (size_t i = 0; i < pragmas.size(); ++i) line += (i ? "," : "") + pragmas[i];
    out.push_back(line + "]");
  }
  return out;
}

std::string generated_text(const Loaded& l, const std::string& pass) {
  for (FileId f = 0; f < l.sources.file_count(); ++f) {
    if (l.sources.path(f).ends_with("[surface " + pass + "]")) return l.sources.text(f);
  }
  return "";
}

struct Expected {
  std::string file;
  std::vector<std::string> passes;
};

class SurfaceExampleTest : public testing::TestWithParam<Expected> {};

TEST_P(SurfaceExampleTest, ProducesTheExpectedPassesAndKeywordSets) {
  Compiler compiler;
  auto l = load(compiler, example(GetParam().file));
  ASSERT_TRUE(l->shader) << (l->diags.size() ? l->diags.all()[0].message : "");
  EXPECT_FALSE(l->diags.has_errors());
  EXPECT_EQ(pass_summary(compiler, *l->shader), GetParam().passes);
}

const std::string kBase = "FORWARD:ForwardBase[multi_compile_fwdbase,multi_compile_fog,multi_compile_instancing]";
const std::string kAdd = "FORWARD_DELTA:ForwardAdd[multi_compile_fwdadd,multi_compile_fog]";
const std::string kAddFull = "FORWARD_DELTA:ForwardAdd[multi_compile_fwdadd_fullshadows,multi_compile_fog]";
const std::string kShadow = "ShadowCaster:ShadowCaster[multi_compile_shadowcaster,multi_compile_instancing]";
// Lighting models with a Lighting<Model>_Deferred function (the built-in
// four) get one; custom models (WrapGI, Toon, Translucent) and alpha:fade do not.
const std::string kDeferred = "DEFERRED:Deferred[multi_compile_prepassfinal,multi_compile_instancing]";

INSTANTIATE_TEST_SUITE_P(
    Examples, SurfaceExampleTest,
    testing::Values(Expected{"SurfaceLambertVertex.shader", {kBase, kAdd, kDeferred, kShadow}},
                    Expected{"SurfaceBlinnPhongNormal.shader", {kBase, kAdd, kDeferred, kShadow}},
                    Expected{"SurfaceStandard.shader", {kBase, kAddFull, kDeferred, kShadow}},
                    Expected{"SurfaceStandardSpecular.shader", {kBase, kAdd, kDeferred, kShadow}},
                    Expected{"SurfaceCustomGI.shader", {kBase, kAdd, kShadow}},
                    // noforwardadd and no Fallback: one pass
                    Expected{"SurfaceCustomOutput.shader", {kBase}},
                    Expected{"SurfaceTranslucent.shader", {kBase, kAddFull, kShadow}},
                    Expected{"SurfaceReflection.shader", {kBase, kAdd, kDeferred, kShadow}},
                    Expected{"SurfaceAlpha.shader", {kBase, kAdd, kShadow}},
                    Expected{"SurfaceCutout.shader", {kBase, kAdd, kDeferred, kShadow}}),
    [](const auto& info) { return info.param.file.substr(0, info.param.file.find('.')); });

TEST(SurfaceLoweringTest, EveryExampleVariantCompiles) {
  Compiler compiler;
  for (const char* name : {"SurfaceStandard.shader", "SurfaceCutout.shader", "SurfaceCustomOutput.shader"}) {
    auto l = load(compiler, example(name));
    ASSERT_TRUE(l->shader) << name;
    CompileOptions options;
    options.jobs = 2;
    auto compiled = compiler.compile(*l->shader, options, l->sources, l->diags);
    ASSERT_TRUE(compiled) << name << ": " << (l->diags.size() ? l->diags.all()[0].message : "");
    EXPECT_GT(compiled->stats.variants, 30u) << name;
  }
}

TEST(SurfaceLoweringTest, OnlyInputFieldsSurfReadsAreInterpolated) {
  Compiler compiler;
  auto l = load(compiler, example("SurfaceStandard.shader"));
  ASSERT_TRUE(l->shader);
  std::string code = generated_text(*l, "FORWARD");
  EXPECT_NE(code.find("surf_uv_MainTex"), std::string::npos) << code;
  EXPECT_EQ(code.find("surf_worldPos"), std::string::npos) << "worldPos is declared but never read";
}

TEST(SurfaceLoweringTest, UvFieldsUseTheirTexturesScaleOffset) {
  Compiler compiler;
  auto l = load(compiler, example("SurfaceStandard.shader"));
  ASSERT_TRUE(l->shader);
  std::string code = generated_text(*l, "FORWARD");
  EXPECT_NE(code.find("TRANSFORM_TEX(v.texcoord, _MainTex)"), std::string::npos) << code;
  EXPECT_NE(code.find("float4 _MainTex_ST;"), std::string::npos);
  EXPECT_EQ(code.find(" MainTex_ST"), std::string::npos) << "uv_MainTex names _MainTex, not MainTex";
}

TEST(SurfaceLoweringTest, WritingTheNormalGivesATangentFrame) {
  Compiler compiler;
  auto normal_mapped = load(compiler, example("SurfaceBlinnPhongNormal.shader"));
  auto plain = load(compiler, example("SurfaceStandardSpecular.shader"));
  ASSERT_TRUE(normal_mapped->shader && plain->shader);
  EXPECT_NE(generated_text(*normal_mapped, "FORWARD").find("tSpace0"), std::string::npos);
  EXPECT_EQ(generated_text(*plain, "FORWARD").find("tSpace0"), std::string::npos);
}

TEST(SurfaceLoweringTest, LightingFormsAreReadFromTheCode) {
  Compiler compiler;
  auto custom_gi = load(compiler, example("SurfaceCustomGI.shader"));
  auto legacy = load(compiler, example("SurfaceCustomOutput.shader"));
  ASSERT_TRUE(custom_gi->shader && legacy->shader);
  std::string gi = generated_text(*custom_gi, "FORWARD");
  EXPECT_NE(gi.find("LightingWrapGI_GI(o, giInput, gi);"), std::string::npos);
  EXPECT_NE(gi.find("c += LightingWrapGI(o, gi);"), std::string::npos);
  EXPECT_EQ(generated_text(*custom_gi, "FORWARD_DELTA").find("_GI(o"), std::string::npos) << "no GI in ForwardAdd";
  EXPECT_NE(generated_text(*legacy, "FORWARD").find("c += LightingToon(o, lightDir, atten);"), std::string::npos);
}

TEST(SurfaceLoweringTest, ForwardAddIsAdditiveWithoutDepthWrites) {
  Compiler compiler;
  auto l = load(compiler, example("SurfaceAlpha.shader"));
  ASSERT_TRUE(l->shader);
  const auto& passes = l->shader->subshaders[0].passes;
  ASSERT_EQ(passes.size(), 3u);
  ASSERT_EQ(passes[0].state.blend.size(), 1u);  // alpha:fade
  EXPECT_EQ(passes[0].state.blend[0].src.literal, "SrcAlpha");
  EXPECT_EQ(passes[0].state.blend[0].dst.literal, "OneMinusSrcAlpha");
  ASSERT_EQ(passes[1].state.blend.size(), 1u);
  EXPECT_EQ(passes[1].state.blend[0].src.literal, "SrcAlpha");
  EXPECT_EQ(passes[1].state.blend[0].dst.literal, "One");
  ASSERT_TRUE(passes[1].state.zwrite);
  EXPECT_EQ(passes[1].state.zwrite->literal, "Off");
  EXPECT_TRUE(passes[2].state.blend.empty());
}

TEST(SurfaceLoweringTest, ErrorsInTheUsersCodeKeepTheirShaderLines) {
  Compiler compiler;
  std::string text = R"(Shader "T" { SubShader { CGPROGRAM
#pragma surface surf Lambert
struct Input { float2 uv_MainTex; };
void surf(Input IN, inout SurfaceOutput o) {
  o.Albedo = undefined_thing;
}
ENDCG } })";
  auto l = load_text(compiler, text);
  ASSERT_FALSE(l->shader);
  ASSERT_TRUE(l->diags.has_errors());
  const Diagnostic& d = l->diags.all()[0];
  EXPECT_NE(d.message.find("undefined_thing"), std::string::npos) << d.message;
  EXPECT_EQ(l->sources.path(d.span.file), "surface_test.shader");
  EXPECT_EQ(l->sources.line_column(d.span.file, d.span.begin).line, 5u);
}

struct BadCase {
  const char* name;
  std::string code;
  std::string message;
};

class SurfaceBadInputTest : public testing::TestWithParam<BadCase> {};

TEST_P(SurfaceBadInputTest, IsAClearError) {
  Compiler compiler;
  auto l = load_text(compiler, "Shader \"T\" { SubShader { CGPROGRAM\n" + GetParam().code + "\nENDCG } }");
  ASSERT_FALSE(l->shader);
  ASSERT_TRUE(l->diags.has_errors());
  std::string all;
  for (const Diagnostic& d : l->diags.all()) all += d.message + "\n";
  EXPECT_NE(all.find(GetParam().message), std::string::npos) << all;
}

const std::string kInput = "struct Input { float2 uv_MainTex; };\n";

INSTANTIATE_TEST_SUITE_P(
    Cases, SurfaceBadInputTest,
    testing::Values(
        BadCase{"NoModel", "#pragma surface surf\n", "needs a surface function and a lighting model"},
        BadCase{"MissingSurf", "#pragma surface surf Lambert\n" + kInput, "the surface function 'surf' is not defined"},
        BadCase{"SurfWithOneParameter",
                "#pragma surface surf Lambert\n" + kInput + "void surf(Input IN) {}\n",
                "surface function 'surf' has the wrong parameters"},
        BadCase{"UnknownModel",
                "#pragma surface surf Nope\n" + kInput + "void surf(Input IN, inout SurfaceOutput o) {}\n",
                "the lighting function 'LightingNope' is not defined"},
        BadCase{"CustomGIModelWithoutGI",
                "#pragma surface surf Mine\n" + kInput +
                    "half4 LightingMine(SurfaceOutput s, UnityGI gi) { return 0; }\n"
                    "void surf(Input IN, inout SurfaceOutput o) {}\n",
                "'LightingMine_GI' is not defined"},
        BadCase{"OutputStructMismatch",
                "#pragma surface surf Standard\n" + kInput + "void surf(Input IN, inout SurfaceOutput o) {}\n",
                "'LightingStandard' takes 'SurfaceOutputStandard' but 'surf' writes 'SurfaceOutput'"},
        BadCase{"BadAlphaMode",
                "#pragma surface surf Lambert alpha:sometimes\n" + kInput +
                    "void surf(Input IN, inout SurfaceOutput o) {}\n",
                "unknown alpha mode 'sometimes'"},
        // Found by fuzz_frontend: the analysis parse crashed inside glslang.
        BadCase{"GlobalNamedLikeTheOutputStruct",
                "#pragma surface surf Standard\n" + kInput + "half _Gloss SurfaceOutputStandard;\n" +
                    "void surf(Input IN, inout SurfaceOutputStandard o) {}\n",
                "a global cannot take a struct's name"},
        BadCase{"UnbalancedParenthesis",
                "#pragma surface surf Standard\n" + kInput + "half _Gloss o) {}\n" +
                    "void surf(Input IN, inout SurfaceOutputStandard o) {}\n",
                "')' closes nothing"},
        BadCase{"MissingVertexModifier",
                "#pragma surface surf Lambert vertex:vert\n" + kInput +
                    "void surf(Input IN, inout SurfaceOutput o) {}\n",
                "the vertex modifier 'vert' is not defined"}),
    [](const auto& info) { return std::string(info.param.name); });

// A Lambert surface shader writing white albedo, with `options` after the model.
std::unique_ptr<Loaded> lambert_with(const Compiler& compiler, const std::string& options) {
  return load_text(compiler, "Shader \"T\" { SubShader { CGPROGRAM\n#pragma surface surf Lambert" + options + "\n" +
                                 kInput + "void surf(Input IN, inout SurfaceOutput o) { o.Albedo = 1; }\nENDCG } }");
}

// ForwardBase adds Shade4PointLights under VERTEXLIGHT_ON in the vertex
// stage; novertexlights removes the keyword and the code, as in Unity.
TEST(SurfaceLoweringTest, ForwardBaseLightsFourPointLightsPerVertexUnlessNoVertexLights) {
  Compiler compiler;
  auto shader = [&](const std::string& options) { return lambert_with(compiler, options); };
  auto with = shader("");
  ASSERT_TRUE(with->shader) << render_text(with->diags, with->sources);
  std::string code = generated_text(*with, "FORWARD");
  size_t vertex_light = code.find("#ifdef VERTEXLIGHT_ON\n  o.vertexLight = Shade4PointLights(");
  EXPECT_NE(vertex_light, std::string::npos) << code;
  EXPECT_LT(vertex_light, code.find("frag_surf")) << "the vertex stage computes them";
  EXPECT_NE(code.find("giInput.ambient = IN.vertexLight;"), std::string::npos) << code;
  Diagnostics diags;
  auto passes = compiler.select_passes(*with->shader, {}, diags);
  ASSERT_TRUE(passes);
  auto declares = [](const SelectedPass& p, const std::string& keyword) {
    for (const variants::KeywordSet& set : p.keywords.sets) {
      if (std::find(set.keywords.begin(), set.keywords.end(), keyword) != set.keywords.end()) return true;
    }
    return false;
  };
  EXPECT_TRUE(declares((*passes)[0], "VERTEXLIGHT_ON"));

  auto without = shader(" novertexlights");
  ASSERT_TRUE(without->shader) << render_text(without->diags, without->sources);
  EXPECT_EQ(without->diags.size(), 0u) << "novertexlights is no longer an option that changes nothing";
  EXPECT_EQ(generated_text(*without, "FORWARD").find("vertexLight"), std::string::npos);
  auto plain = compiler.select_passes(*without->shader, {}, diags);
  ASSERT_TRUE(plain);
  EXPECT_FALSE(declares((*plain)[0], "VERTEXLIGHT_ON"));
  CompileOptions options;
  options.jobs = 2;
  EXPECT_TRUE(compiler.compile(*with->shader, options, with->sources, diags)) << render_text(diags, with->sources);
}

// The Deferred pass writes the G-buffer and the light buffer through
// Lighting<Model>_Deferred after <Model>_GI with a black light, with no fog
// and no shadow coordinates; exclude_path:deferred leaves it out.
TEST(SurfaceLoweringTest, TheDeferredPassWritesTheGBufferUnlessExcluded) {
  Compiler compiler;
  auto shader = [&](const std::string& options) { return lambert_with(compiler, options); };
  auto with = shader("");
  ASSERT_TRUE(with->shader) << render_text(with->diags, with->sources);
  std::string code = generated_text(*with, "DEFERRED");
  ASSERT_FALSE(code.empty());
  EXPECT_NE(code.find("out half4 outGBuffer0 : SV_Target0"), std::string::npos) << code;
  EXPECT_NE(code.find("out half4 outEmission : SV_Target3"), std::string::npos) << code;
  EXPECT_NE(code.find("LightingLambert_GI(o, giInput, gi);"), std::string::npos) << code;
  EXPECT_NE(code.find("outEmission = LightingLambert_Deferred(o, gi, outGBuffer0, outGBuffer1, outGBuffer2);"),
            std::string::npos) << code;
  EXPECT_EQ(code.find("UNITY_FOG"), std::string::npos) << code;
  EXPECT_EQ(code.find("_ShadowCoord"), std::string::npos) << code;
  Diagnostics diags;
  CompileOptions options;
  options.passes = {"DEFERRED"};
  EXPECT_TRUE(compiler.compile(*with->shader, options, with->sources, diags)) << render_text(diags, with->sources);

  auto without = shader(" exclude_path:deferred");
  ASSERT_TRUE(without->shader) << render_text(without->diags, without->sources);
  EXPECT_EQ(without->diags.size(), 0u);
  EXPECT_TRUE(generated_text(*without, "DEFERRED").empty());
  EXPECT_EQ(pass_summary(compiler, *without->shader).size(), 2u);  // FORWARD, FORWARD_DELTA
}

TEST(SurfaceLoweringTest, UnknownOptionIsAWarningNotAnError) {
  Compiler compiler;
  auto l = load_text(compiler, "Shader \"T\" { SubShader { CGPROGRAM\n#pragma surface surf Lambert sparkles\n" + kInput +
                                   "void surf(Input IN, inout SurfaceOutput o) {}\nENDCG } }");
  ASSERT_TRUE(l->shader);
  ASSERT_EQ(l->diags.size(), 1u);
  EXPECT_EQ(l->diags.all()[0].severity, Severity::warning);
  EXPECT_NE(l->diags.all()[0].message.find("unknown surface shader option 'sparkles'"), std::string::npos);
}

}  // namespace
}  // namespace facet

namespace facet {
namespace {

// finalcolor, screenPos, decal and keepalpha are not in the examples: one
// shader with all of them compiles every variant, and the generated code
// calls the final colour function after lighting and before fog.
TEST(SurfaceLoweringTest, FinalColorScreenPosDecalAndKeepAlphaCompile) {
  Compiler compiler;
  auto l = load_text(compiler, R"(Shader "T/Decal" {
  Properties { _MainTex ("Tex", 2D) = "white" {} _Tint ("Tint", Color) = (1, 1, 1, 1) }
  SubShader {
    CGPROGRAM
    #pragma surface surf Lambert decal:add finalcolor:tint keepalpha nofog noinstancing
    sampler2D _MainTex;
    fixed4 _Tint;
    struct Input { float2 uv_MainTex; float4 screenPos; };
    void tint(Input IN, SurfaceOutput o, inout fixed4 color) { color *= _Tint; }
    void surf(Input IN, inout SurfaceOutput o) {
      float2 screenUV = IN.screenPos.xy / IN.screenPos.w;
      o.Albedo = tex2D(_MainTex, IN.uv_MainTex).rgb * screenUV.x;
      o.Alpha = 0.5;
    }
    ENDCG
  }
})");
  ASSERT_TRUE(l->shader) << (l->diags.size() ? l->diags.all()[0].message : "");
  std::string code = generated_text(*l, "FORWARD");
  size_t lit = code.find("c += LightingLambert(");
  size_t tinted = code.find("tint(surfIN, o, c);");
  ASSERT_NE(lit, std::string::npos);
  ASSERT_NE(tinted, std::string::npos);
  EXPECT_LT(lit, tinted);
  EXPECT_NE(code.find("ComputeScreenPos"), std::string::npos);
  EXPECT_EQ(code.find("UNITY_OPAQUE_ALPHA"), std::string::npos) << "keepalpha and decal keep the alpha";
  EXPECT_EQ(code.find("UNITY_APPLY_FOG"), std::string::npos) << "nofog";
  const ir::Pass& base = l->shader->subshaders[0].passes[0];
  ASSERT_EQ(base.state.blend.size(), 1u);
  EXPECT_EQ(base.state.blend[0].src.literal, "One");
  EXPECT_EQ(base.state.blend[0].dst.literal, "One");
  ASSERT_TRUE(base.state.zwrite && base.state.offset_factor);
  EXPECT_EQ(base.state.zwrite->literal, "Off");
  EXPECT_EQ(base.state.offset_factor->literal, "-1");
  EXPECT_EQ(pass_summary(compiler, *l->shader),
            (std::vector<std::string>{"FORWARD:ForwardBase[multi_compile_fwdbase]",
                                      "FORWARD_DELTA:ForwardAdd[multi_compile_fwdadd]"}));
  CompileOptions options;
  auto compiled = compiler.compile(*l->shader, options, l->sources, l->diags);
  ASSERT_TRUE(compiled) << (l->diags.size() ? l->diags.all()[0].message : "");
  EXPECT_EQ(compiled->stats.variants, 8u + 5u);
}

}  // namespace
}  // namespace facet

namespace facet {
namespace {

// Two surface programs around a written Pass (a two-layer shader): each
// program's passes stand where it is written, and every variant compiles.
TEST(SurfaceLoweringTest, SeveralSurfaceProgramsLowerInFileOrder) {
  Compiler compiler;
  auto l = load_text(compiler, R"(Shader "T/Layers" {
Properties { _MainTex ("Tex", 2D) = "white" {} }
SubShader {
  CGPROGRAM
  #pragma surface inner Lambert
  sampler2D _MainTex;
  struct Input { float2 uv_MainTex; };
  void inner(Input IN, inout SurfaceOutput o) { o.Albedo = tex2D(_MainTex, IN.uv_MainTex).rgb; }
  ENDCG
  Pass { Name "OUTLINE" ColorMask 0 }
  CGPROGRAM
  #pragma surface outer Lambert alpha:fade noforwardadd
  sampler2D _MainTex;
  struct Input { float2 uv_MainTex; };
  void outer(Input IN, inout SurfaceOutput o) { o.Albedo = 1; o.Alpha = tex2D(_MainTex, IN.uv_MainTex).a * 0.5; }
  ENDCG
}
Fallback "Diffuse"
})");
  ASSERT_TRUE(l->shader) << render_text(l->diags, l->sources);
  const ir::SubShader& sub = l->shader->subshaders[0];
  std::vector<std::string> names;
  for (const ir::Pass& p : sub.passes) names.push_back(p.name + ":" + p.tag("LightMode"));
  EXPECT_EQ(names, (std::vector<std::string>{"FORWARD:ForwardBase", "FORWARD_DELTA:ForwardAdd", "DEFERRED:Deferred",
                                             "ShadowCaster:ShadowCaster", "OUTLINE:", "FORWARD:ForwardBase"}));
  EXPECT_NE(generated_text(*l, "FORWARD #1").find("inner("), std::string::npos);
  EXPECT_NE(generated_text(*l, "FORWARD #2").find("outer("), std::string::npos);
  Diagnostics diags;
  auto compiled = compiler.compile(*l->shader, {}, l->sources, diags);
  EXPECT_TRUE(compiled && !diags.has_errors()) << render_text(diags, l->sources);
}

}  // namespace
}  // namespace facet
