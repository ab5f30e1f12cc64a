Shader "Game/Waves" {
  Properties { _Amplitude ("Amplitude", Float) = 0.1 }
  SubShader { Pass {
    CGPROGRAM
    #pragma vertex vert
    #pragma fragment frag
    #pragma multi_compile _ CALM
    #include "Waves.cginc"
    float4 vert(float4 v : POSITION) : SV_POSITION { return wave(v); }
    float4 frag() : SV_Target { return float4(0, 0.3, 1, 1); }
    ENDCG
  } }
}
