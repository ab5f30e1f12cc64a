// Output encodings of the HDR display path (Unity 6's BlitCopyHDRTonemap
// shaders): the display's colour gamut (kColorGamut*, the numbering of
// Unity's ColorGamut enum), the sRGB, gamma 2.2 and SMPTE ST 2084 (PQ)
// transfer curves, the Rec.709 <-> Rec.2020 / Display P3 primaries, and
// SimpleHDRDisplayToneMapAndOETF with its inverse. The sRGB curve is facet's
// exact one (FacetColor.hlsl).
#ifndef UNITY_COLOR_GAMUT_INCLUDED
#define UNITY_COLOR_GAMUT_INCLUDED

#include "UnityCG.cginc"
#include "FacetColor.hlsl"

#define kColorGamutSRGB 0
#define kColorGamutRec709 1
#define kColorGamutRec2020 2
#define kColorGamutDisplayP3 3
#define kColorGamutHDR10 4
#define kColorGamutDolbyHDR 5
#define kColorGamutP3D65G22 6

// The luminance (nits) that scene value 1 has on a Rec.709 (scRGB) display;
// Metal's convention is 100, everyone else's 80.
#if defined(SHADER_API_METAL)
#define kReferenceLuminanceWhiteForRec709 100
#else
#define kReferenceLuminanceWhiteForRec709 80
#endif

float3 LinearToSRGB(float3 color) { return FacetLinearToSRGB(color); }
float3 SRGBToLinear(float3 color) { return FacetSRGBToLinear(color); }

// Linear Rec.709 primaries <-> linear Rec.2020 primaries (ITU-R BT.2087),
// and <-> linear Display P3 (D65) primaries; rows apply to column vectors.
static const float3x3 Rec709ToRec2020 = {
    0.627402, 0.329292, 0.043306,
    0.069095, 0.919544, 0.011360,
    0.016394, 0.088028, 0.895578 };
static const float3x3 Rec2020ToRec709 = {
    1.660496, -0.587656, -0.072840,
    -0.124547, 1.132895, -0.008348,
    -0.018154, -0.100597, 1.118751 };
static const float3x3 Rec709ToP3D65Mat = {
    0.822462, 0.177538, 0.000000,
    0.033194, 0.966806, 0.000000,
    0.017083, 0.072397, 0.910520 };
static const float3x3 P3D65MatToRec709 = {
    1.224940, -0.224940, 0.000000,
    -0.042056, 1.042056, 0.000000,
    -0.019637, -0.078636, 1.098273 };

// SMPTE ST 2084 (PQ) constants: m1, m2, c1, c2, c3.
#define PQ_M1 (2610.0 / 16384.0)
#define PQ_M2 (2523.0 / 32.0)
#define PQ_C1 (3424.0 / 4096.0)
#define PQ_C2 (2413.0 / 128.0)
#define PQ_C3 (2392.0 / 128.0)

// Linear light as a fraction of 10000 nits -> the PQ signal, and back.
float3 LinearToST2084(float3 color)
{
    float3 ym1 = pow(abs(color), PQ_M1);
    return pow((PQ_C1 + PQ_C2 * ym1) / (1.0 + PQ_C3 * ym1), PQ_M2);
}
float3 ST2084ToLinear(float3 color)
{
    float3 e = pow(abs(color), 1.0 / PQ_M2);
    return pow(max(e - PQ_C1, 0.0) / (PQ_C2 - PQ_C3 * e), 1.0 / PQ_M1);
}

float3 LinearToGamma22(float3 color) { return pow(abs(color), 1.0 / 2.2); }
float3 Gamma22ToLinear(float3 color) { return pow(abs(color), 2.2); }

float3 FacetGammaToLinearExact3(float3 c)
{
    return float3(GammaToLinearSpaceExact(c.r), GammaToLinearSpaceExact(c.g), GammaToLinearSpaceExact(c.b));
}
float3 FacetLinearToGammaExact3(float3 c)
{
    return float3(LinearToGammaSpaceExact(c.r), LinearToGammaSpaceExact(c.g), LinearToGammaSpaceExact(c.b));
}

// A linear Rec.709 scene colour (gamma-encoded in gamma colour space or
// with forceGammaToLinear) -> the display's signal: sRGB-encoded for an
// sRGB display (in linear colour space), PQ over Rec.2020 for HDR10 with
// paper white at nitsForPaperWhite, gamma 2.2 over P3 scaled to
// maxDisplayNits for P3D65G22, else scRGB (Rec.709 scaled so that 1 is
// paper white).
float3 SimpleHDRDisplayToneMapAndOETF(float3 scene, int colorGamut, bool forceGammaToLinear, float nitsForPaperWhite,
                                      float maxDisplayNits)
{
    float3 c = (IsGammaSpace() || forceGammaToLinear) ? FacetGammaToLinearExact3(scene) : scene;
    if (colorGamut == kColorGamutSRGB) {
        if (!IsGammaSpace()) c = LinearToSRGB(c);
    } else if (colorGamut == kColorGamutHDR10) {
        c = LinearToST2084(mul(Rec709ToRec2020, c) * (nitsForPaperWhite / 10000.0));
    } else if (colorGamut == kColorGamutP3D65G22) {
        c = LinearToGamma22(mul(Rec709ToP3D65Mat, c) * (nitsForPaperWhite / maxDisplayNits));
    } else {
        c *= nitsForPaperWhite / kReferenceLuminanceWhiteForRec709;
    }
    return c;
}

// The inverse: a display signal back to the scene colour.
float3 InverseSimpleHDRDisplayToneMapAndOETF(float3 signal, int colorGamut, bool forceGammaToLinear,
                                             float nitsForPaperWhite, float maxDisplayNits)
{
    float3 c = signal;
    if (colorGamut == kColorGamutSRGB) {
        if (!IsGammaSpace()) c = SRGBToLinear(c);
    } else if (colorGamut == kColorGamutHDR10) {
        c = mul(Rec2020ToRec709, ST2084ToLinear(c) / (nitsForPaperWhite / 10000.0));
    } else if (colorGamut == kColorGamutP3D65G22) {
        c = mul(P3D65MatToRec709, Gamma22ToLinear(c) / (nitsForPaperWhite / maxDisplayNits));
    } else {
        c /= nitsForPaperWhite / kReferenceLuminanceWhiteForRec709;
    }
    return (IsGammaSpace() || forceGammaToLinear) ? FacetLinearToGammaExact3(c) : c;
}

#endif // UNITY_COLOR_GAMUT_INCLUDED
