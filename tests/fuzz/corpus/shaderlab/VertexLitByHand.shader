// The lighting of FixedFunctionVertexLit.shader written by hand as a
// vertex/fragment program: Unity's vertex-lit lights (unity_LightPosition
// and the rest, in view space, up to 8), the diffuse through UnityCG's
// ShadeVertexLightsFull, a Blinn-Phong specular added after the texture.
// The golden tests render both and compare them.
Shader "Examples/VertexLitByHand" {
    Properties {
        _Color ("Main Color", Color) = (1, 1, 1, 1)
        _SpecColor ("Specular Color", Color) = (0.5, 0.5, 0.5, 1)
        _Emission ("Emissive Color", Color) = (0, 0, 0, 0)
        _Shininess ("Shininess", Range(0.01, 1)) = 0.4
        _MainTex ("Base (RGB)", 2D) = "white" {}
    }
    SubShader {
        Tags { "RenderType" = "Opaque" }
        Pass {
            Tags { "LightMode" = "Vertex" }
            CGPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            #pragma multi_compile_fog
            #include "UnityCG.cginc"

            float4 _Color;
            float4 _SpecColor;
            float4 _Emission;
            float _Shininess;
            sampler2D _MainTex;
            float4 _MainTex_ST;

            struct v2f {
                float4 pos : SV_POSITION;
                float3 diffuse : COLOR0;
                float3 specular : COLOR1;
                float2 uv : TEXCOORD0;
                UNITY_FOG_COORDS(1)
            };

            // Blinn-Phong from every vertex light, only where it faces the surface.
            float3 VertexSpecular(float3 viewPos, float3 viewNormal) {
                float3 eye = normalize(-viewPos);
                float3 total = 0;
                for (int k = 0; k < 8; k++) {
                    float3 l = unity_LightPosition[k].xyz - viewPos * unity_LightPosition[k].w;
                    float d2 = max(dot(l, l), 1e-6);
                    l *= rsqrt(d2);
                    float cone = saturate((max(0.0, dot(l, unity_SpotDirection[k].xyz)) - unity_LightAtten[k].x) *
                                          unity_LightAtten[k].y);
                    float falloff = cone / (1.0 + unity_LightAtten[k].z * d2);
                    // A select rather than an if around pow: lavapipe (Mesa 22.3)
                    // crashes compiling the branch form of this loop.
                    float faces = dot(viewNormal, l) > 0.0 ? 1.0 : 0.0;
                    float facing = max(0.0, dot(viewNormal, normalize(l + eye)));
                    total += unity_LightColor[k].rgb * (faces * pow(facing, max(_Shininess * 128.0, 0.0001)) * falloff);
                }
                return total;
            }

            v2f vert(appdata_base v) {
                v2f o;
                o.pos = UnityObjectToClipPos(v.vertex);
                o.uv = TRANSFORM_TEX(v.texcoord, _MainTex);
                o.diffuse = saturate(_Emission.rgb + _Color.rgb * ShadeVertexLightsFull(v.vertex, v.normal, 8, true));
                float3 viewNormal = normalize(mul((float3x3)UNITY_MATRIX_IT_MV, v.normal));
                o.specular = saturate(VertexSpecular(UnityObjectToViewPos(v.vertex.xyz), viewNormal) * _SpecColor.rgb);
                UNITY_TRANSFER_FOG(o, o.pos);
                return o;
            }

            fixed4 frag(v2f i) : SV_Target {
                fixed4 tex = tex2D(_MainTex, i.uv);
                fixed4 c = fixed4(saturate(saturate(2.0 * tex.rgb * i.diffuse) + i.specular), tex.a * _Color.a);
                UNITY_APPLY_FOG(i.fogCoord, c);
                return c;
            }
            ENDCG
        }
    }
}
