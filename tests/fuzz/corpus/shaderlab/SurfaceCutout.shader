// Cutout leaves: alphatest clips in every pass, and addshadow generates a
// ShadowCaster that runs surf and clips too.
Shader "Examples/Surface/Cutout" {
  Properties {
    _MainTex ("Texture", 2D) = "white" {}
    _Cutoff ("Alpha Cutoff", Range(0, 1)) = 0.5
  }
  SubShader {
    Tags { "Queue" = "AlphaTest" "RenderType" = "TransparentCutout" }
    Cull Off
    CGPROGRAM
    #pragma surface surf Lambert alphatest:_Cutoff addshadow
    sampler2D _MainTex;
    struct Input {
      float2 uv_MainTex;
      float facing : VFACE;
    };
    void surf(Input IN, inout SurfaceOutput o) {
      fixed4 c = tex2D(_MainTex, IN.uv_MainTex);
      o.Albedo = c.rgb * (IN.facing > 0 ? 1.0 : 0.7);
      o.Alpha = c.a;
    }
    ENDCG
  }
}
