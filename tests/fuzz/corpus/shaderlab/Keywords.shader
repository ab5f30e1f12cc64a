// Several keyword sets: material features (shader_feature, some
// fragment-only) and engine features (multi_compile).
Shader "Examples/Keywords" {
    Properties {
        _Color ("Color", Color) = (1, 1, 1, 1)
        _MainTex ("Albedo", 2D) = "white" {}
        [Toggle(_EMISSION)] _EmissionOn ("Emission", Float) = 0
        [HDR] _EmissionColor ("Emission Color", Color) = (0, 0, 0)
        [KeywordEnum(None, Add, Multiply)] _Overlay ("Overlay mode", Float) = 0
        _OverlayTex ("Overlay", 2D) = "black" {}
        [Enum(UnityEngine.Rendering.CullMode)] _Cull ("Cull", Float) = 2
    }
    SubShader {
        Tags { "RenderType"="Opaque" }
        Pass {
            Tags { "LightMode"="ForwardBase" }
            Cull [_Cull]
            CGPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            #pragma multi_compile_fog
            #pragma multi_compile __ FACET_DEBUG_NORMALS
            #pragma shader_feature _EMISSION
            #pragma shader_feature_local_fragment _OVERLAY_NONE _OVERLAY_ADD _OVERLAY_MULTIPLY
            #include "UnityCG.cginc"

            fixed4 _Color;
            sampler2D _MainTex;
            float4 _MainTex_ST;
            half4 _EmissionColor;
            sampler2D _OverlayTex;

            struct v2f {
                float4 pos : SV_POSITION;
                float2 uv : TEXCOORD0;
                float3 normal : TEXCOORD1;
                UNITY_FOG_COORDS(2)
            };

            v2f vert(appdata_base v) {
                v2f o;
                o.pos = UnityObjectToClipPos(v.vertex);
                o.uv = TRANSFORM_TEX(v.texcoord, _MainTex);
                o.normal = UnityObjectToWorldNormal(v.normal);
                UNITY_TRANSFER_FOG(o, o.pos);
                return o;
            }

            fixed4 frag(v2f i) : SV_Target {
                fixed4 c = tex2D(_MainTex, i.uv) * _Color;
            #if defined(_OVERLAY_ADD)
                c.rgb += tex2D(_OverlayTex, i.uv).rgb;
            #elif defined(_OVERLAY_MULTIPLY)
                c.rgb *= tex2D(_OverlayTex, i.uv).rgb;
            #endif
            #ifdef _EMISSION
                c.rgb += _EmissionColor.rgb;
            #endif
            #ifdef FACET_DEBUG_NORMALS
                c.rgb = normalize(i.normal) * 0.5 + 0.5;
            #endif
                UNITY_APPLY_FOG(i.fogCoord, c);
                return c;
            }
            ENDCG
        }
    }
}
