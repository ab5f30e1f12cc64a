// Old Standard BRDF and IBL helpers Unity keeps for source compatibility:
// UnityStandardBRDF.cginc includes this file with
// INCLUDE_UNITY_STANDARD_BRDF_DEPRECATED, UnityImageBasedLighting.cginc with
// INCLUDE_UNITY_IMAGE_BASED_LIGHTING_DEPRECATED (each part needs its file's names).
#ifdef INCLUDE_UNITY_STANDARD_BRDF_DEPRECATED
#ifndef FACET_UNITY_DEPRECATED_BRDF
#define FACET_UNITY_DEPRECATED_BRDF

// Schlick's Fresnel weight (1 - cosA)^5 softened by roughness (Lazarov), or
// with the grazing value capped at max(f0, roughness) (Lagarde).
inline half3 LazarovFresnelTerm(half3 f0, half roughness, half cosA)
{
    half t = Pow5(1 - cosA) / (4 - 3 * roughness);
    return f0 + (1 - f0) * t;
}
inline half3 SebLagardeFresnelTerm(half3 f0, half roughness, half cosA)
{
    return f0 + (max(f0, roughness) - f0) * Pow5(1 - cosA);
}
// Cook-Torrance geometric term over NL*NV.
inline half CookTorranceVisibilityTerm(half NdotL, half NdotV, half NdotH, half VdotH)
{
    VdotH += 1e-5;
    half g = min(1.0, 2.0 * NdotH * min(NdotV, NdotL) / VdotH);
    return g / (NdotL * NdotV + 1e-4);
}
inline half KelemenVisibilityTerm(half LdotH) { return 1.0 / (LdotH * LdotH); }
// Kelemen with Schlick's k = a * sqrt(2/pi).
inline half ModifiedKelemenVisibilityTerm(half LdotH, half perceptualRoughness)
{
    half k = PerceptualRoughnessToRoughness(perceptualRoughness) * 0.797884560802865;
    half gH = LdotH * (1 - k) + k;
    return 1.0 / (gH * gH);
}
// Smith-Schlick with Karis's k = a / 2.
inline half SmithGGXVisibilityTerm(half NdotL, half NdotV, half perceptualRoughness)
{
    return SmithVisibilityTerm(NdotL, NdotV, PerceptualRoughnessToRoughness(perceptualRoughness) / 2);
}
inline half ImplicitVisibilityTerm() { return 1; }
// Normalised Blinn-Phong as a reflectance: (n + 2) / (8 pi) * NH^n.
inline half RDFBlinnPhongNormalizedTerm(half NdotH, half n) { return pow(NdotH, n) * (n + 2.0) / (8.0 * UNITY_PI); }
inline half3 DecodeHDR_NoLinearSupportInSM2(half4 data, half4 decodeInstructions)
{
#if defined(UNITY_COLORSPACE_GAMMA) && (SHADER_TARGET < 30)
    return (data.a * decodeInstructions.x) * data.rgb;
#else
    return DecodeHDR(data, decodeInstructions);
#endif
}
inline half DotClamped(half3 a, half3 b) { return max(0.0, dot(a, b)); }
inline half LambertTerm(half3 normal, half3 lightDir) { return DotClamped(normal, lightDir); }
inline half BlinnTerm(half3 normal, half3 halfDir) { return DotClamped(normal, halfDir); }
half RoughnessToSpecPower(half roughness) { return PerceptualRoughnessToSpecPower(roughness); }
#ifdef UNITY_COLORSPACE_GAMMA
#define unity_LightGammaCorrectionConsts_PIDiv4 ((UNITY_PI / 4) * (UNITY_PI / 4))
#define unity_LightGammaCorrectionConsts_HalfDivPI ((0.5 / UNITY_PI) * (0.5 / UNITY_PI))
#define unity_LightGammaCorrectionConsts_8 (8 * 8)
#define unity_LightGammaCorrectionConsts_SqrtHalfPI (2 / UNITY_PI)
#else
#define unity_LightGammaCorrectionConsts_PIDiv4 (UNITY_PI / 4)
#define unity_LightGammaCorrectionConsts_HalfDivPI (0.5 / UNITY_PI)
#define unity_LightGammaCorrectionConsts_8 (8)
#define unity_LightGammaCorrectionConsts_SqrtHalfPI (0.79788)
#endif

#endif // FACET_UNITY_DEPRECATED_BRDF
#endif // INCLUDE_UNITY_STANDARD_BRDF_DEPRECATED

#ifdef INCLUDE_UNITY_IMAGE_BASED_LIGHTING_DEPRECATED
#ifndef FACET_UNITY_DEPRECATED_IBL
#define FACET_UNITY_DEPRECATED_IBL
// The old form: environment along the normal at a perceptual roughness.
half3 Unity_GlossyEnvironment(UNITY_ARGS_TEXCUBE(tex), half4 hdr, half3 worldNormal, half perceptualRoughness)
{
    Unity_GlossyEnvironmentData g;
    g.roughness = perceptualRoughness;
    g.reflUVW = worldNormal;
    return Unity_GlossyEnvironment(UNITY_PASS_TEXCUBE(tex), hdr, g);
}
#endif // FACET_UNITY_DEPRECATED_IBL
#endif // INCLUDE_UNITY_IMAGE_BASED_LIGHTING_DEPRECATED
