// Helpers of the Standard shader: energy conservation, the metallic setup,
// premultiplied alpha, normal-map scaling and blending, SH per vertex/pixel
// and box projection. Aliases over FacetStandard.hlsl / FacetGI.hlsl.
#ifndef UNITY_STANDARD_UTILS_INCLUDED
#define UNITY_STANDARD_UTILS_INCLUDED

#include "UnityCG.cginc"
#include "UnityStandardConfig.cginc"
#include "FacetStandard.hlsl"
#include "FacetGI.hlsl"

half SpecularStrength(half3 specular) { return FacetSpecularStrength(specular); }

inline half3 EnergyConservationBetweenDiffuseAndSpecular(half3 albedo, half3 specColor, out half oneMinusReflectivity)
{
    return FacetEnergyConservationBetweenDiffuseAndSpecular(albedo, specColor, oneMinusReflectivity);
}

inline half OneMinusReflectivityFromMetallic(half metallic)
{
    return FacetOneMinusReflectivityFromMetallic(metallic, unity_ColorSpaceDielectricSpec);
}

inline half3 DiffuseAndSpecularFromMetallic(half3 albedo, half metallic, out half3 specColor, out half oneMinusReflectivity)
{
    return FacetDiffuseAndSpecularFromMetallic(albedo, metallic, unity_ColorSpaceDielectricSpec, specColor,
                                               oneMinusReflectivity);
}

// Under _ALPHAPREMULTIPLY_ON only the diffuse part fades with alpha.
inline half3 PreMultiplyAlpha(half3 diffColor, half alpha, half oneMinusReflectivity, out half outModifiedAlpha)
{
#if defined(_ALPHAPREMULTIPLY_ON)
    return FacetPreMultiplyAlpha(diffColor, alpha, oneMinusReflectivity, outModifiedAlpha, true);
#else
    return FacetPreMultiplyAlpha(diffColor, alpha, oneMinusReflectivity, outModifiedAlpha, false);
#endif
}

// lerp(1, x, t) for a scalar strength t.
half LerpOneTo(half b, half t) { return 1.0 - t + b * t; }
half3 LerpWhiteTo(half3 b, half t) { return (1.0 - t) + b * t; }

half3 UnpackScaleNormal(half4 packednormal, half bumpScale) { return FacetUnpackScaleNormal(packednormal, bumpScale); }

// "Whiteout" blend of two tangent-space normals: detail on top of base.
half3 BlendNormals(half3 n1, half3 n2) { return normalize(half3(n1.xy + n2.xy, n1.z * n2.z)); }

// Rows: tangent, binormal, normal (world space); the binormal's sign from
// tangent.w and the object's mirroring.
half3x3 CreateTangentToWorldPerVertex(half3 normal, half3 tangent, half tangentSign)
{
    half sign = tangentSign * unity_WorldTransformParams.w;
    half3 binormal = cross(normal, tangent) * sign;
    return half3x3(tangent, binormal, normal);
}

// SH: facet evaluates the full L2 per pixel, so the per-vertex part is the
// ambient passed through and the per-pixel part adds ShadeSH9.
half3 ShadeSHPerVertex(half3 normal, half3 ambient) { return ambient; }
half3 ShadeSHPerPixel(half3 normal, half3 ambient, float3 worldPos)
{
    return max(half3(0, 0, 0), ambient + ShadeSH9(half4(normal, 1.0)));
}

inline float3 BoxProjectedCubemapDirection(float3 worldRefl, float3 worldPos, float4 cubemapCenter, float4 boxMin,
                                           float4 boxMax)
{
    return FacetBoxProjectedDirection(worldRefl, worldPos, cubemapCenter, boxMin, boxMax);
}

#endif // UNITY_STANDARD_UTILS_INCLUDED
