// Reflection-probe sampling: the glossy-environment query of the Standard
// path, over FacetGI.hlsl.
#ifndef UNITY_IMAGE_BASED_LIGHTING_INCLUDED
#define UNITY_IMAGE_BASED_LIGHTING_INCLUDED

#include "UnityCG.cginc"
#include "UnityStandardConfig.cginc"
#include "UnityStandardBRDF.cginc"
#include "FacetGI.hlsl"

struct Unity_GlossyEnvironmentData
{
    half roughness;  // perceptual roughness (1 - smoothness), not its square
    half3 reflUVW;   // the lookup direction, world space
};

Unity_GlossyEnvironmentData UnityGlossyEnvironmentSetup(half Smoothness, half3 worldViewDir, half3 Normal, half3 fresnel0)
{
    Unity_GlossyEnvironmentData g;
    g.roughness = SmoothnessToPerceptualRoughness(Smoothness);
    g.reflUVW = reflect(-worldViewDir, Normal);
    return g;
}

half perceptualRoughnessToMipmapLevel(half perceptualRoughness) { return FacetPerceptualRoughnessToMip(perceptualRoughness); }

// The probe comes as Unity passes it: UNITY_PASS_TEXCUBE(unity_SpecCube0),
// or UNITY_PASS_TEXCUBE_SAMPLER(unity_SpecCube1, unity_SpecCube0).
half3 Unity_GlossyEnvironment(UNITY_ARGS_TEXCUBE(tex), half4 hdr, Unity_GlossyEnvironmentData glossIn)
{
    half mip = perceptualRoughnessToMipmapLevel(glossIn.roughness);
    half4 rgbm = UNITY_SAMPLE_TEXCUBE_LOD(tex, glossIn.reflUVW, mip);
    return DecodeHDR(rgbm, hdr);
}

// The deprecated names of this file (UnityDeprecated.cginc).
#define INCLUDE_UNITY_IMAGE_BASED_LIGHTING_DEPRECATED
#include "UnityDeprecated.cginc"

#endif // UNITY_IMAGE_BASED_LIGHTING_INCLUDED
