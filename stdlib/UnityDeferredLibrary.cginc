// The deferred light pass helpers of Unity's built-in pipeline: the light
// volume's vertex program (vert_deferred) and UnityDeferredCalculateLightParams
// (world position from the camera depth, light direction, attenuation with
// shadows). facet's deferred path (docs/rendering.md) draws each light as a
// full-screen quad with _LightAsQuad = 1, the view ray in its normal. The
// attenuation and shadows are the forward path's own (FacetLight.hlsl,
// AutoLight.cginc), so that both paths light a surface the same: the
// light's falloff is facet's analytic one (not Unity's _LightTextureB0
// ramp, declared, unused); POINT_COOKIE has no cube cookie; _LightColor,
// _LightDir and _LightPos are set with the light's other values.
#ifndef UNITY_DEFERRED_LIBRARY_INCLUDED
#define UNITY_DEFERRED_LIBRARY_INCLUDED

#include "UnityCG.cginc"
#include "FacetLight.hlsl"
#include "UnityShadowLibrary.cginc"

struct unity_v2f_deferred {
    float4 pos : SV_POSITION;
    float4 uv : TEXCOORD0;    // screen position (xy / w)
    float3 ray : TEXCOORD1;   // view ray towards the far plane (or the quad's normal)
};

float _LightAsQuad;           // 1 for a full-screen quad: the ray comes in the normal

unity_v2f_deferred vert_deferred(float4 vertex : POSITION, float3 normal : NORMAL)
{
    unity_v2f_deferred o;
    o.pos = UnityObjectToClipPos(vertex);
    o.uv = ComputeScreenPos(o.pos);
    o.ray = lerp(UnityObjectToViewPos(vertex) * float3(-1, -1, 1), normal, _LightAsQuad);
    return o;
}

UNITY_DECLARE_DEPTH_TEXTURE(_CameraDepthTexture);
float4 _LightDir;             // directional: the light's direction (from the light)
float4 _LightPos;             // xyz = position, w = 1 / range^2
float4 _LightColor;
float4 unity_LightmapFade;
sampler2D _LightTextureB0;
#if defined(SHADOWS_SHADOWMASK)
sampler2D _CameraGBufferTexture4;
#endif

half UnityDeferredSampleShadowMask(float2 uv)
{
#if defined(SHADOWS_SHADOWMASK)
    return saturate(dot(tex2D(_CameraGBufferTexture4, uv), unity_OcclusionMaskSelector));
#else
    return 1.0;
#endif
}

// `vec`: world position (spot, directional) or light-to-point vector (point).
half UnityDeferredSampleRealtimeShadow(half fade, float3 vec, float2 uv)
{
#if defined(SHADOWS_CUBE)
    return FacetSampleShadowCube(vec);
#elif defined(SHADOWS_SCREEN)
    return FacetScreenShadow(float4(uv, 0.0, 1.0));  // the screen-space pass's mask
#elif defined(SHADOWS_DEPTH)
    return FacetShadowAtWorld(vec);
#else
    return 1.0;
#endif
}

half UnityDeferredComputeShadow(float3 vec, float fadeDist, float2 uv)
{
    half fade = UnityComputeShadowFade(fadeDist);
    return UnityMixRealtimeAndBakedShadows(UnityDeferredSampleRealtimeShadow(fade, vec, uv),
                                           UnityDeferredSampleShadowMask(uv), fade);
}

void UnityDeferredCalculateLightParams(unity_v2f_deferred i, out float3 outWorldPos, out float2 outUV,
                                       out half3 outLightDir, out float outAtten, out float outFadeDist)
{
    float3 ray = i.ray * (_ProjectionParams.z / i.ray.z);
    float2 uv = i.uv.xy / i.uv.w;
    float depth01 = Linear01Depth(SAMPLE_DEPTH_TEXTURE(_CameraDepthTexture, uv));
    float4 viewPos = float4(ray * depth01, 1);
    float3 wpos = mul(unity_CameraToWorld, viewPos).xyz;
    float fadeDist = UnityComputeShadowFadeDistance(wpos, viewPos.z);
#if defined(DIRECTIONAL) || defined(DIRECTIONAL_COOKIE)
    half3 lightDir = -_LightDir.xyz;
    float3 shadowVec = wpos;
#else
    half3 lightDir = normalize(_LightPos.xyz - wpos);
#if defined(SHADOWS_CUBE)
    float3 shadowVec = wpos - _LightPos.xyz;
#else
    float3 shadowVec = wpos;
#endif
#endif
    outWorldPos = wpos;
    outUV = uv;
    outLightDir = lightDir;
    outAtten = FacetLightAttenuation(wpos) * UnityDeferredComputeShadow(shadowVec, fadeDist, uv);
    outFadeDist = fadeDist;
}

#endif // UNITY_DEFERRED_LIBRARY_INCLUDED
