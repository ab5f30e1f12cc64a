// BlinnPhong with a normal map: o.Normal is written in tangent space.
Shader "Examples/Surface/BlinnPhongNormal" {
  Properties {
    _MainTex ("Texture", 2D) = "white" {}
    _BumpMap ("Normal Map", 2D) = "bump" {}
    _SpecColor ("Specular Color", Color) = (0.5, 0.5, 0.5, 1)
    _Shininess ("Shininess", Range(0.03, 1)) = 0.078
  }
  SubShader {
    Tags { "RenderType" = "Opaque" }
    CGPROGRAM
    #pragma surface surf BlinnPhong
    sampler2D _MainTex;
    sampler2D _BumpMap;
    half _Shininess;
    struct Input {
      float2 uv_MainTex;
      float2 uv_BumpMap;
    };
    void surf(Input IN, inout SurfaceOutput o) {
      fixed4 c = tex2D(_MainTex, IN.uv_MainTex);
      o.Albedo = c.rgb;
      o.Gloss = c.a;
      o.Specular = _Shininess;
      o.Normal = UnpackNormal(tex2D(_BumpMap, IN.uv_BumpMap));
    }
    ENDCG
  }
  Fallback "Legacy Shaders/VertexLit"
}
