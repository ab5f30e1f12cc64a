// Lambert diffuse from the main directional light plus ambient, written for
// GPU instancing as Unity's manual shows it: multi_compile_instancing, the
// instance ID through the vertex input and the interpolators, and the
// colour a per-instance property. A material with "instancing": true draws
// runs of objects with this shader as one instanced draw each, every object
// with its own _Color.
Shader "Examples/Instanced" {
    Properties {
        _Color ("Diffuse Color", Color) = (1, 1, 1, 1)
    }
    SubShader {
        Tags { "RenderType"="Opaque" }
        Pass {
            Tags { "LightMode"="ForwardBase" }
            CGPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            #pragma multi_compile_instancing
            #include "UnityCG.cginc"
            #include "UnityLightingCommon.cginc"

            UNITY_INSTANCING_BUFFER_START(Props)
                UNITY_DEFINE_INSTANCED_PROP(fixed4, _Color)
            UNITY_INSTANCING_BUFFER_END(Props)

            struct appdata {
                float4 vertex : POSITION;
                float3 normal : NORMAL;
                UNITY_VERTEX_INPUT_INSTANCE_ID
            };

            struct v2f {
                float4 pos : SV_POSITION;
                float3 worldNormal : TEXCOORD0;
                UNITY_VERTEX_INPUT_INSTANCE_ID
            };

            v2f vert(appdata v) {
                v2f o;
                UNITY_SETUP_INSTANCE_ID(v);
                UNITY_TRANSFER_INSTANCE_ID(v, o);
                o.pos = UnityObjectToClipPos(v.vertex);
                o.worldNormal = UnityObjectToWorldNormal(v.normal);
                return o;
            }

            fixed4 frag(v2f i) : SV_Target {
                UNITY_SETUP_INSTANCE_ID(i);
                float3 n = normalize(i.worldNormal);
                float ndotl = max(0, dot(n, normalize(_WorldSpaceLightPos0.xyz)));
                fixed4 albedo = UNITY_ACCESS_INSTANCED_PROP(Props, _Color);
                return fixed4(albedo.rgb * (_LightColor0.rgb * ndotl + ShadeSH9(half4(n, 1))), 1);
            }
            ENDCG
        }
    }
}
