// facet's own "Unlit/Color": one colour, with fog.
Shader "Unlit/Color" {
    Properties {
        _Color ("Main Color", Color) = (1, 1, 1, 1)
    }
    SubShader {
        Tags { "RenderType" = "Opaque" }
        LOD 100

        Pass {
            CGPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            #pragma target 2.0
            #pragma multi_compile_fog
            #define UNLIT_COLOR_ONLY
            #include "UnlitCommon.cginc"
            ENDCG
        }
    }
}
