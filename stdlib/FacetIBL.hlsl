// Image-based lighting math: roughness -> prefiltered mip, the environment
// BRDF (split-sum DFG: analytic fit, table lookup, and the table's integral),
// and SH9 irradiance. C++ twin: reference/include/facet/reference/ibl.h, which
// also generates the DFG table on the CPU; formulas: docs/lighting-models.md.
#ifndef FACET_IBL_INCLUDED
#define FACET_IBL_INCLUDED

#include "FacetBRDF.hlsl"

// Mip of a chain prefiltered with alpha = r^2 per level (Filament: lod = maxMip r).
float FacetPerceptualRoughnessToMipLevel(float perceptualRoughness, float maxMipLevel)
{
    return saturate(perceptualRoughness) * maxMipLevel;
}
// Unity's curve r (1.7 - 0.7 r) * steps (UNITY_SPECCUBE_LOD_STEPS = 6).
float FacetPerceptualRoughnessToMipLevelUnity(float perceptualRoughness, float mipSteps)
{
    float r = saturate(perceptualRoughness);
    return r * (1.7 - 0.7 * r) * mipSteps;
}

// Karis 2014 (after Lazarov 2013) analytic fit of the split-sum scale and bias
// (A, B): specular = f0 A + B. |dA| <= 0.40 against the height-correlated table,
// +47 % at r = 1, NoV = 1. B is floored at 0 (the fit dips to -0.0024).
float2 FacetEnvBRDFApproxAB(float perceptualRoughness, float NoV)
{
    const float4 c0 = float4(-1.0, -0.0275, -0.572, 0.022);
    const float4 c1 = float4(1.0, 0.0425, 1.04, -0.04);
    float4 r = perceptualRoughness * c0 + c1;
    float a004 = min(r.x * r.x, exp2(-9.28 * NoV)) * r.x + r.y;
    float2 scaleBias = float2(-1.04, 1.04) * a004 + r.zw;
    return max(scaleBias, 0.0);
}
float3 FacetEnvBRDFApprox(float3 f0, float perceptualRoughness, float NoV)
{
    float2 scaleBias = FacetEnvBRDFApproxAB(perceptualRoughness, NoV);
    return f0 * scaleBias.x + scaleBias.y;
}

// The DFG table in the multiscatter layout: x = integral of V F_c <n.l>,
// y = integral of V <n.l> (both x 4 D-weighted, F_c = (1 - VoH)^5), with the
// height-correlated V. y is the lobe's directional albedo E for F = 1.
float3 FacetEnvBRDF_DFG(float3 f0, float f90, float2 dfg)
{
    return f0 * (dfg.y - dfg.x) + f90 * dfg.x;
}

// Van der Corput radical inverse in base 2.
float FacetRadicalInverse(uint i) { return float(reversebits(i)) * 2.3283064365386963e-10; }

// The DFG integral by GGX importance sampling on `sampleCount` Hammersley points
// ((i + 0.5)/N, radical inverse of i); the CPU twin builds the table with it
// and the GPU may too.
float2 FacetDFG_Integrate(float NoV, float alpha, uint sampleCount)
{
    float3 v = float3(sqrt(saturate((1.0 - NoV) * (1.0 + NoV))), 0.0, NoV);
    float a2 = alpha * alpha;
    float2 sum = float2(0.0, 0.0);
    for (uint i = 0; i < sampleCount; ++i)
    {
        float u = (float(i) + 0.5) / float(sampleCount);
        float phi = 2.0 * FACET_PI * FacetRadicalInverse(i);
        float cosH = sqrt((1.0 - u) / (1.0 + (a2 - 1.0) * u));
        float sinH = sqrt(saturate((1.0 - cosH) * (1.0 + cosH)));
        float3 h = float3(sinH * cos(phi), sinH * sin(phi), cosH);
        float VoH = dot(v, h);
        float3 l = 2.0 * VoH * h - v;
        float NoL = l.z;
        if (NoL > 0.0 && VoH > 0.0)
        {
            // f <n.l> / pdf(l) with pdf = D NoH / (4 VoH).
            float w = 4.0 * FacetV_SmithGGXCorrelated(NoV, NoL, alpha) * NoL * VoH / cosH;
            float fc = FacetPow5(1.0 - VoH);
            sum += float2(w * fc, w);
        }
    }
    return sum / float(sampleCount);
}

// Irradiance E(n) from the 9 real SH coefficients of the RADIANCE (order
// Y00, Y1-1, Y10, Y11, Y2-2, Y2-1, Y20, Y21, Y22) with Ramamoorthi-Hanrahan's
// cosine-lobe factors pi, 2pi/3, pi/4; floored at 0 (ringing). A Lambert
// surface reflects albedo / pi * E. n must be a unit vector.
float FacetSH9Irradiance(float3 n, float sh[9])
{
    const float c0 = 0.886226925452758;   // pi * 0.282095
    const float c1 = 1.023326707946489;   // 2pi/3 * 0.488603
    const float c2 = 0.858085715393580;   // pi/4 * 1.092548
    const float c3 = 0.247707956747363;   // pi/4 * 0.315392
    const float c4 = 0.429042857696790;   // pi/4 * 0.546274
    float e = c0 * sh[0]
            + c1 * (sh[1] * n.y + sh[2] * n.z + sh[3] * n.x)
            + c2 * (sh[4] * n.x * n.y + sh[5] * n.y * n.z + sh[7] * n.x * n.z)
            + c3 * sh[6] * (3.0 * n.z * n.z - 1.0)
            + c4 * sh[8] * (n.x * n.x - n.y * n.y);
    return max(e, 0.0);
}
float3 FacetSH9Irradiance(float3 n, float3 sh[9])
{
    float r[9], g[9], b[9];
    for (int i = 0; i < 9; ++i)
    {
        r[i] = sh[i].r;
        g[i] = sh[i].g;
        b[i] = sh[i].b;
    }
    return float3(FacetSH9Irradiance(n, r), FacetSH9Irradiance(n, g), FacetSH9Irradiance(n, b));
}

#endif // FACET_IBL_INCLUDED
