Shader "Game/Tinted" {
  Properties { _Tint ("Tint", Color) = (1, 1, 1, 1) }
  SubShader { Pass {
    CGPROGRAM
    #pragma vertex vert
    #pragma fragment frag
    #include "Tint.cginc"
    float4 vert(float4 v : POSITION) : SV_POSITION { return v; }
    float4 frag() : SV_Target { return tint(float4(1, 1, 1, 1)); }
    ENDCG
  } }
}
