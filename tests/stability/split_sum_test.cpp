// T14 on the CPU: under a constant environment L = c the split-sum IBL
// result, c * EnvBRDF(f0, DFG(NoV, alpha)), equals c times the directional
// albedo E(v) of the stdlib's GGX BRDF, which an independent estimator
// integrates (split_sum.h). Exact by construction, so the bound is 1e-3 (the
// estimator's standard error is below 3e-4). A planted bug (the DFG table's
// two terms swapped) is caught at every point. The GPU side is
// split_sum_gpu_test.cpp.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include "stability/split_sum.h"

namespace facet::stability {
namespace {

TEST(SplitSumTest, AConstantEnvironmentGivesItsRadianceTimesTheDirectionalAlbedo) {
  double worst = 0;
  for (size_t i = 0; i < split_sum_points().size(); ++i) {
    const SplitSumPoint& p = split_sum_points()[i];
    glm::dvec3 split = split_sum_on_cpu(p);
    glm::dvec3 direct = split_sum_direct_estimates()[i];
    double error = std::abs(split.x - direct.x) / kSplitSumRadiance;
    worst = std::max(worst, error);
    EXPECT_LE(error, kSplitSumBound) << fmt::format("NoV {} rough {} f0 {}: split sum {:.6f}, direct {:.6f}", p.NoV,
                                                    p.rough, p.f0, split.x, direct.x);
  }
  RecordProperty("worst_error", fmt::format("{:.3g}", worst));
}

TEST(SplitSumPlantedBugTest, SwappedDfgTermsAreCaughtAtEveryPoint) {
  for (size_t i = 0; i < split_sum_points().size(); ++i) {
    const SplitSumPoint& p = split_sum_points()[i];
    glm::dvec3 split = split_sum_on_cpu(p, true);
    EXPECT_GT(std::abs(split.x - split_sum_direct_estimates()[i].x) / kSplitSumRadiance, kSplitSumBound)
        << fmt::format("NoV {} rough {} f0 {}", p.NoV, p.rough, p.f0);
  }
}

}  // namespace
}  // namespace facet::stability
