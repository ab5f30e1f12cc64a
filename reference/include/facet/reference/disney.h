// Double-precision twin of stdlib/FacetDisney.hlsl (Burley 2012 principled BRDF).
#pragma once

#include "facet/reference/brdf.h"

namespace facet::reference {

struct FacetDisneyMaterial {
  glm::dvec3 baseColor{0.82, 0.67, 0.16};  // the BRDF Explorer's defaults
  double subsurface = 0;
  double metallic = 0;
  double specular = 0.5;
  double specularTint = 0;
  double roughness = 0.5;
  double anisotropic = 0;
  double sheen = 0;
  double sheenTint = 0.5;
  double clearcoat = 0;
  double clearcoatGloss = 1;
};

inline double FacetDisneySchlickWeight(double u) { return FacetPow5(1.0 - saturate(u)); }

inline double FacetD_GTR1(double NoH, double a) {
  if (a >= 1.0) return kInvPi;
  double a2 = a * a;
  double t = 1.0 + (a2 - 1.0) * NoH * NoH;
  return (a2 - 1.0) / (kPi * std::log(a2) * t);
}

inline double FacetDisneySmithGGX(double NoV, double alphaG) {
  double a = alphaG * alphaG;
  double b = NoV * NoV;
  return 1.0 / (NoV + std::sqrt(a + b - a * b));
}
inline double FacetDisneySmithGGXAnisotropic(double NoV, double VoX, double VoY, double alphaX, double alphaY) {
  double x = VoX * alphaX;
  double y = VoY * alphaY;
  return 1.0 / (NoV + std::sqrt(x * x + y * y + NoV * NoV));
}

inline glm::dvec3 FacetBRDF_Disney(const FacetDisneyMaterial& m, const glm::dvec3& l, const glm::dvec3& v,
                                   const glm::dvec3& n, const glm::dvec3& x, const glm::dvec3& y) {
  double NoL = glm::dot(n, l);
  double NoV = glm::dot(n, v);
  if (NoL <= 0.0 || NoV <= 0.0) return glm::dvec3(0.0);
  NoV = FacetClampNoV(NoV);
  glm::dvec3 h = FacetSafeNormalize(l + v);
  double NoH = glm::dot(n, h);
  double LoH = glm::dot(l, h);

  const glm::dvec3 one(1.0);
  double luminance = glm::dot(m.baseColor, glm::dvec3(0.3, 0.6, 0.1));
  glm::dvec3 tint = luminance > 0.0 ? m.baseColor / luminance : one;
  glm::dvec3 specular0 = lerp(m.specular * 0.08 * lerp(one, tint, m.specularTint), m.baseColor, m.metallic);
  glm::dvec3 sheenColor = lerp(one, tint, m.sheenTint);

  double FL = FacetDisneySchlickWeight(NoL);
  double FV = FacetDisneySchlickWeight(NoV);
  double fd90 = 0.5 + 2.0 * LoH * LoH * m.roughness;
  double Fd = lerp(1.0, fd90, FL) * lerp(1.0, fd90, FV);
  double fss90 = LoH * LoH * m.roughness;
  double Fss = lerp(1.0, fss90, FL) * lerp(1.0, fss90, FV);
  double ss = 1.25 * (Fss * (1.0 / (NoL + NoV) - 0.5) + 0.5);

  double aspect = std::sqrt(1.0 - 0.9 * m.anisotropic);
  double r2 = m.roughness * m.roughness;
  double alphaX = std::max(0.001, r2 / aspect);
  double alphaY = std::max(0.001, r2 * aspect);
  double Ds = FacetD_GGXAnisotropic(NoH, glm::dot(h, x), glm::dot(h, y), alphaX, alphaY);
  double FH = FacetDisneySchlickWeight(LoH);
  glm::dvec3 Fs = lerp(specular0, one, FH);
  double Vs = FacetDisneySmithGGXAnisotropic(NoL, glm::dot(l, x), glm::dot(l, y), alphaX, alphaY) *
              FacetDisneySmithGGXAnisotropic(NoV, glm::dot(v, x), glm::dot(v, y), alphaX, alphaY);

  glm::dvec3 Fsheen = FH * m.sheen * sheenColor;

  double Dr = FacetD_GTR1(NoH, lerp(0.1, 0.001, m.clearcoatGloss));
  double Fr = lerp(0.04, 1.0, FH);
  double Vr = FacetDisneySmithGGX(NoL, 0.25) * FacetDisneySmithGGX(NoV, 0.25);

  glm::dvec3 diffuse = (kInvPi * lerp(Fd, ss, m.subsurface) * m.baseColor + Fsheen) * (1.0 - m.metallic);
  return diffuse + Ds * Vs * Fs + 0.25 * m.clearcoat * Dr * Vr * Fr;
}

}  // namespace facet::reference
