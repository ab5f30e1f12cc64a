// The Standard shader's BRDF terms and its three tiers under Unity's names,
// as aliases over FacetStandard.hlsl. BRDFn_Unity_PBS(diffColor, specColor,
// oneMinusReflectivity, smoothness, normal, viewDir, light, gi) returns the
// colour of one light plus the indirect terms (alpha 1).
#ifndef UNITY_STANDARD_BRDF_INCLUDED
#define UNITY_STANDARD_BRDF_INCLUDED

#include "UnityCG.cginc"
#include "UnityStandardConfig.cginc"
#include "UnityLightingCommon.cginc"
#include "FacetStandard.hlsl"

half4 Pow4(half4 x) { return x * x * x * x; }
half3 Pow4(half3 x) { return FacetStdPow4(x); }
half2 Pow4(half2 x) { return FacetStdPow4(x); }
half Pow4(half x) { return FacetStdPow4(x); }
half4 Pow5(half4 x) { return x * x * x * x * x; }
half3 Pow5(half3 x) { return FacetStdPow5(x); }
half2 Pow5(half2 x) { return FacetStdPow5(x); }
half Pow5(half x) { return FacetStdPow5(x); }

inline float3 Unity_SafeNormalize(float3 inVec) { return FacetStdSafeNormalize(inVec); }

float SmoothnessToPerceptualRoughness(float smoothness) { return FacetSmoothnessToPerceptualRoughness(smoothness); }
float SmoothnessToRoughness(float smoothness) { return FacetSmoothnessToRoughness(smoothness); }
float PerceptualRoughnessToRoughness(float perceptualRoughness)
{
    return FacetPerceptualRoughnessToRoughness(perceptualRoughness);
}
half RoughnessToPerceptualRoughness(half roughness) { return FacetRoughnessToPerceptualRoughness(roughness); }

inline half3 FresnelTerm(half3 f0, half cosA) { return FacetStdFresnelTerm(f0, cosA); }
inline half3 FresnelLerp(half3 f0, half3 f90, half cosA) { return FacetStdFresnelLerp(f0, f90, cosA); }
inline half3 FresnelLerpFast(half3 f0, half3 f90, half cosA) { return FacetStdFresnelLerpFast(f0, f90, cosA); }

half DisneyDiffuse(half NdotV, half NdotL, half LdotH, half perceptualRoughness)
{
    return FacetStdDisneyDiffuse(NdotV, NdotL, LdotH, perceptualRoughness);
}

inline half SmithVisibilityTerm(half NdotL, half NdotV, half k) { return FacetStdSmithVisibilityTerm(NdotL, NdotV, k); }
inline half SmithBeckmannVisibilityTerm(float NdotL, float NdotV, float roughness)
{
    return FacetStdSmithBeckmannVisibilityTerm(NdotL, NdotV, roughness);
}
inline float SmithJointGGXVisibilityTerm(float NdotL, float NdotV, float roughness)
{
    return FacetStdSmithJointGGXVisibilityTerm(NdotL, NdotV, roughness);
}
inline float GGXTerm(float NdotH, float roughness) { return FacetStdGGXTerm(NdotH, roughness); }
inline half PerceptualRoughnessToSpecPower(half perceptualRoughness)
{
    return FacetStdPerceptualRoughnessToSpecPower(perceptualRoughness);
}
inline half NDFBlinnPhongNormalizedTerm(half NdotH, half n) { return FacetStdNDFBlinnPhongNormalizedTerm(NdotH, n); }

half4 BRDF1_Unity_PBS(half3 diffColor, half3 specColor, half oneMinusReflectivity, half smoothness, float3 normal,
                      float3 viewDir, UnityLight light, UnityIndirect gi)
{
    return FacetStandardBRDF1(diffColor, specColor, oneMinusReflectivity, smoothness, normal, viewDir, light.dir,
                              light.color, gi.diffuse, gi.specular);
}
half4 BRDF2_Unity_PBS(half3 diffColor, half3 specColor, half oneMinusReflectivity, half smoothness, float3 normal,
                      float3 viewDir, UnityLight light, UnityIndirect gi)
{
    return FacetStandardBRDF2(diffColor, specColor, oneMinusReflectivity, smoothness, normal, viewDir, light.dir,
                              light.color, gi.diffuse, gi.specular);
}
half4 BRDF3_Unity_PBS(half3 diffColor, half3 specColor, half oneMinusReflectivity, half smoothness, float3 normal,
                      float3 viewDir, UnityLight light, UnityIndirect gi)
{
    return FacetStandardBRDF3(diffColor, specColor, oneMinusReflectivity, smoothness, normal, viewDir, light.dir,
                              light.color, gi.diffuse, gi.specular);
}

// The deprecated names of this file (UnityDeprecated.cginc).
#define INCLUDE_UNITY_STANDARD_BRDF_DEPRECATED
#include "UnityDeprecated.cginc"

#endif // UNITY_STANDARD_BRDF_INCLUDED
