// Exact sRGB transfer functions (IEC 61966-2-1), scalar and per channel. C++
// twin: reference/include/facet/reference/color.h. pow(x, 1/2.2) is up to 8.5
// 8-bit codes off near black; prefer *_SRGB formats, which do this in hardware.
#ifndef FACET_COLOR_INCLUDED
#define FACET_COLOR_INCLUDED

// Linear -> encoded; negative input is taken as 0.
float FacetLinearToSRGB(float c)
{
    c = max(c, 0.0);
    return c <= 0.0031308 ? 12.92 * c : 1.055 * pow(c, 1.0 / 2.4) - 0.055;
}
// Encoded -> linear; negative input is taken as 0.
float FacetSRGBToLinear(float e)
{
    e = max(e, 0.0);
    return e <= 0.04045 ? e / 12.92 : pow((e + 0.055) / 1.055, 2.4);
}
float3 FacetLinearToSRGB(float3 c)
{
    return float3(FacetLinearToSRGB(c.x), FacetLinearToSRGB(c.y), FacetLinearToSRGB(c.z));
}
float3 FacetSRGBToLinear(float3 e)
{
    return float3(FacetSRGBToLinear(e.x), FacetSRGBToLinear(e.y), FacetSRGBToLinear(e.z));
}

#endif // FACET_COLOR_INCLUDED
