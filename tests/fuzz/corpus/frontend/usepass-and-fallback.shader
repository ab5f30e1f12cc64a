Shader "Fuzz/UsePassAndFallback" {
    Properties { _MainTex ("Tex", 2D) = "white" {} _Cutoff ("Cut", Range(0, 1)) = 0.5 }
    SubShader {
        Pass {
            Tags { "LightMode" = "ForwardBase" }
            CGPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            #include "UnityCG.cginc"
            float4 vert(float4 v : POSITION) : SV_POSITION { return UnityObjectToClipPos(v); }
            fixed4 frag() : SV_Target { return 1; }
            ENDCG
        }
        UsePass "Mobile/VertexLit/SHADOWCASTER"
        UsePass "Fuzz/UsePassAndFallback/MISSING"
    }
    Fallback "Transparent/Cutout/Diffuse"
}
