// Lambert diffuse from the main directional light plus ambient.
Shader "Examples/Diffuse" {
    Properties {
        _Color ("Diffuse Color", Color) = (1, 1, 1, 1)
        _MainTex ("Albedo", 2D) = "white" {}
    }
    SubShader {
        Tags { "RenderType"="Opaque" }
        Pass {
            Tags { "LightMode"="ForwardBase" }
            CGPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            #include "UnityCG.cginc"
            #include "UnityLightingCommon.cginc"

            fixed4 _Color;
            sampler2D _MainTex;
            float4 _MainTex_ST;

            struct v2f {
                float4 pos : SV_POSITION;
                float2 uv : TEXCOORD0;
                float3 worldNormal : TEXCOORD1;
            };

            v2f vert(appdata_base v) {
                v2f o;
                o.pos = UnityObjectToClipPos(v.vertex);
                o.uv = TRANSFORM_TEX(v.texcoord, _MainTex);
                o.worldNormal = UnityObjectToWorldNormal(v.normal);
                return o;
            }

            fixed4 frag(v2f i) : SV_Target {
                float3 n = normalize(i.worldNormal);
                float3 l = normalize(_WorldSpaceLightPos0.xyz);
                float ndotl = max(0, dot(n, l));
                fixed4 albedo = tex2D(_MainTex, i.uv) * _Color;
                fixed3 ambient = ShadeSH9(half4(n, 1));
                return fixed4(albedo.rgb * (_LightColor0.rgb * ndotl + ambient), 1);
            }
            ENDCG
        }
    }
    Fallback "Diffuse"
}
