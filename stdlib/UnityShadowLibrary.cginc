// Unity's shadow-sampling library over FacetShadow.hlsl: shadow-map lookups
// (UnitySampleShadowmap and the PCF forms), shadow fade, baked occlusion
// (shadow mask) and realtime/baked mixing. facet renders one light-space
// shadow map per directional or spot light (no cascades), a distance cube
// per point light (SHADOWS_CUBE), and no shadow mask (unity_ShadowMask is
// white).
#ifndef UNITY_BUILTIN_SHADOW_LIBRARY_INCLUDED
#define UNITY_BUILTIN_SHADOW_LIBRARY_INCLUDED

#include "HLSLSupport.cginc"
#include "UnityShaderVariables.cginc"
#include "FacetShadow.hlsl"

#ifndef unityShadowCoord
#define unityShadowCoord float
#define unityShadowCoord2 float2
#define unityShadowCoord3 float3
#define unityShadowCoord4 float4
#define unityShadowCoord4x4 float4x4
#endif
#define SHADOWMAPSAMPLER_AND_TEXELSIZE_DEFINED

#if defined(SHADOWS_CUBE)
// Visibility towards vec = world position - light position (FacetSampleShadowCube).
inline half UnitySampleShadowmap(float3 vec) { return FacetSampleShadowCube(vec); }
inline float SampleCubeDistance(float3 vec) { return texCUBElod(_ShadowMapTexture, float4(vec, 0.0)).r; }
#else
// Visibility at a projective shadow coordinate (unity_WorldToShadow space):
// 1 lit, _LightShadowData.x fully shadowed (FacetSampleShadow: 3x3 PCF when
// the light's shadows are soft).
inline fixed UnitySampleShadowmap(float4 shadowCoord) { return FacetSampleShadow(shadowCoord); }
#endif

// Receiver-plane depth bias (tilting the PCF kernel along the receiver) is
// off, as in Unity by default: zero.
float3 UnityGetReceiverPlaneDepthBias(float3 shadowCoord, float biasMultiply) { return float3(0, 0, 0); }
float3 UnityCombineShadowcoordComponents(float2 baseUV, float2 deltaUV, float depth, float3 receiverPlaneDepthBias)
{
    return float3(baseUV + deltaUV, depth + receiverPlaneDepthBias.z + dot(deltaUV, receiverPlaneDepthBias.xy));
}

#if !defined(SHADOWS_CUBE)
// Box-filtered comparisons over (2r+1)^2 texels around coord.xy at depth
// coord.z (coord already divided by w): the lit fraction, 0..1, without
// the shadow strength.
half FacetShadowPCF(float4 coord, float3 receiverPlaneDepthBias, int radius)
{
    float2 texel = _ShadowMapTexture_TexelSize.xy;
    float lit = 0.0;
    for (int dy = -radius; dy <= radius; ++dy)
        for (int dx = -radius; dx <= radius; ++dx) {
            float3 c = UnityCombineShadowcoordComponents(coord.xy, float2(dx, dy) * texel, coord.z, receiverPlaneDepthBias);
            lit += FacetShadowCompare(c.xy, c.z);
        }
    float n = 2.0 * radius + 1.0;
    return lit / (n * n);
}
half UnitySampleShadowmap_PCF3x3(float4 coord, float3 receiverPlaneDepthBias) { return FacetShadowPCF(coord, receiverPlaneDepthBias, 1); }
half UnitySampleShadowmap_PCF5x5(float4 coord, float3 receiverPlaneDepthBias) { return FacetShadowPCF(coord, receiverPlaneDepthBias, 2); }
half UnitySampleShadowmap_PCF7x7(float4 coord, float3 receiverPlaneDepthBias) { return FacetShadowPCF(coord, receiverPlaneDepthBias, 3); }
half UnitySampleShadowmap_PCF3x3NoHardwareSupport(float4 coord, float3 receiverPlaneDepthBias) { return FacetShadowPCF(coord, receiverPlaneDepthBias, 1); }
half UnitySampleShadowmap_PCF3x3Tent(float4 coord, float3 receiverPlaneDepthBias) { return FacetShadowPCF(coord, receiverPlaneDepthBias, 1); }
half UnitySampleShadowmap_PCF5x5Tent(float4 coord, float3 receiverPlaneDepthBias) { return FacetShadowPCF(coord, receiverPlaneDepthBias, 2); }
half UnitySampleShadowmap_PCF7x7Tent(float4 coord, float3 receiverPlaneDepthBias) { return FacetShadowPCF(coord, receiverPlaneDepthBias, 3); }
half UnitySampleShadowmap_PCF3x3Gaussian(float4 coord, float3 receiverPlaneDepthBias) { return FacetShadowPCF(coord, receiverPlaneDepthBias, 1); }
half UnitySampleShadowmap_PCF5x5Gaussian(float4 coord, float3 receiverPlaneDepthBias) { return FacetShadowPCF(coord, receiverPlaneDepthBias, 2); }
#endif

// ---- baked occlusion (shadow mask) ------------------------------------------------
// SHADOWS_SHADOWMASK: the light's channel (unity_OcclusionMaskSelector) of
// unity_ShadowMask at the lightmap uv; otherwise 1.
fixed UnitySampleBakedOcclusion(float2 lightmapUV, float3 worldPos)
{
#if defined(SHADOWS_SHADOWMASK)
    return saturate(dot(tex2D(unity_ShadowMask, lightmapUV.xy), unity_OcclusionMaskSelector));
#else
    return 1.0;
#endif
}
fixed4 UnityGetRawBakedOcclusions(float2 lightmapUV, float3 worldPos)
{
#if defined(SHADOWS_SHADOWMASK) && defined(LIGHTMAP_ON)
    return tex2D(unity_ShadowMask, lightmapUV.xy);
#elif defined(SHADOWS_SHADOWMASK)
    return unity_ProbesOcclusion;
#else
    return fixed4(1, 1, 1, 1);
#endif
}

// Realtime shadow faded out with distance (fade 0 near .. 1 far) towards
// the baked one; with LIGHTMAP_SHADOW_MIXING the darker of the two.
// Without realtime shadows the baked value (0 for subtractive lightmaps,
// whose direct light is baked).
half UnityMixRealtimeAndBakedShadows(half realtimeShadowAttenuation, half bakedShadowAttenuation, half fade)
{
#if !defined(SHADOWS_DEPTH) && !defined(SHADOWS_SCREEN) && !defined(SHADOWS_CUBE)
#if defined(LIGHTMAP_ON) && defined(LIGHTMAP_SHADOW_MIXING) && !defined(SHADOWS_SHADOWMASK)
    return 0.0;
#else
    return bakedShadowAttenuation;
#endif
#elif defined(LIGHTMAP_SHADOW_MIXING)
    return min(saturate(realtimeShadowAttenuation + fade), bakedShadowAttenuation);
#else
    return lerp(realtimeShadowAttenuation, bakedShadowAttenuation, fade);
#endif
}

// Shadow fade: distance from the fade centre (sphere fade, .w = 1) or view
// depth z, mapped through _LightShadowData.zw (zero in facet: no fade).
float UnityComputeShadowFadeDistance(float3 wpos, float z)
{
    return lerp(z, distance(wpos, unity_ShadowFadeCenterAndType.xyz), unity_ShadowFadeCenterAndType.w);
}
half UnityComputeShadowFade(float fadeDist) { return saturate(fadeDist * _LightShadowData.z + _LightShadowData.w); }

#endif // UNITY_BUILTIN_SHADOW_LIBRARY_INCLUDED
