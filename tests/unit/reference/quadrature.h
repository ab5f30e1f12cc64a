// Deterministic quadratures over the hemisphere for the property tests.
#pragma once

#include <glm/glm.hpp>

#include <cmath>

#include "facet/reference/hlsl_math.h"

namespace facet::reference::test {

// A direction at cos(theta) = c in the xz plane (the z frame's view vector).
inline glm::dvec3 view_at(double c) { return {std::sqrt(std::max(0.0, 1.0 - c * c)), 0.0, c}; }

// Directional albedo E(v) = integral over l of f(l) <n.l>, n = +z, on a
// half-vector grid: l = reflect(v) about h, dl = 4 (v.h) dh, with
// theta_h = (pi/2) s^2 so that the points crowd near h = n, where every
// specular lobe here peaks (diffuse lobes are smooth and need no help).
template <class F>
double albedo(const glm::dvec3& v, F&& f, int thetaSteps = 160, int phiSteps = 160) {
  double sum = 0.0;
  double ds = 1.0 / thetaSteps, dphi = 2.0 * kPi / phiSteps;
  for (int i = 0; i < thetaSteps; ++i) {
    double s = (i + 0.5) * ds;
    double theta = 0.5 * kPi * s * s;
    double dtheta = kPi * s * ds;
    double st = std::sin(theta), ct = std::cos(theta);
    for (int j = 0; j < phiSteps; ++j) {
      double phi = (j + 0.5) * dphi;
      glm::dvec3 h(st * std::cos(phi), st * std::sin(phi), ct);
      double VoH = glm::dot(v, h);
      if (VoH <= 0.0) continue;
      glm::dvec3 l = 2.0 * VoH * h - v;
      if (l.z <= 0.0) continue;
      sum += f(l) * l.z * 4.0 * VoH * st * dtheta * dphi;
    }
  }
  return sum;
}

// Integral of g(h) over the hemisphere of h with the same crowding near +z.
template <class G>
double hemisphere_integral(G&& g, int thetaSteps = 400, int phiSteps = 64) {
  double sum = 0.0;
  double ds = 1.0 / thetaSteps, dphi = 2.0 * kPi / phiSteps;
  for (int i = 0; i < thetaSteps; ++i) {
    double s = (i + 0.5) * ds;
    double theta = 0.5 * kPi * s * s;
    double st = std::sin(theta), ct = std::cos(theta);
    for (int j = 0; j < phiSteps; ++j) {
      double phi = (j + 0.5) * dphi;
      sum += g(glm::dvec3(st * std::cos(phi), st * std::sin(phi), ct)) * st * kPi * s * ds * dphi;
    }
  }
  return sum;
}

}  // namespace facet::reference::test
