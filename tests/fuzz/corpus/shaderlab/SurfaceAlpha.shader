// Alpha options: a faded, vertex-coloured glass (alpha:fade) in the first
// SubShader's passes, and cutout leaves (alphatest with addshadow) below.
Shader "Examples/Surface/Alpha" {
  Properties {
    _MainTex ("Texture", 2D) = "white" {}
    _Cutoff ("Alpha Cutoff", Range(0, 1)) = 0.5
  }
  SubShader {
    Tags { "Queue" = "Transparent" "RenderType" = "Transparent" }
    ZWrite Off
    CGPROGRAM
    #pragma surface surf Lambert alpha:fade
    sampler2D _MainTex;
    struct Input {
      float2 uv_MainTex;
      float4 color : COLOR;
    };
    void surf(Input IN, inout SurfaceOutput o) {
      fixed4 c = tex2D(_MainTex, IN.uv_MainTex) * IN.color;
      o.Albedo = c.rgb;
      o.Alpha = c.a;
    }
    ENDCG
  }
  Fallback "Transparent/Diffuse"
}
