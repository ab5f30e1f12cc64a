// Double-precision twins of the Unity-named lighting functions of stdlib/
// (UnityStandardBRDF.cginc, UnityStandardUtils.cginc, UnityPBSLighting.cginc,
// Lighting.cginc, UnityCG.cginc) and of the facet functions they alias
// (FacetStandard.hlsl). Same names and arguments; the Unity structs are
// mirrored. The twins follow the default configuration: linear colour space,
// UNITY_BRDF_GGX 1, UNITY_CONSERVE_ENERGY(_MONOCHROME) 1, specular highlights
// on; keyword-driven behaviour (premultiplied alpha, indirect light) is a
// trailing parameter.
#pragma once

#include "facet/reference/hlsl_math.h"

#include <algorithm>
#include <cmath>

namespace facet::reference::unity {

using glm::dvec3;
using glm::dvec4;

struct UnityLight {
  dvec3 color{0};
  dvec3 dir{0, 1, 0};
  double ndotl = 0;
};
struct UnityIndirect {
  dvec3 diffuse{0};
  dvec3 specular{0};
};
struct UnityGI {
  UnityLight light;
  UnityIndirect indirect;
};
struct SurfaceOutput {
  dvec3 Albedo{0}, Normal{0, 0, 1}, Emission{0};
  double Specular = 0, Gloss = 0, Alpha = 1;
};
struct SurfaceOutputStandard {
  dvec3 Albedo{0}, Normal{0, 0, 1}, Emission{0};
  double Metallic = 0, Smoothness = 0, Occlusion = 1, Alpha = 1;
};
struct SurfaceOutputStandardSpecular {
  dvec3 Albedo{0}, Specular{0}, Normal{0, 0, 1}, Emission{0};
  double Smoothness = 0, Occlusion = 1, Alpha = 1;
};
// unity_SHAr ... unity_SHC.
struct SHCoefficients {
  dvec4 SHAr{0}, SHAg{0}, SHAb{0}, SHBr{0}, SHBg{0}, SHBb{0}, SHC{0};
};

// unity_ColorSpaceDielectricSpec in linear space.
inline const dvec4 kDielectricSpec{0.04, 0.04, 0.04, 1.0 - 0.04};

inline double Pow4(double x) { return x * x * x * x; }
inline double Pow5(double x) { return x * x * x * x * x; }
inline dvec3 Pow5(const dvec3& x) { return x * x * x * x * x; }
inline double FacetStdPow5(double x) { return Pow5(x); }
inline dvec3 Unity_SafeNormalize(const dvec3& v) { return v * rsqrt(std::max(0.001, glm::dot(v, v))); }
inline dvec3 FacetStdSafeNormalize(const dvec3& v) { return Unity_SafeNormalize(v); }

inline double SmoothnessToPerceptualRoughness(double s) { return 1.0 - s; }
inline double PerceptualRoughnessToRoughness(double r) { return r * r; }

inline dvec3 FresnelTerm(const dvec3& F0, double cosA) { return F0 + (1.0 - F0) * Pow5(1.0 - cosA); }
inline dvec3 FresnelLerp(const dvec3& F0, const dvec3& F90, double cosA) { return lerp(F0, F90, Pow5(1.0 - cosA)); }
inline dvec3 FresnelLerpFast(const dvec3& F0, const dvec3& F90, double cosA) { return lerp(F0, F90, Pow4(1.0 - cosA)); }

inline double DisneyDiffuse(double NdotV, double NdotL, double LdotH, double perceptualRoughness) {
  double fd90 = 0.5 + 2.0 * LdotH * LdotH * perceptualRoughness;
  return (1.0 + (fd90 - 1.0) * Pow5(1.0 - NdotL)) * (1.0 + (fd90 - 1.0) * Pow5(1.0 - NdotV));
}
inline double SmithVisibilityTerm(double NdotL, double NdotV, double k) {
  return 1.0 / ((NdotL * (1.0 - k) + k) * (NdotV * (1.0 - k) + k) + 1e-5);
}
inline double SmithBeckmannVisibilityTerm(double NdotL, double NdotV, double roughness) {
  return SmithVisibilityTerm(NdotL, NdotV, roughness * 0.797884560802865) * 0.25;
}
inline double SmithJointGGXVisibilityTerm(double NdotL, double NdotV, double roughness) {
  double a = roughness;
  double lambdaV = NdotL * (NdotV * (1.0 - a) + a);
  double lambdaL = NdotV * (NdotL * (1.0 - a) + a);
  return 0.5 / (lambdaV + lambdaL + 1e-5);
}
inline double GGXTerm(double NdotH, double roughness) {
  double a2 = roughness * roughness;
  double d = (NdotH * a2 - NdotH) * NdotH + 1.0;
  return kInvPi * a2 / (d * d + 1e-7);
}
inline double PerceptualRoughnessToSpecPower(double perceptualRoughness) {
  double m = perceptualRoughness * perceptualRoughness;
  double n = 2.0 / std::max(1e-4, m * m) - 2.0;
  return std::max(n, 1e-4);
}
inline double NDFBlinnPhongNormalizedTerm(double NdotH, double n) {
  return (n + 2.0) * (0.5 * kInvPi) * std::pow(NdotH, n);
}

inline double SpecularStrength(const dvec3& s) { return std::max({s.x, s.y, s.z}); }
inline dvec3 EnergyConservationBetweenDiffuseAndSpecular(const dvec3& albedo, const dvec3& specColor,
                                                         double& oneMinusReflectivity) {
  oneMinusReflectivity = 1.0 - SpecularStrength(specColor);
  return albedo * oneMinusReflectivity;
}
inline double OneMinusReflectivityFromMetallic(double metallic) {
  return kDielectricSpec.w - metallic * kDielectricSpec.w;
}
inline dvec3 DiffuseAndSpecularFromMetallic(const dvec3& albedo, double metallic, dvec3& specColor,
                                            double& oneMinusReflectivity) {
  specColor = lerp(dvec3(kDielectricSpec), albedo, metallic);
  oneMinusReflectivity = OneMinusReflectivityFromMetallic(metallic);
  return albedo * oneMinusReflectivity;
}
// `premultiply` stands for _ALPHAPREMULTIPLY_ON.
inline dvec3 PreMultiplyAlpha(dvec3 diffColor, double alpha, double oneMinusReflectivity, double& outModifiedAlpha,
                              bool premultiply = false) {
  if (!premultiply) {
    outModifiedAlpha = alpha;
    return diffColor;
  }
  outModifiedAlpha = 1.0 - oneMinusReflectivity + alpha * oneMinusReflectivity;
  return diffColor * alpha;
}

inline dvec4 BRDF1_Unity_PBS(const dvec3& diffColor, const dvec3& specColor, double oneMinusReflectivity,
                             double smoothness, const dvec3& normal, const dvec3& viewDir, const UnityLight& light,
                             const UnityIndirect& gi) {
  double perceptualRoughness = SmoothnessToPerceptualRoughness(smoothness);
  dvec3 halfDir = Unity_SafeNormalize(light.dir + viewDir);
  double nv = std::abs(glm::dot(normal, viewDir));
  double nl = saturate(glm::dot(normal, light.dir));
  double nh = saturate(glm::dot(normal, halfDir));
  double lh = saturate(glm::dot(light.dir, halfDir));
  double diffuseTerm = DisneyDiffuse(nv, nl, lh, perceptualRoughness) * nl;
  double roughness = std::max(PerceptualRoughnessToRoughness(perceptualRoughness), 0.002);
  double specularTerm = SmithJointGGXVisibilityTerm(nl, nv, roughness) * GGXTerm(nh, roughness) * kPi;
  specularTerm = std::max(0.0, specularTerm * nl);
  double surfaceReduction = 1.0 / (roughness * roughness + 1.0);
  if (specColor == dvec3(0)) specularTerm = 0.0;
  double grazingTerm = saturate(smoothness + (1.0 - oneMinusReflectivity));
  dvec3 color = diffColor * (gi.diffuse + light.color * diffuseTerm) +
                specularTerm * light.color * FresnelTerm(specColor, lh) +
                surfaceReduction * gi.specular * FresnelLerp(specColor, dvec3(grazingTerm), nv);
  return dvec4(color, 1.0);
}

inline dvec4 BRDF2_Unity_PBS(const dvec3& diffColor, const dvec3& specColor, double oneMinusReflectivity,
                             double smoothness, const dvec3& normal, const dvec3& viewDir, const UnityLight& light,
                             const UnityIndirect& gi) {
  dvec3 halfDir = Unity_SafeNormalize(light.dir + viewDir);
  double nl = saturate(glm::dot(normal, light.dir));
  double nh = saturate(glm::dot(normal, halfDir));
  double nv = saturate(glm::dot(normal, viewDir));
  double lh = saturate(glm::dot(light.dir, halfDir));
  double perceptualRoughness = SmoothnessToPerceptualRoughness(smoothness);
  double roughness = PerceptualRoughnessToRoughness(perceptualRoughness);
  double a2 = roughness * roughness;
  double d = nh * nh * (a2 - 1.0) + 1.00001;
  double specularTerm = a2 / (std::max(0.1, lh * lh) * (roughness + 0.5) * (d * d) * 4.0);
  double surfaceReduction = 1.0 - roughness * perceptualRoughness * (0.6 - 0.08 * perceptualRoughness);
  double grazingTerm = saturate(smoothness + (1.0 - oneMinusReflectivity));
  dvec3 color = (diffColor + specularTerm * specColor) * light.color * nl + gi.diffuse * diffColor +
                surfaceReduction * gi.specular * FresnelLerpFast(specColor, dvec3(grazingTerm), nv);
  return dvec4(color, 1.0);
}

// facet's analytic form of the unity_NHxRoughness lookup (FacetStandard.hlsl).
inline double FacetStdBRDF3Specular(double RdotL, double perceptualRoughness) {
  double n = PerceptualRoughnessToSpecPower(perceptualRoughness) * 0.25;
  return std::min((n + 2.0) * 0.5 * std::pow(saturate(RdotL), n), 16.0);
}

inline dvec4 BRDF3_Unity_PBS(const dvec3& diffColor, const dvec3& specColor, double oneMinusReflectivity,
                             double smoothness, const dvec3& normal, const dvec3& viewDir, const UnityLight& light,
                             const UnityIndirect& gi) {
  dvec3 reflDir = glm::reflect(-viewDir, normal);
  double nl = saturate(glm::dot(normal, light.dir));
  double nv = saturate(glm::dot(normal, viewDir));
  double specular = FacetStdBRDF3Specular(glm::dot(reflDir, light.dir), SmoothnessToPerceptualRoughness(smoothness));
  double fresnelTerm = Pow4(1.0 - nv);
  double grazingTerm = saturate(smoothness + (1.0 - oneMinusReflectivity));
  dvec3 color = (diffColor + specular * specColor) * light.color * nl + gi.diffuse * diffColor +
                gi.specular * lerp(specColor, dvec3(grazingTerm), fresnelTerm);
  return dvec4(color, 1.0);
}

// The tier UNITY_BRDF_PBS names (1, 2 or 3).
inline dvec4 UNITY_BRDF_PBS(int tier, const dvec3& diffColor, const dvec3& specColor, double oneMinusReflectivity,
                            double smoothness, const dvec3& normal, const dvec3& viewDir, const UnityLight& light,
                            const UnityIndirect& gi) {
  if (tier == 3) return BRDF3_Unity_PBS(diffColor, specColor, oneMinusReflectivity, smoothness, normal, viewDir, light, gi);
  if (tier == 2) return BRDF2_Unity_PBS(diffColor, specColor, oneMinusReflectivity, smoothness, normal, viewDir, light, gi);
  return BRDF1_Unity_PBS(diffColor, specColor, oneMinusReflectivity, smoothness, normal, viewDir, light, gi);
}

// ---- surface-shader lighting models (Lighting.cginc, UnityPBSLighting.cginc) ------
// `applyIndirect` stands for UNITY_LIGHT_FUNCTION_APPLY_INDIRECT (ForwardBase).
inline dvec4 LightingLambert(const SurfaceOutput& s, const UnityGI& gi, bool applyIndirect = true) {
  double diff = std::max(0.0, glm::dot(s.Normal, gi.light.dir));
  dvec3 c = s.Albedo * gi.light.color * diff;
  if (applyIndirect) c += s.Albedo * gi.indirect.diffuse;
  return dvec4(c, s.Alpha);
}
// `specColor` is the _SpecColor uniform.
inline dvec4 LightingBlinnPhong(const SurfaceOutput& s, const dvec3& viewDir, const UnityGI& gi, const dvec3& specColor,
                                bool applyIndirect = true) {
  dvec3 h = glm::normalize(gi.light.dir + viewDir);
  double diff = std::max(0.0, glm::dot(s.Normal, gi.light.dir));
  double nh = std::max(0.0, glm::dot(s.Normal, h));
  double spec = std::pow(nh, s.Specular * 128.0) * s.Gloss;
  dvec3 c = s.Albedo * gi.light.color * diff + gi.light.color * specColor * spec;
  if (applyIndirect) c += s.Albedo * gi.indirect.diffuse;
  return dvec4(c, s.Alpha);
}
inline dvec4 LightingStandard(SurfaceOutputStandard s, const dvec3& viewDir, const UnityGI& gi, int tier = 1,
                              bool premultiply = false) {
  s.Normal = glm::normalize(s.Normal);
  double oneMinusReflectivity;
  dvec3 specColor;
  s.Albedo = DiffuseAndSpecularFromMetallic(s.Albedo, s.Metallic, specColor, oneMinusReflectivity);
  double outputAlpha;
  s.Albedo = PreMultiplyAlpha(s.Albedo, s.Alpha, oneMinusReflectivity, outputAlpha, premultiply);
  dvec4 c = UNITY_BRDF_PBS(tier, s.Albedo, specColor, oneMinusReflectivity, s.Smoothness, s.Normal, viewDir, gi.light,
                           gi.indirect);
  c.w = outputAlpha;
  return c;
}
inline dvec4 LightingStandardSpecular(SurfaceOutputStandardSpecular s, const dvec3& viewDir, const UnityGI& gi,
                                      int tier = 1, bool premultiply = false) {
  s.Normal = glm::normalize(s.Normal);
  double oneMinusReflectivity;
  s.Albedo = EnergyConservationBetweenDiffuseAndSpecular(s.Albedo, s.Specular, oneMinusReflectivity);
  double outputAlpha;
  s.Albedo = PreMultiplyAlpha(s.Albedo, s.Alpha, oneMinusReflectivity, outputAlpha, premultiply);
  dvec4 c = UNITY_BRDF_PBS(tier, s.Albedo, s.Specular, oneMinusReflectivity, s.Smoothness, s.Normal, viewDir, gi.light,
                           gi.indirect);
  c.w = outputAlpha;
  return c;
}

// ---- colour and SH (UnityCG.cginc) ---------------------------------------------------
inline double Luminance(const dvec3& c) { return glm::dot(c, dvec3(0.2126729, 0.7151522, 0.0721750)); }
inline double LinearToGammaSpace1(double c) {
  c = std::max(c, 0.0);
  return c <= 0.0031308 ? 12.92 * c : 1.055 * std::pow(c, 1.0 / 2.4) - 0.055;
}
inline double GammaToLinearSpace1(double c) {
  return c <= 0.04045 ? c / 12.92 : std::pow(std::max((c + 0.055) / 1.055, 0.0), 2.4);
}
inline dvec3 LinearToGammaSpace(const dvec3& c) {
  return {LinearToGammaSpace1(c.x), LinearToGammaSpace1(c.y), LinearToGammaSpace1(c.z)};
}
inline dvec3 GammaToLinearSpace(const dvec3& c) {
  return {GammaToLinearSpace1(c.x), GammaToLinearSpace1(c.y), GammaToLinearSpace1(c.z)};
}
// ShadeSH9 for a unit normal (n.w = 1) and the seven packed coefficient
// vectors; linear space, clamped at 0.
inline dvec3 ShadeSH9(const dvec4& n, const SHCoefficients& sh) {
  dvec3 l01(glm::dot(sh.SHAr, n), glm::dot(sh.SHAg, n), glm::dot(sh.SHAb, n));
  dvec4 b(n.x * n.y, n.y * n.z, n.z * n.z, n.z * n.x);
  dvec3 l2(glm::dot(sh.SHBr, b), glm::dot(sh.SHBg, b), glm::dot(sh.SHBb, b));
  l2 += dvec3(sh.SHC) * (n.x * n.x - n.y * n.y);
  return glm::max(l01 + l2, dvec3(0));
}
inline dvec3 FacetSHEval(const dvec4& n, const SHCoefficients& sh) { return ShadeSH9(n, sh); }

}  // namespace facet::reference::unity
