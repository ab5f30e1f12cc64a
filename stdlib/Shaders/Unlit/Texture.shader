// facet's own "Unlit/Texture": the texture as it is, with fog; no lighting,
// no shadows cast.
Shader "Unlit/Texture" {
    Properties {
        _MainTex ("Base (RGB)", 2D) = "white" {}
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
            #include "UnlitCommon.cginc"
            ENDCG
        }
    }
}
