// Double-precision twin of stdlib/FacetColor.hlsl (exact sRGB transfer).
#pragma once

#include "facet/reference/hlsl_math.h"

namespace facet::reference {

inline double FacetLinearToSRGB(double c) {
  c = std::max(c, 0.0);
  return c <= 0.0031308 ? 12.92 * c : 1.055 * std::pow(c, 1.0 / 2.4) - 0.055;
}
inline double FacetSRGBToLinear(double e) {
  e = std::max(e, 0.0);
  return e <= 0.04045 ? e / 12.92 : std::pow((e + 0.055) / 1.055, 2.4);
}
inline glm::dvec3 FacetLinearToSRGB(const glm::dvec3& c) {
  return {FacetLinearToSRGB(c.x), FacetLinearToSRGB(c.y), FacetLinearToSRGB(c.z)};
}
inline glm::dvec3 FacetSRGBToLinear(const glm::dvec3& e) {
  return {FacetSRGBToLinear(e.x), FacetSRGBToLinear(e.y), FacetSRGBToLinear(e.z)};
}

}  // namespace facet::reference
