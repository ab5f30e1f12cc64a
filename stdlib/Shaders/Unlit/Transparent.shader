// facet's own "Unlit/Transparent": the texture blended by its alpha over
// what is behind it, without writing depth.
Shader "Unlit/Transparent" {
    Properties {
        _MainTex ("Base (RGB) Trans (A)", 2D) = "white" {}
    }
    SubShader {
        Tags { "Queue" = "Transparent" "IgnoreProjector" = "True" "RenderType" = "Transparent" }
        LOD 100
        ZWrite Off
        Blend SrcAlpha OneMinusSrcAlpha

        Pass {
            CGPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            #pragma target 2.0
            #pragma multi_compile_fog
            #define UNLIT_BLENDED
            #include "UnlitCommon.cginc"
            ENDCG
        }
    }
}
