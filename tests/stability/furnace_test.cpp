// T6/T7 on the GPU: the white furnace E(v) = integral of f(v, l) <n.l> dl of
// every model, with the model evaluated by the fp32 shader and the
// quadrature of tests/unit/reference/quadrature.h (its points are recorded
// by one pass, evaluated on the GPU, and summed by a second pass). F = 1
// (f0 = 1, metallic 1 for Unity's tiers) and albedo 1. Conserving models
// stay <= 1 + quadrature tolerance; violators exceed 1 by their documented
// (docs/stability.md) or, where none is documented, measured amount; the
// energy-compensated GGX is 1 +- 1 %.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <optional>

#include "facet/reference/lighting.h"
#include "stability/gpu.h"
#include "unit/reference/quadrature.h"

namespace facet::stability {
namespace {

using reference::test::albedo;
using reference::test::view_at;

const double kViewCosines[] = {0.02, 0.1, 0.3, 0.5, 0.7, 1.0};
constexpr int kSteps = 128;  // 128 x 128 half-vector grid per view

// Perceptual roughness giving a Blinn-Phong/Phong exponent n through
// FacetAlphaToBlinnPhongExponent (n = 2/alpha^2 - 2).
double roughness_for_exponent(double n) { return std::pow(2.0 / (n + 2.0), 0.25); }

struct Setting {
  std::string model;
  double roughness;
  double f0;
  double expected_max;  // of E over the view cosines
  double tolerance;
  std::string source;  // "documented" (docs/stability.md) or "measured"
};

// E(v) over kViewCosines for one setting; `energy(c)` feeds x[12] (E of the
// compensated model), 0 elsewhere.
class StabilityFurnaceTest : public StabilityGpuTest {
 protected:
  std::vector<double> albedos(const Model& m, double roughness, double f0,
                              const std::function<double(double)>& energy = nullptr) {
    std::vector<double> out;
    for (double c : kViewCosines) {
      glm::dvec3 v = view_at(c);
      std::vector<Point> points;
      albedo(v, [&](const glm::dvec3& l) {
        Inputs in;
        in.v = v, in.l = l, in.roughness = roughness, in.f0 = f0, in.energy = energy ? energy(c) : 0.0;
        points.push_back(pack(in));
        return 0.0;
      }, kSteps, kSteps);
      std::vector<float> gpu = evaluate_model(m, points);
      if (gpu.size() != points.size() * 3) return {};
      size_t i = 0;
      double scale = m.unity ? reference::kInvPi : 1.0;
      out.push_back(albedo(v, [&](const glm::dvec3& l) { return scale * gpu[3 * i++ + 1] / l.z; }, kSteps, kSteps));
    }
    return out;
  }
};

double max_of(const std::vector<double>& e) { return e.empty() ? NAN : *std::max_element(e.begin(), e.end()); }
double min_of(const std::vector<double>& e) { return e.empty() ? NAN : *std::min_element(e.begin(), e.end()); }

std::vector<Setting> conserving_settings() {
  return {
      {"Lambert", 0.5, 0.0, 1.0, 2e-3, "exact"},
      {"Frostbite", 1.0, 0.0, 1.006, 4e-3, "documented"},
      {"Phong normalized", roughness_for_exponent(10), 0.0, 1.0, 4e-3, "documented"},
      {"Phong normalized", roughness_for_exponent(100), 0.0, 1.0, 4e-3, "documented"},
      {"Ward", std::sqrt(0.1), 0.0, 0.971, 0.01, "documented"},
      {"Ward", std::sqrt(0.3), 0.0, 0.794, 0.01, "documented"},
      {"Ashikhmin-Shirley specular", roughness_for_exponent(10), 1.0, 0.697, 0.01, "documented"},
      {"Ashikhmin-Shirley specular", roughness_for_exponent(100), 1.0, 0.961, 0.01, "documented"},
      {"Ashikhmin-Shirley diffuse", 0.5, 0.0, 0.9687, 3e-3, "measured"},
      {"Cook-Torrance GGX", 0.5, 1.0, 0.9673, 3e-3, "measured"},
      {"Cook-Torrance GGX", 1.0, 1.0, 0.9197, 3e-3, "measured"},
      {"Cook-Torrance Beckmann", 0.5, 1.0, 1.0000, 3e-3, "measured"},
      {"GGX FP16-safe D + Hammon V", 0.5, 1.0, 0.9081, 3e-3, "measured"},
      {"GGX separable Smith", 0.5, 1.0, 0.9157, 3e-3, "measured"},
      {"GGX Schlick-GGX", 0.5, 1.0, 0.8950, 3e-3, "measured"},
      {"GGX Schlick-GGX Karis", 0.5, 1.0, 0.8598, 3e-3, "measured"},
      {"BRDF1_Unity_PBS", 0.5, 1.0, 0.9078, 3e-3, "measured"},
      {"BRDF3_Unity_PBS", 0.2, 1.0, 0.3325, 3e-3, "measured"},
      {"BRDF3_Unity_PBS", 0.5, 1.0, 1.0000, 3e-3, "measured"},
      {"BRDF3_Unity_PBS", 0.8, 1.0, 1.0000, 3e-3, "measured"},
      {"Oren-Nayar full", 1.0, 0.0, 0.9205, 3e-3, "measured"},
      {"LightingStandard", 0.5, 1.0, 0.9078, 3e-3, "measured"},
      {"LightingLambert", 0.5, 0.0, 1.0, 2e-3, "exact"},
  };
}

std::vector<Setting> violator_settings() {
  return {
      {"Burley", 1.0, 0.0, 1.519, 0.01, "documented"},
      {"Oren-Nayar qualitative", 0.25, 0.0, 1.010, 0.003, "documented"},
      {"Blinn-Phong normalized", roughness_for_exponent(10), 0.0, 1.075, 0.005, "documented"},
      {"Disney", 1.0, 0.0, 1.6496, 5e-3, "measured"},
      {"BRDF2_Unity_PBS", 0.2, 1.0, 1.82, 5e-3, "documented (energy ratio)"},
      {"BRDF2_Unity_PBS", 0.5, 1.0, 1.0970, 3e-3, "measured"},
  };
}

TEST_F(StabilityFurnaceTest, EnergyConservingModelsStayAtOrBelowOneOnTheGpu) {
  for (const Setting& s : conserving_settings()) {
    std::vector<double> e = albedos(model(s.model), s.roughness, s.f0);
    std::printf("[ furnace ] %-28s r=%.4f E in [%.4f, %.4f] (%s %.4f)\n", s.model.c_str(), s.roughness, min_of(e),
                max_of(e), s.source.c_str(), s.expected_max);
    ASSERT_EQ(e.size(), std::size(kViewCosines)) << s.model;
    EXPECT_LE(max_of(e), std::max(1.0, s.expected_max) + 2e-3) << s.model << " r=" << s.roughness;
    EXPECT_NEAR(max_of(e), s.expected_max, s.tolerance) << s.model << " r=" << s.roughness;
  }
}

TEST_F(StabilityFurnaceTest, KnownViolatorsExceedOneByTheirDocumentedAmountOnTheGpu) {
  for (const Setting& s : violator_settings()) {
    std::vector<double> e = albedos(model(s.model), s.roughness, s.f0);
    std::printf("[ furnace ] %-28s r=%.4f E in [%.4f, %.4f] (%s %.4f)\n", s.model.c_str(), s.roughness, min_of(e),
                max_of(e), s.source.c_str(), s.expected_max);
    ASSERT_EQ(e.size(), std::size(kViewCosines)) << s.model;
    EXPECT_GT(max_of(e), 1.0) << s.model;
    EXPECT_NEAR(max_of(e), s.expected_max, s.tolerance) << s.model << " r=" << s.roughness;
  }
}

// Every model is classified: a new model must say what it promises.
TEST(StabilityFurnaceClassesTest, EveryBrdfHasAFurnaceSetting) {
  const std::vector<Setting> conserving_list = conserving_settings(), violator_list = violator_settings();
  std::vector<Setting> all = conserving_list;
  all.insert(all.end(), violator_list.begin(), violator_list.end());
  for (const Model& m : models()) {
    if (m.energy == Energy::none) continue;
    bool found = std::any_of(all.begin(), all.end(), [&](const Setting& s) { return s.model == m.name; });
    bool conserving = std::any_of(conserving_list.begin(), conserving_list.end(),
                                  [&](const Setting& s) { return s.model == m.name; });
    EXPECT_TRUE(found || m.name == "GGX + energy compensation") << m.name << " has no furnace setting";
    if (found) {
      EXPECT_EQ(conserving, m.energy == Energy::conserving) << m.name;
    }
  }
}

// T7: E for the compensation from the shader's own DFG integral (32 768
// samples, FacetIBL.hlsl), then the compensated lobe's furnace: 1 +- 1 %.
TEST_F(StabilityFurnaceTest, EnergyCompensatedGGXIsAWhiteFurnaceOnTheGpu) {
  auto dfg = compile_functions(context(), {{.includes = "#include \"FacetIBL.hlsl\"\n",
                                            .hlsl = "r.xy = FacetDFG_Integrate(x[0], x[1], 32768u);",
                                            .input_count = 2, .output_count = 2}});
  ASSERT_NE(dfg, nullptr);
  for (double rough : {0.25, 0.5, 0.75, 1.0}) {
    double alpha = reference::FacetClampAlpha(rough * rough);
    std::vector<float> in;
    for (double c : kViewCosines) in.insert(in.end(), {float(c), float(alpha)});
    std::vector<float> E = run_function(context(), *dfg, 0, in, uint32_t(std::size(kViewCosines)));
    ASSERT_EQ(E.size(), 2 * std::size(kViewCosines));
    std::vector<double> e = albedos(model("GGX + energy compensation"), rough, 1.0, [&](double c) {
      size_t i = size_t(std::find(std::begin(kViewCosines), std::end(kViewCosines), c) - std::begin(kViewCosines));
      return double(E[2 * i + 1]);
    });
    std::printf("[ furnace ] GGX compensated r=%.2f E in [%.4f, %.4f]\n", rough, min_of(e), max_of(e));
    ASSERT_EQ(e.size(), std::size(kViewCosines));
    for (size_t i = 0; i < e.size(); ++i) {
      if (kViewCosines[i] < 0.05) continue;  // T7: NoV >= 0.05
      EXPECT_NEAR(e[i], 1.0, 0.01) << "r " << rough << " NoV " << kViewCosines[i];
    }
  }
}

}  // namespace
}  // namespace facet::stability
