// T9: every importance sampler of the reference against its density, by a
// chi-square test (10^6 samples, 101 x 202 cells, Sidak-corrected p >= 0.01
// over the whole table), and two planted bugs the test must catch.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <vector>

#include "chi2.h"
#include "facet/reference/sampling.h"

namespace facet::stability {
namespace {

using namespace facet::reference;

struct SamplerCase {
  std::string name;
  DirectionSampler sample;
  DirectionDensity pdf;
};

glm::dvec3 view_at(double degrees) {
  double t = degrees * kPi / 180;
  return {std::sin(t), 0, std::cos(t)};
}

std::vector<SamplerCase> sampler_cases() {
  std::vector<SamplerCase> cases;
  cases.push_back({"cosine", sample_cosine, pdf_cosine});
  for (double alpha : {0.1, 0.5, 1.0}) {
    cases.push_back({fmt::format("ggx_ndf_alpha_{}", alpha),
                     [alpha](double u1, double u2) { return sample_ggx_ndf(u1, u2, alpha); },
                     [alpha](const glm::dvec3& h) { return pdf_ggx_ndf(h, alpha); }});
  }
  for (double alpha : {0.2, 0.6}) {
    for (double view : {0.0, 60.0, 85.0}) {
      glm::dvec3 v = view_at(view);
      cases.push_back({fmt::format("ggx_vndf_alpha_{}_view_{}", alpha, view),
                       [alpha, v](double u1, double u2) { return sample_ggx_vndf(v, u1, u2, alpha); },
                       [alpha, v](const glm::dvec3& h) { return pdf_ggx_vndf(v, h, alpha); }});
    }
  }
  for (double e : {10.0, 100.0}) {
    cases.push_back({fmt::format("blinn_ndf_exponent_{}", e),
                     [e](double u1, double u2) { return sample_blinn_ndf(u1, u2, e); },
                     [e](const glm::dvec3& h) { return pdf_blinn_ndf(h, e); }});
  }
  for (double alpha : {0.1, 0.5}) {
    cases.push_back({fmt::format("beckmann_ndf_alpha_{}", alpha),
                     [alpha](double u1, double u2) { return sample_beckmann_ndf(u1, u2, alpha); },
                     [alpha](const glm::dvec3& h) { return pdf_beckmann_ndf(h, alpha); }});
  }
  for (SamplerCase& c : cases) {
    for (char& ch : c.name) ch = ch == '.' ? 'p' : ch;  // a test name
  }
  return cases;
}

double significance() { return sidak_significance(0.01, int(sampler_cases().size())); }

class SamplerChi2Test : public testing::TestWithParam<SamplerCase> {};

TEST_P(SamplerChi2Test, HistogramMatchesTheDensity) {
  const SamplerCase& c = GetParam();
  Chi2Result r = chi2_test(c.sample, c.pdf);
  EXPECT_NEAR(r.expected_total, 1e6, 1e6 * 2e-3) << "the density integrates to 1";
  EXPECT_EQ(r.samples_in_zero_cells, 0u);
  EXPECT_GE(r.p_value, significance()) << "chi2 " << r.statistic << " with " << r.degrees_of_freedom << " dof";
}

INSTANTIATE_TEST_SUITE_P(Samplers, SamplerChi2Test, testing::ValuesIn(sampler_cases()),
                         [](const testing::TestParamInfo<SamplerCase>& info) { return info.param.name; });

// GGX's inversion with alpha where alpha^2 belongs: a lobe too wide.
TEST(SamplerChi2PlantedBugTest, AGgxSamplerWithTheWrongAlphaPowerIsRejected) {
  const double alpha = 0.5;
  Chi2Result r = chi2_test(
      [&](double u1, double u2) {
        double tan2 = alpha * u1 / (1.0 - u1);
        return spherical_direction(1.0 / std::sqrt(1.0 + tan2), 2.0 * kPi * u2);
      },
      [&](const glm::dvec3& h) { return pdf_ggx_ndf(h, alpha); });
  EXPECT_LT(r.p_value, significance()) << "chi2 " << r.statistic;
}

// Uniform hemisphere samples claimed to be cosine-weighted.
TEST(SamplerChi2PlantedBugTest, AUniformSamplerClaimedCosineIsRejected) {
  Chi2Result r = chi2_test([](double u1, double u2) { return spherical_direction(1.0 - u1, 2.0 * kPi * u2); },
                           pdf_cosine);
  EXPECT_LT(r.p_value, significance()) << "chi2 " << r.statistic;
}

TEST(Chi2Test, TheGammaTailMatchesKnownValues) {
  // chi-square with 2 dof: Q(1, x/2) = exp(-x/2); with 10 dof at 18.307 (the
  // table's 5 % point): 0.05; Q(50, 50) by Simpson quadrature of the gamma
  // density's tail (2 * 10^5 steps).
  EXPECT_NEAR(regularized_gamma_q(1.0, 1.5), std::exp(-1.5), 1e-12);
  EXPECT_NEAR(regularized_gamma_q(5.0, 18.307 / 2), 0.05, 1e-5);
  EXPECT_NEAR(regularized_gamma_q(50.0, 50.0), 0.481191684527943, 1e-9);
  // The series branch (x < a + 1) where P is not negligible: for an integer
  // a, Q(a, x) = exp(-x) * sum_{k < a} x^k / k!.
  EXPECT_NEAR(regularized_gamma_q(5.0, 3.0), 0.8152632445237721, 1e-12);
}

}  // namespace
}  // namespace facet::stability
