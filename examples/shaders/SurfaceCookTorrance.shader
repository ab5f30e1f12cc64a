// A custom lighting model for surface shaders, as the book builds its
// Cook-Torrance shader: GGX distribution, height-correlated Smith
// visibility and Schlick Fresnel for the specular lobe, Lambert for the
// diffuse, metallic workflow; indirect light from the ambient SH and the
// reflection probe, the probe weighted by the split-sum environment BRDF.
Shader "Examples/Surface/CookTorrance" {
  Properties {
    _Color ("Albedo", Color) = (1, 1, 1, 1)
    _Metallic ("Metallic", Range(0, 1)) = 0
    _Roughness ("Perceptual roughness", Range(0.05, 1)) = 0.5
  }
  SubShader {
    Tags { "RenderType" = "Opaque" }
    CGPROGRAM
    #pragma surface surf CookTorrance fullforwardshadows
    #include "FacetIBL.hlsl"

    fixed4 _Color;
    half _Metallic, _Roughness;

    struct Input {
      float3 worldPos;
    };

    half4 LightingCookTorrance(SurfaceOutputStandard s, half3 viewDir, UnityGI gi) {
      float3 n = normalize(s.Normal), v = normalize(viewDir), l = gi.light.dir;
      float roughness = 1.0 - s.Smoothness;
      float3 f0 = lerp(unity_ColorSpaceDielectricSpec.rgb, s.Albedo, s.Metallic);
      float3 diffuse = s.Albedo * (1.0 - s.Metallic);
      float nl = saturate(dot(n, l));
      // Unity's light colour is the irradiance of a surface facing the
      // light times pi: the BRDF's 1/pi is folded into the diffuse term.
      float3 specular = UNITY_PI * FacetBRDF_CookTorranceGGX(n, v, l, f0, roughness);
      float3 direct = (diffuse + specular) * gi.light.color * nl;
      float3 environment = FacetEnvBRDFApprox(f0, roughness, saturate(dot(n, v)));
      float3 indirect = diffuse * gi.indirect.diffuse + gi.indirect.specular * environment;
      return half4(direct + indirect, s.Alpha);
    }

    // The ambient SH and the probe at this surface's roughness, as Standard's.
    void LightingCookTorrance_GI(SurfaceOutputStandard s, UnityGIInput data, inout UnityGI gi) {
      LightingStandard_GI(s, data, gi);
    }

    void surf(Input IN, inout SurfaceOutputStandard o) {
      o.Albedo = _Color.rgb;
      o.Metallic = _Metallic;
      o.Smoothness = 1.0 - _Roughness;
      o.Alpha = 1.0;
    }
    ENDCG
  }
  Fallback "Diffuse"
}
