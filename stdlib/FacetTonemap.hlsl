// Tone mappers: scene-referred linear RGB (>= 0; negative input is taken as 0)
// to display-referred linear RGB in [0, 1], to be sRGB-encoded afterwards
// (FacetColor.hlsl or an *_SRGB target). C++ twin:
// reference/include/facet/reference/tonemap.h; formulas: docs/lighting-models.md.
#ifndef FACET_TONEMAP_INCLUDED
#define FACET_TONEMAP_INCLUDED

// Reinhard et al. 2002, per channel.
float3 FacetTonemapReinhard(float3 x)
{
    x = max(x, 0.0);
    return x / (1.0 + x);
}
// Reinhard extended: `white` maps to 1.
float3 FacetTonemapReinhardExtended(float3 x, float white)
{
    x = max(x, 0.0);
    return saturate(x * (1.0 + x / (white * white)) / (1.0 + x));
}

// Hable's Uncharted 2 curve, the blog constants (A..F = .15 .50 .10 .20 .02 .30),
// exposure bias 2, white point 11.2.
float3 FacetHableCurve(float3 x)
{
    const float shoulderA = 0.15, linearB = 0.50, angleC = 0.10, toeD = 0.20, toeNumE = 0.02, toeDenF = 0.30;
    return (x * (shoulderA * x + angleC * linearB) + toeD * toeNumE) / (x * (shoulderA * x + linearB) + toeD * toeDenF) - toeNumE / toeDenF;
}
float3 FacetTonemapHable(float3 x)
{
    x = max(x, 0.0);
    float3 white = FacetHableCurve(float3(11.2, 11.2, 11.2));
    return saturate(FacetHableCurve(2.0 * x) / white);
}

// Narkowicz 2015 fit of the ACES RRT+ODT (luminance-only, saturates highlights).
float3 FacetTonemapACESNarkowicz(float3 x)
{
    x = max(x, 0.0);
    return saturate(x * (2.51 * x + 0.03) / (x * (2.43 * x + 0.59) + 0.14));
}

// Hill's fit (BakingLab): sRGB -> AP1 with the RRT saturation, the RRT+ODT
// rational fit, back to sRGB. The fit alone is slightly NEGATIVE near 0
// (-0.000090537 / 0.238081 = -3.8e-4 at v = 0), hence the saturate.
float3 FacetACESHillRRTODTFit(float3 v)
{
    float3 a = v * (v + 0.0245786) - 0.000090537;
    float3 b = v * (0.983729 * v + 0.4329510) + 0.238081;
    return a / b;
}
float3 FacetTonemapACESHill(float3 color)
{
    const float3x3 inputMat = float3x3(0.59719, 0.35458, 0.04823,
                                       0.07600, 0.90834, 0.01566,
                                       0.02840, 0.13383, 0.83777);
    const float3x3 outputMat = float3x3(1.60475, -0.53108, -0.07367,
                                        -0.10208, 1.10813, -0.00605,
                                        -0.00327, -0.07276, 1.07602);
    float3 v = mul(inputMat, max(color, 0.0));
    v = FacetACESHillRRTODTFit(v);
    return saturate(mul(outputMat, v));
}

// Khronos PBR Neutral (2024): identity below 0.76 apart from a small black
// offset, then a smooth highlight compression towards desaturated white.
float3 FacetTonemapPBRNeutral(float3 color)
{
    const float startCompression = 0.8 - 0.04;
    const float desaturation = 0.15;
    color = max(color, 0.0);
    float x = min(color.r, min(color.g, color.b));
    float offset = x < 0.08 ? x - 6.25 * x * x : 0.04;
    color -= offset;
    float peak = max(color.r, max(color.g, color.b));
    if (peak < startCompression)
        return color;
    const float d = 1.0 - startCompression;
    float newPeak = 1.0 - d * d / (peak + d - startCompression);
    color *= newPeak / peak;
    float g = 1.0 - 1.0 / (desaturation * (peak - newPeak) + 1.0);
    return lerp(color, float3(newPeak, newPeak, newPeak), g);
}

// AgX, the minimal sRGB form: inset matrix, log2 encoding over
// [-12.47393, 4.026069] EV around middle grey, the 7th-order contrast curve,
// outset (inverse) matrix, and pow 2.2 back to linear.
float3 FacetAgXContrast(float3 x)
{
    float3 p = -17.86 * x + 78.01;
    p = p * x - 126.7;
    p = p * x + 92.06;
    p = p * x - 28.72;
    p = p * x + 4.361;
    p = p * x - 0.1718;
    return p * x + 0.002857;
}
float3 FacetTonemapAgX(float3 color)
{
    const float3x3 inset = float3x3(0.842479062253094, 0.0784335999999992, 0.0792237451477643,
                                    0.0423282422610123, 0.878468636469772, 0.0791661274605434,
                                    0.0423756549057051, 0.0784336, 0.879142973793104);
    const float3x3 outset = float3x3(1.19687900512017, -0.0980208811401368, -0.0990297440797205,
                                     -0.0528968517574562, 1.15190312990417, -0.0989611768448433,
                                     -0.0529716355144438, -0.0980434501171241, 1.15107367264116);
    const float minEv = -12.47393;
    const float maxEv = 4.026069;
    float3 v = mul(inset, max(color, 0.0));
    v = log2(max(v, 1e-10));
    v = saturate((v - minEv) / (maxEv - minEv));
    v = FacetAgXContrast(v);
    v = mul(outset, v);
    return saturate(pow(max(v, 0.0), 2.2));
}

#endif // FACET_TONEMAP_INCLUDED
