// The Monte Carlo reference renderer (facet/reference/monte_carlo.h): it
// renders a white furnace as 1, integrates a GGX lobe to the DFG integral's
// albedo, converges as 1/sqrt(N) with standard errors that describe its
// actual error, and gives the same image whatever the thread count.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "facet/reference/brdf.h"
#include "facet/reference/ibl.h"
#include "facet/reference/monte_carlo.h"

namespace facet::reference::monte_carlo {
namespace {

Model lambert(double albedo) {
  return [albedo](const ShadingPoint&) { return Brdf([albedo](const glm::dvec3&, const glm::dvec3&) { return albedo * kInvPi; }); };
}

// GGX single scatter, F = 1, at the point's roughness.
Model ggx() {
  return [](const ShadingPoint& p) {
    double alpha = p.material.roughness * p.material.roughness;
    return Brdf([alpha](const glm::dvec3& v, const glm::dvec3& l) {
      if (l.z <= 0 || v.z <= 0) return 0.0;
      glm::dvec3 h = glm::normalize(v + l);
      return FacetD_GGX(h.z, alpha) * FacetV_SmithGGXCorrelated(v.z, l.z, alpha);
    });
  };
}

// Lambert plus GGX: what the convergence test integrates under the sky.
Model lambert_plus_ggx() {
  return [](const ShadingPoint& p) {
    Brdf specular = ggx()(p);
    return Brdf([specular](const glm::dvec3& v, const glm::dvec3& l) { return 0.5 * kInvPi + specular(v, l); });
  };
}

Scene small_scene(Lighting lighting) {
  Scene s{.name = "small", .lighting = lighting};
  s.roughness = {0.15, 0.6};
  s.metallic = {0.0};
  s.sphere_pixels = 8;
  return s;
}

TEST(MonteCarloReference, AWhiteLambertSphereInTheWhiteFurnaceRendersOne) {
  Scene scene = study_scenes()[1];
  ASSERT_EQ(scene.lighting, Lighting::uniform);
  Rendering r = render(scene, {lambert(1.0)}, {}, {.samples = 256});
  ASSERT_GT(r.points.size(), 1000u);
  double sum = 0;
  size_t within_three = 0;
  for (const Estimate& e : r.models[0]) {
    EXPECT_NEAR(e.value, 1.0, std::max(5.0 * e.std_error, 0.005));
    within_three += std::abs(e.value - 1.0) <= 3.0 * e.std_error;
    sum += e.value;
  }
  EXPECT_GT(double(within_three) / double(r.points.size()), 0.97);
  EXPECT_NEAR(sum / double(r.points.size()), 1.0, 2e-3);
}

TEST(MonteCarloReference, AGgxLobeInTheWhiteFurnaceRendersItsAlbedo) {
  Scene scene = small_scene(Lighting::uniform);
  Rendering r = render(scene, {ggx()}, {}, {.samples = 4096});
  double worst_z = 0;
  for (size_t i = 0; i < r.points.size(); ++i) {
    const ShadingPoint& p = r.points[i];
    double alpha = p.material.roughness * p.material.roughness;
    double albedo = FacetDFG_Integrate(p.n.z, alpha, 1u << 16).y;  // A + B: the albedo with F = 1
    const Estimate& e = r.models[0][i];
    worst_z = std::max(worst_z, std::abs(e.value - albedo) / (e.std_error + 1e-4));
  }
  EXPECT_LT(worst_z, 5.0);
}

TEST(MonteCarloReference, UnderTheDirectionalLightAPixelIsTheBrdfTimesTheCosine) {
  Scene scene = small_scene(Lighting::directional);
  Rendering r = render(scene, {lambert(0.5)}, {}, {.samples = 16});
  for (size_t i = 0; i < r.points.size(); ++i) {
    double cosine = std::max(0.0, glm::dot(r.points[i].n, scene.light_direction));
    EXPECT_NEAR(r.models[0][i].value, 0.5 * cosine, 1e-12);
    EXPECT_EQ(r.models[0][i].std_error, 0.0);
  }
}

// RMSE against a 64x longer render falls as 1/sqrt(N) (a slope of -1/2 on
// log-log axes), and the stated standard errors match the actual errors.
TEST(MonteCarloReference, ConvergesAsOneOverTheSquareRootOfTheSampleCount) {
  Scene scene = small_scene(Lighting::sky);
  const uint32_t truth_samples = 1u << 16;
  Rendering truth = render(scene, {lambert_plus_ggx()}, {}, {.samples = truth_samples, .seed = 99});
  std::vector<double> log_n, log_rmse;
  double calibration = 0;
  for (uint32_t n : {64u, 256u, 1024u, 4096u}) {
    Rendering r = render(scene, {lambert_plus_ggx()}, {}, {.samples = n, .seed = n});
    double sq = 0, z2 = 0;
    for (size_t i = 0; i < r.points.size(); ++i) {
      double err = r.models[0][i].value - truth.models[0][i].value;
      sq += err * err;
      z2 += err * err / std::max(r.models[0][i].std_error * r.models[0][i].std_error, 1e-30);
    }
    log_n.push_back(std::log(double(n)));
    log_rmse.push_back(0.5 * std::log(sq / double(r.points.size())));
    std::printf("[ convergence ] N = %u: RMSE %.4g\n", n, std::exp(log_rmse.back()));
    calibration = std::sqrt(z2 / double(r.points.size()));  // RMS of error / stated error, at the largest N
  }
  // The least-squares slope of log RMSE over log N.
  double mean_x = 0, mean_y = 0;
  for (size_t i = 0; i < log_n.size(); ++i) mean_x += log_n[i] / double(log_n.size()), mean_y += log_rmse[i] / double(log_n.size());
  double sxy = 0, sxx = 0;
  for (size_t i = 0; i < log_n.size(); ++i) {
    sxy += (log_n[i] - mean_x) * (log_rmse[i] - mean_y);
    sxx += (log_n[i] - mean_x) * (log_n[i] - mean_x);
  }
  double slope = sxy / sxx;
  std::printf("[ convergence ] slope %.3f, RMS(error / stated error) %.3f\n", slope, calibration);
  EXPECT_NEAR(slope, -0.5, 0.1);
  EXPECT_GT(calibration, 0.7);
  EXPECT_LT(calibration, 1.4);
}

TEST(MonteCarloReference, TheImageDoesNotDependOnTheThreadCount) {
  Scene scene = small_scene(Lighting::sky);
  Rendering one = render(scene, {lambert_plus_ggx()}, {}, {.samples = 64, .threads = 1});
  Rendering three = render(scene, {lambert_plus_ggx()}, {}, {.samples = 64, .threads = 3});
  for (size_t i = 0; i < one.points.size(); ++i) {
    EXPECT_EQ(one.models[0][i].value, three.models[0][i].value);
    EXPECT_EQ(one.models[0][i].std_error, three.models[0][i].std_error);
  }
}

// Two close models share their samples, so their contrast's error is far
// below either model's.
TEST(MonteCarloReference, AContrastOfTwoCloseModelsHasASmallStandardError) {
  Scene scene = small_scene(Lighting::sky);
  Model a = lambert_plus_ggx();
  Model b = [a](const ShadingPoint& p) {
    Brdf f = a(p);
    return Brdf([f](const glm::dvec3& v, const glm::dvec3& l) { return 1.01 * f(v, l); });
  };
  Rendering r = render(scene, {a, b}, {{1, 0}}, {.samples = 256});
  for (size_t i = 0; i < r.points.size(); ++i) {
    EXPECT_NEAR(r.contrasts[0][i].value, r.models[1][i].value - r.models[0][i].value, 1e-9 * r.models[0][i].value + 1e-12);
    EXPECT_LE(r.contrasts[0][i].std_error, 0.011 * r.models[0][i].std_error + 1e-12);
  }
}

}  // namespace
}  // namespace facet::reference::monte_carlo
