// The camera's background when a scene has an environment (camera "clear":
// "sky"): the environment itself, mip 0 of the reflection cube every object
// samples as unity_SpecCube0, so what shows behind an object is exactly what
// a mirror-smooth object reflects. Drawn by the runtime on a full-screen
// quad before the scene.
Shader "Hidden/Facet/EnvironmentSky" {
    SubShader {
        Cull Off ZWrite Off ZTest Always
        Pass {
            CGPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            #include "UnityCG.cginc"

            struct v2f {
                float4 pos : SV_POSITION;
                float2 ndc : TEXCOORD0;
            };

            // The runtime's blit matrices make the quad cover the screen.
            v2f vert(appdata_img v) {
                v2f o;
                o.pos = UnityObjectToClipPos(v.vertex);
                o.ndc = o.pos.xy / o.pos.w;
                return o;
            }

            float4 frag(v2f i) : SV_Target {
                // The view ray through this pixel, as ProceduralSky.shader finds it.
                float4 ray = mul(unity_CameraInvProjection, float4(i.ndc, 1.0, 1.0));
                float3 view = unity_OrthoParams.w > 0.5 ? float3(0.0, 0.0, -1.0) : ray.xyz / ray.w;
                float3 dir = normalize(mul((float3x3)unity_CameraToWorld, float3(view.xy, -view.z)));
                half4 texel = UNITY_SAMPLE_TEXCUBE_LOD(unity_SpecCube0, dir, 0);
                return float4(DecodeHDR(texel, unity_SpecCube0_HDR), 1.0);
            }
            ENDCG
        }
    }
}
