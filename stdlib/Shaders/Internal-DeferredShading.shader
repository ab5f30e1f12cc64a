// The light pass of the deferred path (camera "rendering_path": "deferred"):
// the runtime draws it once a light, over the whole screen, adding what the
// light gives each pixel of the G-buffer into the light buffer. The surface
// comes from the G-buffer (UnityGBuffer.cginc), the position from the depth,
// the light's attenuation and shadows from UnityDeferredLibrary.cginc, and
// the lighting from UNITY_BRDF_PBS, the same function the Standard shader's
// forward passes call, with no indirect light (the G-buffer pass added it).
// Named as Unity's, whose deferred light shader is replaced the same way.
Shader "Hidden/Internal-DeferredShading" {
    Properties {
        _LightTexture0 ("", any) = "" {}
        _ShadowMapTexture ("", any) = "" {}
        // One One adds into the HDR light buffer (facet's, always); an LDR
        // buffer (exp2-encoded) would take DstColor Zero.
        _SrcBlend ("", Float) = 1
        _DstBlend ("", Float) = 1
    }
    SubShader {
        Pass {
            ZWrite Off ZTest Always Cull Off
            Blend [_SrcBlend] [_DstBlend]

            CGPROGRAM
            #pragma target 3.0
            #pragma vertex vert_deferred
            #pragma fragment frag
            #pragma multi_compile_lightpass
            #pragma multi_compile ___ UNITY_HDR_ON
            #pragma exclude_renderers nomrt

            #include "UnityCG.cginc"
            #include "UnityDeferredLibrary.cginc"
            #include "UnityPBSLighting.cginc"
            #include "UnityStandardUtils.cginc"
            #include "UnityGBuffer.cginc"

            sampler2D _CameraGBufferTexture0;
            sampler2D _CameraGBufferTexture1;
            sampler2D _CameraGBufferTexture2;

            half4 frag(unity_v2f_deferred i) : SV_Target {
                float3 worldPos;
                float2 uv;
                float atten, fadeDist;
                UnityLight light;
                UNITY_INITIALIZE_OUTPUT(UnityLight, light);
                UnityDeferredCalculateLightParams(i, worldPos, uv, light.dir, atten, fadeDist);
                light.color = _LightColor.rgb * atten;

                UnityStandardData surface = UnityStandardDataFromGbuffer(tex2D(_CameraGBufferTexture0, uv),
                                                                         tex2D(_CameraGBufferTexture1, uv),
                                                                         tex2D(_CameraGBufferTexture2, uv));
                float3 toEye = normalize(_WorldSpaceCameraPos - worldPos);
                half oneMinusReflectivity = 1 - SpecularStrength(surface.specularColor);
                UnityIndirect none;
                none.diffuse = 0;
                none.specular = 0;
                half4 lit = UNITY_BRDF_PBS(surface.diffuseColor, surface.specularColor, oneMinusReflectivity,
                                           surface.smoothness, surface.normalWorld, toEye, light, none);
            #ifdef UNITY_HDR_ON
                return lit;
            #else
                // The LDR light buffer holds exp2(-light): lights multiply into it.
                return exp2(-lit);
            #endif
            }
            ENDCG
        }
    }
    Fallback Off
}
