// facet's indirect light for the Standard path: SH irradiance and the
// reflection probes unity_SpecCube0 (and 1, blended in) with roughness -> mip. UnityGlobalIllumination.cginc
// and UnityImageBasedLighting.cginc are thin aliases over these.
#ifndef FACET_GI_INCLUDED
#define FACET_GI_INCLUDED

#include "FacetCore.hlsl"

// Mips of the prefiltered probe from mirror (0) to fully rough.
#ifndef UNITY_SPECCUBE_LOD_STEPS
#define UNITY_SPECCUBE_LOD_STEPS 6
#endif

// The probe's mips were convolved for spec powers, not for GGX: r (1.7 - 0.7 r)
// bends the linear mapping towards the GGX lobe width (within 0.03 mip of
// the exact remap r (4 / (1 + 3 r^4))^(1/4)).
float FacetPerceptualRoughnessToMip(float perceptualRoughness)
{
    float r = perceptualRoughness * (1.7 - 0.7 * perceptualRoughness);
    return r * UNITY_SPECCUBE_LOD_STEPS;
}

// Prefiltered radiance from unity_SpecCube0 in direction `dir` for a
// perceptual roughness, decoded with `hdr` (DecodeHDR instructions).
float3 FacetGlossyEnvironment(float3 dir, float perceptualRoughness, float4 hdr)
{
    float mip = FacetPerceptualRoughnessToMip(perceptualRoughness);
    float4 rgbm = unity_SpecCube0.SampleLevel(samplerunity_SpecCube0, dir, mip);
    return FacetDecodeHDR(rgbm, hdr);
}

// The same from unity_SpecCube1, the probe blended in (sampled with
// unity_SpecCube0's sampler, as Unity's UNITY_PASS_TEXCUBE_SAMPLER does).
float3 FacetGlossyEnvironment1(float3 dir, float perceptualRoughness, float4 hdr)
{
    float mip = FacetPerceptualRoughnessToMip(perceptualRoughness);
    float4 rgbm = unity_SpecCube1.SampleLevel(samplerunity_SpecCube0, dir, mip);
    return FacetDecodeHDR(rgbm, hdr);
}

// Box projection: where the ray from worldPos along dir leaves the probe's
// box, seen from the probe's capture point. probePosition.w > 0 enables it.
float3 FacetBoxProjectedDirection(float3 dir, float3 worldPos, float4 probePosition, float4 boxMin, float4 boxMax)
{
    if (probePosition.w > 0.0) {
        float3 nrdir = normalize(dir);
        float3 rbmax = (boxMax.xyz - worldPos) / nrdir;
        float3 rbmin = (boxMin.xyz - worldPos) / nrdir;
        float3 rbminmax = (nrdir > 0.0f) ? rbmax : rbmin;
        float fa = min(min(rbminmax.x, rbminmax.y), rbminmax.z);
        worldPos -= probePosition.xyz;
        dir = worldPos + nrdir * fa;
    }
    return dir;
}

// The average environment radiance, used for reflections when glossy
// reflections are off: the SH constant term (facet has no separate
// "indirect specular colour" uniform).
float3 FacetAverageEnvironment() { return max(float3(unity_SHAr.w, unity_SHAg.w, unity_SHAb.w), 0.0); }

#endif // FACET_GI_INCLUDED
