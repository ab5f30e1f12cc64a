// The input sets of T1/T2 (docs/stability.md): the hard-case grid and the
// full input set, as evaluator points (models.h layout).
#pragma once

#include <array>
#include <vector>

#include "stability/models.h"

namespace facet::stability {

using Point = std::array<float, kInputs>;

inline constexpr double kIntensities[] = {0.0, 1.0, 65504.0, 1e6};

// Grazing and back-facing NoV/NoL (-0.3, -1e-6, 0, 1e-7, 1e-4, 0.5, 1), L = -V,
// L = V, the mirror direction (NoH = 1), L = V = N, denormal components;
// normals unit, 0.98 and 1.02 long, zero, denormal and nearly so; roughness
// 0, 0.045, 0.5, 1; f0 0, 0.04, 1; every intensity above.
std::vector<Point> hard_case_grid();

// 4 096 Hammersley (v, l) pairs over the upper hemisphere per (roughness,
// f0), roughness in {0, 0.01, 0.045, 0.089, 0.1, 0.25, 0.5, 0.75, 1}, f0 in
// {0.02, 0.04, 0.16, 1}, unit normal, intensity 1.
std::vector<Point> full_input_set();

// A unit direction at cos(theta) = c, azimuth phi, about +z.
glm::dvec3 direction(double c, double phi);

}  // namespace facet::stability
