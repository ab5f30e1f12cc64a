// The StandardSpecular lighting model, emission from a texture.
Shader "Examples/Surface/StandardSpecular" {
  Properties {
    _MainTex ("Albedo", 2D) = "white" {}
    _SpecColor ("Specular", Color) = (0.2, 0.2, 0.2, 1)
    _Glossiness ("Smoothness", Range(0, 1)) = 0.7
    _EmissionMap ("Emission", 2D) = "black" {}
  }
  SubShader {
    Tags { "RenderType" = "Opaque" }
    CGPROGRAM
    #pragma surface surf StandardSpecular
    sampler2D _MainTex;
    sampler2D _EmissionMap;
    half _Glossiness;
    struct Input {
      float2 uv_MainTex;
    };
    void surf(Input IN, inout SurfaceOutputStandardSpecular o) {
      o.Albedo = tex2D(_MainTex, IN.uv_MainTex).rgb;
      o.Specular = _SpecColor.rgb;
      o.Smoothness = _Glossiness;
      o.Emission = tex2D(_EmissionMap, IN.uv_MainTex).rgb;
    }
    ENDCG
  }
  FallBack "Diffuse"
}
