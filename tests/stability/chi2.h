// A chi-square goodness-of-fit test of a direction sampler against its
// density, the protocol of pbrt's and Mitsuba's sampler tests: a histogram
// of (theta, phi) over the sphere at an odd resolution, expected counts from
// the density integrated over each cell (Simpson's rule), cells with an
// expected count under 5 pooled, and the p-value of the statistic. A sample
// in a cell where the density integrates to zero fails outright.
#pragma once

#include <glm/glm.hpp>

#include <cstdint>
#include <functional>
#include <string>

namespace facet::stability {

struct Chi2Options {
  uint64_t samples = 1000000;
  int theta_bins = 101;
  int phi_bins = 202;
  uint64_t seed = 1;
};

struct Chi2Result {
  double statistic = 0;
  int degrees_of_freedom = 0;
  double p_value = 0;
  uint64_t samples_in_zero_cells = 0;
  double expected_total = 0;  // the density's integral times the samples: about `samples`
};

using DirectionSampler = std::function<glm::dvec3(double u1, double u2)>;
using DirectionDensity = std::function<double(const glm::dvec3& w)>;

Chi2Result chi2_test(const DirectionSampler& sample, const DirectionDensity& pdf, const Chi2Options& options = {});

// The per-test significance that keeps the chance of any false failure among
// `tests` independent tests at `alpha` (Sidak's correction).
double sidak_significance(double alpha, int tests);

// The regularized upper incomplete gamma function Q(a, x): the chi-square
// distribution's tail is Q(dof / 2, statistic / 2).
double regularized_gamma_q(double a, double x);

}  // namespace facet::stability
