Shader "Game/Plain" {
  SubShader { Pass {
    CGPROGRAM
    #pragma vertex vert
    #pragma fragment frag
    float4 vert(float4 v : POSITION) : SV_POSITION { return v; }
    float4 frag() : SV_Target { return float4(1, 0, 0, 1); }
    ENDCG
  } }
}
