Shader "Test/DX9"
{
    SubShader
    {
        Pass
        {
            CGPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            #pragma target 3.0
            #include "UnityCG.cginc"
            #include "UnityLightingCommon.cginc"

            sampler2D _MainTex;
            samplerCUBE _Cube;
            float _Roughness;

            struct v2f
            {
                float4 pos : SV_POSITION;
                float3 worldNormal : TEXCOORD0;
                float4 worldPos : TEXCOORD1;
                float2 uv : TEXCOORD2;
            };

            inline float3 Tint(float3 c) { return c * 0.5f; }

            v2f vert (appdata_base v)
            {
                v2f o;
                o.pos = UnityObjectToClipPos(v.vertex);
                o.worldNormal = UnityObjectToWorldNormal(v.normal);
                o.worldPos = mul(unity_ObjectToWorld, v.vertex);
                o.uv = v.texcoord;
                return o;
            }

            fixed4 frag (v2f i) : COLOR
            {
                float3 normal = normalize(i.worldNormal);
                float3 viewDir = normalize(UnityWorldSpaceViewDir(i.worldPos));
                float3 lightDir = normalize(UnityWorldSpaceLightDir(i.worldPos));
                float3 albedo = tex2D(_MainTex, i.uv) * _SpecColor;
                float nl = max(0.0, dot(normal, lightDir));
                float3 diffuse = albedo * _LightColor0 * nl;
                float3 specularDot = max(0.0, dot(reflect(-lightDir, normal), viewDir));
                float3 env = texCUBElod(_Cube, fixed4(reflect(-viewDir, normal), _Roughness * 6)).rgb;
                float lum = Luminance(albedo);
                float3 tinted = lum > 0 ? albedo / lum : float3(1, 1, 1);
                fixed4 c = fixed4(diffuse + pow(specularDot, 32.0f) + env * Tint(tinted), 1.0f);
                c.rgb += ShadeSH9(half4(normal, 1));
                return c;
            }
            ENDCG
        }
    }
}
