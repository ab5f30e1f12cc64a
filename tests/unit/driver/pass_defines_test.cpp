// Unity's compiler (2018.1 and later) defines UNITY_PASS_<MODE> from a
// pass's LightMode: a pass sees its own define and no other, a SubShader-level
// LightMode counts, and a program that defines the name itself is left alone.
#include <gtest/gtest.h>

#include "stdlib_compile.h"

namespace facet {
namespace {

// A pass whose fragment program fails to compile unless `condition` holds.
std::string probe(std::string_view tags, std::string_view condition, std::string_view own_define = "") {
  return std::string(R"(Shader "Test/PassDefines" { SubShader { Pass {
)") + std::string(tags) + R"(
CGPROGRAM
#pragma vertex vert
#pragma fragment frag
)" + std::string(own_define) + R"(
#if !()" + std::string(condition) + R"()
#error the pass defines are not as expected
#endif
float4 vert(float4 v : POSITION) : SV_Position { return UnityObjectToClipPos(v); }
float4 frag() : SV_Target { return 1; }
ENDCG
} } }
)";
}

void expect_compiles(const std::string& text) {
  auto out = stdlib_test::compile_text("pass_defines.shader", text);
  EXPECT_TRUE(out.ok) << out.log;
}

TEST(PassDefinesTest, EachLightModeDefinesItsOwnUnityPassName) {
  const std::pair<const char*, const char*> modes[] = {
      {"ForwardBase", "UNITY_PASS_FORWARDBASE"}, {"ForwardAdd", "UNITY_PASS_FORWARDADD"},
      {"Deferred", "UNITY_PASS_DEFERRED"},       {"ShadowCaster", "UNITY_PASS_SHADOWCASTER"},
      {"PrepassBase", "UNITY_PASS_PREPASSBASE"}, {"PrepassFinal", "UNITY_PASS_PREPASSFINAL"},
      {"Meta", "UNITY_PASS_META"}};
  for (auto [mode, name] : modes) {
    std::string others;
    for (auto [m, other] : modes) {
      if (std::string(other) != name) others += std::string(" && !defined(") + other + ")";
    }
    SCOPED_TRACE(mode);
    expect_compiles(probe(std::string("Tags { \"LightMode\" = \"") + mode + "\" }", std::string("defined(") + name + ")" + others));
  }
}

TEST(PassDefinesTest, TheLightModeIsMatchedWithoutRegardToCase) {
  expect_compiles(probe(R"(Tags { "LightMode" = "shadowcaster" })", "defined(UNITY_PASS_SHADOWCASTER)"));
}

TEST(PassDefinesTest, APassWithoutLightModeDefinesNoPassName) {
  expect_compiles(probe("", "!defined(UNITY_PASS_FORWARDBASE) && !defined(UNITY_PASS_META)"));
  expect_compiles(probe(R"(Tags { "LightMode" = "Always" })", "!defined(UNITY_PASS_FORWARDBASE)"));
}

TEST(PassDefinesTest, AProgramThatDefinesThePassNameItselfKeepsItsOwnValue) {
  expect_compiles(probe(R"(Tags { "LightMode" = "ForwardBase" })", "UNITY_PASS_FORWARDBASE == 7",
                        "#define UNITY_PASS_FORWARDBASE 7"));
}

TEST(PassDefinesTest, ASubShaderLightModeCopiedIntoThePassCounts) {
  std::string text = probe("", "defined(UNITY_PASS_META)");
  text.replace(text.find("SubShader {"), 11, R"(SubShader { Tags { "LightMode" = "Meta" })");
  expect_compiles(text);
}

TEST(PassDefinesTest, Unity2017DefinesNoPassNames) {
  CompileOptions options;
  options.backend.unity_version = 201740;
  auto out = stdlib_test::compile_text(
      "pass_defines.shader", probe(R"(Tags { "LightMode" = "Meta" })", "!defined(UNITY_PASS_META)"), options);
  EXPECT_TRUE(out.ok) << out.log;
  options.backend.unity_version = 201810;
  out = stdlib_test::compile_text("pass_defines.shader",
                                  probe(R"(Tags { "LightMode" = "Meta" })", "defined(UNITY_PASS_META)"), options);
  EXPECT_TRUE(out.ok) << out.log;
}

}  // namespace
}  // namespace facet
