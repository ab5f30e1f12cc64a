// Translucency: light through thin geometry, a fast subsurface
// approximation (view-dependent back light), in a view-dependent UnityGI
// lighting function.
Shader "Examples/Surface/Translucent" {
  Properties {
    _Color ("Color", Color) = (1, 0.6, 0.4, 1)
    _Distortion ("Distortion", Range(0, 1)) = 0.2
    _Power ("Power", Range(1, 16)) = 4
    _Scale ("Scale", Range(0, 4)) = 1
  }
  SubShader {
    Tags { "RenderType" = "Opaque" }
    CGPROGRAM
    #pragma surface surf Translucent fullforwardshadows
    fixed4 _Color;
    half _Distortion, _Power, _Scale;
    struct Input {
      float3 worldNormal;
    };
    half4 LightingTranslucent(SurfaceOutputStandard s, half3 viewDir, UnityGI gi) {
      half4 pbr = LightingStandard(s, viewDir, gi);
      half3 h = normalize(gi.light.dir + s.Normal * _Distortion);
      half through = pow(saturate(dot(viewDir, -h)), _Power) * _Scale;
      pbr.rgb += s.Albedo * gi.light.color * through;
      return pbr;
    }
    void LightingTranslucent_GI(SurfaceOutputStandard s, UnityGIInput data, inout UnityGI gi) {
      LightingStandard_GI(s, data, gi);
    }
    void surf(Input IN, inout SurfaceOutputStandard o) {
      o.Albedo = _Color.rgb * (0.75 + 0.25 * IN.worldNormal.y);
      o.Smoothness = 0.4;
    }
    ENDCG
  }
  Fallback "Diffuse"
}
