// The screen-space shadow pass (the runtime draws it once a shadowed
// directional light, before the camera's passes): the world position of
// every pixel of the camera depth texture, rebuilt through the inverse
// projection, looked up in the light's shadow map (the cascade its distance falls
// in) with FacetShadowAtWorld, the same function a receiver without the
// pass would call. The R8 result is the mask SHADOWS_SCREEN receivers read
// (AutoLight.cginc, FacetScreenShadow). Named as Unity's.
Shader "Hidden/Internal-ScreenSpaceShadows" {
    SubShader {
        Pass {
            ZWrite Off ZTest Always Cull Off

            CGPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            #include "UnityCG.cginc"
            #include "UnityShadowLibrary.cginc"

            UNITY_DECLARE_DEPTH_TEXTURE(_CameraDepthTexture);

            struct v2f {
                float4 pos : SV_POSITION;
                float4 screen : TEXCOORD0;
            };

            v2f vert(float4 vertex : POSITION) {
                v2f o;
                o.pos = UnityObjectToClipPos(vertex);
                o.screen = ComputeScreenPos(o.pos);
                return o;
            }

            // The pixel's position, back through the camera's projection
            // (perspective or orthographic) from its clip position and depth.
            fixed4 frag(v2f i) : SV_Target {
                float2 uv = i.screen.xy / i.screen.w;
                float depth = SAMPLE_DEPTH_TEXTURE(_CameraDepthTexture, uv);
                float4 view = mul(unity_CameraInvProjection, float4(uv * 2.0 - 1.0, depth, 1.0));
                float3 worldPos = mul(unity_MatrixInvV, float4(view.xyz / view.w, 1.0)).xyz;
                return FacetShadowAtWorld(worldPos);
            }
            ENDCG
        }
    }
    Fallback Off
}
