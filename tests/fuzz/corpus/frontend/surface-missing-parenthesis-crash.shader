// The Standard (metallic) lighting model with a normal map.
Shader "Examples/Surface/Standard" {
  Properties {
    _Color ("Color", Color) = (1, 1, 1, 1)
    _MainTex ("Albedo", 2D) = "white" {}
    _BumpMap ("Normal Map", 2D) = "bump" {}
    _Glossiness ("Smoothness", Range(0, 1)) = 0.5
    _Metallic ("Metallic", Range(0, 1)) = 0.0
  }
  SubShader {
    Tags { "RenderType" = "Opaque" }
    CGPROGRAM
    #pragma surface surf Standard fullforwardshadows
    #pragma target 3.0
    sampler2D _MainTex;
    sampler2D _BumpMap;
    fixed4 _Color;
    half _Glossineut SurfaceOutputStandard o) {
      fixed4 c = tex2D(_MainTex, IN.uv_MainTex) * _Color;
      o.Albedo = c.rgb;
      o.Normal = UnpackNormal(tex2D(_BumpMap, IN.uv_MainTex));
      o.Metallic = _Metallic;
      o.Smoothness = _Glossiness;
      o.Alpha = c.a;
    }
    ENDCG
  }
  FallBack "Diffuse"
}
