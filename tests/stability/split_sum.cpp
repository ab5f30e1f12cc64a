// The shared pieces of T14 (split_sum.h): the 18 points, the Monte Carlo
// estimate c * E(v) over GGX visible normals, and the CPU twin's split sum.
#include "stability/split_sum.h"

#include <random>

#include "facet/reference/ibl.h"
#include "facet/reference/sampling.h"

namespace facet::stability {
namespace {

using namespace facet::reference;

glm::dvec3 view_at(double NoV) { return {std::sqrt(1.0 - NoV * NoV), 0.0, NoV}; }

// c * E(v): the light reflected towards v under the constant environment.
glm::dvec3 reflected_by_monte_carlo(double NoV, double rough, const glm::dvec3& f0, uint32_t samples) {
  const glm::dvec3 n(0, 0, 1), v = view_at(NoV);
  const double alpha = FacetClampAlpha(rough * rough);
  std::mt19937_64 rng(7);
  auto u01 = [&] { return double(rng() >> 11) * 0x1.0p-53; };
  glm::dvec3 sum(0.0);
  for (uint32_t i = 0; i < samples; ++i) {
    glm::dvec3 h = sample_ggx_vndf(v, u01(), u01(), alpha);
    double VoH = glm::dot(v, h);
    glm::dvec3 l = 2.0 * VoH * h - v;
    if (l.z <= 0 || VoH <= 0) continue;
    double pdf_l = pdf_ggx_vndf(v, h, alpha) / (4.0 * VoH);
    sum += FacetBRDF_CookTorranceGGX(n, v, l, f0, rough) * l.z / pdf_l;
  }
  return kSplitSumRadiance * sum / double(samples);
}

}  // namespace

const std::vector<SplitSumPoint>& split_sum_points() {
  static const std::vector<SplitSumPoint> all = [] {
    std::vector<SplitSumPoint> out;
    for (double NoV : {0.1, 0.5, 0.95}) {
      for (double rough : {0.25, 0.5, 0.9}) {
        for (double f0 : {0.04, 1.0}) out.push_back({NoV, rough, f0});
      }
    }
    return out;
  }();
  return all;
}

const std::vector<glm::dvec3>& split_sum_direct_estimates() {
  static const std::vector<glm::dvec3> estimates = [] {
    std::vector<glm::dvec3> out;
    for (const SplitSumPoint& p : split_sum_points()) {
      out.push_back(reflected_by_monte_carlo(p.NoV, p.rough, glm::dvec3(p.f0), 1u << 20));
    }
    return out;
  }();
  return estimates;
}

glm::dvec3 split_sum_on_cpu(const SplitSumPoint& p, bool swap_terms, uint32_t samples) {
  glm::dvec2 dfg = FacetDFG_Integrate(p.NoV, FacetClampAlpha(p.rough * p.rough), samples);
  if (swap_terms) dfg = {dfg.y, dfg.x};
  // The prefiltered constant environment is c at every mip.
  return kSplitSumRadiance * FacetEnvBRDF_DFG(glm::dvec3(p.f0), 1.0, dfg);
}

}  // namespace facet::stability
