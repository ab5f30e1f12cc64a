// facet's core shader functions: transforms, colour, depth, normals, HDR
// decoding, spherical harmonics and fog. UnityCG.cginc and friends are thin
// aliases over these. Meanings and formulas: docs/stdlib.md.
#ifndef FACET_CORE_INCLUDED
#define FACET_CORE_INCLUDED

#include "FacetBuiltins.hlsl"

#define FACET_PI 3.14159265358979323846

// ---- transforms (column vectors: mul(M, v)) ---------------------------------
float3 FacetObjectToWorldPos(float3 pos) { return mul(unity_ObjectToWorld, float4(pos, 1.0)).xyz; }
float4 FacetWorldToClipPos(float3 pos) { return mul(unity_MatrixVP, float4(pos, 1.0)); }
float4 FacetObjectToClipPos(float3 pos) { return mul(unity_MatrixVP, mul(unity_ObjectToWorld, float4(pos, 1.0))); }
float4 FacetViewToClipPos(float3 pos) { return mul(unity_MatrixP, float4(pos, 1.0)); }
float3 FacetWorldToViewPos(float3 pos) { return mul(unity_MatrixV, float4(pos, 1.0)).xyz; }
float3 FacetObjectToViewPos(float3 pos) { return FacetWorldToViewPos(FacetObjectToWorldPos(pos)); }
// Directions are normalised; normals use the inverse transpose.
float3 FacetObjectToWorldDir(float3 dir) { return normalize(mul((float3x3)unity_ObjectToWorld, dir)); }
float3 FacetWorldToObjectDir(float3 dir) { return normalize(mul((float3x3)unity_WorldToObject, dir)); }
float3 FacetObjectToWorldNormal(float3 n) { return normalize(mul(n, (float3x3)unity_WorldToObject)); }
// Unnormalised: from the point towards the camera / the light.
float3 FacetWorldViewDir(float3 worldPos) { return _WorldSpaceCameraPos.xyz - worldPos; }
float3 FacetWorldLightDir(float3 worldPos) { return _WorldSpaceLightPos0.xyz - worldPos * _WorldSpaceLightPos0.w; }

// ---- colour -----------------------------------------------------------------
// The exact sRGB transfer functions (IEC 61966-2-1), per channel.
float3 FacetSrgbToLinear(float3 c)
{
    float3 lo = c / 12.92;
    float3 hi = pow(max((c + 0.055) / 1.055, 0.0), 2.4);
    return lerp(hi, lo, step(c, 0.04045));
}
float3 FacetLinearToSrgb(float3 c)
{
    c = max(c, 0.0);
    float3 lo = c * 12.92;
    float3 hi = 1.055 * pow(c, 1.0 / 2.4) - 0.055;
    return lerp(hi, lo, step(c, 0.0031308));
}
// Relative luminance of a linear Rec.709 colour.
float FacetLuminance(float3 linearRgb) { return dot(linearRgb, float3(0.2126729, 0.7151522, 0.0721750)); }

// ---- depth (clip depth 0..1, not reversed; see _ZBufferParams) --------------
float FacetLinear01Depth(float z) { return 1.0 / (_ZBufferParams.x * z + _ZBufferParams.y); }
float FacetLinearEyeDepth(float z) { return 1.0 / (_ZBufferParams.z * z + _ZBufferParams.w); }

// ---- normal maps --------------------------------------------------------------
// x and y from the map scaled to -1..1, z rebuilt so the normal has length 1.
// x is multiplied by alpha so that maps with x in alpha (DXT5nm) decode too;
// plain RGB maps have alpha 1. With UNITY_NO_DXT5nm, xyz are used as stored.
float3 FacetUnpackNormal(float4 packed)
{
#if defined(UNITY_NO_DXT5nm)
    return packed.xyz * 2.0 - 1.0;
#else
    packed.x *= packed.w;
    float3 n;
    n.xy = packed.xy * 2.0 - 1.0;
    n.z = sqrt(1.0 - saturate(dot(n.xy, n.xy)));
    return n;
#endif
}

// The same with the tangent-plane part scaled by `scale` (normal-map
// strength); z is rebuilt after scaling so the result stays unit length
// (for |scale| <= 1 and in-range samples).
float3 FacetUnpackScaleNormal(float4 packed, float scale)
{
#if defined(UNITY_NO_DXT5nm)
    float3 n = packed.xyz * 2.0 - 1.0;
    n.xy *= scale;
    return n;
#else
    packed.x *= packed.w;
    float3 n;
    n.xy = (packed.xy * 2.0 - 1.0) * scale;
    n.z = sqrt(1.0 - saturate(dot(n.xy, n.xy)));
    return n;
#endif
}

// ---- HDR textures ---------------------------------------------------------------
// instructions: x = multiplier, y = exponent applied to alpha, w = 1 when
// alpha carries a range (RGBM), 0 when the texture is plain HDR.
float3 FacetDecodeHDR(float4 data, float4 instructions)
{
    float alpha = instructions.w * (data.a - 1.0) + 1.0;
    return (instructions.x * pow(max(alpha, 0.0), instructions.y)) * data.rgb;
}

// ---- spherical harmonics -------------------------------------------------------
// Irradiance for a unit world normal n (n.w must be 1): the L0+L1 terms are a
// dot product with unity_SHA*, the L2 terms use n.xyzz * n.yzzx and
// n.x^2 - n.y^2 (Sloan, "Stupid Spherical Harmonics Tricks", 2008).
// FacetSHEval takes the seven coefficient vectors as arguments (for tests
// and for SH data other than the environment's).
float3 FacetSHEvalL0L1(float4 n, float4 shAr, float4 shAg, float4 shAb)
{
    return float3(dot(shAr, n), dot(shAg, n), dot(shAb, n));
}
float3 FacetSHEvalL2(float4 n, float4 shBr, float4 shBg, float4 shBb, float4 shC)
{
    float4 b = n.xyzz * n.yzzx;
    return float3(dot(shBr, b), dot(shBg, b), dot(shBb, b)) + shC.rgb * (n.x * n.x - n.y * n.y);
}
float3 FacetSHEval(float4 n, float4 shAr, float4 shAg, float4 shAb, float4 shBr, float4 shBg, float4 shBb, float4 shC)
{
    return max(FacetSHEvalL0L1(n, shAr, shAg, shAb) + FacetSHEvalL2(n, shBr, shBg, shBb, shC), 0.0);
}
float3 FacetShadeSH9(float4 n)
{
    return FacetSHEval(n, unity_SHAr, unity_SHAg, unity_SHAb, unity_SHBr, unity_SHBg, unity_SHBb, unity_SHC);
}

// ---- view-space normals in two channels ------------------------------------------
// Stereographic projection from (0, 0, -1), scaled by 1/1.7777 to fit the
// hemisphere facing the camera into 0..1 (the layout of Unity's
// _CameraDepthNormalsTexture).
float2 FacetEncodeViewNormal(float3 n)
{
    float2 p = n.xy / (n.z + 1.0);
    return p * (0.5 / 1.7777) + 0.5;
}
float3 FacetDecodeViewNormal(float2 enc)
{
    float2 p = (enc * 2.0 - 1.0) * 1.7777;
    float k = 2.0 / (dot(p, p) + 1.0);
    return float3(p * k, k - 1.0);
}

// ---- vertex lights ---------------------------------------------------------------
// Diffuse light of four point lights given as columns (positions split by
// axis, squared-distance attenuation factors), at a world position/normal:
// sum of colour * max(0, n.l) / (1 + d^2 * atten).
float3 FacetShade4PointLights(float4 posX, float4 posY, float4 posZ, float3 col0, float3 col1, float3 col2,
                              float3 col3, float4 attenSq, float3 pos, float3 normal)
{
    float4 dx = posX - pos.x;
    float4 dy = posY - pos.y;
    float4 dz = posZ - pos.z;
    float4 distSq = max(dx * dx + dy * dy + dz * dz, 0.000001);
    float4 ndotl = max(0.0, (dx * normal.x + dy * normal.y + dz * normal.z) * rsqrt(distSq));
    float4 diff = ndotl / (1.0 + distSq * attenSq);
    return col0 * diff.x + col1 * diff.y + col2 * diff.z + col3 * diff.w;
}

// Ordered-dither threshold of a pixel, in (0, 1): a 4x4 Bayer matrix.
float FacetDitherThreshold(float2 pixel)
{
    static const float kBayer[16] = {0, 8, 2, 10, 12, 4, 14, 6, 3, 11, 1, 9, 15, 7, 13, 5};
    uint2 p = uint2(pixel) & 3u;
    return (kBayer[p.y * 4u + p.x] + 0.5) / 16.0;
}

// ---- fog -------------------------------------------------------------------------
// Distance from the camera plane for a clip-space position: w for a
// perspective projection, near + z * (far - near) for an orthographic one.
float FacetFogDistance(float4 clipPos)
{
    float ortho = _ProjectionParams.y + clipPos.z * (_ProjectionParams.z - _ProjectionParams.y);
    return lerp(clipPos.w, ortho, unity_OrthoParams.w);
}
// The fog interpolator with the fog distance in .x, for interpolators of any
// width (UNITY_FOG_COORDS declares a float1, UNITY_FOG_COORDS_PACKED wider
// ones). Returned rather than written through `inout`/`.x`: glslang 12
// cannot write through a float1 struct member.
float FacetWithFogDistance(float coord, float distance) { return distance; }
float2 FacetWithFogDistance(float2 coord, float distance) { coord.x = distance; return coord; }
float3 FacetWithFogDistance(float3 coord, float distance) { coord.x = distance; return coord; }
float4 FacetWithFogDistance(float4 coord, float distance) { coord.x = distance; return coord; }
// 1 = no fog, 0 = only fog colour, following the FOG_* keyword in use.
float FacetFogFactor(float distance)
{
#if defined(FOG_LINEAR)
    return saturate(distance * unity_FogParams.z + unity_FogParams.w);
#elif defined(FOG_EXP)
    return saturate(exp2(-unity_FogParams.y * distance));
#elif defined(FOG_EXP2)
    float d = unity_FogParams.x * distance;
    return saturate(exp2(-d * d));
#else
    return 1.0;
#endif
}

#endif // FACET_CORE_INCLUDED
