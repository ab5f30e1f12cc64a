// Fixed-function passes compile: the program sema generates for each
// combiner form, for vertex lighting, alpha test and every fog mode goes
// through the real back end and gives valid SPIR-V.
#include <gtest/gtest.h>

#include "stdlib_compile.h"

namespace facet {
namespace {

std::string shader(std::string_view pass_body) {
  return std::string(R"(Shader "Test/FixedFunction" {
Properties {
  _Color ("Color", Color) = (1,1,1,1)
  _SpecColor ("Spec", Color) = (1,1,1,1)
  _Emission ("Emission", Color) = (0,0,0,0)
  _Shininess ("Shininess", Range(0.01, 1)) = 0.7
  _MainTex ("Base", 2D) = "white" {}
  _Mask ("Mask", 2D) = "white" {}
  _Cube ("Reflection", Cube) = "" { TexGen CubeReflect }
  _Cutoff ("Cutoff", Range(0,1)) = 0.5
}
SubShader { Pass {
)") + std::string(pass_body) + "\n} } }";
}

void expect_compiles(std::string_view pass_body, size_t min_blobs = 2) {
  auto out = stdlib_test::compile_text("ff.shader", shader(pass_body));
  ASSERT_TRUE(out.ok) << out.log;
  EXPECT_GE(stdlib_test::expect_valid_spirv(out.shader->package), min_blobs);
}

class FixedFunctionCombinerCompileTest : public testing::TestWithParam<std::string> {};

TEST_P(FixedFunctionCombinerCompileTest, CompilesToValidSpirv) {
  expect_compiles("Fog { Mode Off }\nSetTexture [_MainTex] { constantColor [_Color] combine texture * primary }\n"
                  "SetTexture [_Mask] { constantColor (0.5, 0.5, 0.5, 0.5) combine " + GetParam() + " }");
}

INSTANTIATE_TEST_SUITE_P(
    Forms, FixedFunctionCombinerCompileTest,
    testing::Values("texture", "previous * texture", "texture + previous", "previous - texture",
                    "previous +- texture", "texture lerp (constant) previous", "previous * texture + constant",
                    "previous * texture +- constant", "previous * texture - constant", "texture * previous Double",
                    "texture * previous QUAD, texture", "one - texture * previous, one - previous alpha",
                    "texture alpha * constant", "previous, texture * constant Double",
                    "texture lerp (previous) constant"));

TEST(FixedFunctionCompileTest, VertexLitWithSeparateSpecular) {
  expect_compiles(R"(Material { Diffuse [_Color] Ambient [_Color] Shininess [_Shininess] Specular [_SpecColor] Emission [_Emission] }
Lighting On
SeparateSpecular On
SetTexture [_MainTex] { constantColor [_Color] Combine texture * primary DOUBLE, texture * constant })");
}

TEST(FixedFunctionCompileTest, VertexLitColorMaterial) {
  expect_compiles("Lighting On\nColorMaterial AmbientAndDiffuse\nMaterial { Diffuse (1,1,1,1) Specular (1,1,1,1) }");
  expect_compiles("Lighting On\nColorMaterial Emission\nSetTexture [_MainTex] { combine texture * primary }");
}

TEST(FixedFunctionCompileTest, AlphaTestReflectionAndMatrix) {
  expect_compiles(R"(AlphaTest GEqual [_Cutoff]
Color [_Color]
SetTexture [_MainTex] { matrix [_TexMatrix] combine texture * primary }
SetTexture [_Cube] { combine texture * previous alpha + previous })");
}

TEST(FixedFunctionCompileTest, EveryFogMode) {
  // Global: a variant per fog keyword set (none, FOG_LINEAR, FOG_EXP, FOG_EXP2);
  // identical stage programs are stored once, so fewer than 8 blobs.
  expect_compiles("SetTexture [_MainTex] { combine texture }", 4);
  for (std::string mode : {"Off", "Linear", "Exp", "Exp2"}) {
    expect_compiles("Fog { Mode " + mode + " Color (0, 0, 0, 0) }\nSetTexture [_MainTex] { combine texture }");
  }
}

TEST(FixedFunctionCompileTest, SolidColourWithoutTextures) { expect_compiles("Color (1, 0, 0, 1)\nFog { Mode Off }"); }

}  // namespace
}  // namespace facet
