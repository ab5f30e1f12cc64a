// The Disney "principled" BRDF (Burley 2012, "Physically-Based Shading at
// Disney", and the BRDF Explorer's disney.brdf): one lobe set driven by ten
// artist parameters. C++ twin: reference/include/facet/reference/disney.h;
// formulas and energy figures: docs/lighting-models.md.
#ifndef FACET_DISNEY_INCLUDED
#define FACET_DISNEY_INCLUDED

#include "FacetBRDF.hlsl"

// All parameters in [0, 1]; baseColor is LINEAR (convert sRGB textures first).
struct FacetDisneyMaterial
{
    float3 baseColor;
    float subsurface;      // 0 = Burley diffuse, 1 = Hanrahan-Krueger-like flattening
    float metallic;
    float specular;        // 0.5 = f0 of 0.04 (IOR 1.5)
    float specularTint;    // tints f0 towards the hue of baseColor
    float roughness;       // perceptual
    float anisotropic;     // 0 = isotropic, 1 = 10:1 stretch along X
    float sheen;
    float sheenTint;
    float clearcoat;       // second, fixed-IOR 1.5 GTR1 lobe, weight 0.25
    float clearcoatGloss;  // 0 = "satin" (alpha 0.1), 1 = "gloss" (alpha 0.001)
};

// (1 - u)^5 with u saturated, Disney's "SchlickFresnel" weight.
float FacetDisneySchlickWeight(float u) { return FacetPow5(1.0 - saturate(u)); }

// Berry's GTR with gamma = 1 (the clear coat NDF); a >= 1 gives the constant 1/pi.
float FacetD_GTR1(float NoH, float a)
{
    if (a >= 1.0)
        return FACET_INV_PI;
    float a2 = a * a;
    float t = 1.0 + (a2 - 1.0) * NoH * NoH;
    return (a2 - 1.0) / (FACET_PI * log(a2) * t);
}

// Separable Smith GGX as Disney writes it: 1 / (NoV + sqrt(alpha^2 + NoV^2 - alpha^2 NoV^2))
// is G1 / (2 NoV), so the product for l and v is G / (4 NoL NoV).
float FacetDisneySmithGGX(float NoV, float alphaG)
{
    float a = alphaG * alphaG;
    float b = NoV * NoV;
    return 1.0 / (NoV + sqrt(a + b - a * b));
}
float FacetDisneySmithGGXAnisotropic(float NoV, float VoX, float VoY, float alphaX, float alphaY)
{
    float x = VoX * alphaX;
    float y = VoY * alphaY;
    return 1.0 / (NoV + sqrt(x * x + y * y + NoV * NoV));
}

// The whole BRDF (without the cosine). l, v unit; (n, x, y) an orthonormal
// frame (normal, tangent, bitangent); 0 when l or v is below the surface. NoV
// gets the library's 1e-4 floor so the subsurface term's 1 / (NoL + NoV)
// stays finite in fp32 when both directions graze.
float3 FacetBRDF_Disney(FacetDisneyMaterial m, float3 l, float3 v, float3 n, float3 x, float3 y)
{
    float NoL = dot(n, l);
    float NoV = dot(n, v);
    if (NoL <= 0.0 || NoV <= 0.0)
        return float3(0.0, 0.0, 0.0);
    NoV = FacetClampNoV(NoV);
    float3 h = FacetSafeNormalize(l + v);
    float NoH = dot(n, h);
    float LoH = dot(l, h);

    float luminance = dot(m.baseColor, float3(0.3, 0.6, 0.1));
    float3 tint = luminance > 0.0 ? m.baseColor / luminance : float3(1.0, 1.0, 1.0);
    float3 specular0 = lerp(m.specular * 0.08 * lerp(float3(1.0, 1.0, 1.0), tint, m.specularTint),
                            m.baseColor, m.metallic);
    float3 sheenColor = lerp(float3(1.0, 1.0, 1.0), tint, m.sheenTint);

    float fresnelL = FacetDisneySchlickWeight(NoL);
    float fresnelV = FacetDisneySchlickWeight(NoV);
    float fd90 = 0.5 + 2.0 * LoH * LoH * m.roughness;
    float Fd = lerp(1.0, fd90, fresnelL) * lerp(1.0, fd90, fresnelV);
    float fss90 = LoH * LoH * m.roughness;
    float Fss = lerp(1.0, fss90, fresnelL) * lerp(1.0, fss90, fresnelV);
    float ss = 1.25 * (Fss * (1.0 / (NoL + NoV) - 0.5) + 0.5);

    float aspect = sqrt(1.0 - 0.9 * m.anisotropic);
    float r2 = m.roughness * m.roughness;
    float alphaX = max(0.001, r2 / aspect);
    float alphaY = max(0.001, r2 * aspect);
    float Ds = FacetD_GGXAnisotropic(NoH, dot(h, x), dot(h, y), alphaX, alphaY);
    float fresnelH = FacetDisneySchlickWeight(LoH);
    float3 Fs = lerp(specular0, float3(1.0, 1.0, 1.0), fresnelH);
    float Vs = FacetDisneySmithGGXAnisotropic(NoL, dot(l, x), dot(l, y), alphaX, alphaY) *
               FacetDisneySmithGGXAnisotropic(NoV, dot(v, x), dot(v, y), alphaX, alphaY);

    float3 Fsheen = fresnelH * m.sheen * sheenColor;

    float Dr = FacetD_GTR1(NoH, lerp(0.1, 0.001, m.clearcoatGloss));
    float Fr = lerp(0.04, 1.0, fresnelH);
    float Vr = FacetDisneySmithGGX(NoL, 0.25) * FacetDisneySmithGGX(NoV, 0.25);

    float3 diffuse = (FACET_INV_PI * lerp(Fd, ss, m.subsurface) * m.baseColor + Fsheen) * (1.0 - m.metallic);
    return diffuse + Ds * Vs * Fs + 0.25 * m.clearcoat * Dr * Vr * Fr;
}

#endif // FACET_DISNEY_INCLUDED
