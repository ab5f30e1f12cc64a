// Importance samplers of the reference, in the local frame (normal = +z), in
// double precision: each maps two uniform numbers in [0, 1) to a direction
// and has the density it samples, per solid angle. The microfacet samplers
// return the half vector h, distributed as D(h) (h.n) (or, for the visible
// normals, as D_v(h) = G1(v) max(0, v.h) D(h) / (v.n)). The stability suite
// checks every one with a chi-square test of its histogram against the
// integral of its density (docs/stability.md, T9).
#pragma once

#include <algorithm>
#include <cmath>

#include "facet/reference/hlsl_math.h"

namespace facet::reference {

inline glm::dvec3 spherical_direction(double cos_theta, double phi) {
  double sin_theta = std::sqrt(std::max(0.0, 1.0 - cos_theta * cos_theta));
  return {sin_theta * std::cos(phi), sin_theta * std::sin(phi), cos_theta};
}

// ---- cosine-weighted hemisphere ----
inline glm::dvec3 sample_cosine(double u1, double u2) {
  return spherical_direction(std::sqrt(1.0 - u1), 2.0 * kPi * u2);
}
inline double pdf_cosine(const glm::dvec3& w) { return w.z > 0 ? w.z / kPi : 0.0; }

// ---- GGX (Trowbridge-Reitz), isotropic ----
inline double ggx_d(double cos_theta, double alpha) {
  if (cos_theta <= 0) return 0.0;
  double a2 = alpha * alpha, c2 = cos_theta * cos_theta;
  double t = c2 * (a2 - 1.0) + 1.0;
  return a2 / (kPi * t * t);
}
inline glm::dvec3 sample_ggx_ndf(double u1, double u2, double alpha) {
  double tan2 = alpha * alpha * u1 / (1.0 - u1);
  return spherical_direction(1.0 / std::sqrt(1.0 + tan2), 2.0 * kPi * u2);
}
inline double pdf_ggx_ndf(const glm::dvec3& h, double alpha) { return ggx_d(h.z, alpha) * std::max(0.0, h.z); }

// Smith's G1 for GGX.
inline double ggx_g1(const glm::dvec3& w, double alpha) {
  if (w.z <= 0) return 0.0;
  double tan2 = std::max(0.0, 1.0 - w.z * w.z) / (w.z * w.z);
  return 2.0 / (1.0 + std::sqrt(1.0 + alpha * alpha * tan2));
}

// Visible normals from `v` (Heitz 2018, "Sampling the GGX Distribution of
// Visible Normals"): stretch, sample the projected hemisphere, unstretch.
inline glm::dvec3 sample_ggx_vndf(const glm::dvec3& v, double u1, double u2, double alpha) {
  glm::dvec3 vh = glm::normalize(glm::dvec3(alpha * v.x, alpha * v.y, v.z));
  double len2 = vh.x * vh.x + vh.y * vh.y;
  glm::dvec3 t1 = len2 > 0 ? glm::dvec3(-vh.y, vh.x, 0) / std::sqrt(len2) : glm::dvec3(1, 0, 0);
  glm::dvec3 t2 = glm::cross(vh, t1);
  double r = std::sqrt(u1), phi = 2.0 * kPi * u2;
  double p1 = r * std::cos(phi), p2 = r * std::sin(phi);
  double s = 0.5 * (1.0 + vh.z);
  p2 = (1.0 - s) * std::sqrt(std::max(0.0, 1.0 - p1 * p1)) + s * p2;
  glm::dvec3 nh = p1 * t1 + p2 * t2 + std::sqrt(std::max(0.0, 1.0 - p1 * p1 - p2 * p2)) * vh;
  return glm::normalize(glm::dvec3(alpha * nh.x, alpha * nh.y, std::max(0.0, nh.z)));
}
inline double pdf_ggx_vndf(const glm::dvec3& v, const glm::dvec3& h, double alpha) {
  if (v.z <= 0) return 0.0;
  return ggx_g1(v, alpha) * std::max(0.0, glm::dot(v, h)) * ggx_d(h.z, alpha) / v.z;
}

// ---- normalised Blinn-Phong NDF, D = (e + 2) / (2 pi) cos^e ----
inline glm::dvec3 sample_blinn_ndf(double u1, double u2, double exponent) {
  return spherical_direction(std::pow(1.0 - u1, 1.0 / (exponent + 2.0)), 2.0 * kPi * u2);
}
inline double pdf_blinn_ndf(const glm::dvec3& h, double exponent) {
  if (h.z <= 0) return 0.0;
  return (exponent + 2.0) / (2.0 * kPi) * std::pow(h.z, exponent + 1.0);
}

// ---- Beckmann ----
inline double beckmann_d(double cos_theta, double alpha) {
  if (cos_theta <= 0) return 0.0;
  double c2 = cos_theta * cos_theta, tan2 = (1.0 - c2) / c2, a2 = alpha * alpha;
  return std::exp(-tan2 / a2) / (kPi * a2 * c2 * c2);
}
inline glm::dvec3 sample_beckmann_ndf(double u1, double u2, double alpha) {
  double tan2 = -alpha * alpha * std::log(1.0 - u1);
  return spherical_direction(1.0 / std::sqrt(1.0 + tan2), 2.0 * kPi * u2);
}
inline double pdf_beckmann_ndf(const glm::dvec3& h, double alpha) {
  return beckmann_d(h.z, alpha) * std::max(0.0, h.z);
}

}  // namespace facet::reference
