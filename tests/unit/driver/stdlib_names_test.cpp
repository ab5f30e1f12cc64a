// Every include file and built-in name of docs/stdlib.md §8 is provided by stdlib/:
// one shader uses all of them (each in a way that fails to compile when the
// name is missing); when it fails, each name is compiled alone so that the
// failure names the missing ones.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>

#include "stdlib_compile.h"

namespace facet {
namespace {

using stdlib_test::compile_text;

// One name and the code that uses it; `with` names entries it needs.
struct Use {
  std::string name;
  std::string global;   // at file scope
  std::string member;   // in the v2f struct
  std::string vert;     // in vert(), with `vin v` and `v2f o`
  std::string frag;     // in frag(), with `v2f i`; adds to `float4 acc`
  std::vector<std::string> with;
};

Use uniform(const std::string& name) { return {name, "", "", "", "acc.xyz += " + name + ".xyz;"}; }
Use matrix(const std::string& name) { return {name, "", "", "", "acc += mul(" + name + ", float4(i.wp, 1));"}; }
Use frag(const std::string& name, const std::string& code) { return {name, "", "", "", "{ " + code + " }"}; }

// docs/stdlib.md §8, in its order.
std::vector<Use> builtin_uses() {
  std::vector<Use> u;
  for (const char* m : {"unity_ObjectToWorld", "unity_WorldToObject", "UNITY_MATRIX_M", "UNITY_MATRIX_V",
                        "UNITY_MATRIX_P", "UNITY_MATRIX_VP", "UNITY_MATRIX_MV", "UNITY_MATRIX_MVP", "UNITY_MATRIX_IT_MV",
                        "unity_WorldToCamera", "unity_CameraToWorld"})
    u.push_back(matrix(m));
  for (const char* n : {"_WorldSpaceCameraPos", "_WorldSpaceLightPos0", "_LightColor0", "_SpecColor", "_Time",
                        "_SinTime", "_CosTime", "_ProjectionParams", "_ScreenParams", "_ZBufferParams",
                        "unity_FogColor", "unity_FogParams", "unity_SHAr", "unity_SHAg", "unity_SHAb", "unity_SHBr",
                        "unity_SHBg", "unity_SHBb", "unity_SHC", "unity_SpecCube0_HDR",
                        "unity_ColorSpaceDielectricSpec"})
    u.push_back(uniform(n));
  u.push_back(frag("unity_SpecCube0", "acc += unity_SpecCube0.Sample(samplerunity_SpecCube0, i.n);"));
  // By convention the program declares the camera depth itself (docs/binding-model.md).
  u.push_back({"_CameraDepthTexture", "sampler2D _CameraDepthTexture;", "", "",
               "acc += tex2D(_CameraDepthTexture, i.uv);"});
  u.push_back(frag("_LightTexture0", "acc += tex2D(_LightTexture0, i.uv);"));
  u.push_back(frag("_ShadowMapTexture", "acc += tex2D(_ShadowMapTexture, i.uv);"));

  // Functions and macros.
  u.push_back({"UnityObjectToClipPos", "", "", "o.pos = UnityObjectToClipPos(v.vertex); o.pos += UnityObjectToClipPos(v.vertex.xyz);", ""});
  u.push_back({"UnityObjectToWorldNormal", "", "", "o.n = UnityObjectToWorldNormal(v.normal);", ""});
  u.push_back({"UnityObjectToWorldDir", "", "", "o.n += UnityObjectToWorldDir(v.tangent.xyz);", ""});
  u.push_back(frag("UnityWorldSpaceViewDir", "acc.xyz += UnityWorldSpaceViewDir(i.wp);"));
  u.push_back(frag("UnityWorldSpaceLightDir", "acc.xyz += UnityWorldSpaceLightDir(i.wp);"));
  u.push_back({"UnityWorldToClipPos", "", "", "o.pos += UnityWorldToClipPos(o.wp);", ""});
  u.push_back({"UnityViewToClipPos", "", "", "o.pos += UnityViewToClipPos(o.wp);", ""});
  u.push_back({"UnityObjectToViewPos", "", "", "o.wp += UnityObjectToViewPos(v.vertex); o.wp += UnityObjectToViewPos(v.vertex.xyz);", ""});
  u.push_back({"TRANSFORM_TEX", "sampler2D _MainTex; float4 _MainTex_ST;", "", "o.uv = TRANSFORM_TEX(v.texcoord, _MainTex);", ""});
  u.push_back({"UNITY_FOG_COORDS", "", "UNITY_FOG_COORDS(5)", "", ""});
  u.push_back({"UNITY_TRANSFER_FOG", "", "", "UNITY_TRANSFER_FOG(o, o.pos);", "", {"UNITY_FOG_COORDS"}});
  u.push_back({"UNITY_APPLY_FOG", "", "", "", "UNITY_APPLY_FOG(i.fogCoord, acc);", {"UNITY_FOG_COORDS", "UNITY_TRANSFER_FOG"}});
  u.push_back({"UNITY_FOG_COORDS_PACKED", "struct packed_fog { UNITY_FOG_COORDS_PACKED(0, float4) };", "", "",
               "{ packed_fog p = (packed_fog)0; acc += p.fogCoord; }"});
  u.push_back({"UNITY_SAMPLE_DEPTH", "sampler2D _DepthForSample;", "", "",
               "acc.x += UNITY_SAMPLE_DEPTH(tex2D(_DepthForSample, i.uv));"});
  u.push_back(frag("Linear01Depth", "acc.x += Linear01Depth(i.uv.x);"));
  u.push_back(frag("LinearEyeDepth", "acc.x += LinearEyeDepth(i.uv.x);"));
  u.push_back(frag("UnpackNormal", "acc.xyz += UnpackNormal(float4(i.uv, 0.5, 1));"));
  u.push_back(frag("DecodeHDR", "acc.xyz += DecodeHDR(UNITY_SAMPLE_TEXCUBE(unity_SpecCube0, i.n), unity_SpecCube0_HDR);"));
  u.push_back(frag("ShadeSH9", "acc.xyz += ShadeSH9(float4(i.n, 1));"));
  u.push_back(frag("UNITY_SAMPLE_TEXCUBE", "acc += UNITY_SAMPLE_TEXCUBE(unity_SpecCube0, i.n);"));
  u.push_back(frag("UNITY_SAMPLE_TEXCUBE_LOD", "acc += UNITY_SAMPLE_TEXCUBE_LOD(unity_SpecCube0, i.n, 2.0);"));
  u.push_back({"LIGHTING_COORDS", "", "LIGHTING_COORDS(3, 4)", "TRANSFER_VERTEX_TO_FRAGMENT(o);", ""});
  u.push_back({"SHADOW_COORDS", "struct shadow_v2f { float4 pos : SV_POSITION; SHADOW_COORDS(1) };", "", "",
               "{ shadow_v2f s = (shadow_v2f)0; acc += s.pos; }"});
  u.push_back({"TRANSFER_SHADOW", "", "", "TRANSFER_SHADOW(o);", "", {"LIGHTING_COORDS"}});
  u.push_back({"SHADOW_ATTENUATION", "", "", "", "acc += SHADOW_ATTENUATION(i);", {"LIGHTING_COORDS"}});
  u.push_back({"LIGHT_ATTENUATION", "", "", "", "acc += LIGHT_ATTENUATION(i);", {"LIGHTING_COORDS"}});
  u.push_back(frag("UNITY_LIGHT_ATTENUATION", "UNITY_LIGHT_ATTENUATION(atten, i, i.wp); acc += atten;"));
  u.push_back(frag("UnityGlobalIllumination",
                   "UnityGIInput d = (UnityGIInput)0; d.worldPos = i.wp; d.atten = 1;"
                   " UnityGI gi = UnityGlobalIllumination(d, 1.0, i.n);"
                   " Unity_GlossyEnvironmentData g = UnityGlossyEnvironmentSetup(0.5, float3(0, 0, 1), i.n, 0.04);"
                   " UnityGI gi2 = UnityGlobalIllumination(d, 1.0, i.n, g);"
                   " acc.xyz += gi.indirect.diffuse + gi2.indirect.specular + gi.light.color;"));
  u.push_back(frag("Unity_SafeNormalize", "acc.xyz += Unity_SafeNormalize(i.wp);"));
  u.push_back(frag("FresnelTerm", "acc.xyz += FresnelTerm(float3(0.04, 0.04, 0.04), i.uv.x);"));
  u.push_back(frag("FresnelLerp", "acc.xyz += FresnelLerp(float3(0.04, 0.04, 0.04), float3(1, 1, 1), i.uv.x);"));
  u.push_back(frag("Pow5", "acc.x += Pow5(i.uv.x); acc.xyz += Pow5(i.wp);"));
  u.push_back(frag("DisneyDiffuse", "acc.x += DisneyDiffuse(i.uv.x, i.uv.y, 0.5, 0.3);"));
  u.push_back(frag("GGXTerm", "acc.x += GGXTerm(i.uv.x, 0.25);"));
  u.push_back(frag("SmithJointGGXVisibilityTerm", "acc.x += SmithJointGGXVisibilityTerm(i.uv.x, i.uv.y, 0.25);"));
  u.push_back(frag("EnergyConservationBetweenDiffuseAndSpecular",
                   "half omr; acc.xyz += EnergyConservationBetweenDiffuseAndSpecular(i.wp, float3(0.2, 0.2, 0.2), omr); acc.x += omr;"));
  u.push_back(frag("PreMultiplyAlpha", "half a; acc.xyz += PreMultiplyAlpha(i.wp, 0.5, 0.9, a); acc.w += a;"));
  for (const char* brdf : {"BRDF1_Unity_PBS", "BRDF2_Unity_PBS", "BRDF3_Unity_PBS", "UNITY_BRDF_PBS"}) {
    u.push_back(frag(brdf, std::string("UnityLight l = (UnityLight)0; l.dir = float3(0, 1, 0); l.color = 1;"
                                       " UnityIndirect ind = (UnityIndirect)0;"
                                       " acc += ") + brdf + "(float3(0.5, 0.5, 0.5), float3(0.04, 0.04, 0.04), 0.96, 0.5, i.n, float3(0, 0, 1), l, ind);"));
  }
  u.push_back(frag("LinearToGammaSpace", "acc.xyz += LinearToGammaSpace(i.wp);"));
  u.push_back(frag("GammaToLinearSpace", "acc.xyz += GammaToLinearSpace(i.wp);"));
  u.push_back(frag("Luminance", "acc.x += Luminance(i.wp);"));
  u.push_back({"ComputeScreenPos", "", "", "o.wp += ComputeScreenPos(o.pos).xyz;", ""});
  u.push_back({"UNITY_INITIALIZE_OUTPUT", "", "", "UNITY_INITIALIZE_OUTPUT(v2f, o);", ""});
  // Instancing and stereo, off: they must expand to valid code.
  u.push_back({"UNITY_VERTEX_INPUT_INSTANCE_ID", "struct inst_in { float4 p : POSITION; UNITY_VERTEX_INPUT_INSTANCE_ID };",
               "", "", "{ inst_in s = (inst_in)0; acc += s.p; }"});
  u.push_back({"UNITY_SETUP_INSTANCE_ID", "", "", "UNITY_SETUP_INSTANCE_ID(v);", "UNITY_SETUP_INSTANCE_ID(i);"});
  u.push_back({"UNITY_TRANSFER_INSTANCE_ID", "", "", "UNITY_TRANSFER_INSTANCE_ID(v, o);", ""});
  u.push_back({"UNITY_VERTEX_OUTPUT_STEREO", "", "UNITY_VERTEX_OUTPUT_STEREO", "", ""});
  u.push_back({"UNITY_INITIALIZE_VERTEX_OUTPUT_STEREO", "", "", "UNITY_INITIALIZE_VERTEX_OUTPUT_STEREO(o);", ""});
  u.push_back({"UNITY_SETUP_STEREO_EYE_INDEX_POST_VERTEX", "", "", "", "UNITY_SETUP_STEREO_EYE_INDEX_POST_VERTEX(i);"});
  u.push_back({"UNITY_INSTANCING_BUFFER_START", "UNITY_INSTANCING_BUFFER_START(Props) UNITY_DEFINE_INSTANCED_PROP(float4, _InstColor) UNITY_INSTANCING_BUFFER_END(Props)",
               "", "", "acc += UNITY_ACCESS_INSTANCED_PROP(Props, _InstColor);"});
  u.push_back({"UNITY_INSTANCING_CBUFFER_START", "UNITY_INSTANCING_CBUFFER_START(Old) UNITY_DEFINE_INSTANCED_PROP(float4, _OldColor) UNITY_INSTANCING_CBUFFER_END",
               "", "", "acc += UNITY_ACCESS_INSTANCED_PROP(Old, _OldColor);"});

  // Structs.
  for (const char* s : {"appdata_base", "appdata_tan", "appdata_full", "SurfaceOutput", "SurfaceOutputStandard",
                        "SurfaceOutputStandardSpecular", "UnityLight", "UnityIndirect", "UnityGI", "UnityGIInput"})
    u.push_back(frag(s, std::string(s) + " s = (" + s + ")0; acc.x += 0.0;"));
  // The lighting models of the surface-shader path, every form.
  const std::string gi = "UnityGI gi = (UnityGI)0; gi.light.dir = float3(0, 1, 0); gi.light.color = 1;"
                         " UnityGIInput d = (UnityGIInput)0; d.worldPos = i.wp; d.atten = 1; d.worldViewDir = float3(0, 0, 1);";
  u.push_back(frag("LightingLambert", "SurfaceOutput s = (SurfaceOutput)0; s.Normal = i.n; " + gi +
                                          " acc += LightingLambert(s, gi); LightingLambert_GI(s, d, gi);"
                                          " half4 g0, g1, g2; acc += LightingLambert_Deferred(s, gi, g0, g1, g2);"
                                          " acc += LightingLambert_PrePass(s, half4(1, 1, 1, 1));"));
  u.push_back(frag("LightingBlinnPhong", "SurfaceOutput s = (SurfaceOutput)0; s.Normal = i.n; " + gi +
                                             " acc += LightingBlinnPhong(s, float3(0, 0, 1), gi); LightingBlinnPhong_GI(s, d, gi);"
                                             " half4 g0, g1, g2; acc += LightingBlinnPhong_Deferred(s, float3(0, 0, 1), gi, g0, g1, g2);"
                                             " acc += LightingBlinnPhong_PrePass(s, half4(1, 1, 1, 1));"));
  u.push_back(frag("LightingStandard", "SurfaceOutputStandard s = (SurfaceOutputStandard)0; s.Normal = i.n; " + gi +
                                           " LightingStandard_GI(s, d, gi); acc += LightingStandard(s, float3(0, 0, 1), gi);"
                                           " half4 g0, g1, g2; acc += LightingStandard_Deferred(s, float3(0, 0, 1), gi, g0, g1, g2);"));
  u.push_back(frag("LightingStandardSpecular",
                   "SurfaceOutputStandardSpecular s = (SurfaceOutputStandardSpecular)0; s.Normal = i.n; " + gi +
                       " LightingStandardSpecular_GI(s, d, gi); acc += LightingStandardSpecular(s, float3(0, 0, 1), gi);"
                       " half4 g0, g1, g2; acc += LightingStandardSpecular_Deferred(s, float3(0, 0, 1), gi, g0, g1, g2);"));
  // Defines the library provides (the others it honours are tested below).
  for (const char* d : {"SHADER_TARGET", "UNITY_BRDF_GGX", "SHADER_API_VULKAN", "UNITY_PI"})
    u.push_back({d, std::string("#ifndef ") + d + "\n#error " + d + " is not defined\n#endif\n", "", "", ""});
  return u;
}

const char* const kIncludes[] = {
    "UnityCG.cginc", "UnityShaderVariables.cginc", "HLSLSupport.cginc", "UnityLightingCommon.cginc",
    "Lighting.cginc", "AutoLight.cginc", "UnityPBSLighting.cginc", "UnityStandardBRDF.cginc",
    "UnityStandardUtils.cginc", "UnityGlobalIllumination.cginc", "UnityImageBasedLighting.cginc",
    "UnityStandardCore.cginc", "UnityStandardCoreForward.cginc", "UnityStandardCoreForwardSimple.cginc",
    "UnityStandardInput.cginc", "UnityStandardConfig.cginc", "UnityStandardShadow.cginc", "UnityStandardMeta.cginc",
};

std::string names_shader(const std::vector<const Use*>& uses) {
  std::string global, member, vert, frag;
  for (const Use* u : uses) {
    global += u->global + "\n";
    member += u->member + "\n";
    vert += u->vert + "\n";
    frag += u->frag + "\n";
  }
  std::string includes;
  for (const char* inc : {"UnityCG.cginc", "Lighting.cginc", "AutoLight.cginc", "UnityPBSLighting.cginc"})
    includes += std::string("#include \"") + inc + "\"\n";
  return R"(Shader "Test/StdlibNames" { SubShader { Pass { Tags { "LightMode"="ForwardBase" }
CGPROGRAM
#pragma vertex vert
#pragma fragment frag
#pragma target 3.0
#pragma multi_compile FOG_LINEAR FOG_EXP2
#pragma multi_compile POINT SPOT
#pragma multi_compile _ UNITY_COLORSPACE_GAMMA
#define UNITY_PASS_FORWARDBASE
)" + includes + global +
         R"(
struct vin { float4 vertex : POSITION; float3 normal : NORMAL; float4 tangent : TANGENT; float2 texcoord : TEXCOORD0; };
struct v2f { float4 pos : SV_POSITION; float2 uv : TEXCOORD0; float3 wp : TEXCOORD1; float3 n : TEXCOORD2;
)" + member + R"(};
v2f vert(vin v) {
  v2f o = (v2f)0;
  o.pos = v.vertex; o.wp = v.vertex.xyz; o.n = v.normal; o.uv = v.texcoord;
)" + vert + R"(  return o;
}
float4 frag(v2f i) : SV_Target {
  float4 acc = 0;
)" + frag + R"(  return acc;
}
ENDCG
} } })";
}

TEST(StdlibNamesTest, EveryBuiltinNameOfSpecSection5IsProvided) {
  std::vector<Use> uses = builtin_uses();
  std::vector<const Use*> all;
  std::map<std::string, const Use*> by_name;
  for (const Use& u : uses) {
    all.push_back(&u);
    by_name[u.name] = &u;
  }
  EXPECT_EQ(uses.size(), 108u) << "the docs/stdlib.md §8 list changed size";
  EXPECT_EQ(by_name.size(), uses.size()) << "names are listed once";
  auto compiled = compile_text("names.shader", names_shader(all));
  if (compiled.ok) {
    ASSERT_EQ(compiled.shader->package.passes.size(), 1u);
    EXPECT_EQ(compiled.shader->package.passes[0].variants.size(), 8u);
    stdlib_test::expect_valid_spirv(compiled.shader->package);
    return;
  }
  // Name the missing ones: each use alone (with what it needs).
  for (const Use& u : uses) {
    std::vector<const Use*> one;
    for (const std::string& w : u.with) one.push_back(by_name.at(w));
    one.push_back(&u);
    auto alone = compile_text("name.shader", names_shader(one), {.keywords = std::vector<std::string>{"FOG_LINEAR", "POINT"}});
    EXPECT_TRUE(alone.ok) << "missing or broken: " << u.name << "\n" << alone.log;
  }
  FAIL() << compiled.log;
}

TEST(StdlibNamesTest, EveryIncludeFileCompilesOnItsOwn) {
  for (const char* inc : kIncludes) {
    std::string text = std::string(R"(Shader "Test/Include" { SubShader { Pass {
CGPROGRAM
#pragma vertex vert
#pragma fragment frag
#pragma target 3.0
#include ")") + inc + R"("
float4 vert(float4 p : POSITION) : SV_POSITION { return p; }
float4 frag() : SV_Target { return 1; }
ENDCG
} } })";
    auto compiled = compile_text(inc, text);
    EXPECT_TRUE(compiled.ok) << inc << "\n" << compiled.log;
  }
}

// ---- identifier hygiene -----------------------------------------------------
// A user keyword or `#define` may use any all-uppercase name (C, N, IN, OUT,
// F0, ...), so no stdlib identifier may be one: `float C` in a stdlib
// function breaks every program that defines C. The names are collected from
// the stdlib's HLSL text (.cginc/.hlsl; the .glslinc files are GLSL): every
// all-uppercase token in code or in a #define body, except
//   - macros the stdlib #defines (Unity's API: UNITY_*, SHADOWS_*, ...),
//   - names the stdlib tests with #if/#ifdef/defined(): keywords and
//     switches a program is meant to define (_NORMALMAP, POINT, ...),
//   - macro parameters, operands of ##, and HLSL semantics (after ':', or
//     POSITION/TEXCOORD/VPOS-like names),
//   - the back end's prelude macros and a few Unity API spellings below.
// Then every include file is compiled with `#define NAME 1` for each.
struct StdlibText {
  std::string file;
  std::string text;  // comments removed, line continuations joined
};

// Comments removed (a block comment becomes a space), line continuations joined.
std::string strip_comments(const std::string& raw) {
  std::string text;
  for (size_t i = 0; i < raw.size();) {
    if (raw.compare(i, 2, "//") == 0) {
      while (i < raw.size() && raw[i] != '\n') ++i;
    } else if (raw.compare(i, 2, "/*") == 0) {
      size_t end = raw.find("*/", i + 2);
      i = end == std::string::npos ? raw.size() : end + 2;
      text += ' ';
    } else if (raw[i] == '\\' && i + 1 < raw.size() && (raw[i + 1] == '\n' || raw.compare(i + 1, 2, "\r\n") == 0)) {
      i += raw[i + 1] == '\n' ? 2 : 3;
      text += ' ';
    } else {
      text += raw[i++];
    }
  }
  return text;
}

std::vector<StdlibText> stdlib_hlsl_files() {
  namespace fs = std::filesystem;
  std::vector<StdlibText> out;
  for (const auto& e : fs::directory_iterator(fs::path(FACET_SOURCE_DIR) / "stdlib")) {
    const std::string ext = e.path().extension().string();
    if (!e.is_regular_file() || (ext != ".cginc" && ext != ".hlsl")) continue;
    std::ifstream in(e.path(), std::ios::binary);
    std::stringstream ss;
    ss << in.rdbuf();
    const std::string text = strip_comments(ss.str());
    out.push_back({e.path().filename().string(), text});
  }
  std::sort(out.begin(), out.end(), [](const StdlibText& a, const StdlibText& b) { return a.file < b.file; });
  return out;
}

bool all_upper(const std::string& t) {
  if (t.empty() || !(t[0] == '_' || (t[0] >= 'A' && t[0] <= 'Z'))) return false;
  bool letter = false;
  for (char c : t) {
    if (c >= 'A' && c <= 'Z') letter = true;
    else if (!(c == '_' || (c >= '0' && c <= '9'))) return false;
  }
  return letter;
}

// name -> the files that use it.
std::map<std::string, std::set<std::string>> user_definable_stdlib_names(const std::vector<StdlibText>& files) {
  const std::regex token(R"([0-9][\w.]*|[A-Za-z_]\w*|##|[^\s])");
  const std::regex word(R"(\w+)");
  const std::regex define(R"(^\s*#\s*define\s+(\w+)(\([^)]*\))?(.*)$)");
  const std::regex conditional(R"(^\s*#\s*(if|ifdef|ifndef|elif)\b(.*)$)");
  const std::regex semantic("(SV_\\w+|POSITION|NORMAL|TANGENT|BINORMAL|COLOR|TEXCOORD|BLENDWEIGHT|BLENDINDICES|"
                            "PSIZE|FOG|DEPTH|VPOS|VFACE|WPOS)[0-9]*");
  // The back end's prelude (docs/stdlib.md §1) and Unity API names that are
  // all-uppercase by Unity's choice.
  const std::set<std::string> api = {"SHADER_TARGET", "UNITY_VERSION", "UNITY_COMPILER_HLSL", "UNITY_COMPILER_HLSLCC",
                                     "_AO" /* the 2.x tree material's ambient-occlusion property */};
  std::set<std::string> defined, tested;
  std::map<std::string, std::set<std::string>> used;
  for (const StdlibText& f : files) {
    std::istringstream lines(f.text);
    std::string line;
    while (std::getline(lines, line)) {
      std::smatch m;
      std::string code;
      std::set<std::string> params;
      if (std::regex_match(line, m, define)) {
        defined.insert(m[1].str());
        std::string p = m[2].str();
        for (std::sregex_iterator it(p.begin(), p.end(), word), end; it != end; ++it)
          params.insert(it->str());
        code = m[3].str();
      } else if (std::regex_match(line, m, conditional)) {
        std::string cond = m[2].str();
        for (std::sregex_iterator it(cond.begin(), cond.end(), token), end; it != end; ++it)
          if (all_upper(it->str())) tested.insert(it->str());
        continue;
      } else if (line.find_first_not_of(" \t") != std::string::npos && line[line.find_first_not_of(" \t")] == '#') {
        continue;  // #include, #pragma, #endif, #else, #undef, #error
      } else {
        code = line;
      }
      std::vector<std::string> toks;
      for (std::sregex_iterator it(code.begin(), code.end(), token), end; it != end; ++it) toks.push_back(it->str());
      for (size_t k = 0; k < toks.size(); ++k) {
        const std::string& t = toks[k];
        if (!all_upper(t) || params.count(t) || std::regex_match(t, semantic)) continue;
        if ((k > 0 && (toks[k - 1] == ":" || toks[k - 1] == "##")) || (k + 1 < toks.size() && toks[k + 1] == "##"))
          continue;
        used[t].insert(f.file);
      }
    }
  }
  for (auto it = used.begin(); it != used.end();) {
    const std::string& n = it->first;
    bool excluded = defined.count(n) || tested.count(n) || api.count(n) || n.rfind("SHADER_API_", 0) == 0 ||
                    n.rfind("SHADER_STAGE_", 0) == 0;
    it = excluded ? used.erase(it) : std::next(it);
  }
  return used;
}

TEST(StdlibNamesTest, ScannerFindsAllUppercaseIdentifiers) {
  const std::vector<StdlibText> probe = {
      {"probe.hlsl", strip_comments("#define UNITY_THING(X) X\n#ifdef MY_KEYWORD\n#endif\n"
                     "float Shade(float3 N, float3 L) { float C = dot(N, L); float F0 = 0.04; /* float Q; */\n"
                     "  return C + F0 + UNITY_THING(1) + MY_KEYWORD; } // float R;\n"
                     "struct v { float4 p : POSITION; float4 c : COLOR0; float2 uv : TEXCOORD##1; };\n")}};
  std::map<std::string, std::set<std::string>> names = user_definable_stdlib_names(probe);
  std::set<std::string> found;
  for (const auto& [n, f] : names) found.insert(n);
  EXPECT_EQ(found, (std::set<std::string>{"C", "F0", "L", "N"}));
}

TEST(StdlibNamesTest, NoStdlibIdentifierIsANameAUserCouldDefineAway) {
  const std::vector<StdlibText> files = stdlib_hlsl_files();
  ASSERT_GT(files.size(), 50u);
  const std::map<std::string, std::set<std::string>> names = user_definable_stdlib_names(files);
  // Any such name is a bug in itself; name the files before compiling.
  for (const auto& [name, where] : names) {
    std::string list;
    for (const std::string& f : where) list += " " + f;
    ADD_FAILURE() << "stdlib identifier '" << name << "' is all-uppercase (a user #define breaks it):" << list;
  }
  // What a file needs before it that Unity's users always include.
  const std::map<std::string, std::string> before = {{"TerrainSplatmapCommon.cginc", "Lighting.cginc"}};
  // Every all-uppercase name the stdlib uses that is no macro of its own: a
  // program defining all of them must still compile each include file.
  std::set<std::string> hostile = {"C", "N", "L", "V", "H", "IN", "OUT", "F0", "R", "T", "B", "D", "G", "P", "X", "Y", "Z"};
  for (const auto& [name, where] : names) hostile.insert(name);
  CompileOptions options;
  options.keywords = std::vector<std::string>{};
  for (const std::string& n : hostile) options.backend.defines.push_back({n, "1"});
  for (const StdlibText& f : files) {
    std::string pre;
    if (auto it = before.find(f.file); it != before.end()) pre = "#include \"" + it->second + "\"\n";
    std::string text = R"(Shader "Test/Hygiene" { SubShader { Pass {
CGPROGRAM
#pragma vertex hygiene_vert
#pragma fragment hygiene_frag
#pragma target 3.0
)" + pre + "#include \"" + f.file + R"("
float4 hygiene_vert(float4 p : POSITION) : SV_POSITION { return p; }
float4 hygiene_frag() : SV_Target { return 1; }
ENDCG
} } })";
    auto compiled = compile_text(f.file + ".shader", text, options);
    EXPECT_TRUE(compiled.ok) << f.file << " does not compile with `#define NAME 1` for every all-uppercase name\n"
                             << compiled.log;
  }
}

// The tier choice: an explicit UNITY_BRDF_PBS wins, then shader model < 3.0
// or UNITY_PBS_USE_BRDF3, then UNITY_PBS_USE_BRDF2, else BRDF1. The shader
// names only the expected choice, so any other expansion is an undeclared
// identifier.
struct Choice {
  std::string defines;
  std::string target;
  std::string expected;  // what UNITY_BRDF_PBS must expand to
};

TEST(StdlibNamesTest, UnityBrdfPbsFollowsTheTierDefinesAndShaderTarget) {
  const std::string custom =
      "#include \"UnityStandardBRDF.cginc\"\n"
      "half4 MyBRDF(half3 d, half3 s, half omr, half sm, float3 n, float3 v, UnityLight l, UnityIndirect g)"
      " { return half4(1, 0, 0, 1); }\n#define UNITY_BRDF_PBS MyBRDF\n";
  const Choice choices[] = {
      {"", "3.0", "BRDF1_Unity_PBS"},
      {"", "2.0", "BRDF3_Unity_PBS"},
      {"#define UNITY_PBS_USE_BRDF1 1\n", "3.0", "BRDF1_Unity_PBS"},
      {"#define UNITY_PBS_USE_BRDF2 1\n", "3.0", "BRDF2_Unity_PBS"},
      {"#define UNITY_PBS_USE_BRDF3 1\n", "3.0", "BRDF3_Unity_PBS"},
      {"#define SHADER_TARGET_SURFACE_ANALYSIS 1\n", "3.0", "BRDF1_Unity_PBS"},
      {"#define UNITY_PBS_USE_BRDF1 1\n", "2.0", "BRDF3_Unity_PBS"},
      {custom, "2.0", "MyBRDF"},
  };
  for (const Choice& c : choices) {
    std::string text = R"(Shader "Test/Choice" { SubShader { Pass {
CGPROGRAM
#pragma vertex vert
#pragma fragment frag
#pragma target )" + c.target + "\n" + c.defines + R"(
#include "UnityPBSLighting.cginc"
#define CHOICE_)" + c.expected + R"( 1.0
#define CHOICE_CAT2(a, b) a##b
#define CHOICE_CAT(a, b) CHOICE_CAT2(a, b)
float4 vert(float4 p : POSITION) : SV_POSITION { return p; }
float4 frag() : SV_Target { return CHOICE_CAT(CHOICE_, UNITY_BRDF_PBS); }
ENDCG
} } })";
    auto compiled = compile_text("choice.shader", text);
    EXPECT_TRUE(compiled.ok) << c.defines << " target " << c.target << " -> " << c.expected << "\n" << compiled.log;
  }
}

// Indirect light belongs to ForwardBase only (docs/rendering.md).
TEST(StdlibNamesTest, ApplyIndirectIsDefinedOnlyInForwardBase) {
  const std::pair<const char*, bool> passes[] = {{"UNITY_PASS_FORWARDBASE", true},
                                                 {"UNITY_PASS_FORWARDADD", false},
                                                 {"UNITY_PASS_SHADOWCASTER", false}};
  for (auto [pass, defined] : passes) {
    std::string text = std::string(R"(Shader "Test/Indirect" { SubShader { Pass {
CGPROGRAM
#pragma vertex vert
#pragma fragment frag
#define )") + pass + R"(
#include "Lighting.cginc"
#include "UnityPBSLighting.cginc"
#if )" + (defined ? "!" : "") + R"(defined(UNITY_LIGHT_FUNCTION_APPLY_INDIRECT)
#error UNITY_LIGHT_FUNCTION_APPLY_INDIRECT is wrong for this pass
#endif
float4 vert(float4 p : POSITION) : SV_POSITION { return p; }
float4 frag() : SV_Target { return 1; }
ENDCG
} } })";
    auto compiled = compile_text("indirect.shader", text);
    EXPECT_TRUE(compiled.ok) << pass << "\n" << compiled.log;
  }
}

// The light and shadow macros compile for every light and shadow keyword of
// the built-in sets, with and without fog.
TEST(StdlibNamesTest, LightAndShadowMacrosCompileForEveryLightKeyword) {
  auto compiled = compile_text("lights.shader", R"(Shader "Test/Lights" { SubShader {
Pass { Tags { "LightMode"="ForwardBase" }
CGPROGRAM
#pragma vertex vert
#pragma fragment frag
#pragma multi_compile_fwdbase
#pragma multi_compile_fog
#define UNITY_PASS_FORWARDBASE
#include "UnityCG.cginc"
#include "AutoLight.cginc"
#include "Lighting.cginc"
struct v2f { float4 pos : SV_POSITION; float3 wp : TEXCOORD0; LIGHTING_COORDS(1, 2) UNITY_FOG_COORDS(3) };
v2f vert(appdata_base v) { v2f o = (v2f)0; o.pos = UnityObjectToClipPos(v.vertex); o.wp = mul(unity_ObjectToWorld, v.vertex).xyz;
  TRANSFER_VERTEX_TO_FRAGMENT(o); UNITY_TRANSFER_FOG(o, o.pos); return o; }
float4 frag(v2f i) : SV_Target { UNITY_LIGHT_ATTENUATION(atten, i, i.wp); float4 c = _LightColor0 * atten * LIGHT_ATTENUATION(i) * SHADOW_ATTENUATION(i);
  UNITY_APPLY_FOG(i.fogCoord, c); return c; }
ENDCG
}
Pass { Tags { "LightMode"="ForwardAdd" }
CGPROGRAM
#pragma vertex vert
#pragma fragment frag
#pragma multi_compile_fwdadd_fullshadows
#pragma multi_compile_fog
#define UNITY_PASS_FORWARDADD
#include "UnityCG.cginc"
#include "AutoLight.cginc"
struct v2f { float4 pos : SV_POSITION; float3 wp : TEXCOORD0; UNITY_LIGHTING_COORDS(1, 2) UNITY_FOG_COORDS(3) };
v2f vert(appdata_base v) { v2f o = (v2f)0; o.pos = UnityObjectToClipPos(v.vertex); o.wp = mul(unity_ObjectToWorld, v.vertex).xyz;
  UNITY_TRANSFER_LIGHTING(o, v.texcoord.xy); UNITY_TRANSFER_FOG(o, o.pos); return o; }
float4 frag(v2f i) : SV_Target { UNITY_LIGHT_ATTENUATION(atten, i, i.wp); float4 c = atten * UNITY_SHADOW_ATTENUATION(i, i.wp);
  UNITY_APPLY_FOG(i.fogCoord, c); return c; }
ENDCG
}
Pass { Tags { "LightMode"="ShadowCaster" }
CGPROGRAM
#pragma vertex vert
#pragma fragment frag
#pragma multi_compile_shadowcaster
#define UNITY_PASS_SHADOWCASTER
#include "UnityCG.cginc"
struct v2f { V2F_SHADOW_CASTER; };
v2f vert(appdata_base v) { v2f o = (v2f)0; TRANSFER_SHADOW_CASTER_NORMALOFFSET(o) return o; }
float4 frag(v2f i) : SV_Target { SHADOW_CASTER_FRAGMENT(i) }
ENDCG
}
} })");
  ASSERT_TRUE(compiled.ok) << compiled.log;
  const package::Package& pkg = compiled.shader->package;
  ASSERT_EQ(pkg.passes.size(), 3u);
  EXPECT_EQ(pkg.passes[0].variants.size(), 8u * 4u);
  // fwdadd_fullshadows: Unity's 47 combinations, 13 without the shadowmask keywords.
  EXPECT_EQ(pkg.passes[1].variants.size(), 13u * 4u);
  EXPECT_EQ(pkg.passes[2].variants.size(), 2u);
  stdlib_test::expect_valid_spirv(pkg);
}

}  // namespace
}  // namespace facet
