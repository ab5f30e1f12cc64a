// Real-world inputs through the real facetc: Fallback-only shaders, Unity's
// version define, Unity-style includes (a byte-order mark, matrix swizzles,
// the implicit UnityShaderUtilities).
#include <nlohmann/json.hpp>

#include "facetc_test_util.h"

namespace facet::tools::testing {
namespace {

using ::testing::HasSubstr;

const char* kFallbackOnly = "Shader \"Legacy/Alias\" {\n  Fallback \"Diffuse\"\n}\n";

TEST_F(FacetcTest, AFallbackOnlyShaderCompilesToItsFallbacksPasses) {
  write_all(dir_ / "alias.shader", kFallbackOnly);
  FacetcRun run = facetc({"alias.shader", "-o", "alias.facetpkg"});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_THAT(run.err, HasSubstr("alias.shader:2:3: note: shader 'Legacy/Alias' has no SubShader; it is drawn with "
                                 "its Fallback 'Diffuse' ("));
  FacetcRun dump = facetc({"--dump", "alias.facetpkg"});
  ASSERT_EQ(dump.exit_code, 0) << dump.err;
  auto json = nlohmann::json::parse(dump.out);
  std::vector<std::string> passes;
  for (const auto& p : json["passes"]) passes.push_back(p["name"]);
  EXPECT_EQ(passes, (std::vector<std::string>{"FORWARD", "FORWARD_DELTA", "DEFERRED", "ShadowCaster"}));  // Legacy Diffuse's
  EXPECT_EQ(json["shader"]["fallback"], "Diffuse");
}

TEST_F(FacetcTest, AFallbackOnlyShaderWhoseFallbackIsNotFoundCompilesToNoPasses) {
  write_all(dir_ / "alias.shader", "Shader \"Legacy/Alias\" {\n  Fallback \"Company/Missing\"\n}\n");
  FacetcRun run = facetc({"alias.shader", "-o", "alias.facetpkg"});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_THAT(run.err, HasSubstr("alias.shader:2:3: warning: Fallback 'Company/Missing' is not used: no shader named "
                                 "'Company/Missing' in the shader search path; the shader has nothing to draw"));
  EXPECT_THAT(run.err, HasSubstr("note: shader 'Legacy/Alias' has no SubShader; Unity draws it with its Fallback"));
  FacetcRun dump = facetc({"--dump", "alias.facetpkg"});
  ASSERT_EQ(dump.exit_code, 0) << dump.err;
  EXPECT_TRUE(nlohmann::json::parse(dump.out)["passes"].empty());
}

TEST_F(FacetcTest, AShaderWithNeitherSubShaderNorFallbackFails) {
  write_all(dir_ / "empty.shader", "Shader \"Empty\" {\n}\n");
  FacetcRun run = facetc({"empty.shader", "-o", "empty.facetpkg"});
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_THAT(run.err, HasSubstr("empty.shader:1:1: error: shader 'Empty' has no SubShader"));
  EXPECT_EQ(files(), std::vector<std::string>{"empty.shader"});
}

// UNITY_VERSION as Unity writes it; the default is 2019.4.
const char* kVersionProbe = R"(Shader "T" { SubShader { Pass {
CGPROGRAM
#pragma vertex vert
#pragma fragment frag
#if UNITY_VERSION != EXPECTED
#error wrong UNITY_VERSION
#endif
#if !defined(UNITY_COMPILER_HLSL) || !defined(SHADER_API_DESKTOP)
#error the Unity compiler defines are missing
#endif
float4 vert(float4 v : POSITION) : SV_Position { return UnityObjectToClipPos(v); }
float4 frag() : SV_Target { return 1; }
ENDCG
} } }
)";

TEST_F(FacetcTest, UnityVersionDefinesUnityVersionAndUnityObjectToClipPosNeedsNoInclude) {
  write_all(dir_ / "v.shader", kVersionProbe);
  EXPECT_EQ(facetc({"v.shader", "-DEXPECTED=201940", "-o", "a.facetpkg"}).exit_code, 0);
  EXPECT_EQ(facetc({"v.shader", "--unity-version", "2017.4", "-DEXPECTED=201740", "-o", "b.facetpkg"}).exit_code, 0);
  EXPECT_EQ(facetc({"v.shader", "--unity-version", "2018.4.36", "-DEXPECTED=201849", "-o", "c.facetpkg"}).exit_code, 0);
  FacetcRun wrong = facetc({"v.shader", "--unity-version", "2017.4", "-DEXPECTED=201940", "-o", "d.facetpkg"});
  EXPECT_EQ(wrong.exit_code, 1);
  EXPECT_THAT(wrong.err, HasSubstr("wrong UNITY_VERSION"));
}

TEST_F(FacetcTest, ABadUnityVersionIsAUsageError) {
  write_all(dir_ / "v.shader", kVersionProbe);
  for (const char* bad : {"2017", "latest", "2017.4b", "2017.12"}) {
    FacetcRun run = facetc({"v.shader", "--unity-version", bad, "-o", "x.facetpkg"});
    EXPECT_EQ(run.exit_code, 2) << bad;
    EXPECT_THAT(run.err, HasSubstr("--unity-version needs a version such as 2017.4")) << bad;
    EXPECT_FALSE(fs::exists(dir_ / "x.facetpkg"));
  }
}

TEST_F(FacetcTest, AnIncludeWithAByteOrderMarkAndMatrixSwizzlesCompiles) {
  // ROW builds a swizzle that only exists after preprocessing.
  write_all(dir_ / "lib.cginc", "\xEF\xBB\xBF// saved by a Windows editor\n"
                                "float3 ObjectOrigin() { return unity_ObjectToWorld._14_24_34; }\n"
                                "float ObjectScaleX() { return unity_ObjectToWorld._m00; }\n"
                                "#define ROW(m, r) m.r\n"
                                "float3 ObjectRow2() { return ROW(unity_ObjectToWorld, _21_22_23); }\n");
  write_all(dir_ / "s.shader", R"(Shader "T" { SubShader { Pass {
CGPROGRAM
#pragma vertex vert
#pragma fragment frag
#include "lib.cginc"
float4 vert(float4 v : POSITION) : SV_Position { return UnityObjectToClipPos(v.xyz + ObjectOrigin() * ObjectScaleX() + ObjectRow2()); }
float4 frag() : SV_Target { return 1; }
ENDCG
} } }
)");
  FacetcRun run = facetc({"s.shader", "-o", "s.facetpkg"});
  EXPECT_EQ(run.exit_code, 0) << run.err;
}

}  // namespace
}  // namespace facet::tools::testing

namespace facet::tools::testing {
namespace {

std::string truncation_shader(const std::string& functions, const std::string& call) {
  return "Shader \"T\" { SubShader { Pass {\nCGPROGRAM\n#pragma vertex vert\n#pragma fragment frag\nfloat4 _C;\n" +
         functions + "\nfloat4 vert(float4 v : POSITION) : SV_Position { return v; }\n" +
         "float4 frag() : SV_Target {\n  float x = " + call + ";\n  return x;\n}\nENDCG\n} } }\n";
}

// fxc truncates a float4 argument to a float parameter (warning X3206);
// facet does the same, with a warning at the call.
TEST_F(FacetcTest, AWiderVectorArgumentIsTruncatedWithALocatedWarning) {
  write_all(dir_ / "t.shader", truncation_shader("float spec(float n, float f0) { return n * f0; }", "spec(0.5, _C)"));
  FacetcRun run = facetc({"t.shader", "-o", "t.facetpkg"});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_THAT(run.err, HasSubstr("t.shader:9:13: warning: implicit truncation of vector type in a call to 'spec'"));
  EXPECT_THAT(run.err, HasSubstr("[-Wimplicit-truncation]"));
  FacetcRun werror = facetc({"t.shader", "-Werror", "-o", "w.facetpkg"});
  EXPECT_EQ(werror.exit_code, 1);
  EXPECT_FALSE(fs::exists(dir_ / "w.facetpkg"));
}

TEST_F(FacetcTest, TruncationIsNotGuessedBetweenOverloadsOfOneArity) {
  write_all(dir_ / "t.shader", truncation_shader("float spec(float n, float f0) { return n * f0; }\n"
                                                 "float spec(float2 n, float f0) { return n.x * f0; }",
                                                 "spec(0.5, _C)"));
  FacetcRun run = facetc({"t.shader", "-o", "t.facetpkg"});
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_THAT(run.err, HasSubstr("t.shader:10:13: error: 'spec': no matching overloaded function found"));
}

TEST_F(FacetcTest, AnOutArgumentIsNeverCast) {
  write_all(dir_ / "t.shader", truncation_shader("float get(out float r) { r = 1; return r; }", "get(_C)"));
  FacetcRun run = facetc({"t.shader", "-o", "t.facetpkg"});
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_THAT(run.err, HasSubstr("error:"));
  EXPECT_FALSE(fs::exists(dir_ / "t.facetpkg"));
}

}  // namespace
}  // namespace facet::tools::testing

namespace facet::tools::testing {
namespace {

// The book's ch13 include: two calls in an included file, glslang reporting
// only the first; both get their casts and a warning each.
TEST_F(FacetcTest, TruncatingCallsInAnIncludedFileAreCastOneAfterTheOther) {
  write_all(dir_ / "brdf.cginc", "\xEF\xBB\xBF" "float spec(float n, float f0) { return n * f0; }\n"
                                 "float first(float4 c) {\n  return spec(0.5, c);\n}\n"
                                 "float second(float4 c) {\n  float x = 0.25;\n  return spec(x, c);\n}\n");
  write_all(dir_ / "s.shader", R"(Shader "T" { SubShader { Pass {
CGPROGRAM
#pragma vertex vert
#pragma fragment frag
#include "brdf.cginc"
float4 _C;
float4 vert(float4 v : POSITION) : SV_Position { return v; }
float4 frag() : SV_Target { return first(_C) + second(_C); }
ENDCG
} } }
)");
  FacetcRun run = facetc({"s.shader", "-o", "s.facetpkg"});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_THAT(run.err, HasSubstr("brdf.cginc:3:10: warning: implicit truncation of vector type in a call to 'spec'"));
  EXPECT_THAT(run.err, HasSubstr("brdf.cginc:7:10: warning: implicit truncation of vector type in a call to 'spec'"));
}

// The other way round: the call in the shader, the definition (with an
// inout parameter and a default argument) in an included file.
TEST_F(FacetcTest, ACallInTheShaderToAFunctionOfAnIncludedFileIsCast) {
  write_all(dir_ / "sdf.cginc", "float cells(inout float2 p, float count, bool mirror = false) {\n"
                               "  p *= count;\n  return mirror ? -count : count;\n}\n");
  write_all(dir_ / "s.shader", R"(Shader "T" { SubShader { Pass {
CGPROGRAM
#pragma vertex vert
#pragma fragment frag
#include "sdf.cginc"
float4 vert(float4 v : POSITION) : SV_Position { return v; }
float4 frag() : SV_Target {
  float2 p = 1, period = 6;
  return cells(p, period, true);
}
ENDCG
} } }
)");
  FacetcRun run = facetc({"s.shader", "-o", "s.facetpkg"});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_THAT(run.err, HasSubstr("s.shader:9:10: warning: implicit truncation of vector type in a call to 'cells'"));
}

}  // namespace
}  // namespace facet::tools::testing

namespace facet::tools::testing {
namespace {

// What shaders written for Unity 5.3 and earlier do, and Unity still builds:
// the matrix names Unity 5.4 renamed, a file saved with two byte-order marks,
// globals declared in a list and assigned (fxc writes a per-invocation copy),
// and a keyword shortcut Unity does not have (ignored, with a warning).
const char* kUnityFiveShader = "\xEF\xBB\xBF\xEF\xBB\xBF" R"(Shader "Old/Upgraded" { SubShader { Pass {
Tags { "LightMode" = "ForwardBase" }
CGPROGRAM
#pragma vertex vert
#pragma fragment frag
#pragma multi_compile_fwdbase_fullshadows
float A, T, N;
float3 col = float3(0, 0, 0);
struct v2f { float4 pos : SV_POSITION; float3 world : TEXCOORD0; float3 normal : TEXCOORD1; };
v2f vert(float4 v : POSITION, float3 n : NORMAL) {
  v2f o;
  o.pos = UnityObjectToClipPos(v);
  o.world = mul(_Object2World, v).xyz;
  o.normal = normalize(mul(float4(n, 0), _World2Object).xyz);
  return o;
}
float4 frag(v2f i) : SV_Target {
  for (int k = 0; k < 4; ++k) { T += N; col += i.world * T; }
  return float4(col * A + i.normal, 1);
}
ENDCG
} } }
)";

TEST_F(FacetcTest, AUnityFiveShaderBuildsAsUnityUpgradesIt) {
  write_all(dir_ / "old.shader", kUnityFiveShader);
  FacetcRun run = facetc({"old.shader", "-o", "old.facetpkg"});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_THAT(run.err, HasSubstr("old.shader:6:1: warning: unknown keyword shortcut 'multi_compile_fwdbase_fullshadows' "
                                 "adds no keywords"));
  EXPECT_THAT(run.err, HasSubstr("[-Wunknown-pragma]"));
  FacetcRun dump = facetc({"--dump", "old.facetpkg"});
  ASSERT_EQ(dump.exit_code, 0) << dump.err;
  EXPECT_THAT(dump.out, HasSubstr("\"T\"")) << "the assigned global stays a uniform under its own name";
  FacetcRun werror = facetc({"old.shader", "-Werror", "-o", "w.facetpkg"});
  EXPECT_EQ(werror.exit_code, 1);
  EXPECT_FALSE(fs::exists(dir_ / "w.facetpkg"));
}

}  // namespace
}  // namespace facet::tools::testing

namespace facet::tools::testing {
namespace {

// fxc compiles only what the entry point reaches; shaders rely on it (a
// geometry helper calling an overload that only exists with the geometry
// stage on, a recursive helper no stage calls).
const char* kUnreachableHelpers = R"(Shader "T" { SubShader { Pass {
CGPROGRAM
#pragma vertex vert
#pragma fragment frag
struct VertexIn { float4 vertex : POSITION; };
float4 Proxy(VertexIn v) { return UnityObjectToClipPos(v.vertex); }
float4 FromGeometry(float3 p) { return Proxy(p, 2); }
float Depth(float x) { return x < 1 ? x : Depth(x * 0.5); }
float Remap(float x) { return x * 0.5 + 0.5; }
static float Time = Remap(_Time.y);
float4 vert(VertexIn v) : SV_Position { return Proxy(v); }
float4 frag() : SV_Target { return USED; }
ENDCG
} } }
)";

TEST_F(FacetcTest, AnIncludeWrittenWithBackslashesIsFound) {
  fs::create_directories(dir_ / "CGIncludes");
  fs::create_directories(dir_ / "Shaders");
  write_all(dir_ / "CGIncludes" / "Core.cginc", "float4 Tint() { return 1; }\n");
  write_all(dir_ / "Shaders" / "s.shader", R"(Shader "T" { SubShader { Pass {
CGPROGRAM
#pragma vertex vert
#pragma fragment frag
#include "..\CGIncludes\Core.cginc"
float4 vert(float4 v : POSITION) : SV_Position { return v; }
float4 frag() : SV_Target { return Tint(); }
ENDCG
} } }
)");
  FacetcRun run = facetc({"Shaders/s.shader", "-o", "s.facetpkg"});
  EXPECT_EQ(run.exit_code, 0) << run.err;
}

// Unity's declaring macros end in their own ';', and generated shaders
// (Amplify Shader Editor's) call them without one.
TEST_F(FacetcTest, UnitysDeclaringMacrosNeedNoSemicolonAfterThem) {
  write_all(dir_ / "s.shader", R"(Shader "T" { SubShader { Pass {
Tags { "LightMode" = "ForwardAdd" }
CGPROGRAM
#pragma vertex vert
#pragma fragment frag
#pragma multi_compile_fwdadd
#include "UnityCG.cginc"
#include "AutoLight.cginc"
UNITY_DECLARE_SCREENSPACE_TEXTURE(_GrabTexture)
struct v2f { float4 pos : SV_POSITION; float3 worldPos : TEXCOORD0; SHADOW_COORDS(1) };
v2f vert(appdata_base v) {
  v2f o;
  o.pos = UnityObjectToClipPos(v.vertex);
  o.worldPos = mul(unity_ObjectToWorld, v.vertex).xyz;
  TRANSFER_SHADOW(o)
  return o;
}
float4 frag(v2f i) : SV_Target {
  UNITY_LIGHT_ATTENUATION(atten, i, i.worldPos)
  return atten * UNITY_SAMPLE_SCREENSPACE_TEXTURE(_GrabTexture, i.pos.xy);
}
ENDCG
} } }
)");
  FacetcRun run = facetc({"--check", "--all-variants", "s.shader"});
  EXPECT_EQ(run.exit_code, 0) << run.out << run.err;
}

TEST_F(FacetcTest, ASwitchOnAFloatIsASwitchOnItsIntegerPart) {
  write_all(dir_ / "s.shader", R"(Shader "T" { SubShader { Pass {
CGPROGRAM
#pragma vertex vert
#pragma fragment frag
float _Shape;
float4 vert(float4 v : POSITION) : SV_Position { return v; }
float4 frag() : SV_Target {
  switch (_Shape * 2) { case 0: return 1; case 1: return 0.5; default: return 0; }
}
ENDCG
} } }
)");
  FacetcRun run = facetc({"s.shader", "-o", "s.facetpkg"});
  EXPECT_EQ(run.exit_code, 0) << run.err;
  FacetcRun e = facetc({"s.shader", "-E"});
  EXPECT_THAT(e.out, HasSubstr("switch(_Shape * 2)")) << "-E shows the program as written, uncast";
}

// A stage input or output with no members (a shader that only discards):
// glslang leaves it out of the entry point's interface and without a
// Location; the module facet writes is valid for Vulkan all the same.
TEST_F(FacetcTest, EmptyStageStructsGiveValidSpirv) {
  write_all(dir_ / "s.shader", R"(Shader "T" { SubShader { Pass {
CGPROGRAM
#pragma vertex vert
#pragma fragment frag
struct appdata { };
struct v2f { };
v2f vert(appdata v) { v2f o; return o; }
fixed4 frag(v2f i) : SV_Target { clip(-1); return 0; }
ENDCG
} } }
)");
  FacetcRun run = facetc({"s.shader", "-o", "s.facetpkg"});
  EXPECT_EQ(run.exit_code, 0) << run.err;
}

TEST_F(FacetcTest, FunctionsNoEntryPointReachesAreNotCompiled) {
  write_all(dir_ / "s.shader", kUnreachableHelpers);
  FacetcRun run = facetc({"s.shader", "-DUSED=1", "-o", "s.facetpkg"});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  // The same helper reached from the fragment stage is an error at its line.
  FacetcRun reached = facetc({"s.shader", "-DUSED=FromGeometry(1).x", "-o", "r.facetpkg"});
  EXPECT_EQ(reached.exit_code, 1);
  EXPECT_THAT(reached.err, HasSubstr("s.shader:7:"));
  EXPECT_THAT(reached.err, ::testing::Not(HasSubstr("Recursion"))) << "the static initialiser calls Remap";
  EXPECT_FALSE(fs::exists(dir_ / "r.facetpkg"));
  FacetcRun recursive = facetc({"s.shader", "-DUSED=Depth(4)", "-o", "d.facetpkg"});
  EXPECT_EQ(recursive.exit_code, 1);
  EXPECT_THAT(recursive.err, HasSubstr("Recursion"));
}

}  // namespace
}  // namespace facet::tools::testing
