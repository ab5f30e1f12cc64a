#include "chi2.h"

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

namespace facet::stability {
namespace {

constexpr double kPi = 3.14159265358979323846;

// Simpson's rule over one (theta, phi) cell of the sphere, of pdf * sin(theta).
double cell_integral(const DirectionDensity& pdf, double t0, double t1, double p0, double p1) {
  constexpr int kSteps = 8;  // even
  double ht = (t1 - t0) / kSteps, hp = (p1 - p0) / kSteps, sum = 0;
  for (int i = 0; i <= kSteps; ++i) {
    double wt = i == 0 || i == kSteps ? 1 : i % 2 ? 4 : 2;
    double theta = t0 + i * ht;
    double sin_theta = std::sin(theta), cos_theta = std::cos(theta);
    for (int j = 0; j <= kSteps; ++j) {
      double wp = j == 0 || j == kSteps ? 1 : j % 2 ? 4 : 2;
      double phi = p0 + j * hp;
      glm::dvec3 w(sin_theta * std::cos(phi), sin_theta * std::sin(phi), cos_theta);
      sum += wt * wp * pdf(w) * sin_theta;
    }
  }
  return sum * ht * hp / 9.0;
}

double uniform01(std::mt19937_64& rng) { return double(rng() >> 11) * 0x1.0p-53; }

double gamma_series(double a, double x) {
  double term = 1.0 / a, sum = term;
  for (int n = 1; n < 100000; ++n) {
    term *= x / (a + n);
    sum += term;
    if (std::abs(term) < std::abs(sum) * 1e-15) break;
  }
  return sum * std::exp(-x + a * std::log(x) - std::lgamma(a));  // P(a, x)
}

// Q(a, x) by Lentz's continued fraction, for x >= a + 1.
double gamma_continued_fraction(double a, double x) {
  constexpr double kTiny = 1e-300;
  double b = x + 1.0 - a, c = 1.0 / kTiny, d = 1.0 / b, h = d;
  for (int i = 1; i < 100000; ++i) {
    double an = -i * (i - a);
    b += 2.0;
    d = an * d + b;
    if (std::abs(d) < kTiny) d = kTiny;
    c = b + an / c;
    if (std::abs(c) < kTiny) c = kTiny;
    d = 1.0 / d;
    double delta = d * c;
    h *= delta;
    if (std::abs(delta - 1.0) < 1e-15) break;
  }
  return std::exp(-x + a * std::log(x) - std::lgamma(a)) * h;
}

}  // namespace

double regularized_gamma_q(double a, double x) {
  if (x <= 0) return 1.0;
  return x < a + 1.0 ? 1.0 - gamma_series(a, x) : gamma_continued_fraction(a, x);
}

double sidak_significance(double alpha, int tests) { return 1.0 - std::pow(1.0 - alpha, 1.0 / tests); }

Chi2Result chi2_test(const DirectionSampler& sample, const DirectionDensity& pdf, const Chi2Options& options) {
  const int nt = options.theta_bins, np = options.phi_bins;
  std::vector<double> observed(size_t(nt) * np, 0), expected(size_t(nt) * np, 0);
  std::mt19937_64 rng(options.seed);
  for (uint64_t s = 0; s < options.samples; ++s) {
    double u1 = uniform01(rng), u2 = uniform01(rng);
    glm::dvec3 w = sample(u1, u2);
    double len = glm::length(w);
    if (!(len > 0) || !std::isfinite(len)) continue;  // counted nowhere: the expected counts catch the loss
    w /= len;
    double theta = std::acos(std::clamp(w.z, -1.0, 1.0));
    double phi = std::atan2(w.y, w.x);
    if (phi < 0) phi += 2 * kPi;
    int i = std::min(nt - 1, int(theta / kPi * nt)), j = std::min(np - 1, int(phi / (2 * kPi) * np));
    observed[size_t(i) * np + j] += 1;
  }
  Chi2Result result;
  for (int i = 0; i < nt; ++i) {
    for (int j = 0; j < np; ++j) {
      double e = cell_integral(pdf, kPi * i / nt, kPi * (i + 1) / nt, 2 * kPi * j / np, 2 * kPi * (j + 1) / np);
      expected[size_t(i) * np + j] = e * double(options.samples);
      result.expected_total += e * double(options.samples);
    }
  }
  std::vector<size_t> order(expected.size());
  for (size_t k = 0; k < order.size(); ++k) order[k] = k;
  std::sort(order.begin(), order.end(), [&](size_t a, size_t b) { return expected[a] < expected[b]; });
  constexpr double kMinExpected = 5;
  double pooled_observed = 0, pooled_expected = 0;
  for (size_t k : order) {
    if (expected[k] <= 0) {
      result.samples_in_zero_cells += uint64_t(observed[k]);
    } else if (expected[k] < kMinExpected || (pooled_expected > 0 && pooled_expected < kMinExpected)) {
      pooled_observed += observed[k];
      pooled_expected += expected[k];
    } else {
      double d = observed[k] - expected[k];
      result.statistic += d * d / expected[k];
      ++result.degrees_of_freedom;
    }
  }
  if (pooled_expected > 0) {
    double d = pooled_observed - pooled_expected;
    result.statistic += d * d / pooled_expected;
    ++result.degrees_of_freedom;
  }
  result.degrees_of_freedom -= 1;
  result.p_value = result.degrees_of_freedom > 0
                       ? regularized_gamma_q(0.5 * result.degrees_of_freedom, 0.5 * result.statistic)
                       : 1.0;
  return result;
}

}  // namespace facet::stability
