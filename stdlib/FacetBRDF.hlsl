// facet's lighting library: the BRDF terms (diffuse, specular D/V/G/F, the
// classic lobes) and their assembly. Every function here has a double-precision
// C++ twin of the same name in reference/include/facet/reference/, and every
// formula, input range, energy figure and cost is in docs/lighting-models.md.
//
// Conventions: BRDFs are returned WITHOUT the cosine (multiply by NoL);
// alpha = perceptualRoughness^2 ("linear roughness"); NoV etc. are cosines
// already prepared by the caller: NoL = saturate(dot(n, l)),
// NoV = FacetClampNoV(dot(n, v)), alpha >= FACET_MIN_ALPHA, unless the
// function says otherwise. FacetComputeAngles does this preparation.
// The file needs no resources (no cbuffers, no textures), so any stage or a
// compute shader can include it.
#ifndef FACET_BRDF_INCLUDED
#define FACET_BRDF_INCLUDED

#ifndef FACET_PI
#define FACET_PI 3.14159265358979323846
#endif
#define FACET_INV_PI 0.31830988618379067154

// Clamps (docs/lighting-models.md, docs/stability.md "The models").
#define FACET_MIN_NOV 1e-4                    // ~0.0057 degrees of bias at grazing views
#define FACET_MIN_PERCEPTUAL_ROUGHNESS 0.045  // fp32: alpha = 0.002025
#define FACET_MIN_ALPHA 0.002025
#define FACET_MIN_PERCEPTUAL_ROUGHNESS_FP16 0.089  // alpha^2 stays a normal fp16 number
#define FACET_MIN_ALPHA_FP16 0.007921
#define FACET_HALF_MIN 6.103515625e-5         // smallest normal fp16 number, 2^-14
#define FACET_HALF_MAX 65504.0
#define FACET_GGX_FP16_K_MAX 453.5            // 453.5^2/pi = 65464 < 65504

// ---- helpers -------------------------------------------------------------------
// x^5 by multiplies: same cost as pow() and no NaN for a slightly negative x.
float FacetPow5(float x)
{
    float x2 = x * x;
    return x2 * x2 * x;
}
// acos to 2.2e-8 (Abramowitz & Stegun 4.4.46), for x in [-1, 1]: the GPU's
// own acos is not good to 1e-4 relative in the Oren-Nayar terms (lavapipe).
float FacetAcos(float x)
{
    float a = abs(x);
    float p = -0.0012624911;
    p = p * a + 0.0066700901;
    p = p * a - 0.0170881256;
    p = p * a + 0.0308918810;
    p = p * a - 0.0501743046;
    p = p * a + 0.0889789874;
    p = p * a - 0.2145988016;
    p = p * a + 1.5707963050;
    float r = sqrt(saturate(1.0 - a)) * p;
    return x >= 0.0 ? r : FACET_PI - r;
}
float FacetClampNoV(float NoV) { return max(NoV, FACET_MIN_NOV); }
float FacetClampAlpha(float alpha) { return max(alpha, FACET_MIN_ALPHA); }
float FacetPerceptualRoughnessToAlpha(float perceptualRoughness) { return perceptualRoughness * perceptualRoughness; }
// A zero vector stays zero instead of becoming NaN (L = -V gives H = 0); the
// floor is the smallest normal fp16 number so the guard also holds in half.
float3 FacetSafeNormalize(float3 v) { return v * rsqrt(max(dot(v, v), FACET_HALF_MIN)); }

// The cosines every lobe needs, with the clamps of the conventions above.
struct FacetAngles
{
    float NoV;  // clamped to >= FACET_MIN_NOV (a back-facing view shades as grazing)
    float NoL;  // saturated: a light behind the surface gives NoL = 0
    float NoH;
    float LoH;  // == VoH
    float LoV;  // signed
};
FacetAngles FacetComputeAngles(float3 n, float3 v, float3 l)
{
    n = FacetSafeNormalize(n);
    v = FacetSafeNormalize(v);
    l = FacetSafeNormalize(l);
    float3 h = FacetSafeNormalize(v + l);
    FacetAngles a;
    a.NoV = FacetClampNoV(dot(n, v));
    a.NoL = saturate(dot(n, l));
    a.NoH = saturate(dot(n, h));
    a.LoH = saturate(dot(l, h));
    a.LoV = clamp(dot(l, v), -1.0, 1.0);
    return a;
}

// ---- diffuse (all include the 1/pi; multiply by the albedo) ---------------------
float FacetFd_Lambert() { return FACET_INV_PI; }

// Burley 2012 ("Disney diffuse"); roughness is PERCEPTUAL here, as in Burley's
// notes and Unity (Filament passes alpha). Not energy conserving (albedo 1.52).
float FacetFd_Burley(float NoV, float NoL, float LoH, float perceptualRoughness)
{
    float fd90 = 0.5 + 2.0 * perceptualRoughness * LoH * LoH;
    float lightScatter = 1.0 + (fd90 - 1.0) * FacetPow5(1.0 - NoL);
    float viewScatter = 1.0 + (fd90 - 1.0) * FacetPow5(1.0 - NoV);
    return lightScatter * viewScatter * FACET_INV_PI;
}

// Frostbite's renormalised Burley (Lagarde & de Rousiers 2014); alpha is LINEAR
// roughness. Albedo <= 1.006 at alpha = 1.
float FacetFd_Frostbite(float NoV, float NoL, float LoH, float alpha)
{
    float energyBias = 0.5 * alpha;
    float energyFactor = lerp(1.0, 1.0 / 1.51, alpha);
    float fd90 = energyBias + 2.0 * alpha * LoH * LoH;
    float lightScatter = 1.0 + (fd90 - 1.0) * FacetPow5(1.0 - NoL);
    float viewScatter = 1.0 + (fd90 - 1.0) * FacetPow5(1.0 - NoV);
    return lightScatter * viewScatter * energyFactor * FACET_INV_PI;
}

// Oren-Nayar "qualitative" model in vector form (no trigonometry):
// (A + B max(0, cos dphi) sin(alpha) tan(beta)) / pi, with
// cos(dphi) sin(theta_i) sin(theta_r) = LoV - NoL NoV and
// sin(alpha) tan(beta) = that / max(NoL, NoV). sigma = slope deviation (radians).
float FacetFd_OrenNayarQualitative(float NoV, float NoL, float LoV, float sigma)
{
    float s2 = sigma * sigma;
    float orenA = 1.0 - 0.5 * s2 / (s2 + 0.33);
    float orenB = 0.45 * s2 / (s2 + 0.09);
    float s = LoV - NoL * NoV;
    float t = max(max(NoL, NoV), FACET_MIN_NOV);
    return (orenA + orenB * max(s, 0.0) / t) * FACET_INV_PI;
}

// Oren-Nayar full model (1994): the C1..C3 direct terms and the interreflection
// term, which is quadratic in the albedo, so the albedo is an argument and the
// result is the whole BRDF (not a factor). Cosines must be in [0, 1].
// sin(alpha), tan(beta) and tan((alpha + beta)/2) = (sin a + sin b)/(cos a + cos b)
// come from square roots and the angles from FacetAcos: the GPU's sin, tan
// and acos are too loose for 1e-4 relative (measured on lavapipe).
float FacetFd_OrenNayar(float NoV, float NoL, float LoV, float sigma, float albedo)
{
    float s2 = sigma * sigma;
    float cosA = saturate(min(NoL, NoV));  // alpha = the larger polar angle
    float cosB = saturate(max(NoL, NoV));  // beta = the smaller
    float sinA = sqrt(saturate((1.0 - cosA) * (1.0 + cosA)));
    float sinB = sqrt(saturate((1.0 - cosB) * (1.0 + cosB)));
    float alphaAngle = FacetAcos(cosA);
    float betaAngle = FacetAcos(cosB);
    // cos of the azimuth difference; 0 when either direction is the normal,
    // where every term that uses it is multiplied by a zero anyway.
    float sinProduct = sinA * sinB;
    float cosPhi = sinProduct > 1e-6 ? clamp((LoV - NoL * NoV) / sinProduct, -1.0, 1.0) : 0.0;
    float twoBetaOverPi = 2.0 * betaAngle * FACET_INV_PI;
    float coefC1 = 1.0 - 0.5 * s2 / (s2 + 0.33);
    float coefC2 = 0.45 * s2 / (s2 + 0.09);
    coefC2 *= cosPhi >= 0.0 ? sinA : sinA - twoBetaOverPi * twoBetaOverPi * twoBetaOverPi;
    float fourAlphaBeta = 4.0 * alphaAngle * betaAngle * FACET_INV_PI * FACET_INV_PI;
    float coefC3 = 0.125 * s2 / (s2 + 0.09) * fourAlphaBeta * fourAlphaBeta;
    float tanBeta = sinB / max(cosB, FACET_MIN_NOV);
    float tanHalfSum = (sinA + sinB) / max(cosA + cosB, FACET_MIN_NOV);
    float direct = coefC1 + cosPhi * coefC2 * tanBeta + (1.0 - abs(cosPhi)) * coefC3 * tanHalfSum;
    float inter = 0.17 * albedo * s2 / (s2 + 0.13) * (1.0 - cosPhi * twoBetaOverPi * twoBetaOverPi);
    return albedo * FACET_INV_PI * (direct + inter);
}

// ---- Phong and Blinn-Phong ------------------------------------------------------
// RoV = dot(reflect(-l, n), v). The exponent is floored at 1e-4 and the base at 0
// so that pow(0, 0) and pow(negative, n) (both NaN) cannot happen.
float FacetPhong(float RoV, float exponent)
{
    return pow(max(RoV, 0.0), max(exponent, 1e-4));
}
// Lewis 1994 normalisation: albedo <= 1 for every exponent.
float FacetPhongNormalized(float RoV, float exponent)
{
    float n = max(exponent, 1e-4);
    return (n + 2.0) * (0.5 * FACET_INV_PI) * pow(max(RoV, 0.0), n);
}
float FacetBlinnPhong(float NoH, float exponent)
{
    return pow(max(NoH, 0.0), max(exponent, 1e-4));
}
// The whole-BRDF approximation (n+8)/(8 pi): albedo up to 1.075 (n = 10).
float FacetBlinnPhongNormalized(float NoH, float exponent)
{
    float n = max(exponent, 1e-4);
    return (n + 8.0) * (0.125 * FACET_INV_PI) * pow(max(NoH, 0.0), n);
}
// Blinn-Phong as a normalised NDF, integral of D(h)(n.h) = 1.
float FacetD_BlinnPhong(float NoH, float exponent)
{
    float n = max(exponent, 1e-4);
    return (n + 2.0) * (0.5 * FACET_INV_PI) * pow(max(NoH, 0.0), n);
}
// Walter 2007's match between Blinn-Phong and Beckmann/GGX widths.
float FacetAlphaToBlinnPhongExponent(float alpha)
{
    return max(2.0 / max(alpha * alpha, 1e-4) - 2.0, 1e-4);
}

// ---- normal distribution functions ----------------------------------------------
// GGX / Trowbridge-Reitz, the plain form 1 - NoH^2 (1 - alpha^2) (2 mad). In fp32
// it cancels near NoH = 1 when alpha is small; in fp16 it is off by up to 76x at
// alpha = 0.0079. Use FacetD_GGX_FP16Safe there.
float FacetD_GGX(float NoH, float alpha)
{
    float a2 = alpha * alpha;
    float d = (NoH * a2 - NoH) * NoH + 1.0;
    return a2 / (FACET_PI * d * d);
}
// GGX with 1 - NoH^2 taken as |n x h|^2 (Lagrange identity), which keeps its
// relative precision near the highlight, and the fp16 overflow guard k <= 453.5
// (so D <= 65464). n and h must be unit vectors.
float FacetD_GGX_FP16Safe(float3 n, float3 h, float alpha)
{
    float3 nxh = cross(n, h);
    float oneMinusNoH2 = dot(nxh, nxh);
    float a = dot(n, h) * alpha;
    float k = min(alpha / (oneMinusNoH2 + a * a), FACET_GGX_FP16_K_MAX);
    return k * (k * FACET_INV_PI);  // not (k * k) / pi: k^2 alone overflows half for k > 256
}
// Anisotropic GGX (Burley 2012) in Filament's arrangement; HoX/HoY are against
// the tangent/bitangent, alphaX/alphaY >= FACET_MIN_ALPHA.
float FacetD_GGXAnisotropic(float NoH, float HoX, float HoY, float alphaX, float alphaY)
{
    float a2 = alphaX * alphaY;
    float3 d = float3(alphaY * HoX, alphaX * HoY, a2 * NoH);
    float d2 = dot(d, d);
    float b2 = a2 / d2;
    return a2 * b2 * b2 * FACET_INV_PI;
}
// Beckmann: exp(-tan^2/alpha^2) / (pi alpha^2 cos^4). 1 - NoH^2 is written as
// (1 - NoH)(1 + NoH), exact for NoH in [0.5, 1], so no cancellation at the peak.
float FacetD_Beckmann(float NoH, float alpha)
{
    float a2 = alpha * alpha;
    float c2 = max(NoH * NoH, 1e-6);
    float tan2 = (1.0 - NoH) * (1.0 + NoH) / c2;
    return exp(-tan2 / a2) / (FACET_PI * a2 * c2 * c2);
}

// ---- masking-shadowing (V = G / (4 NoL NoV), G1, Lambda) ------------------------
// Smith GGX Lambda, (-1 + sqrt(1 + alpha^2 tan^2)) / 2 written without the
// cancellation: alpha^2 tan^2 / (2 (1 + sqrt(1 + alpha^2 tan^2))).
float FacetLambda_SmithGGX(float NoV, float alpha)
{
    float c2 = max(NoV * NoV, 1e-12);
    float x = alpha * alpha * (1.0 - NoV) * (1.0 + NoV) / c2;
    return x / (2.0 * (1.0 + sqrt(1.0 + x)));
}
// Exact Smith GGX G1 = 2 NoV / (NoV + sqrt(alpha^2 + (1 - alpha^2) NoV^2)).
float FacetG1_SmithGGX(float NoV, float alpha)
{
    float a2 = alpha * alpha;
    return 2.0 * NoV / (NoV + sqrt(a2 + (1.0 - a2) * NoV * NoV));
}
// Exact separable Smith GGX, G1(v) G1(l) / (4 NoL NoV) with the 4 NoL NoV
// cancelled, so no division by a grazing cosine.
float FacetV_SmithGGXSeparable(float NoV, float NoL, float alpha)
{
    float a2 = alpha * alpha;
    float gv = NoV + sqrt(a2 + (1.0 - a2) * NoV * NoV);
    float gl = NoL + sqrt(a2 + (1.0 - a2) * NoL * NoL);
    return 1.0 / (gv * gl);
}
// Height-correlated Smith GGX (Heitz 2014), Filament's form. Finite for
// NoV >= FACET_MIN_NOV and alpha > 0.
float FacetV_SmithGGXCorrelated(float NoV, float NoL, float alpha)
{
    float a2 = alpha * alpha;
    float lambdaV = NoL * sqrt((NoV - a2 * NoV) * NoV + a2);
    float lambdaL = NoV * sqrt((NoL - a2 * NoL) * NoL + a2);
    return 0.5 / (lambdaV + lambdaL);
}
// Hammon 2017 approximation of the height-correlated V (no square roots);
// max relative error -27.5 % (alpha = 0.05), exact at alpha = 1.
float FacetV_SmithGGXCorrelatedFast(float NoV, float NoL, float alpha)
{
    return 0.5 / lerp(2.0 * NoL * NoV, NoL + NoV, alpha);
}
// Smith with Schlick's G1 = NoV / (NoV (1 - k) + k), as a V.
float FacetV_SmithSchlick(float NoV, float NoL, float k)
{
    float gv = NoV * (1.0 - k) + k;
    float gl = NoL * (1.0 - k) + k;
    return 0.25 / (gv * gl);
}
// Schlick-GGX with k = alpha / 2 (Karis 2013, for image-based lighting).
float FacetV_SchlickGGX(float NoV, float NoL, float alpha)
{
    return FacetV_SmithSchlick(NoV, NoL, 0.5 * alpha);
}
// Schlick-GGX with Karis' analytic-light k = (r + 1)^2 / 8 (Disney's "hotness"
// remap); r is PERCEPTUAL roughness. Deliberately darker than Smith.
float FacetV_SchlickGGXKaris(float NoV, float NoL, float perceptualRoughness)
{
    float r1 = perceptualRoughness + 1.0;
    return FacetV_SmithSchlick(NoV, NoL, r1 * r1 * 0.125);
}
// Smith Beckmann G1 with Walter 2007's rational fit of the erf form
// (relative error < 0.35 %).
float FacetG1_SmithBeckmann(float NoV, float alpha)
{
    float sinV = sqrt(saturate((1.0 - NoV) * (1.0 + NoV)));
    float a = NoV / max(alpha * sinV, 1e-12);
    float g = (3.535 * a + 2.181 * a * a) / (1.0 + 2.276 * a + 2.577 * a * a);
    return a < 1.6 ? g : 1.0;
}
// The original Cook-Torrance (1982) V-groove G.
float FacetG_CookTorrance(float NoV, float NoL, float NoH, float VoH)
{
    float g = 2.0 * NoH * min(NoV, NoL) / max(VoH, 1e-6);
    return min(1.0, g);
}

// ---- Fresnel ----------------------------------------------------------------------
// Schlick, pow5 by multiplies (Unity's BSDF.hlsl counts sub mul mul mul sub mad).
float FacetF_Schlick(float f0, float f90, float VoH)
{
    return f0 + (f90 - f0) * FacetPow5(1.0 - VoH);
}
float3 FacetF_Schlick(float3 f0, float f90, float VoH)
{
    return f0 + (f90 - f0) * FacetPow5(1.0 - VoH);
}
// Schlick with the spherical-Gaussian exponent 2^((-5.55473 c - 6.98316) c)
// (Karis 2013): |w - (1 - c)^5| <= 0.0038.
float3 FacetF_SchlickSG(float3 f0, float f90, float VoH)
{
    float w = exp2((-5.55473 * VoH - 6.98316) * VoH);
    return f0 + (f90 - f0) * w;
}
// Filament's f90: any f0 under 2 % is taken as pre-baked occlusion.
float FacetF90FromF0(float3 f0) { return saturate(dot(f0, float3(16.5, 16.5, 16.5))); }
float FacetF0FromIOR(float eta)
{
    float r = (eta - 1.0) / (eta + 1.0);
    return r * r;
}
// Exact unpolarised Fresnel reflectance of a dielectric with relative IOR eta
// (transmitted / incident side), total internal reflection gives 1.
float FacetF_Dielectric(float eta, float cosI)
{
    float c = saturate(cosI);
    float g2 = eta * eta - 1.0 + c * c;
    if (g2 <= 0.0)
        return 1.0;
    float g = sqrt(g2);
    float a = (g - c) / (g + c);
    float b = (c * (g + c) - 1.0) / (c * (g - c) + 1.0);
    return 0.5 * a * a * (1.0 + b * b);
}
// Exact unpolarised Fresnel reflectance of a conductor with complex IOR
// eta + i k (from air), per channel. a^2 = (|t| + t) / 2 is formed without
// cancellation when t = eta^2 - k^2 - sin^2 is negative (most metals).
float3 FacetF_Conductor(float3 eta, float3 k, float cosI)
{
    float c = saturate(cosI);
    float c2 = c * c;
    float s2 = (1.0 - c) * (1.0 + c);
    float3 t = eta * eta - k * k - s2;
    float3 ek2 = eta * eta * k * k;
    float3 w = sqrt(t * t + 4.0 * ek2);  // a^2 + b^2
    float3 aPos = 0.5 * (w + t);
    float3 aNeg = 2.0 * ek2 / max(w - t, 1e-30);
    float3 a2 = lerp(aNeg, aPos, step(0.0, t));
    float3 a = sqrt(a2);
    float3 rs = (w - 2.0 * a * c + c2) / (w + 2.0 * a * c + c2);
    float3 pTerm = 2.0 * a * c * s2;
    float3 rp = rs * (c2 * w - pTerm + s2 * s2) / (c2 * w + pTerm + s2 * s2);
    return 0.5 * (rs + rp);
}

// ---- specular lobes -----------------------------------------------------------------
// Cook-Torrance with GGX: D_GGX V_SmithGGXCorrelated F_Schlick (the HIGH path).
float3 FacetSpecular_GGX(float NoV, float NoL, float NoH, float LoH, float alpha, float3 f0, float f90)
{
    return FacetD_GGX(NoH, alpha) * FacetV_SmithGGXCorrelated(NoV, NoL, alpha) * FacetF_Schlick(f0, f90, LoH);
}
// Cook-Torrance with Beckmann: D_Beckmann, separable Smith Beckmann G, Schlick.
float3 FacetSpecular_Beckmann(float NoV, float NoL, float NoH, float LoH, float alpha, float3 f0, float f90)
{
    float g = FacetG1_SmithBeckmann(NoV, alpha) * FacetG1_SmithBeckmann(NoL, alpha);
    float v = g / max(4.0 * NoL * NoV, 1e-12);
    return FacetD_Beckmann(NoH, alpha) * v * FacetF_Schlick(f0, f90, LoH);
}
// Ashikhmin-Shirley 2000 anisotropic specular with Schlick F(HoV) from rs.
// The exponent (nu HoX^2 + nv HoY^2) / (1 - NoH^2) uses HoX^2 + HoY^2 as the
// denominator (equal for an orthonormal frame), which stays well defined at
// NoH = 1 where the limit does not matter (pow(1, any) = 1).
float FacetSpecular_AshikhminShirley(float NoV, float NoL, float NoH, float HoV, float HoX, float HoY,
                                     float nu, float nv, float rs)
{
    float x2 = HoX * HoX;
    float y2 = HoY * HoY;
    float n = max((nu * x2 + nv * y2) / max(x2 + y2, 1e-12), 1e-4);
    float norm = sqrt((nu + 1.0) * (nv + 1.0)) * (0.125 * FACET_INV_PI);
    float fresnel = FacetF_Schlick(rs, 1.0, HoV);
    return norm * fresnel * pow(max(NoH, 0.0), n) / max(HoV * max(NoV, NoL), 1e-6);
}
// Ashikhmin-Shirley's coupled diffuse (energy left over by a specular rs).
float FacetFd_AshikhminShirley(float NoV, float NoL, float rd, float rs)
{
    float k = 28.0 / (23.0 * FACET_PI);
    float fl = 1.0 - FacetPow5(1.0 - 0.5 * NoL);
    float fv = 1.0 - FacetPow5(1.0 - 0.5 * NoV);
    return k * rd * (1.0 - rs) * fl * fv;
}
// Ward, anisotropic, with Walter's 2005 normalisation. NoL NoV is floored at
// 1e-6 (the lobe grows as 1/sqrt(NoL NoV) at grazing).
float FacetSpecular_Ward(float NoV, float NoL, float NoH, float HoX, float HoY, float alphaX, float alphaY)
{
    float x = HoX / alphaX;
    float y = HoY / alphaY;
    float e = -(x * x + y * y) / max(NoH * NoH, 1e-6);
    return exp(e) / (4.0 * FACET_PI * alphaX * alphaY * sqrt(max(NoL * NoV, 1e-6)));
}

// ---- multiscatter energy compensation -------------------------------------------------
// Scales single-scatter specular by 1 + f0 (1/E - 1), E = the directional albedo
// of the lobe with F = 1 (dfg.y of the DFG table). Depends on v only: not reciprocal.
float3 FacetEnergyCompensation(float3 f0, float directionalAlbedo)
{
    return 1.0 + f0 * (1.0 / directionalAlbedo - 1.0);
}

// ---- translucency ------------------------------------------------------------------------
// Barre-Brisebois & Bouchard 2011 fast subsurface look: light shining through,
// seen against the light. Multiply by the light colour, attenuation and albedo.
float FacetTranslucency(float3 n, float3 v, float3 l, float distortion, float power, float scale,
                        float ambient, float thickness)
{
    float3 h = l + n * distortion;
    float intensity = pow(saturate(dot(v, -h)), max(power, 1e-4)) * scale;
    return (intensity + ambient) * thickness;
}

// ---- assembled lobes (vector inputs; robust on the hard-case grid) ------------------------
// Cook-Torrance GGX + Lambert is not bundled: callers add FacetFd_* themselves.
// perceptualRoughness in [0, 1] is clamped to FACET_MIN_ALPHA; f90 = 1.
float3 FacetBRDF_CookTorranceGGX(float3 n, float3 v, float3 l, float3 f0, float perceptualRoughness)
{
    FacetAngles a = FacetComputeAngles(n, v, l);
    float alpha = FacetClampAlpha(perceptualRoughness * perceptualRoughness);
    return FacetSpecular_GGX(a.NoV, a.NoL, a.NoH, a.LoH, alpha, f0, 1.0);
}
float3 FacetBRDF_CookTorranceBeckmann(float3 n, float3 v, float3 l, float3 f0, float perceptualRoughness)
{
    FacetAngles a = FacetComputeAngles(n, v, l);
    float alpha = FacetClampAlpha(perceptualRoughness * perceptualRoughness);
    return FacetSpecular_Beckmann(a.NoV, a.NoL, a.NoH, a.LoH, alpha, f0, 1.0);
}

#endif // FACET_BRDF_INCLUDED
