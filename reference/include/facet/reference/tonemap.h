// Double-precision twin of stdlib/FacetTonemap.hlsl.
#pragma once

#include "facet/reference/hlsl_math.h"

namespace facet::reference {

// HLSL float3x3(a..i) lists rows and mul(M, v) is M v; glm::dmat3 takes
// columns, so the twins build matrices from rows with this helper.
inline glm::dmat3 rows_to_dmat3(const glm::dvec3& r0, const glm::dvec3& r1, const glm::dvec3& r2) {
  return glm::transpose(glm::dmat3(r0, r1, r2));
}

inline glm::dvec3 FacetTonemapReinhard(glm::dvec3 x) {
  x = max3(x, 0.0);
  return x / (1.0 + x);
}
inline glm::dvec3 FacetTonemapReinhardExtended(glm::dvec3 x, double white) {
  x = max3(x, 0.0);
  return saturate(x * (1.0 + x / (white * white)) / (1.0 + x));
}

inline glm::dvec3 FacetHableCurve(const glm::dvec3& x) {
  const double A = 0.15, B = 0.50, C = 0.10, D = 0.20, E = 0.02, F = 0.30;
  return (x * (A * x + C * B) + D * E) / (x * (A * x + B) + D * F) - E / F;
}
inline glm::dvec3 FacetTonemapHable(glm::dvec3 x) {
  x = max3(x, 0.0);
  glm::dvec3 white = FacetHableCurve(glm::dvec3(11.2));
  return saturate(FacetHableCurve(2.0 * x) / white);
}

inline glm::dvec3 FacetTonemapACESNarkowicz(glm::dvec3 x) {
  x = max3(x, 0.0);
  return saturate(x * (2.51 * x + 0.03) / (x * (2.43 * x + 0.59) + 0.14));
}

inline glm::dvec3 FacetACESHillRRTODTFit(const glm::dvec3& v) {
  glm::dvec3 a = v * (v + 0.0245786) - 0.000090537;
  glm::dvec3 b = v * (0.983729 * v + 0.4329510) + 0.238081;
  return a / b;
}
inline glm::dmat3 FacetACESHillInputMatrix() {
  return rows_to_dmat3({0.59719, 0.35458, 0.04823}, {0.07600, 0.90834, 0.01566}, {0.02840, 0.13383, 0.83777});
}
inline glm::dmat3 FacetACESHillOutputMatrix() {
  return rows_to_dmat3({1.60475, -0.53108, -0.07367}, {-0.10208, 1.10813, -0.00605}, {-0.00327, -0.07276, 1.07602});
}
inline glm::dvec3 FacetTonemapACESHill(const glm::dvec3& color) {
  glm::dvec3 v = FacetACESHillInputMatrix() * max3(color, 0.0);
  v = FacetACESHillRRTODTFit(v);
  return saturate(FacetACESHillOutputMatrix() * v);
}

inline glm::dvec3 FacetTonemapPBRNeutral(glm::dvec3 color) {
  const double startCompression = 0.8 - 0.04;
  const double desaturation = 0.15;
  color = max3(color, 0.0);
  double x = std::min(color.r, std::min(color.g, color.b));
  double offset = x < 0.08 ? x - 6.25 * x * x : 0.04;
  color -= offset;
  double peak = std::max(color.r, std::max(color.g, color.b));
  if (peak < startCompression) return color;
  const double d = 1.0 - startCompression;
  double newPeak = 1.0 - d * d / (peak + d - startCompression);
  color *= newPeak / peak;
  double g = 1.0 - 1.0 / (desaturation * (peak - newPeak) + 1.0);
  return lerp(color, glm::dvec3(newPeak), g);
}

inline glm::dvec3 FacetAgXContrast(const glm::dvec3& x) {
  glm::dvec3 p = -17.86 * x + 78.01;
  p = p * x - 126.7;
  p = p * x + 92.06;
  p = p * x - 28.72;
  p = p * x + 4.361;
  p = p * x - 0.1718;
  return p * x + 0.002857;
}
inline glm::dmat3 FacetAgXInsetMatrix() {
  return rows_to_dmat3({0.842479062253094, 0.0784335999999992, 0.0792237451477643},
                       {0.0423282422610123, 0.878468636469772, 0.0791661274605434},
                       {0.0423756549057051, 0.0784336, 0.879142973793104});
}
inline glm::dmat3 FacetAgXOutsetMatrix() {
  return rows_to_dmat3({1.19687900512017, -0.0980208811401368, -0.0990297440797205},
                       {-0.0528968517574562, 1.15190312990417, -0.0989611768448433},
                       {-0.0529716355144438, -0.0980434501171241, 1.15107367264116});
}
inline glm::dvec3 FacetTonemapAgX(const glm::dvec3& color) {
  const double minEv = -12.47393;
  const double maxEv = 4.026069;
  glm::dvec3 v = FacetAgXInsetMatrix() * max3(color, 0.0);
  v = glm::log2(max3(v, 1e-10));
  v = saturate((v - minEv) / (maxEv - minEv));
  v = FacetAgXContrast(v);
  v = FacetAgXOutsetMatrix() * v;
  return saturate(glm::pow(max3(v, 0.0), glm::dvec3(2.2)));
}

}  // namespace facet::reference
