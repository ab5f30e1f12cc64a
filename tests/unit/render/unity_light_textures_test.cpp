// Unity's AutoLight.cginc takes a point light's falloff from _LightTexture0,
// a spot light's from _LightTextureB0 and its cone from _LightTexture0 (the
// default spot cookie), where facet's stdlib computes them analytically. A
// program that declares those textures itself (as Unity's include files do,
// outside facet's light set) gets textures of facet's falloff and cone, so
// it lights a floor as facet's own AutoLight does. The Unity-style program
// here is written for this test (Unity's formulas, not Unity's files).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "render_test_support.h"

namespace facet::runtime {
namespace {

using UnityLightTexturesTest = test_support::RenderTest;

// ForwardAdd only writes light: the base pass is black.
constexpr const char* kBasePass = R"(
    Pass {
      Tags { "LightMode" = "ForwardBase" }
      HLSLPROGRAM
      #pragma vertex vert
      #pragma fragment frag
      float4x4 unity_ObjectToWorld;
      float4x4 unity_MatrixVP;
      float4 vert(float4 v : POSITION) : SV_POSITION { return mul(unity_MatrixVP, mul(unity_ObjectToWorld, v)); }
      float4 frag() : SV_Target { return float4(0, 0, 0, 1); }
      ENDHLSL
    })";

std::string write_shader(const std::string& name, const std::string& text) {
  std::filesystem::path path = test_support::test_dir() / name;
  std::ofstream(path) << text;
  return path.string();
}

// Unity's AutoLight formulas over textures, with its own declarations.
std::string unity_style_shader() {
  return write_shader("UnityStyleAutoLight.shader", std::string(R"(Shader "Test/UnityStyleAutoLight" {
  SubShader {)") + kBasePass + R"(
    Pass {
      Tags { "LightMode" = "ForwardAdd" }
      Blend One One
      HLSLPROGRAM
      #pragma vertex vert
      #pragma fragment frag
      #pragma multi_compile POINT SPOT
      float4x4 unity_ObjectToWorld;
      float4x4 unity_MatrixVP;
      float4x4 unity_WorldToLight;
      float4 _LightColor0;
      sampler2D _LightTexture0;
      sampler2D _LightTextureB0;
      struct v2f { float4 pos : SV_POSITION; float3 world : TEXCOORD0; };
      v2f vert(float4 v : POSITION) {
        v2f o;
        float4 w = mul(unity_ObjectToWorld, v);
        o.world = w.xyz;
        o.pos = mul(unity_MatrixVP, w);
        return o;
      }
      float4 frag(v2f i) : SV_Target {
        float4 c = mul(unity_WorldToLight, float4(i.world, 1));
      #if defined(POINT)
        float atten = tex2D(_LightTexture0, dot(c.xyz, c.xyz).rr).r;
      #else
        float atten = (c.z > 0) * tex2D(_LightTexture0, c.xy / c.w + 0.5).w * tex2D(_LightTextureB0, dot(c.xyz, c.xyz).xx).r;
      #endif
        return float4(_LightColor0.rgb * atten, 1);
      }
      ENDHLSL
    }
  }
})");
}

// The same light through facet's stdlib.
std::string facet_shader() {
  return write_shader("FacetAutoLight.shader", std::string(R"(Shader "Test/FacetAutoLight" {
  SubShader {)") + kBasePass + R"(
    Pass {
      Tags { "LightMode" = "ForwardAdd" }
      Blend One One
      CGPROGRAM
      #pragma vertex vert
      #pragma fragment frag
      #pragma multi_compile POINT SPOT
      #include "UnityCG.cginc"
      #include "AutoLight.cginc"
      #include "UnityLightingCommon.cginc"
      struct v2f { float4 pos : SV_POSITION; float3 world : TEXCOORD0; };
      v2f vert(appdata_base v) {
        v2f o;
        o.world = mul(unity_ObjectToWorld, v.vertex).xyz;
        o.pos = UnityObjectToClipPos(v.vertex);
        return o;
      }
      float4 frag(v2f i) : SV_Target {
        UNITY_LIGHT_ATTENUATION(atten, i, i.world)
        return float4(_LightColor0.rgb * atten, 1);
      }
      ENDCG
    }
  }
})");
}

std::string floor_scene(const std::string& shader) {
  return R"({"width": 64, "height": 64, "ambient": [0, 0, 0],
    "camera": {"type": "orthographic", "size": 3, "position": [0, 5, 0], "look_at": [0, 0, 0], "clear_color": [0, 0, 0]},
    "lights": [{"type": "point", "position": [-1.2, 1, 0.8], "range": 3, "intensity": 1.5},
               {"type": "spot", "position": [1.2, 2, -0.8], "look_at": [1.4, 0, -1.2], "range": 4, "spot_angle": 60,
                "inner_spot_angle": 30, "intensity": 2, "color": [0.5, 0.8, 1]}],
    "objects": [{"name": "floor", "mesh": "plane", "scale": 0.6, "material": {"shader": ")" +
         shader + R"("}}]})";
}

TEST_F(UnityLightTexturesTest, AProgramReadingUnitysAttenuationTexturesLightsAsFacetsStdlibDoes) {
  RenderedFrame facet = render("autolight_facet", floor_scene(facet_shader()));
  RenderedFrame unity = render("autolight_unity", floor_scene(unity_style_shader()));
  ASSERT_FALSE(facet.hdr.empty());
  ASSERT_EQ(facet.hdr.size(), unity.hdr.size());
  float worst = 0, brightest = 0;
  size_t lit = 0, dark = 0;
  for (size_t i = 0; i + 3 < facet.hdr.size(); i += 4) {
    for (int c = 0; c < 3; ++c) {
      worst = std::max(worst, std::abs(facet.hdr[i + size_t(c)] - unity.hdr[i + size_t(c)]));
      brightest = std::max(brightest, facet.hdr[i + size_t(c)]);
    }
    lit += facet.hdr[i] > 0.05f;
    dark += facet.hdr[i] == 0 && facet.hdr[i + 2] == 0;
  }
  EXPECT_GT(lit, 200u) << "the lights reach the floor";
  EXPECT_GT(dark, 200u) << "beyond the range and outside the cone the floor is dark";
  // The ramp's 256 texels and half floats against the analytic falloff.
  EXPECT_LT(worst, 0.01f * brightest) << "worst " << worst << " of " << brightest;
  std::printf("[ unity light textures ] worst difference %.5f of the brightest %.4f\n", worst, brightest);
}

}  // namespace
}  // namespace facet::runtime
