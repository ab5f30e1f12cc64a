// facet's own "Legacy Shaders/Transparent/Cutout/VertexLit": VertexLit with
// the pixels whose alpha (texture alpha times _Color's) is below _Cutoff cut
// away, in the lit pass and in the shadow it casts.
Shader "Legacy Shaders/Transparent/Cutout/VertexLit" {
    Properties {
        _Color ("Main Color", Color) = (1, 1, 1, 1)
        _SpecColor ("Spec Color", Color) = (1, 1, 1, 0)
        _Emission ("Emissive Color", Color) = (0, 0, 0, 0)
        _Shininess ("Shininess", Range(0.1, 1)) = 0.7
        _MainTex ("Base (RGB) Trans (A)", 2D) = "white" {}
        _Cutoff ("Alpha cutoff", Range(0, 1)) = 0.5
    }
    SubShader {
        Tags { "Queue" = "AlphaTest" "IgnoreProjector" = "True" "RenderType" = "TransparentCutout" }
        LOD 100

        Pass {
            Tags { "LightMode" = "Vertex" }
            AlphaTest Greater [_Cutoff]
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
            Name "Caster"
            Tags { "LightMode" = "ShadowCaster" }
            Cull Off

            CGPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            #pragma target 2.0
            #pragma multi_compile_shadowcaster
            #pragma multi_compile_instancing
            #include "UnityCG.cginc"

            sampler2D _MainTex;
            float4 _MainTex_ST;
            fixed _Cutoff;
            fixed4 _Color;

            struct v2f {
                V2F_SHADOW_CASTER;
                float2 uv : TEXCOORD1;
                UNITY_VERTEX_OUTPUT_STEREO
            };

            v2f vert(appdata_base v) {
                v2f o;
                UNITY_SETUP_INSTANCE_ID(v);
                UNITY_INITIALIZE_VERTEX_OUTPUT_STEREO(o);
                TRANSFER_SHADOW_CASTER_NORMALOFFSET(o)
                o.uv = TRANSFORM_TEX(v.texcoord, _MainTex);
                return o;
            }

            float4 frag(v2f i) : SV_Target {
                clip(tex2D(_MainTex, i.uv).a * _Color.a - _Cutoff);
                SHADOW_CASTER_FRAGMENT(i)
            }
            ENDCG
        }
    }
}
