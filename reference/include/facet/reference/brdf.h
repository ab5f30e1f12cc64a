// Double-precision twins of stdlib/FacetBRDF.hlsl: same names, same arguments
// (float -> double, float3 -> glm::dvec3), same formulas and clamps. The case
// table (cases.h) pairs each with its HLSL original; docs/lighting-models.md
// documents them.
#pragma once

#include "facet/reference/hlsl_math.h"

namespace facet::reference {

inline constexpr double FACET_MIN_NOV = 1e-4;
inline constexpr double FACET_MIN_PERCEPTUAL_ROUGHNESS = 0.045;
inline constexpr double FACET_MIN_ALPHA = 0.002025;
inline constexpr double FACET_MIN_PERCEPTUAL_ROUGHNESS_FP16 = 0.089;
inline constexpr double FACET_MIN_ALPHA_FP16 = 0.007921;
inline constexpr double FACET_HALF_MIN = 6.103515625e-5;
inline constexpr double FACET_HALF_MAX = 65504.0;
inline constexpr double FACET_GGX_FP16_K_MAX = 453.5;

// ---- helpers ----
inline double FacetPow5(double x) {
  double x2 = x * x;
  return x2 * x2 * x;
}
// The HLSL side is a polynomial within 2.2e-8 of acos; the twin is exact.
inline double FacetAcos(double x) { return std::acos(std::clamp(x, -1.0, 1.0)); }
inline double FacetClampNoV(double NoV) { return std::max(NoV, FACET_MIN_NOV); }
inline double FacetClampAlpha(double alpha) { return std::max(alpha, FACET_MIN_ALPHA); }
inline double FacetPerceptualRoughnessToAlpha(double r) { return r * r; }
inline glm::dvec3 FacetSafeNormalize(const glm::dvec3& v) {
  return v * rsqrt(std::max(glm::dot(v, v), FACET_HALF_MIN));
}

struct FacetAngles {
  double NoV = 0;
  double NoL = 0;
  double NoH = 0;
  double LoH = 0;
  double LoV = 0;
};
inline FacetAngles FacetComputeAngles(glm::dvec3 n, glm::dvec3 v, glm::dvec3 l) {
  n = FacetSafeNormalize(n);
  v = FacetSafeNormalize(v);
  l = FacetSafeNormalize(l);
  glm::dvec3 h = FacetSafeNormalize(v + l);
  FacetAngles a;
  a.NoV = FacetClampNoV(glm::dot(n, v));
  a.NoL = saturate(glm::dot(n, l));
  a.NoH = saturate(glm::dot(n, h));
  a.LoH = saturate(glm::dot(l, h));
  a.LoV = std::clamp(glm::dot(l, v), -1.0, 1.0);
  return a;
}

// ---- diffuse ----
inline double FacetFd_Lambert() { return kInvPi; }

inline double FacetFd_Burley(double NoV, double NoL, double LoH, double perceptualRoughness) {
  double fd90 = 0.5 + 2.0 * perceptualRoughness * LoH * LoH;
  double lightScatter = 1.0 + (fd90 - 1.0) * FacetPow5(1.0 - NoL);
  double viewScatter = 1.0 + (fd90 - 1.0) * FacetPow5(1.0 - NoV);
  return lightScatter * viewScatter * kInvPi;
}

inline double FacetFd_Frostbite(double NoV, double NoL, double LoH, double alpha) {
  double energyBias = 0.5 * alpha;
  double energyFactor = lerp(1.0, 1.0 / 1.51, alpha);
  double fd90 = energyBias + 2.0 * alpha * LoH * LoH;
  double lightScatter = 1.0 + (fd90 - 1.0) * FacetPow5(1.0 - NoL);
  double viewScatter = 1.0 + (fd90 - 1.0) * FacetPow5(1.0 - NoV);
  return lightScatter * viewScatter * energyFactor * kInvPi;
}

inline double FacetFd_OrenNayarQualitative(double NoV, double NoL, double LoV, double sigma) {
  double s2 = sigma * sigma;
  double A = 1.0 - 0.5 * s2 / (s2 + 0.33);
  double B = 0.45 * s2 / (s2 + 0.09);
  double s = LoV - NoL * NoV;
  double t = std::max(std::max(NoL, NoV), FACET_MIN_NOV);
  return (A + B * std::max(s, 0.0) / t) * kInvPi;
}

inline double FacetFd_OrenNayar(double NoV, double NoL, double LoV, double sigma, double albedo) {
  double s2 = sigma * sigma;
  double cosA = saturate(std::min(NoL, NoV));
  double cosB = saturate(std::max(NoL, NoV));
  double sinA = std::sqrt(saturate((1.0 - cosA) * (1.0 + cosA)));
  double sinB = std::sqrt(saturate((1.0 - cosB) * (1.0 + cosB)));
  double alphaAngle = std::acos(cosA);
  double betaAngle = std::acos(cosB);
  double sinProduct = sinA * sinB;
  double cosPhi = sinProduct > 1e-6 ? std::clamp((LoV - NoL * NoV) / sinProduct, -1.0, 1.0) : 0.0;
  double twoBetaOverPi = 2.0 * betaAngle * kInvPi;
  double C1 = 1.0 - 0.5 * s2 / (s2 + 0.33);
  double C2 = 0.45 * s2 / (s2 + 0.09);
  C2 *= cosPhi >= 0.0 ? sinA : sinA - twoBetaOverPi * twoBetaOverPi * twoBetaOverPi;
  double fourAlphaBeta = 4.0 * alphaAngle * betaAngle * kInvPi * kInvPi;
  double C3 = 0.125 * s2 / (s2 + 0.09) * fourAlphaBeta * fourAlphaBeta;
  double tanBeta = sinB / std::max(cosB, FACET_MIN_NOV);
  double tanHalfSum = (sinA + sinB) / std::max(cosA + cosB, FACET_MIN_NOV);
  double direct = C1 + cosPhi * C2 * tanBeta + (1.0 - std::abs(cosPhi)) * C3 * tanHalfSum;
  double inter = 0.17 * albedo * s2 / (s2 + 0.13) * (1.0 - cosPhi * twoBetaOverPi * twoBetaOverPi);
  return albedo * kInvPi * (direct + inter);
}

// ---- Phong and Blinn-Phong ----
inline double FacetPhong(double RoV, double exponent) {
  return std::pow(std::max(RoV, 0.0), std::max(exponent, 1e-4));
}
inline double FacetPhongNormalized(double RoV, double exponent) {
  double n = std::max(exponent, 1e-4);
  return (n + 2.0) * (0.5 * kInvPi) * std::pow(std::max(RoV, 0.0), n);
}
inline double FacetBlinnPhong(double NoH, double exponent) {
  return std::pow(std::max(NoH, 0.0), std::max(exponent, 1e-4));
}
inline double FacetBlinnPhongNormalized(double NoH, double exponent) {
  double n = std::max(exponent, 1e-4);
  return (n + 8.0) * (0.125 * kInvPi) * std::pow(std::max(NoH, 0.0), n);
}
inline double FacetD_BlinnPhong(double NoH, double exponent) {
  double n = std::max(exponent, 1e-4);
  return (n + 2.0) * (0.5 * kInvPi) * std::pow(std::max(NoH, 0.0), n);
}
inline double FacetAlphaToBlinnPhongExponent(double alpha) {
  return std::max(2.0 / std::max(alpha * alpha, 1e-4) - 2.0, 1e-4);
}

// ---- normal distribution functions ----
inline double FacetD_GGX(double NoH, double alpha) {
  double a2 = alpha * alpha;
  double d = (NoH * a2 - NoH) * NoH + 1.0;
  return a2 / (kPi * d * d);
}
inline double FacetD_GGX_FP16Safe(const glm::dvec3& n, const glm::dvec3& h, double alpha) {
  glm::dvec3 nxh = glm::cross(n, h);
  double oneMinusNoH2 = glm::dot(nxh, nxh);
  double a = glm::dot(n, h) * alpha;
  double k = std::min(alpha / (oneMinusNoH2 + a * a), FACET_GGX_FP16_K_MAX);
  return k * (k * kInvPi);
}
inline double FacetD_GGXAnisotropic(double NoH, double HoX, double HoY, double alphaX, double alphaY) {
  double a2 = alphaX * alphaY;
  glm::dvec3 d(alphaY * HoX, alphaX * HoY, a2 * NoH);
  double d2 = glm::dot(d, d);
  double b2 = a2 / d2;
  return a2 * b2 * b2 * kInvPi;
}
inline double FacetD_Beckmann(double NoH, double alpha) {
  double a2 = alpha * alpha;
  double c2 = std::max(NoH * NoH, 1e-6);
  double tan2 = (1.0 - NoH) * (1.0 + NoH) / c2;
  return std::exp(-tan2 / a2) / (kPi * a2 * c2 * c2);
}

// ---- masking-shadowing ----
inline double FacetLambda_SmithGGX(double NoV, double alpha) {
  double c2 = std::max(NoV * NoV, 1e-12);
  double x = alpha * alpha * (1.0 - NoV) * (1.0 + NoV) / c2;
  return x / (2.0 * (1.0 + std::sqrt(1.0 + x)));
}
inline double FacetG1_SmithGGX(double NoV, double alpha) {
  double a2 = alpha * alpha;
  return 2.0 * NoV / (NoV + std::sqrt(a2 + (1.0 - a2) * NoV * NoV));
}
inline double FacetV_SmithGGXSeparable(double NoV, double NoL, double alpha) {
  double a2 = alpha * alpha;
  double gv = NoV + std::sqrt(a2 + (1.0 - a2) * NoV * NoV);
  double gl = NoL + std::sqrt(a2 + (1.0 - a2) * NoL * NoL);
  return 1.0 / (gv * gl);
}
inline double FacetV_SmithGGXCorrelated(double NoV, double NoL, double alpha) {
  double a2 = alpha * alpha;
  double lambdaV = NoL * std::sqrt((NoV - a2 * NoV) * NoV + a2);
  double lambdaL = NoV * std::sqrt((NoL - a2 * NoL) * NoL + a2);
  return 0.5 / (lambdaV + lambdaL);
}
inline double FacetV_SmithGGXCorrelatedFast(double NoV, double NoL, double alpha) {
  return 0.5 / lerp(2.0 * NoL * NoV, NoL + NoV, alpha);
}
inline double FacetV_SmithSchlick(double NoV, double NoL, double k) {
  double gv = NoV * (1.0 - k) + k;
  double gl = NoL * (1.0 - k) + k;
  return 0.25 / (gv * gl);
}
inline double FacetV_SchlickGGX(double NoV, double NoL, double alpha) {
  return FacetV_SmithSchlick(NoV, NoL, 0.5 * alpha);
}
inline double FacetV_SchlickGGXKaris(double NoV, double NoL, double perceptualRoughness) {
  double r1 = perceptualRoughness + 1.0;
  return FacetV_SmithSchlick(NoV, NoL, r1 * r1 * 0.125);
}
inline double FacetG1_SmithBeckmann(double NoV, double alpha) {
  double sinV = std::sqrt(saturate((1.0 - NoV) * (1.0 + NoV)));
  double a = NoV / std::max(alpha * sinV, 1e-12);
  double g = (3.535 * a + 2.181 * a * a) / (1.0 + 2.276 * a + 2.577 * a * a);
  return a < 1.6 ? g : 1.0;
}
inline double FacetG_CookTorrance(double NoV, double NoL, double NoH, double VoH) {
  double g = 2.0 * NoH * std::min(NoV, NoL) / std::max(VoH, 1e-6);
  return std::min(1.0, g);
}

// ---- Fresnel ----
inline double FacetF_Schlick(double f0, double f90, double VoH) {
  return f0 + (f90 - f0) * FacetPow5(1.0 - VoH);
}
inline glm::dvec3 FacetF_Schlick(const glm::dvec3& f0, double f90, double VoH) {
  return f0 + (f90 - f0) * FacetPow5(1.0 - VoH);
}
inline glm::dvec3 FacetF_SchlickSG(const glm::dvec3& f0, double f90, double VoH) {
  double w = std::exp2((-5.55473 * VoH - 6.98316) * VoH);
  return f0 + (f90 - f0) * w;
}
inline double FacetF90FromF0(const glm::dvec3& f0) { return saturate(glm::dot(f0, glm::dvec3(16.5))); }
inline double FacetF0FromIOR(double eta) {
  double r = (eta - 1.0) / (eta + 1.0);
  return r * r;
}
inline double FacetF_Dielectric(double eta, double cosI) {
  double c = saturate(cosI);
  double g2 = eta * eta - 1.0 + c * c;
  if (g2 <= 0.0) return 1.0;
  double g = std::sqrt(g2);
  double a = (g - c) / (g + c);
  double b = (c * (g + c) - 1.0) / (c * (g - c) + 1.0);
  return 0.5 * a * a * (1.0 + b * b);
}
inline glm::dvec3 FacetF_Conductor(const glm::dvec3& eta, const glm::dvec3& k, double cosI) {
  double c = saturate(cosI);
  double c2 = c * c;
  double s2 = (1.0 - c) * (1.0 + c);
  glm::dvec3 t = eta * eta - k * k - s2;
  glm::dvec3 ek2 = eta * eta * k * k;
  glm::dvec3 w = glm::sqrt(t * t + 4.0 * ek2);
  glm::dvec3 aPos = 0.5 * (w + t);
  glm::dvec3 aNeg = 2.0 * ek2 / max3(w - t, 1e-30);
  glm::dvec3 a2 = lerp(aNeg, aPos, step(0.0, t));
  glm::dvec3 a = glm::sqrt(a2);
  glm::dvec3 rs = (w - 2.0 * a * c + c2) / (w + 2.0 * a * c + c2);
  glm::dvec3 pTerm = 2.0 * a * c * s2;
  glm::dvec3 rp = rs * (c2 * w - pTerm + s2 * s2) / (c2 * w + pTerm + s2 * s2);
  return 0.5 * (rs + rp);
}

// ---- specular lobes ----
inline glm::dvec3 FacetSpecular_GGX(double NoV, double NoL, double NoH, double LoH, double alpha,
                                    const glm::dvec3& f0, double f90) {
  return FacetD_GGX(NoH, alpha) * FacetV_SmithGGXCorrelated(NoV, NoL, alpha) * FacetF_Schlick(f0, f90, LoH);
}
inline glm::dvec3 FacetSpecular_Beckmann(double NoV, double NoL, double NoH, double LoH, double alpha,
                                         const glm::dvec3& f0, double f90) {
  double g = FacetG1_SmithBeckmann(NoV, alpha) * FacetG1_SmithBeckmann(NoL, alpha);
  double v = g / std::max(4.0 * NoL * NoV, 1e-12);
  return FacetD_Beckmann(NoH, alpha) * v * FacetF_Schlick(f0, f90, LoH);
}
inline double FacetSpecular_AshikhminShirley(double NoV, double NoL, double NoH, double HoV, double HoX,
                                             double HoY, double nu, double nv, double rs) {
  double x2 = HoX * HoX;
  double y2 = HoY * HoY;
  double n = std::max((nu * x2 + nv * y2) / std::max(x2 + y2, 1e-12), 1e-4);
  double norm = std::sqrt((nu + 1.0) * (nv + 1.0)) * (0.125 * kInvPi);
  double F = FacetF_Schlick(rs, 1.0, HoV);
  return norm * F * std::pow(std::max(NoH, 0.0), n) / std::max(HoV * std::max(NoV, NoL), 1e-6);
}
inline double FacetFd_AshikhminShirley(double NoV, double NoL, double rd, double rs) {
  double k = 28.0 / (23.0 * kPi);
  double fl = 1.0 - FacetPow5(1.0 - 0.5 * NoL);
  double fv = 1.0 - FacetPow5(1.0 - 0.5 * NoV);
  return k * rd * (1.0 - rs) * fl * fv;
}
inline double FacetSpecular_Ward(double NoV, double NoL, double NoH, double HoX, double HoY, double alphaX,
                                 double alphaY) {
  double x = HoX / alphaX;
  double y = HoY / alphaY;
  double e = -(x * x + y * y) / std::max(NoH * NoH, 1e-6);
  return std::exp(e) / (4.0 * kPi * alphaX * alphaY * std::sqrt(std::max(NoL * NoV, 1e-6)));
}

// ---- multiscatter energy compensation ----
inline glm::dvec3 FacetEnergyCompensation(const glm::dvec3& f0, double E) { return 1.0 + f0 * (1.0 / E - 1.0); }

// ---- translucency ----
inline double FacetTranslucency(const glm::dvec3& n, const glm::dvec3& v, const glm::dvec3& l, double distortion,
                                double power, double scale, double ambient, double thickness) {
  glm::dvec3 h = l + n * distortion;
  double I = std::pow(saturate(glm::dot(v, -h)), std::max(power, 1e-4)) * scale;
  return (I + ambient) * thickness;
}

// ---- assembled lobes ----
inline glm::dvec3 FacetBRDF_CookTorranceGGX(const glm::dvec3& n, const glm::dvec3& v, const glm::dvec3& l,
                                            const glm::dvec3& f0, double perceptualRoughness) {
  FacetAngles a = FacetComputeAngles(n, v, l);
  double alpha = FacetClampAlpha(perceptualRoughness * perceptualRoughness);
  return FacetSpecular_GGX(a.NoV, a.NoL, a.NoH, a.LoH, alpha, f0, 1.0);
}
inline glm::dvec3 FacetBRDF_CookTorranceBeckmann(const glm::dvec3& n, const glm::dvec3& v, const glm::dvec3& l,
                                                 const glm::dvec3& f0, double perceptualRoughness) {
  FacetAngles a = FacetComputeAngles(n, v, l);
  double alpha = FacetClampAlpha(perceptualRoughness * perceptualRoughness);
  return FacetSpecular_Beckmann(a.NoV, a.NoL, a.NoH, a.LoH, alpha, f0, 1.0);
}

}  // namespace facet::reference
