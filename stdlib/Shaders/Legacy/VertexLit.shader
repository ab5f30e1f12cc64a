// facet's own "Legacy Shaders/VertexLit" (also found as "VertexLit"): the
// end of most of Unity's Fallback chains. Lit per vertex by up to 8 lights
// (LightMode Vertex, drawn when a shader has no forward passes), and the
// ShadowCaster that `Fallback "Diffuse"` and
// `UsePass "Legacy Shaders/VertexLit/SHADOWCASTER"` give other shaders.
Shader "Legacy Shaders/VertexLit" {
    Properties {
        _Color ("Main Color", Color) = (1, 1, 1, 1)
        _SpecColor ("Spec Color", Color) = (1, 1, 1, 1)
        _Emission ("Emissive Color", Color) = (0, 0, 0, 0)
        _Shininess ("Shininess", Range(0.01, 1)) = 0.7
        _MainTex ("Base (RGB)", 2D) = "white" {}
    }
    SubShader {
        Tags { "RenderType" = "Opaque" }
        LOD 100

        Pass {
            Tags { "LightMode" = "Vertex" }
            Lighting On
            SeparateSpecular On
            Material {
                Ambient [_Color]
                Diffuse [_Color]
                Emission [_Emission]
                Shininess [_Shininess]
                Specular [_SpecColor]
            }
            SetTexture [_MainTex] {
                Combine texture * primary DOUBLE, texture * primary
            }
        }

        Pass {
            Name "ShadowCaster"
            Tags { "LightMode" = "ShadowCaster" }
            ZWrite On
            ZTest LEqual

            CGPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            #pragma target 2.0
            #pragma multi_compile_shadowcaster
            #pragma multi_compile_instancing
            #include "UnityCG.cginc"

            struct v2f {
                V2F_SHADOW_CASTER;
                UNITY_VERTEX_OUTPUT_STEREO
            };

            v2f vert(appdata_base v) {
                v2f o;
                UNITY_SETUP_INSTANCE_ID(v);
                UNITY_INITIALIZE_VERTEX_OUTPUT_STEREO(o);
                TRANSFER_SHADOW_CASTER_NORMALOFFSET(o)
                return o;
            }

            float4 frag(v2f i) : SV_Target {
                SHADOW_CASTER_FRAGMENT(i)
            }
            ENDCG
        }
    }
}
