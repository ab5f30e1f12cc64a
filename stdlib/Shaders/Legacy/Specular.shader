// facet's own "Legacy Shaders/Specular" ("Specular"): Blinn-Phong, the
// texture's alpha scaling the highlight.
Shader "Legacy Shaders/Specular" {
    Properties {
        _Color ("Main Color", Color) = (1, 1, 1, 1)
        _SpecColor ("Specular Color", Color) = (0.5, 0.5, 0.5, 1)
        _Shininess ("Shininess", Range(0.03, 1)) = 0.078125
        _MainTex ("Base (RGB) Gloss (A)", 2D) = "white" {}
    }
    SubShader {
        Tags { "RenderType" = "Opaque" }
        LOD 300

        CGPROGRAM
        #pragma surface surf BlinnPhong

        sampler2D _MainTex;
        fixed4 _Color;
        half _Shininess;

        struct Input {
            float2 uv_MainTex;
        };

        void surf(Input IN, inout SurfaceOutput o) {
            fixed4 texel = tex2D(_MainTex, IN.uv_MainTex);
            o.Albedo = texel.rgb * _Color.rgb;
            o.Gloss = texel.a;
            o.Alpha = texel.a * _Color.a;
            o.Specular = _Shininess;
        }
        ENDCG
    }
    Fallback "Legacy Shaders/VertexLit"
}
