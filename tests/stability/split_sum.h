// T14, the split-sum identity under a constant environment (docs/stability.md):
// the 18 points, the split-sum result of the CPU twin, and the independent
// Monte Carlo estimate c * E(v) both the CPU test (split_sum_test.cpp) and the
// GPU test (split_sum_gpu_test.cpp) compare with.
#pragma once

#include <cstdint>
#include <vector>

#include "facet/reference/brdf.h"

namespace facet::stability {

inline constexpr double kSplitSumRadiance = 2.5;            // the constant environment c
inline constexpr uint32_t kSplitSumDfgSamples = 1u << 18;   // the DFG integral's Hammersley points
inline constexpr double kSplitSumBound = 1e-3;              // |split sum - c E(v)| / c, in double

struct SplitSumPoint {
  double NoV, rough, f0;
};

// NoV 0.1, 0.5, 0.95 x perceptual roughness 0.25, 0.5, 0.9 x f0 0.04, 1, in
// that nesting order.
const std::vector<SplitSumPoint>& split_sum_points();

// c * E(v) at every point: Monte Carlo over GGX visible normals (Heitz 2018)
// of FacetBRDF_CookTorranceGGX * NoL, 2^20 samples (standard error below
// 3e-4 of c); computed once per process.
const std::vector<glm::dvec3>& split_sum_direct_estimates();

// c * EnvBRDF(f0, f90 = 1, DFG(NoV, alpha)) on the CPU twin in double, the
// DFG integral on `samples` Hammersley points, its two terms swapped when
// `swap_terms` (the planted bug).
glm::dvec3 split_sum_on_cpu(const SplitSumPoint& p, bool swap_terms = false, uint32_t samples = kSplitSumDfgSamples);

}  // namespace facet::stability
