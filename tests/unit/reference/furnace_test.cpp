// T6/T7 white-furnace tests (docs/stability.md): the directional albedo
// E(v) = integral of f(v, l) <n.l> dl with F = 1 / albedo 1, over a grid of
// view angles. Energy-conserving models must stay <= 1 (+ quadrature
// tolerance); the known violators must exceed 1 by their documented amount.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <functional>
#include <string>

#include "facet/reference/lighting.h"
#include "unit/reference/quadrature.h"

namespace facet::reference {
namespace {

using test::albedo;
using test::view_at;

const double kViewCosines[] = {0.02, 0.05, 0.1, 0.2, 0.3, 0.5, 0.7, 0.9, 1.0};
// The quadrature's own error on these lobes, measured by the Lambert and
// GGX-against-DFG checks below: well under this.
constexpr double kQuadratureTolerance = 2e-3;

using Brdf = std::function<double(const glm::dvec3& v, const glm::dvec3& l)>;

struct AlbedoRange {
  double min = 1e9, max = -1e9, argmax_cos = 0;
};
AlbedoRange albedo_range(const Brdf& f) {
  AlbedoRange r;
  for (double c : kViewCosines) {
    glm::dvec3 v = view_at(c);
    double e = albedo(v, [&](const glm::dvec3& l) { return f(v, l); });
    r.min = std::min(r.min, e);
    if (e > r.max) r.max = e, r.argmax_cos = c;
  }
  return r;
}

FacetAngles angles(const glm::dvec3& v, const glm::dvec3& l) { return FacetComputeAngles({0, 0, 1}, v, l); }

struct FurnaceCase {
  std::string name;
  Brdf f;
  double expected_max;  // documented (docs/stability.md) or, where it gives none, measured here
  double tolerance;
};

std::vector<FurnaceCase> conserving_models() {
  std::vector<FurnaceCase> m;
  m.push_back({"Lambert", [](auto&, auto&) { return FacetFd_Lambert(); }, 1.0, kQuadratureTolerance});
  m.push_back({"Frostbite alpha=1", [](auto& v, auto& l) {
                 FacetAngles a = angles(v, l);
                 return FacetFd_Frostbite(a.NoV, a.NoL, a.LoH, 1.0);
               }, 1.006, 0.004});
  for (double n : {10.0, 100.0}) {
    m.push_back({"Phong normalized n=" + std::to_string(int(n)), [n](auto& v, auto& l) {
                   FacetAngles a = angles(v, l);
                   return FacetPhongNormalized(2.0 * a.NoL * a.NoV - a.LoV, n);
                 }, 1.0, 4e-3});
  }
  const std::pair<double, double> ward[] = {{0.1, 0.971}, {0.3, 0.794}, {0.5, 0.586}};
  for (auto [alpha, documented] : ward) {
    m.push_back({"Ward alpha=" + std::to_string(alpha), [alpha](auto& v, auto& l) {
                   FacetAngles a = angles(v, l);
                   glm::dvec3 h = glm::normalize(v + l);
                   return FacetSpecular_Ward(a.NoV, a.NoL, a.NoH, h.x, h.y, alpha, alpha);
                 }, documented, 0.01});
  }
  const std::pair<double, double> as[] = {{10, 0.697}, {100, 0.961}, {1000, 0.996}};
  for (auto [n, documented] : as) {
    m.push_back({"Ashikhmin-Shirley n=" + std::to_string(int(n)), [n](auto& v, auto& l) {
                   FacetAngles a = angles(v, l);
                   glm::dvec3 h = glm::normalize(v + l);
                   return FacetSpecular_AshikhminShirley(a.NoV, a.NoL, a.NoH, a.LoH, h.x, h.y, n, n, 1.0);
                 }, documented, 0.01});
  }
  return m;
}

std::vector<FurnaceCase> violators() {
  std::vector<FurnaceCase> m;
  m.push_back({"Burley r=1", [](auto& v, auto& l) {
                 FacetAngles a = angles(v, l);
                 return FacetFd_Burley(a.NoV, a.NoL, a.LoH, 1.0);
               }, 1.519, 0.01});
  m.push_back({"Blinn-Phong (n+8)/8pi n=10", [](auto& v, auto& l) {
                 return FacetBlinnPhongNormalized(angles(v, l).NoH, 10.0);
               }, 1.075, 0.005});
  m.push_back({"Oren-Nayar qualitative sigma=0.25", [](auto& v, auto& l) {
                 FacetAngles a = angles(v, l);
                 return FacetFd_OrenNayarQualitative(a.NoV, a.NoL, a.LoV, 0.25);
               }, 1.010, 0.003});
  return m;
}

TEST(ReferenceFurnaceTest, EnergyConservingModelsStayAtOrBelowOne) {
  for (const FurnaceCase& c : conserving_models()) {
    AlbedoRange r = albedo_range(c.f);
    std::printf("  %-32s E in [%.4f, %.4f] (max at NoV=%.2f)\n", c.name.c_str(), r.min, r.max, r.argmax_cos);
    EXPECT_LE(r.max, std::max(1.0, c.expected_max) + c.tolerance) << c.name;
    EXPECT_NEAR(r.max, c.expected_max, c.tolerance) << c.name;
  }
}

TEST(ReferenceFurnaceTest, KnownViolatorsExceedOneByTheDocumentedAmount) {
  for (const FurnaceCase& c : violators()) {
    AlbedoRange r = albedo_range(c.f);
    std::printf("  %-32s E in [%.4f, %.4f] (max at NoV=%.2f)\n", c.name.c_str(), r.min, r.max, r.argmax_cos);
    EXPECT_GT(r.max, 1.0) << c.name;
    EXPECT_NEAR(r.max, c.expected_max, c.tolerance) << c.name;
  }
}

TEST(ReferenceFurnaceTest, BurleyAtHalfRoughnessExceedsOneAtEveryViewAngle) {
  AlbedoRange r = albedo_range([](auto& v, auto& l) {
    FacetAngles a = angles(v, l);
    return FacetFd_Burley(a.NoV, a.NoL, a.LoH, 0.5);
  });
  std::printf("  Burley r=0.5 E in [%.4f, %.4f]\n", r.min, r.max);
  EXPECT_GT(r.min, 1.0);
  EXPECT_NEAR(r.max, 1.026, 0.005);
}

// Single-scatter GGX (F = 1) loses energy with roughness: the average albedo
// 2 integral E(mu) mu dmu matches the documented E_avg.
TEST(ReferenceFurnaceTest, SingleScatterGGXAverageAlbedoMatchesTheDocumentedLoss) {
  const std::pair<double, double> documented[] = {{0.25, 0.882}, {0.5, 0.700}, {0.75, 0.536}, {1.0, 0.409}};
  for (auto [alpha, e_avg] : documented) {
    double sum = 0.0;
    const int steps = 32;
    for (int i = 0; i < steps; ++i) {
      double mu = (i + 0.5) / steps;
      glm::dvec3 v = view_at(mu);
      double e = albedo(v, [&](const glm::dvec3& l) {
        FacetAngles a = angles(v, l);
        return FacetD_GGX(a.NoH, alpha) * FacetV_SmithGGXCorrelated(a.NoV, a.NoL, alpha);
      }, 96, 96);
      EXPECT_LE(e, 1.0 + kQuadratureTolerance) << "alpha " << alpha << " NoV " << mu;
      sum += 2.0 * e * mu / steps;
    }
    std::printf("  GGX alpha=%.2f E_avg %.4f\n", alpha, sum);
    EXPECT_NEAR(sum, e_avg, 0.005) << alpha;
  }
}

// T7: with f0 = 1 the compensated lobe E_ss (1 + 1/E - 1) = E_ss/E is 1 when
// the table's E agrees with the integral; here E comes from FacetDFG_Integrate
// (importance sampled) and E_ss from the grid, two independent quadratures.
// NDF sampling converges slowly at grazing views: at NoV = 0.05, r = 0.5 it
// is 1.5 % high with 2 048 samples, 0.3 % with 16 384; hence 32 768 here.
TEST(ReferenceFurnaceTest, EnergyCompensationRestoresAWhiteFurnaceForAMirrorMetal) {
  for (double rough : {0.25, 0.5, 0.75, 1.0}) {
    double alpha = rough * rough;
    for (double c : {0.05, 0.2, 0.5, 1.0}) {
      glm::dvec3 v = view_at(c);
      double e_ss = albedo(v, [&](const glm::dvec3& l) {
        FacetAngles a = angles(v, l);
        return FacetD_GGX(a.NoH, alpha) * FacetV_SmithGGXCorrelated(a.NoV, a.NoL, alpha);
      });
      double E = FacetDFG_Integrate(c, alpha, 32768).y;
      double compensated = e_ss * FacetEnergyCompensation(glm::dvec3(1.0), E).x;
      EXPECT_NEAR(compensated, 1.0, 0.01) << "r " << rough << " NoV " << c;
    }
  }
}

}  // namespace
}  // namespace facet::reference
