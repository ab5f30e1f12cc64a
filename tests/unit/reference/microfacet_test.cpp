// T8 microfacet identities (Heitz 2014) and the algebraic links between the
// masking forms, on the twins.
#include <gtest/gtest.h>

#include "facet/reference/lighting.h"
#include "unit/reference/quadrature.h"

namespace facet::reference {
namespace {

using test::hemisphere_integral;
using test::view_at;

const double kAlphas[] = {0.05, 0.25, 0.5, 1.0};

// integral of D(h) (n.h) dh = 1: the projected microfacet area is the macro area.
TEST(ReferenceMicrofacetTest, NormalDistributionsIntegrateToOneProjected) {
  for (double alpha : kAlphas) {
    double ggx = hemisphere_integral([&](const glm::dvec3& h) { return FacetD_GGX(h.z, alpha) * h.z; });
    double fp16 = hemisphere_integral(
        [&](const glm::dvec3& h) { return FacetD_GGX_FP16Safe({0, 0, 1}, h, alpha) * h.z; });
    double beckmann = hemisphere_integral([&](const glm::dvec3& h) { return FacetD_Beckmann(h.z, alpha) * h.z; });
    double aniso = hemisphere_integral(
        [&](const glm::dvec3& h) { return FacetD_GGXAnisotropic(h.z, h.x, h.y, alpha, 0.5 * alpha + 0.02) * h.z; });
    EXPECT_NEAR(ggx, 1.0, 1e-3) << alpha;
    EXPECT_NEAR(fp16, 1.0, 1e-3) << alpha;
    EXPECT_NEAR(beckmann, 1.0, 1e-3) << alpha;
    EXPECT_NEAR(aniso, 1.0, 1e-3) << alpha;
  }
  for (double n : {10.0, 100.0, 1000.0}) {
    double blinn = hemisphere_integral([&](const glm::dvec3& h) { return FacetD_BlinnPhong(h.z, n) * h.z; });
    EXPECT_NEAR(blinn, 1.0, 1e-3) << n;
  }
}

// integral of G1(o) <o.h> D(h) dh = n.o for every o (projected area), which
// with F = 1 is the weak white furnace: the masking-only lobe integrates to 1.
TEST(ReferenceMicrofacetTest, SmithGGXMaskingSatisfiesTheWeakWhiteFurnace) {
  for (double alpha : kAlphas) {
    for (double c : {0.1, 0.3, 0.6, 1.0}) {
      glm::dvec3 o = view_at(c);
      double projected = hemisphere_integral([&](const glm::dvec3& h) {
        return std::max(0.0, glm::dot(o, h)) * FacetD_GGX(h.z, alpha);
      }, 600, 128);
      EXPECT_NEAR(FacetG1_SmithGGX(c, alpha) * projected / c, 1.0, 1e-3) << "alpha " << alpha << " NoV " << c;
    }
  }
}

TEST(ReferenceMicrofacetTest, MaskingFormsAgreeWithTheirLambdaDefinitions) {
  for (double alpha : kAlphas) {
    for (double v = 0.01; v <= 1.0; v += 0.07) {
      double lv = FacetLambda_SmithGGX(v, alpha);
      EXPECT_NEAR(FacetG1_SmithGGX(v, alpha), 1.0 / (1.0 + lv), 1e-12);
      for (double l = 0.01; l <= 1.0; l += 0.09) {
        double ll = FacetLambda_SmithGGX(l, alpha);
        double correlated = 1.0 / (1.0 + lv + ll) / (4.0 * v * l);
        double separable = FacetG1_SmithGGX(v, alpha) * FacetG1_SmithGGX(l, alpha) / (4.0 * v * l);
        EXPECT_NEAR(FacetV_SmithGGXCorrelated(v, l, alpha) / correlated, 1.0, 1e-12);
        EXPECT_NEAR(FacetV_SmithGGXSeparable(v, l, alpha) / separable, 1.0, 1e-12);
      }
    }
  }
}

// The two GGX D forms are the same function wherever the k clamp is inactive.
TEST(ReferenceMicrofacetTest, FP16SafeGGXEqualsThePlainFormBelowItsClamp) {
  for (double alpha : {0.01, 0.1, 0.5, 1.0}) {
    for (double t = 0.0; t < 1.5; t += 0.01) {
      glm::dvec3 h(std::sin(t), 0.0, std::cos(t));
      double plain = FacetD_GGX(h.z, alpha);
      if (std::sqrt(plain * kPi) >= FACET_GGX_FP16_K_MAX) continue;
      EXPECT_NEAR(FacetD_GGX_FP16Safe({0, 0, 1}, h, alpha) / plain, 1.0, 1e-9) << alpha << " " << t;
    }
  }
}

// docs/lighting-models.md: Hammon's V is exact at alpha = 1 and off by at most
// 27.5 % (alpha = 0.05) elsewhere.
TEST(ReferenceMicrofacetTest, HammonFastVisibilityStaysWithinItsDocumentedError) {
  const std::pair<double, double> documented[] = {{0.05, 0.275}, {0.2, 0.225}, {0.5, 0.134}, {1.0, 0.0}};
  for (auto [alpha, bound] : documented) {
    double worst = 0.0;
    for (double v = 0.01; v <= 1.0; v += 0.01)
      for (double l = 0.01; l <= 1.0; l += 0.01)
        worst = std::max(worst, std::abs(FacetV_SmithGGXCorrelatedFast(v, l, alpha) /
                                             FacetV_SmithGGXCorrelated(v, l, alpha) - 1.0));
    EXPECT_NEAR(worst, bound, 0.01) << alpha;
  }
}

}  // namespace
}  // namespace facet::reference
