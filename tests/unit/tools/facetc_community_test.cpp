// Constructs of community shaders (VRChat toon suites and the like) that
// Unity accepts, each in a shader of our own: they compile to valid SPIR-V.
#include <nlohmann/json.hpp>

#include "facetc_test_util.h"

namespace facet::tools::testing {
namespace {

using ::testing::HasSubstr;

std::string pass_shader(const std::string& pragmas, const std::string& code) {
  return "Shader \"Community\" {\n"
         "  Properties { _MainTex (\"Tex\", 2D) = \"white\" {} _Strength (\"Strength\", Float) = 1 }\n"
         "  SubShader { Pass {\n"
         "    Tags { \"LightMode\" = \"ForwardBase\" }\n"
         "    CGPROGRAM\n"
         "    #pragma vertex vert\n"
         "    #pragma fragment frag\n" +
         pragmas + "    #include \"UnityCG.cginc\"\n" + code + "    ENDCG\n  } }\n}\n";
}

const char* kVert = "    float4 vert(float4 v : POSITION) : SV_POSITION { return UnityObjectToClipPos(v); }\n";

TEST_F(FacetcTest, VertexLightsDeclaredBesideForwardBaseCompileEveryVariant) {
  write_all(dir_ / "v.shader", pass_shader("    #pragma multi_compile _ VERTEXLIGHT_ON\n    #pragma multi_compile_fwdbase\n",
                                           std::string(kVert) +
                                               "    float4 frag() : SV_Target {\n"
                                               "    #ifdef VERTEXLIGHT_ON\n      return 1;\n    #else\n      return 0;\n"
                                               "    #endif\n    }\n"));
  FacetcRun list = facetc({"v.shader", "--list-variants"});
  ASSERT_EQ(list.exit_code, 0) << list.err;
  EXPECT_THAT(list.out, HasSubstr("  pass       132"));
  FacetcRun build = facetc({"v.shader", "--build-unreachable", "-o", "v.facetpkg"});
  ASSERT_EQ(build.exit_code, 0) << build.err;
  EXPECT_THAT(build.err, ::testing::Not(HasSubstr("error")));
}

TEST_F(FacetcTest, ATextureDeclaredWithItsSamplerMaySampleThroughEitherName) {
  write_all(dir_ / "s.shader",
            pass_shader("", "    UNITY_DECLARE_TEX2D(_MainTex);\n    UNITY_DECLARE_TEX2D_NOSAMPLER(_Mask);\n" +
                                std::string(kVert) +
                                "    float4 frag(float4 p : SV_POSITION) : SV_Target {\n"
                                "      float2 uv = p.xy / 256;\n"
                                "      float4 a = _MainTex.SampleGrad(sampler_MainTex, uv, ddx(uv), ddy(uv));\n"
                                "      return a * UNITY_SAMPLE_TEX2D(_MainTex, uv) * UNITY_SAMPLE_TEX2D_SAMPLER(_Mask, _MainTex, uv)\n"
                                "           * UNITY_SAMPLE_TEX2D_LOD(_MainTex, uv, 0);\n"
                                "    }\n"));
  FacetcRun reflect = facetc({"s.shader", "--reflect", "--pass", "0"});
  ASSERT_EQ(reflect.exit_code, 0) << reflect.err;
  EXPECT_THAT(reflect.out, HasSubstr("\"name\": \"sampler_MainTex\""));
  EXPECT_THAT(reflect.out, HasSubstr("\"kind\": \"separate_image\""));
  EXPECT_THAT(reflect.out, HasSubstr("\"kind\": \"separate_sampler\""));
}

TEST_F(FacetcTest, AUniformAssignedThroughAMacroGetsItsStaticCopy) {
  write_all(dir_ / "m.shader",
            pass_shader("", "    float _Strength;\n"
                            "    #define CLAMP_STRENGTH if (_Strength > 10) { _Strength = 10; }\n" +
                                std::string(kVert) + "    float4 frag() : SV_Target { CLAMP_STRENGTH; return _Strength; }\n"));
  FacetcRun build = facetc({"m.shader", "-o", "m.facetpkg"});
  ASSERT_EQ(build.exit_code, 0) << build.err;
  FacetcRun dump = facetc({"--dump", "m.facetpkg"});
  ASSERT_EQ(dump.exit_code, 0) << dump.err;
  EXPECT_THAT(dump.out, HasSubstr("\"_Strength\"")) << "the assigned global stays a uniform under its own name";
}

TEST_F(FacetcTest, AFrontFaceParameterOfAnyTypeCompiles) {
  for (const char* parameter : {"uint facing : SV_IsFrontFace", "float facing : VFACE", "fixed facing : VFACE"}) {
    write_all(dir_ / "f.shader",
              pass_shader("", std::string(kVert) + "    float4 frag(float4 p : SV_POSITION, " + parameter +
                                  ") : SV_Target { return facing > 0 ? 1 : 0; }\n"));
    FacetcRun build = facetc({"f.shader", "-o", "f.facetpkg"});
    EXPECT_EQ(build.exit_code, 0) << parameter << "\n" << build.err;
  }
}

TEST_F(FacetcTest, DirectXNineLowerCaseTextureTypesAreTheirTypes) {
  write_all(dir_ / "t.shader",
            pass_shader("", "    texture2D _Outline; SamplerState sampler_Outline; texture3D _Vol; textureCUBE _Env;\n" +
                                std::string(kVert) +
                                "    float4 frag(float4 p : SV_POSITION) : SV_Target { return _Outline.Sample(sampler_Outline, p.xy); }\n"));
  FacetcRun build = facetc({"t.shader", "-o", "t.facetpkg"});
  EXPECT_EQ(build.exit_code, 0) << build.err;
}

// A '{' in a comment before the declaration (`// if (x) {`) is no block.
TEST_F(FacetcTest, AUniformAssignedAfterABraceInACommentGetsItsStaticCopy) {
  write_all(dir_ / "c.shader", pass_shader("", "    // if (unused) {\n    float _Strength;\n" + std::string(kVert) +
                                                   "    float4 frag() : SV_Target { _Strength = 0; return _Strength; }\n"));
  FacetcRun build = facetc({"c.shader", "-o", "c.facetpkg"});
  EXPECT_EQ(build.exit_code, 0) << build.err;
}

// fxc switches on a float; glslang wants an integer: in an included file
// too, and as many switches as a program has (glslang reports a few a round).
TEST_F(FacetcTest, SwitchesOnFloatsCompileInIncludedFilesAndInNumbers) {
  write_all(dir_ / "Pick.cginc", "float pick(float mode) {\n  switch (mode) { case 1: return 0.5; default: return 1; }\n}\n");
  std::string many;
  for (int i = 0; i < 8; ++i) {
    many += "    float pick" + std::to_string(i) + "(float m) { switch (m) { case 1: return " + std::to_string(i) +
            "; default: return 0; } }\n";
  }
  std::string sum = "pick(_Strength)";
  for (int i = 0; i < 8; ++i) sum += " + pick" + std::to_string(i) + "(_Strength)";
  write_all(dir_ / "w.shader", pass_shader("", "    float _Strength;\n    #include \"Pick.cginc\"\n" + many +
                                                   std::string(kVert) + "    float4 frag() : SV_Target { return " +
                                                   sum + "; }\n"));
  FacetcRun build = facetc({"w.shader", "-o", "w.facetpkg"});
  EXPECT_EQ(build.exit_code, 0) << build.err;
}

// fxc converts float case labels too: 0.0 and 1.0 stay two cases.
TEST_F(FacetcTest, FloatCaseLabelsOfASwitchOnAFloatBecomeIntegers) {
  write_all(dir_ / "l.shader",
            pass_shader("", "    float _Strength;\n" + std::string(kVert) +
                                "    float4 frag() : SV_Target {\n      switch (_Strength) {\n        case 0.0: return 0;\n"
                                "        case 1.0f: return 0.5;\n        case -2.: return 0.25;\n        default: return 1;\n"
                                "      }\n    }\n"));
  FacetcRun build = facetc({"l.shader", "-o", "l.facetpkg"});
  EXPECT_EQ(build.exit_code, 0) << build.err;
  // A switch on an int with two equal labels stays the user's error.
  write_all(dir_ / "d.shader",
            pass_shader("", "    int _Mode;\n" + std::string(kVert) +
                                "    float4 frag() : SV_Target {\n      switch (_Mode) { case 1: return 0; case 1: return 1; "
                                "default: return 2; }\n    }\n"));
  FacetcRun dup = facetc({"d.shader", "-o", "d.facetpkg"});
  EXPECT_EQ(dup.exit_code, 1);
  EXPECT_THAT(dup.err, HasSubstr("'case': duplicated value"));
}

// Debian's glslang 12 throws std::length_error from its preprocessor's
// output writer when a '##' with an empty argument inside another macro's
// argument runs to the end of an included file (a token at column 0): a
// located error and exit 1, never an abort.
TEST_F(FacetcTest, AnExceptionInsideGlslangIsAnErrorNotACrash) {
  write_all(dir_ / "paste.cginc", "#define PASS_THROUGH(tok) tok\n#define MAKE_NAME(suffix) PASS_THROUGH(_Layer##suffix)\n"
                                  "MAKE_NAME()\n");
  write_all(dir_ / "p.shader", "Shader \"P\" { SubShader { Pass {\nCGPROGRAM\n#pragma vertex vert\n#pragma fragment frag\n"
                               "#include \"paste.cginc\"\nENDCG\n} } }\n");
  for (const char* mode : {"-S", "-E"}) {
    FacetcRun run = facetc({"p.shader", mode, "-o", "out.txt"});
    EXPECT_EQ(run.exit_code, 1) << mode << "\n" << run.err;
    EXPECT_THAT(run.err, HasSubstr("glslang failed in its preprocessor (basic_string::_M_create)")) << mode;
    EXPECT_FALSE(fs::exists(dir_ / "out.txt")) << mode;
  }
}

// glslang's HLSL parser crashes (SIGSEGV in handleAssign) on an entry point
// whose parameter is a struct holding a buffer, a form no check before
// glslang refuses: the parse runs in a child process, so the program gets a
// located error, exit 1 and no output, and the other input still compiles.
TEST_F(FacetcTest, ACrashInsideGlslangIsALocatedErrorAndTheOtherInputsCompile) {
  write_all(dir_ / "c.shader", pass_shader("", "    struct O { RWStructuredBuffer<float4> b; };\n"
                                               "    float4 vert(O o) : SV_Position { return 0; }\n"
                                               "    float4 frag() : SV_Target { return 1; }\n"));
  write_all(dir_ / "fine.shader", pass_shader("", std::string(kVert) + "    float4 frag() : SV_Target { return 1; }\n"));
  FacetcRun run = facetc({"c.shader", "fine.shader", "--out-dir", "out"});
  EXPECT_EQ(run.exit_code, 1) << run.err;
  EXPECT_THAT(run.err, ::testing::ContainsRegex("c\\.shader:[0-9]+:[0-9]+: error: 'vert': glslang crashed on this program"));
  EXPECT_FALSE(fs::exists(dir_ / "out" / "c.facetpkg"));
  EXPECT_TRUE(fs::exists(dir_ / "out" / "fine.facetpkg")) << run.err;
}

// glslang lowers GetRenderTargetSampleCount() to gl_NumSamples and its
// SPIR-V generator crashes on it (SIGSEGV): facet's targets have one sample.
TEST_F(FacetcTest, GetRenderTargetSampleCountIsOne) {
  write_all(dir_ / "n.shader",
            pass_shader("", std::string(kVert) +
                                "    half4 frag() : SV_Target { half n = GetRenderTargetSampleCount(); return n; }\n"));
  FacetcRun build = facetc({"n.shader", "-o", "n.facetpkg"});
  EXPECT_EQ(build.exit_code, 0) << build.err;
  FacetcRun glsl = facetc({"n.shader", "--stage", "fragment", "-S", "--emit=glsl", "-o", "-"});
  EXPECT_EQ(glsl.exit_code, 0) << glsl.err;
  EXPECT_THAT(glsl.out, ::testing::Not(HasSubstr("gl_NumSamples")));
}

}  // namespace
}  // namespace facet::tools::testing
