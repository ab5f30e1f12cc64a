// T14 on the CPU: under a constant environment L = c the split-sum IBL
// result, c * EnvBRDF(f0, DFG(NoV, alpha)), equals c times the directional
// albedo E(v) of the stdlib's GGX BRDF, which an independent estimator
// integrates here: Monte Carlo over visible normals (Heitz 2018) of
// FacetBRDF_CookTorranceGGX * NoL. Exact by construction, so the bound is
// 1e-3 (the estimator's standard error is below 3e-4). A planted bug (the DFG
// table's two terms swapped) is caught at every point.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <random>

#include "facet/reference/brdf.h"
#include "facet/reference/ibl.h"
#include "facet/reference/sampling.h"

namespace facet::stability {
namespace {

using namespace facet::reference;

constexpr double kRadiance = 2.5;  // the constant environment

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
  return kRadiance * sum / double(samples);
}

glm::dvec3 reflected_by_split_sum(double NoV, double rough, const glm::dvec3& f0, bool swap_terms = false) {
  glm::dvec2 dfg = FacetDFG_Integrate(NoV, FacetClampAlpha(rough * rough), 1u << 18);
  if (swap_terms) dfg = {dfg.y, dfg.x};
  return kRadiance * FacetEnvBRDF_DFG(f0, 1.0, dfg);  // the prefiltered constant environment is c at every mip
}

struct Point {
  double NoV, rough, f0;
};

// The 18 points, in a static so that references into it stay valid.
const std::vector<Point>& points() {
  static const std::vector<Point> all = [] {
    std::vector<Point> out;
    for (double NoV : {0.1, 0.5, 0.95}) {
      for (double rough : {0.25, 0.5, 0.9}) {
        for (double f0 : {0.04, 1.0}) out.push_back({NoV, rough, f0});
      }
    }
    return out;
  }();
  return all;
}

// The independent estimate at every point, computed once for both tests.
const std::vector<glm::dvec3>& direct_estimates() {
  static const std::vector<glm::dvec3> estimates = [] {
    std::vector<glm::dvec3> out;
    for (const Point& p : points()) out.push_back(reflected_by_monte_carlo(p.NoV, p.rough, glm::dvec3(p.f0), 1u << 20));
    return out;
  }();
  return estimates;
}

TEST(SplitSumTest, AConstantEnvironmentGivesItsRadianceTimesTheDirectionalAlbedo) {
  double worst = 0;
  for (size_t i = 0; i < points().size(); ++i) {
    const Point& p = points()[i];
    glm::dvec3 f0(p.f0);
    glm::dvec3 split = reflected_by_split_sum(p.NoV, p.rough, f0);
    glm::dvec3 direct = direct_estimates()[i];
    double error = std::abs(split.x - direct.x) / kRadiance;
    worst = std::max(worst, error);
    EXPECT_LE(error, 1e-3) << fmt::format("NoV {} rough {} f0 {}: split sum {:.6f}, direct {:.6f}", p.NoV, p.rough,
                                          p.f0, split.x, direct.x);
  }
  RecordProperty("worst_error", fmt::format("{:.3g}", worst));
}

TEST(SplitSumPlantedBugTest, SwappedDfgTermsAreCaughtAtEveryPoint) {
  for (size_t i = 0; i < points().size(); ++i) {
    const Point& p = points()[i];
    glm::dvec3 split = reflected_by_split_sum(p.NoV, p.rough, glm::dvec3(p.f0), true);
    EXPECT_GT(std::abs(split.x - direct_estimates()[i].x) / kRadiance, 1e-3)
        << fmt::format("NoV {} rough {} f0 {}", p.NoV, p.rough, p.f0);
  }
}

}  // namespace
}  // namespace facet::stability
