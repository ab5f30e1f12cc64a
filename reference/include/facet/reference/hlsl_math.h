// The few HLSL intrinsics the twins need, in double precision, so that a twin
// reads like its HLSL original line for line.
#pragma once

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>

namespace facet::reference {

inline constexpr double kPi = 3.14159265358979323846;
inline constexpr double kInvPi = 0.31830988618379067154;

inline double saturate(double x) { return std::clamp(x, 0.0, 1.0); }
inline glm::dvec3 saturate(const glm::dvec3& v) { return glm::clamp(v, 0.0, 1.0); }
inline double lerp(double a, double b, double t) { return a + (b - a) * t; }
inline glm::dvec3 lerp(const glm::dvec3& a, const glm::dvec3& b, double t) { return a + (b - a) * t; }
inline glm::dvec3 lerp(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& t) { return a + (b - a) * t; }
inline double rsqrt(double x) { return 1.0 / std::sqrt(x); }
// HLSL step(edge, x): 1 where x >= edge.
inline glm::dvec3 step(double edge, const glm::dvec3& x) { return glm::step(glm::dvec3(edge), x); }
inline glm::dvec3 max3(const glm::dvec3& v, double m) { return glm::max(v, glm::dvec3(m)); }

}  // namespace facet::reference
