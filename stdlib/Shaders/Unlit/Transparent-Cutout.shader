// facet's own "Unlit/Transparent Cutout": the texture with the pixels whose
// alpha is below _Cutoff cut away.
Shader "Unlit/Transparent Cutout" {
    Properties {
        _MainTex ("Base (RGB) Trans (A)", 2D) = "white" {}
        _Cutoff ("Alpha cutoff", Range(0, 1)) = 0.5
    }
    SubShader {
        Tags { "Queue" = "AlphaTest" "IgnoreProjector" = "True" "RenderType" = "TransparentCutout" }
        LOD 100

        Pass {
            CGPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            #pragma target 2.0
            #pragma multi_compile_fog
            #define UNLIT_CUTOUT
            #include "UnlitCommon.cginc"
            ENDCG
        }
    }
}
