// UnityGlobalIllumination: fills the UnityGI that lighting functions get.
// Direct light: data.light with its colour times data.atten. Indirect
// diffuse: SH irradiance (ShadeSH9) plus data.ambient, times occlusion.
// Indirect specular (the overloads with Unity_GlossyEnvironmentData):
// unity_SpecCube0 at the roughness's mip (box-projected when the probe says
// so), decoded with data.probeHDR[0], times occlusion. facet has no
// lightmaps and one reflection probe: lightmap keywords change nothing.
#ifndef UNITY_GLOBAL_ILLUMINATION_INCLUDED
#define UNITY_GLOBAL_ILLUMINATION_INCLUDED

#include "UnityImageBasedLighting.cginc"
#include "UnityStandardUtils.cginc"
#include "UnityLightingCommon.cginc"

inline void ResetUnityLight(out UnityLight outLight)
{
    outLight.color = half3(0, 0, 0);
    outLight.dir = half3(0, 1, 0);
    outLight.ndotl = 0;
}

inline void ResetUnityGI(out UnityGI outGI)
{
    ResetUnityLight(outGI.light);
    outGI.indirect.diffuse = 0;
    outGI.indirect.specular = 0;
}

inline UnityGI UnityGI_Base(UnityGIInput data, half occlusion, half3 normalWorld)
{
    UnityGI o_gi;
    ResetUnityGI(o_gi);
    o_gi.light = data.light;
    o_gi.light.color *= data.atten;
#if UNITY_SHOULD_SAMPLE_SH
    o_gi.indirect.diffuse = ShadeSHPerPixel(normalWorld, data.ambient, data.worldPos);
#else
    o_gi.indirect.diffuse = data.ambient;
#endif
    o_gi.indirect.diffuse *= occlusion;
    return o_gi;
}

inline half3 UnityGI_IndirectSpecular(UnityGIInput data, half occlusion, Unity_GlossyEnvironmentData glossIn)
{
    half3 specular;
#ifdef _GLOSSYREFLECTIONS_OFF
    specular = unity_IndirectSpecColor.rgb;
#else
    half3 reflected = glossIn.reflUVW;
#if UNITY_SPECCUBE_BOX_PROJECTION
    glossIn.reflUVW = BoxProjectedCubemapDirection(reflected, data.worldPos, data.probePosition[0],
                                                   data.boxMin[0], data.boxMax[0]);
#endif
    specular = FacetGlossyEnvironment(glossIn.reflUVW, glossIn.roughness, data.probeHDR[0]);
#if UNITY_SPECCUBE_BLENDING
    // boxMin[0].w is probe 0's weight; below 1 the second probe (or the
    // environment) takes the rest, as Unity's blending does.
    const float kBlendFactor = 0.99999;
    float blendLerp = data.boxMin[0].w;
    if (blendLerp < kBlendFactor) {
        float3 direction1 = reflected;
#if UNITY_SPECCUBE_BOX_PROJECTION
        direction1 = BoxProjectedCubemapDirection(reflected, data.worldPos, data.probePosition[1], data.boxMin[1],
                                                  data.boxMax[1]);
#endif
        half3 specular1 = FacetGlossyEnvironment1(direction1, glossIn.roughness, data.probeHDR[1]);
        specular = lerp(specular1, specular, blendLerp);
    }
#endif
#endif
    return specular * occlusion;
}

inline UnityGI UnityGlobalIllumination(UnityGIInput data, half occlusion, half3 normalWorld)
{
    return UnityGI_Base(data, occlusion, normalWorld);
}

inline UnityGI UnityGlobalIllumination(UnityGIInput data, half occlusion, half3 normalWorld,
                                       Unity_GlossyEnvironmentData glossIn)
{
    UnityGI o_gi = UnityGI_Base(data, occlusion, normalWorld);
    o_gi.indirect.specular = UnityGI_IndirectSpecular(data, occlusion, glossIn);
    return o_gi;
}

// The older form with the reflection inputs spelled out.
inline UnityGI UnityGlobalIllumination(UnityGIInput data, half occlusion, half smoothness, half3 normalWorld,
                                       bool reflections)
{
    if (reflections) {
        Unity_GlossyEnvironmentData g = UnityGlossyEnvironmentSetup(smoothness, data.worldViewDir, normalWorld, half3(0, 0, 0));
        return UnityGlobalIllumination(data, occlusion, normalWorld, g);
    }
    return UnityGlobalIllumination(data, occlusion, normalWorld);
}

// Fills data.probe* from the built-in probe uniforms (what the generated
// surface-shader passes and the Standard core do before calling the above).
inline void FacetSetupGIInputProbes(inout UnityGIInput data)
{
    data.probeHDR[0] = unity_SpecCube0_HDR;
    data.probeHDR[1] = unity_SpecCube1_HDR;
    data.boxMin[0] = unity_SpecCube0_BoxMin;
    data.boxMax[0] = unity_SpecCube0_BoxMax;
    data.probePosition[0] = unity_SpecCube0_ProbePosition;
    data.boxMin[1] = unity_SpecCube1_BoxMin;
    data.boxMax[1] = unity_SpecCube1_BoxMax;
    data.probePosition[1] = unity_SpecCube1_ProbePosition;
}

#endif // UNITY_GLOBAL_ILLUMINATION_INCLUDED
