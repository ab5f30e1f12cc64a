// Fixed-function passes: which passes get a generated program, the HLSL each
// combiner form, lighting, alpha test and fog produce, scope inheritance, and
// located errors for malformed legacy commands. (Compiling the generated
// programs to SPIR-V is tests/unit/driver/fixed_function_compile_test.cpp.)
#include <gtest/gtest.h>

#include <memory>

#include "facet/sema.h"
#include "lower.h"
#include "sema_test_util.h"

namespace facet::sema {
namespace {

using test_util::Analyzed;

std::unique_ptr<Analyzed> analyze_text(std::string text) { return test_util::analyze_text(std::move(text), {}, "ff.shader"); }

const char* kProps = R"(Properties {
  _Color ("Color", Color) = (1,1,1,1)
  _MainTex ("Base", 2D) = "white" {}
  _Cutoff ("Cutoff", Range(0,1)) = 0.5
  _Cube ("Reflection", Cube) = "_Skybox" { TexGen CubeReflect }
})";

std::string ff_pass(std::string_view body) {
  return std::string("Shader \"T\" {\n") + kProps + "\nSubShader { Pass {\n" + std::string(body) + "\n} } }";
}

std::unique_ptr<Analyzed> ok(std::string_view body) {
  auto a = analyze_text(ff_pass(body));
  EXPECT_TRUE(a->ir.has_value()) << (a->diags.size() ? a->diags.all()[0].message : "");
  EXPECT_FALSE(a->diags.has_errors());
  return a;
}

TEST(FixedFunctionTest, PassWithLegacyCommandsGetsAGeneratedProgram) {
  auto a = ok("SetTexture [_MainTex] { combine texture * primary }");
  ASSERT_TRUE(a->pass().program);
  const ir::Program& p = *a->pass().program;
  EXPECT_EQ(p.language, ir::ProgramLanguage::cg);
  EXPECT_EQ(p.entry_points[size_t(Stage::vertex)], "ff_vert");
  EXPECT_EQ(p.entry_points[size_t(Stage::fragment)], "ff_frag");
  EXPECT_NE(p.body.line_file.find("fixed-function subshader 0 pass 0"), std::string::npos);
  EXPECT_NE(p.body.text.find("#include \"UnityCG.cginc\""), std::string::npos);
  EXPECT_NE(p.body.text.find("sampler2D _MainTex;"), std::string::npos);
  EXPECT_NE(p.body.text.find("float4 _MainTex_ST;"), std::string::npos);
  EXPECT_NE(p.body.text.find("ffTexture.rgb * ffPrimary.rgb"), std::string::npos) << p.body.text;
  // Fog is global by default: the fog keywords become variants.
  bool fog = false;
  for (const ir::Pragma& pr : p.pragmas) fog |= pr.name == "multi_compile_fog";
  EXPECT_TRUE(fog);
}

TEST(FixedFunctionTest, PassWithoutLegacyCommandsStaysWithoutProgram) {
  auto a = ok("ZWrite On ColorMask 0");
  EXPECT_FALSE(a->pass().program);
}

TEST(FixedFunctionTest, ProgrammablePassIgnoresLegacyCommands) {
  auto a = ok("Lighting On\nSetTexture [_MainTex] { combine bogus }\nCGPROGRAM\n#pragma vertex v\n#pragma fragment f\nENDCG");
  ASSERT_TRUE(a->pass().program);
  EXPECT_EQ(a->pass().program->entry_points[size_t(Stage::vertex)], "v");
}

struct CombinerCase {
  std::string combine;
  std::string color;  // the expected colour part of the stage
  std::string alpha;  // the expected alpha part
};

class FixedFunctionCombinerTest : public testing::TestWithParam<CombinerCase> {};

TEST_P(FixedFunctionCombinerTest, LowersToTheExpectedExpression) {
  auto a = ok("SetTexture [_MainTex] { constantColor (1, 0.5, 0.25, 1) combine " + GetParam().combine + " }");
  ASSERT_TRUE(a->pass().program);
  std::string expected = "ffPrevious = float4(" + GetParam().color + ", " + GetParam().alpha + ");";
  EXPECT_NE(a->hlsl().find(expected), std::string::npos) << expected << "\n" << a->hlsl();
}

INSTANTIATE_TEST_SUITE_P(
    Forms, FixedFunctionCombinerTest,
    testing::Values(
        CombinerCase{"texture", "saturate(ffTexture.rgb)", "saturate(ffTexture.a)"},
        CombinerCase{"texture * primary", "saturate(ffTexture.rgb * ffPrimary.rgb)", "saturate(ffTexture.a * ffPrimary.a)"},
        CombinerCase{"texture + previous", "saturate(ffTexture.rgb + ffPrevious.rgb)", "saturate(ffTexture.a + ffPrevious.a)"},
        CombinerCase{"texture - constant", "saturate(ffTexture.rgb - ffConstant.rgb)", "saturate(ffTexture.a - ffConstant.a)"},
        CombinerCase{"texture +- primary", "saturate(ffTexture.rgb + ffPrimary.rgb - 0.5)",
                     "saturate(ffTexture.a + ffPrimary.a - 0.5)"},
        CombinerCase{"texture lerp (constant) previous", "saturate(lerp(ffPrevious.rgb, ffTexture.rgb, ffConstant.a))",
                     "saturate(lerp(ffPrevious.a, ffTexture.a, ffConstant.a))"},
        CombinerCase{"texture * primary + constant", "saturate(ffTexture.rgb * ffPrimary.rgb + ffConstant.rgb)",
                     "saturate(ffTexture.a * ffPrimary.a + ffConstant.a)"},
        CombinerCase{"texture * primary +- constant", "saturate(ffTexture.rgb * ffPrimary.rgb + ffConstant.rgb - 0.5)",
                     "saturate(ffTexture.a * ffPrimary.a + ffConstant.a - 0.5)"},
        CombinerCase{"texture * primary - constant", "saturate(ffTexture.rgb * ffPrimary.rgb - ffConstant.rgb)",
                     "saturate(ffTexture.a * ffPrimary.a - ffConstant.a)"},
        CombinerCase{"texture * primary DOUBLE", "saturate((ffTexture.rgb * ffPrimary.rgb) * 2.0)",
                     "saturate((ffTexture.a * ffPrimary.a) * 2.0)"},
        CombinerCase{"texture * primary Quad, texture", "saturate((ffTexture.rgb * ffPrimary.rgb) * 4.0)",
                     "saturate(ffTexture.a)"},
        CombinerCase{"texture * primary, texture * constant Double", "saturate(ffTexture.rgb * ffPrimary.rgb)",
                     "saturate((ffTexture.a * ffConstant.a) * 2.0)"},
        CombinerCase{"one - texture", "saturate((1.0 - ffTexture.rgb))", "saturate((1.0 - ffTexture.a))"},
        CombinerCase{"texture alpha * primary", "saturate(ffTexture.aaa * ffPrimary.rgb)",
                     "saturate(ffTexture.a * ffPrimary.a)"},
        CombinerCase{"one - texture alpha, previous", "saturate((1.0 - ffTexture.aaa))", "saturate(ffPrevious.a)"}));

TEST(FixedFunctionTest, ConstantColorMayBeAProperty) {
  auto a = ok("SetTexture [_MainTex] { constantColor [_Color] combine texture * constant }");
  EXPECT_NE(a->hlsl().find("ffConstant = _Color;"), std::string::npos);
  EXPECT_NE(a->hlsl().find("float4 _Color;"), std::string::npos);
}

TEST(FixedFunctionTest, AConstantColorComponentMayBeAFloatProperty) {
  // Unity's legacy motion blur: "ConstantColor (0,0,0,[_AccumOrig])".
  auto a = ok("SetTexture [_MainTex] { ConstantColor (0,0,0,[_AccumOrig]) Combine texture, constant }");
  EXPECT_NE(a->hlsl().find("ffConstant = float4(0, 0, 0, _AccumOrig);"), std::string::npos) << a->hlsl();
  EXPECT_NE(a->hlsl().find("float _AccumOrig;"), std::string::npos);
}

TEST(FixedFunctionTest, ATextureTheStdlibDeclaresIsNotDeclaredAgain) {
  // Unity's VertexLM passes: "SetTexture [unity_Lightmap] { matrix [unity_LightmapMatrix] ... }".
  auto a = ok("SetTexture [unity_Lightmap] { matrix [unity_LightmapMatrix] combine texture }");
  EXPECT_EQ(a->hlsl().find("sampler2D unity_Lightmap;"), std::string::npos) << a->hlsl();
  EXPECT_NE(a->hlsl().find("tex2D(unity_Lightmap, i.uv0)"), std::string::npos) << a->hlsl();
  EXPECT_NE(a->hlsl().find("float4x4 unity_LightmapMatrix;"), std::string::npos);
}

TEST(FixedFunctionTest, MatrixTransformsTheUVs) {
  auto a = ok("SetTexture [_MainTex] { matrix [_TexMatrix] combine texture }");
  EXPECT_NE(a->hlsl().find("float4x4 _TexMatrix;"), std::string::npos);
  EXPECT_NE(a->hlsl().find("mul(_TexMatrix, float4(o.uv0, 0.0, 1.0)).xy"), std::string::npos);
}

TEST(FixedFunctionTest, StagesChainThroughPrevious) {
  auto a = ok("SetTexture [_MainTex] { combine texture * primary }\nSetTexture [_Cube] { combine texture * previous }");
  EXPECT_NE(a->hlsl().find("ffTexture = tex2D(_MainTex, i.uv0);"), std::string::npos);
  EXPECT_NE(a->hlsl().find("ffTexture = texCUBE(_Cube, i.uv1);"), std::string::npos);
  EXPECT_NE(a->hlsl().find("samplerCUBE _Cube;"), std::string::npos);
  // TexGen CubeReflect: a world-space reflection vector.
  EXPECT_NE(a->hlsl().find("o.uv1 = reflect(worldPos - _WorldSpaceCameraPos, worldN);"), std::string::npos);
}

TEST(FixedFunctionTest, LightingWithMaterialIsVertexLit) {
  auto a = ok(R"(Material { Diffuse [_Color] Ambient (0.2, 0.2, 0.2, 1) Specular (1,1,1,1) Shininess 0.7 Emission (0,0,0,0) }
Lighting On
SeparateSpecular On
SetTexture [_MainTex] { combine texture * primary DOUBLE, texture * primary })");
  const std::string& h = a->hlsl();
  EXPECT_NE(h.find("float4 matDiffuse = _Color;"), std::string::npos) << h;
  EXPECT_NE(h.find("for (int i = 0; i < 8; i++)"), std::string::npos);
  EXPECT_NE(h.find("unity_LightPosition[i]"), std::string::npos);
  EXPECT_NE(h.find("unity_SpotDirection[i]"), std::string::npos);
  EXPECT_NE(h.find("max(0.7 * 128.0, 0.0001)"), std::string::npos);
  EXPECT_NE(h.find("float4 specular : COLOR1;"), std::string::npos);
  EXPECT_NE(h.find("ffPrevious.rgb = saturate(ffPrevious.rgb + i.specular.rgb);"), std::string::npos);
}

TEST(FixedFunctionTest, SpecularWithoutSeparateSpecularGoesIntoPrimary) {
  auto a = ok("Lighting On\nMaterial { Diffuse (1,1,1,1) Specular (1,1,1,1) Shininess [_Cutoff] }");
  EXPECT_NE(a->hlsl().find("lit += spec;"), std::string::npos);
  EXPECT_NE(a->hlsl().find("float _Cutoff;"), std::string::npos);
  EXPECT_EQ(a->hlsl().find("COLOR1"), std::string::npos);
}

TEST(FixedFunctionTest, ColorMaterialUsesTheVertexColour) {
  auto a = ok("Lighting On\nColorMaterial AmbientAndDiffuse\nMaterial { Diffuse (1,1,1,1) }");
  EXPECT_NE(a->hlsl().find("float4 matDiffuse = v.color;"), std::string::npos) << a->hlsl();
  auto e = ok("Lighting On\nColorMaterial Emission");
  EXPECT_NE(e->hlsl().find("float3 lit = (v.color).rgb"), std::string::npos) << e->hlsl();
}

TEST(FixedFunctionTest, UnlitPrimaryIsColorOrVertexColour) {
  EXPECT_NE(ok("Color (1, 0, 0, 1)")->hlsl().find("o.primary = float4(1, 0, 0, 1);"), std::string::npos);
  EXPECT_NE(ok("Color [_Color]")->hlsl().find("o.primary = _Color;"), std::string::npos);
  EXPECT_NE(ok("Lighting Off\nSetTexture [_MainTex] { combine texture * primary }")->hlsl().find("saturate(v.color)"),
            std::string::npos);
}

TEST(FixedFunctionTest, AlphaTestIsAClip) {
  auto a = ok("AlphaTest Greater [_Cutoff]\nSetTexture [_MainTex] { combine texture }");
  EXPECT_NE(a->hlsl().find("clip((ffPrevious.a > _Cutoff) ? 1.0 : -1.0);"), std::string::npos) << a->hlsl();
  EXPECT_NE(ok("AlphaTest LEqual 0.25")->hlsl().find("ffPrevious.a <= 0.25"), std::string::npos);
  EXPECT_NE(ok("AlphaTest Never")->hlsl().find("clip(-1.0);"), std::string::npos);
  EXPECT_EQ(ok("AlphaTest Off")->hlsl().find("clip("), std::string::npos);
}

TEST(FixedFunctionTest, FogModes) {
  auto off = ok("Fog { Mode Off }\nColor (1,1,1,1)");
  EXPECT_EQ(off->hlsl().find("FOG"), std::string::npos) << off->hlsl();
  for (const ir::Pragma& p : off->pass().program->pragmas) EXPECT_NE(p.name, "multi_compile_fog");
  auto color = ok("Fog { Color (0,0,0,0) }\nColor (1,1,1,1)");
  EXPECT_NE(color->hlsl().find("UNITY_APPLY_FOG_COLOR(i.fogCoord, ffPrevious, float4(0, 0, 0, 0));"), std::string::npos);
  EXPECT_NE(ok("Fog { Mode Exp2 }\nColor (1,1,1,1)")->hlsl().find("#define FOG_EXP2 1"), std::string::npos);
}

TEST(FixedFunctionTest, ScopesAreInheritedInnerWins) {
  auto a = analyze_text(std::string("Shader \"T\" {\n") + kProps +
                        "\nCategory { Fog { Mode Off } Lighting On\nSubShader { Color (1,1,1,1)\nPass { }\n} } }");
  ASSERT_TRUE(a->ir) << (a->diags.size() ? a->diags.all()[0].message : "");
  // The Pass itself has no commands; the Category and SubShader's apply.
  ASSERT_TRUE(a->pass().program);
  EXPECT_NE(a->hlsl().find("for (int i = 0; i < 8; i++)"), std::string::npos);
  EXPECT_EQ(a->hlsl().find("FOG"), std::string::npos);
  auto inner = ok("Lighting On\nLighting Off");
  EXPECT_EQ(inner->hlsl().find("unity_LightPosition"), std::string::npos);
}

TEST(FixedFunctionTest, BindChannelsPicksTheUVSet) {
  auto a = ok(R"(BindChannels { Bind "Vertex", vertex Bind "texcoord1", texcoord0 Bind "texcoord", texcoord1 }
SetTexture [_MainTex] { combine texture }
SetTexture [_MainTex] { combine texture * previous })");
  EXPECT_NE(a->hlsl().find("o.uv0 = v.texcoord1.xy"), std::string::npos) << a->hlsl();
  EXPECT_NE(a->hlsl().find("o.uv1 = v.texcoord0.xy"), std::string::npos);
}

// --- errors -----------------------------------------------------------------------

void expect_error(std::string_view body, std::string_view at, std::string_view message_part) {
  auto a = analyze_text(ff_pass(body));
  EXPECT_FALSE(a->ir.has_value());
  const Diagnostic* d = a->find(DiagId::sema_bad_legacy_command);
  ASSERT_NE(d, nullptr) << body;
  EXPECT_EQ(d->severity, Severity::error);
  EXPECT_EQ(a->text_at(*d), at) << d->message;
  EXPECT_NE(d->message.find(message_part), std::string::npos) << d->message;
}

TEST(FixedFunctionErrorTest, UnknownCombinerSource) {
  expect_error("SetTexture [_MainTex] { combine texture * primery }", "primery", "unknown combiner source 'primery'");
}

TEST(FixedFunctionErrorTest, CombinerMissingOperand) {
  expect_error("SetTexture [_MainTex] { combine texture * }", "}", "expected a combiner source");
  expect_error("SetTexture [_MainTex] { combine texture lerp texture }", "texture", "expected '('");
}

TEST(FixedFunctionErrorTest, SetTextureWithoutAProperty) {
  expect_error("SetTexture _MainTex { combine texture }", "_MainTex", "expected a texture property");
  // Without any value the parser reports it.
  auto a = analyze_text(ff_pass("SetTexture { combine texture }"));
  EXPECT_FALSE(a->ir.has_value());
  EXPECT_TRUE(a->diags.has_errors());
}

TEST(FixedFunctionErrorTest, MalformedMaterial) {
  expect_error("Material { Difuse (1,1,1,1) }", "Difuse", "did you mean 'Diffuse'");
  expect_error("Material { Diffuse (1,1) }", "(1,1)", "3 or 4 numbers");
  expect_error("Material { Shininess (1,1,1,1) }", "(", "expected a number");
}

TEST(FixedFunctionErrorTest, BadOnOffAndComparisons) {
  expect_error("Lighting Maybe", "Maybe", "expected 'On' or 'Off'");
  expect_error("AlphaTest Greatr 0.5", "Greatr", "did you mean 'Greater'");
  expect_error("Fog { Mode Fast }", "Fast", "expected Off, Global, Linear, Exp or Exp2");
  expect_error("SetTexture [_MainTex] { combin texture }", "combin", "unknown SetTexture field");
}

}  // namespace
}  // namespace facet::sema
