// facet's Standard lighting: the three quality tiers of Unity's Standard
// shader (BRDF1 = Disney diffuse + GGX microfacet specular, BRDF2 =
// "minimalist" Cook-Torrance, BRDF3 = normalized Phong in R.L), the
// metallic/specular setups and the helpers they share. UnityStandardBRDF.cginc
// and UnityStandardUtils.cginc are thin aliases over these. Unity's
// conventions are kept on purpose: diffuse is not divided by pi and specular
// is multiplied by pi (so a white Lambert surface lit head-on by a light of
// colour 1 returns 1), and the clamps below are Unity's so that the numbers
// match. Formulas, ranges and cost: docs/stdlib.md and docs/lighting-models.md;
// CPU twins: reference/include/facet/reference/unity_standard.h.
//
// Switches read here: UNITY_COLORSPACE_GAMMA (gamma-space project),
// UNITY_BRDF_GGX (0: normalized Blinn-Phong NDF in BRDF1/2), SHADER_API_MOBILE
// (fp16 overflow guards in BRDF2), _SPECULARHIGHLIGHTS_OFF (no direct
// specular), UNITY_CONSERVE_ENERGY(_MONOCHROME) (see the setups).
#ifndef FACET_STANDARD_INCLUDED
#define FACET_STANDARD_INCLUDED

#ifndef UNITY_BRDF_GGX
#define UNITY_BRDF_GGX 1
#endif
#ifndef UNITY_CONSERVE_ENERGY
#define UNITY_CONSERVE_ENERGY 1
#endif
#ifndef UNITY_CONSERVE_ENERGY_MONOCHROME
#define UNITY_CONSERVE_ENERGY_MONOCHROME 1
#endif

#define FACET_STD_INV_PI 0.31830988618379067

// ---- small helpers ------------------------------------------------------------
// Powers by multiplication: as cheap as pow() and no NaN for a negative base.
float FacetStdPow4(float x) { return x * x * x * x; }
float2 FacetStdPow4(float2 x) { return x * x * x * x; }
float3 FacetStdPow4(float3 x) { return x * x * x * x; }
float FacetStdPow5(float x) { return x * x * x * x * x; }
float2 FacetStdPow5(float2 x) { return x * x * x * x * x; }
float3 FacetStdPow5(float3 x) { return x * x * x * x * x; }

// normalize() that returns a finite vector for v = 0 (e.g. L + V with L = -V).
float3 FacetStdSafeNormalize(float3 v) { return v * rsqrt(max(0.001, dot(v, v))); }

float FacetSmoothnessToPerceptualRoughness(float smoothness) { return 1.0 - smoothness; }
float FacetPerceptualRoughnessToRoughness(float perceptualRoughness) { return perceptualRoughness * perceptualRoughness; }
float FacetRoughnessToPerceptualRoughness(float roughness) { return sqrt(roughness); }
float FacetSmoothnessToRoughness(float smoothness) { return (1.0 - smoothness) * (1.0 - smoothness); }

// ---- Fresnel ------------------------------------------------------------------
// Schlick: F0 + (1 - F0)(1 - cos)^5.
float3 FacetStdFresnelTerm(float3 f0, float cosA) { return f0 + (1.0 - f0) * FacetStdPow5(1.0 - cosA); }
// Schlick between F0 and a chosen grazing value F90.
float3 FacetStdFresnelLerp(float3 f0, float3 f90, float cosA) { return lerp(f0, f90, FacetStdPow5(1.0 - cosA)); }
// The same with a 4th power (BRDF2, BRDF3's indirect term): one multiply less.
float3 FacetStdFresnelLerpFast(float3 f0, float3 f90, float cosA) { return lerp(f0, f90, FacetStdPow4(1.0 - cosA)); }

// ---- diffuse ------------------------------------------------------------------
// Burley's diffuse retro-reflection factor (the /pi is left to the caller):
// fd90 = 0.5 + 2 r LdotH^2, (1 + (fd90 - 1)(1 - NdotL)^5)(1 + (fd90 - 1)(1 - NdotV)^5).
float FacetStdDisneyDiffuse(float NdotV, float NdotL, float LdotH, float perceptualRoughness)
{
    float fd90 = 0.5 + 2.0 * LdotH * LdotH * perceptualRoughness;
    float lightScatter = 1.0 + (fd90 - 1.0) * FacetStdPow5(1.0 - NdotL);
    float viewScatter = 1.0 + (fd90 - 1.0) * FacetStdPow5(1.0 - NdotV);
    return lightScatter * viewScatter;
}

// ---- visibility (G / (4 NdotL NdotV)) -------------------------------------------
// Smith with Schlick's k; the 1e-5 keeps the grazing case finite.
float FacetStdSmithVisibilityTerm(float NdotL, float NdotV, float k)
{
    float gL = NdotL * (1.0 - k) + k;
    float gV = NdotV * (1.0 - k) + k;
    return 1.0 / (gL * gV + 1e-5);
}
// Smith-Schlick fitted to Beckmann: k = roughness * sqrt(2/pi), with the 1/4.
float FacetStdSmithBeckmannVisibilityTerm(float NdotL, float NdotV, float roughness)
{
    float k = roughness * 0.797884560802865;
    return FacetStdSmithVisibilityTerm(NdotL, NdotV, k) * 0.25;
}
// Height-correlated Smith for GGX with its square roots replaced by linear
// interpolation (not exact, close; what Unity's Standard shader ships):
// 0.5 / (NdotL (NdotV (1 - a) + a) + NdotV (NdotL (1 - a) + a) + 1e-5).
float FacetStdSmithJointGGXVisibilityTerm(float NdotL, float NdotV, float roughness)
{
    float a = roughness;
    float lambdaV = NdotL * (NdotV * (1.0 - a) + a);
    float lambdaL = NdotV * (NdotL * (1.0 - a) + a);
    return 0.5 / (lambdaV + lambdaL + 1e-5);
}

// ---- normal distributions ---------------------------------------------------------
// GGX / Trowbridge-Reitz: a^2 / (pi ((a^2 - 1) NdotH^2 + 1)^2), with a 1e-7
// floor on the denominator for a = 0 at NdotH = 1.
float FacetStdGGXTerm(float NdotH, float roughness)
{
    float a2 = roughness * roughness;
    float d = (NdotH * a2 - NdotH) * NdotH + 1.0;
    return FACET_STD_INV_PI * a2 / (d * d + 1e-7);
}
// Blinn-Phong exponent for a perceptual roughness: n = 2 / a^4 - 2 with
// a = r^2 (Walter 2007's Beckmann match), floored at 1e-4 (no pow(0, 0)).
float FacetStdPerceptualRoughnessToSpecPower(float perceptualRoughness)
{
    float m = FacetPerceptualRoughnessToRoughness(perceptualRoughness);
    float sq = max(1e-4, m * m);
    float n = 2.0 / sq - 2.0;
    return max(n, 1e-4);
}
// Normalized Blinn-Phong NDF: (n + 2) / (2 pi) NdotH^n.
float FacetStdNDFBlinnPhongNormalizedTerm(float NdotH, float n)
{
    float normTerm = (n + 2.0) * (0.5 * FACET_STD_INV_PI);
    return normTerm * pow(NdotH, n);
}

// ---- metallic / specular setups ---------------------------------------------------
float FacetSpecularStrength(float3 specular)
{
#if UNITY_CONSERVE_ENERGY_MONOCHROME
    return max(max(specular.r, specular.g), specular.b);
#else
    return specular.r;
#endif
}
// Scales the diffuse albedo so that diffuse + specular reflect at most the
// incoming light: 1 - max(specColor).
float3 FacetEnergyConservationBetweenDiffuseAndSpecular(float3 albedo, float3 specColor, out float oneMinusReflectivity)
{
    oneMinusReflectivity = 1.0 - FacetSpecularStrength(specColor);
#if !UNITY_CONSERVE_ENERGY
    return albedo;
#elif UNITY_CONSERVE_ENERGY_MONOCHROME
    return albedo * oneMinusReflectivity;
#else
    return albedo * (1.0 - specColor);
#endif
}
// Metals reflect with their albedo as F0, dielectrics with dielectricSpec.rgb
// (0.04 linear); the diffuse share falls linearly from dielectricSpec.a to 0.
float FacetOneMinusReflectivityFromMetallic(float metallic, float4 dielectricSpec)
{
    float oneMinusDielectricSpec = dielectricSpec.a;
    return oneMinusDielectricSpec - metallic * oneMinusDielectricSpec;
}
float3 FacetDiffuseAndSpecularFromMetallic(float3 albedo, float metallic, float4 dielectricSpec,
                                           out float3 specColor, out float oneMinusReflectivity)
{
    specColor = lerp(dielectricSpec.rgb, albedo, metallic);
    oneMinusReflectivity = FacetOneMinusReflectivityFromMetallic(metallic, dielectricSpec);
    return albedo * oneMinusReflectivity;
}
// Premultiplied transparency fades only the diffuse part: the reflection
// stays (glass). Without premultiply the alpha passes through.
float3 FacetPreMultiplyAlpha(float3 diffColor, float alpha, float oneMinusReflectivity, out float outModifiedAlpha,
                             bool premultiply)
{
    if (premultiply) {
        diffColor *= alpha;
        outModifiedAlpha = 1.0 - oneMinusReflectivity + alpha * oneMinusReflectivity;
    } else {
        outModifiedAlpha = alpha;
    }
    return diffColor;
}

// ---- BRDF1: Disney diffuse + GGX (or normalized Blinn-Phong) microfacet ------------
// Returns the outgoing colour of one light plus the indirect terms. `normal`,
// `viewDir` and `lightDir` are unit world vectors (viewDir towards the eye,
// lightDir towards the light); lightColor includes attenuation.
float4 FacetStandardBRDF1(float3 diffColor, float3 specColor, float oneMinusReflectivity, float smoothness,
                          float3 normal, float3 viewDir, float3 lightDir, float3 lightColor,
                          float3 indirectDiffuse, float3 indirectSpecular)
{
    float perceptualRoughness = FacetSmoothnessToPerceptualRoughness(smoothness);
    float3 halfDir = FacetStdSafeNormalize(lightDir + viewDir);
    // abs: back-facing view directions (normal maps, interpolation) stay lit
    // instead of turning black.
    float nv = abs(dot(normal, viewDir));
    float nl = saturate(dot(normal, lightDir));
    float nh = saturate(dot(normal, halfDir));
    float lh = saturate(dot(lightDir, halfDir));

    float diffuseTerm = FacetStdDisneyDiffuse(nv, nl, lh, perceptualRoughness) * nl;

    float roughness = FacetPerceptualRoughnessToRoughness(perceptualRoughness);
#if UNITY_BRDF_GGX
    // Roughness 0 would make the highlight vanish (an infinitely thin peak).
    roughness = max(roughness, 0.002);
    float visTerm = FacetStdSmithJointGGXVisibilityTerm(nl, nv, roughness);
    float ndfTerm = FacetStdGGXTerm(nh, roughness);
#else
    float visTerm = FacetStdSmithBeckmannVisibilityTerm(nl, nv, roughness);
    float ndfTerm = FacetStdNDFBlinnPhongNormalizedTerm(nh, FacetStdPerceptualRoughnessToSpecPower(perceptualRoughness));
#endif
    float specularTerm = visTerm * ndfTerm * 3.14159265358979323846;
#ifdef UNITY_COLORSPACE_GAMMA
    specularTerm = sqrt(max(1e-4, specularTerm));
#endif
    specularTerm = max(0.0, specularTerm * nl);
#if defined(_SPECULARHIGHLIGHTS_OFF)
    specularTerm = 0.0;
#endif
    // Rough surfaces reflect less of the environment: 1 / (a^2 + 1).
#ifdef UNITY_COLORSPACE_GAMMA
    float surfaceReduction = 1.0 - 0.28 * roughness * perceptualRoughness;
#else
    float surfaceReduction = 1.0 / (roughness * roughness + 1.0);
#endif
    // A black specular colour gives pure Lambert (no residual highlight).
    specularTerm *= any(specColor) ? 1.0 : 0.0;

    float grazingTerm = saturate(smoothness + (1.0 - oneMinusReflectivity));
    float3 color = diffColor * (indirectDiffuse + lightColor * diffuseTerm)
                 + specularTerm * lightColor * FacetStdFresnelTerm(specColor, lh)
                 + surfaceReduction * indirectSpecular * FacetStdFresnelLerp(specColor, grazingTerm, nv);
    return float4(color, 1.0);
}

// ---- BRDF2: minimalist Cook-Torrance (Zioma 2015) ----------------------------------
// GGX D with V * F folded into 1 / (LdotH^2 (roughness + 0.5)); no Fresnel
// curve on direct light.
float4 FacetStandardBRDF2(float3 diffColor, float3 specColor, float oneMinusReflectivity, float smoothness,
                          float3 normal, float3 viewDir, float3 lightDir, float3 lightColor,
                          float3 indirectDiffuse, float3 indirectSpecular)
{
    float3 halfDir = FacetStdSafeNormalize(lightDir + viewDir);
    float nl = saturate(dot(normal, lightDir));
    float nh = saturate(dot(normal, halfDir));
    float nv = saturate(dot(normal, viewDir));
    float lh = saturate(dot(lightDir, halfDir));

    float perceptualRoughness = FacetSmoothnessToPerceptualRoughness(smoothness);
    float roughness = FacetPerceptualRoughnessToRoughness(perceptualRoughness);
#if UNITY_BRDF_GGX
    float a2 = roughness * roughness;
    // 1.00001: d > 0 also for a = 0 at nh = 1.
    float d = nh * nh * (a2 - 1.0) + 1.00001;
#ifdef UNITY_COLORSPACE_GAMMA
    float specularTerm = roughness / (max(0.32, lh) * (1.5 + roughness) * d);
#else
    float specularTerm = a2 / (max(0.1, lh * lh) * (roughness + 0.5) * (d * d) * 4.0);
#endif
#if defined(SHADER_API_MOBILE)
    specularTerm = specularTerm - 1e-4;
#endif
#else
    float specularPower = FacetStdPerceptualRoughnessToSpecPower(perceptualRoughness);
    float invV = lh * lh * smoothness + perceptualRoughness * perceptualRoughness;
    float invF = lh;
    float specularTerm = ((specularPower + 1.0) * pow(nh, specularPower)) / (8.0 * invV * invF + 1e-4);
#ifdef UNITY_COLORSPACE_GAMMA
    specularTerm = sqrt(max(1e-4, specularTerm));
#endif
#endif
#if defined(SHADER_API_MOBILE)
    // fp16 overflow guard.
    specularTerm = clamp(specularTerm, 0.0, 100.0);
#endif
#if defined(_SPECULARHIGHLIGHTS_OFF)
    specularTerm = 0.0;
#endif
    // 1 - a r (0.6 - 0.08 r): a polynomial fit of 1 / (a^2 + 1).
#ifdef UNITY_COLORSPACE_GAMMA
    float surfaceReduction = 1.0 - 0.28 * roughness * perceptualRoughness;
#else
    float surfaceReduction = 1.0 - roughness * perceptualRoughness * (0.6 - 0.08 * perceptualRoughness);
#endif
    float grazingTerm = saturate(smoothness + (1.0 - oneMinusReflectivity));
    float3 color = (diffColor + specularTerm * specColor) * lightColor * nl
                 + indirectDiffuse * diffColor
                 + surfaceReduction * indirectSpecular * FacetStdFresnelLerpFast(specColor, grazingTerm, nv);
    return float4(color, 1.0);
}

// ---- BRDF3: normalized Phong in R.L (the SM2.0 tier) --------------------------------
// facet evaluates Unity's unity_NHxRoughness lookup analytically: with
// a = r^2 and the Blinn-Phong exponent n = 2/a^2 - 2, the Phong lobe around
// the reflection vector has exponent n/4 (the R.L angle is twice the N.H
// angle) and its energy normalization (n/4 + 2)/2 (pi folded in, as in
// BRDF1); the value is capped at 16, the lookup's range.
float FacetStdBRDF3Specular(float RdotL, float perceptualRoughness)
{
    float n = FacetStdPerceptualRoughnessToSpecPower(perceptualRoughness) * 0.25;
    float s = (n + 2.0) * 0.5 * pow(saturate(RdotL), n);
    return min(s, 16.0);
}
float4 FacetStandardBRDF3(float3 diffColor, float3 specColor, float oneMinusReflectivity, float smoothness,
                          float3 normal, float3 viewDir, float3 lightDir, float3 lightColor,
                          float3 indirectDiffuse, float3 indirectSpecular)
{
    float3 reflDir = reflect(-viewDir, normal);
    float nl = saturate(dot(normal, lightDir));
    float nv = saturate(dot(normal, viewDir));
    float perceptualRoughness = FacetSmoothnessToPerceptualRoughness(smoothness);
    float specular = FacetStdBRDF3Specular(dot(reflDir, lightDir), perceptualRoughness);
#if defined(_SPECULARHIGHLIGHTS_OFF)
    specular = 0.0;
#endif
    float fresnelTerm = FacetStdPow4(1.0 - nv);
    float grazingTerm = saturate(smoothness + (1.0 - oneMinusReflectivity));
    float3 color = (diffColor + specular * specColor) * lightColor * nl
                 + indirectDiffuse * diffColor
                 + indirectSpecular * lerp(specColor, float3(grazingTerm, grazingTerm, grazingTerm), fresnelTerm);
    return float4(color, 1.0);
}

#endif // FACET_STANDARD_INCLUDED
