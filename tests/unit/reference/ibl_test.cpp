// T13/T14-style checks of the IBL twins: the DFG table, EnvBRDFApprox's
// documented error, and SH9 irradiance on environments it represents exactly.
#include <gtest/gtest.h>

#include <cmath>

#include "facet/reference/ibl.h"
#include "unit/reference/quadrature.h"

namespace facet::reference {
namespace {

// At alpha = 1, NoV = 1 the albedo of GGX + height-correlated Smith is 1 - ln 2.
TEST(ReferenceIblTest, DfgAtFullRoughnessHeadOnIsOneMinusLnTwo) {
  glm::dvec2 dfg = FacetDFG_Integrate(1.0, 1.0, 4096);
  EXPECT_NEAR(dfg.y, 1.0 - std::log(2.0), 2e-3);
  EXPECT_NEAR(FacetEnvBRDF_DFG(glm::dvec3(1.0), 1.0, dfg).x, dfg.y, 1e-15);
}

// The table's integrals agree with the half-vector grid quadrature, are
// bounded by 1, and the Fresnel part is a fraction of the whole.
TEST(ReferenceIblTest, DfgTableIsBoundedAndAgreesWithDirectQuadrature) {
  DfgTable table = FacetBuildDfgTable(16, 512);
  for (int j = 0; j < table.size; ++j)
    for (int i = 0; i < table.size; ++i) {
      glm::dvec2 t = table.at(i, j);
      EXPECT_LE(t.y, 1.0 + 2e-3);
      EXPECT_GE(t.x, 0.0);
      EXPECT_LE(t.x, t.y);
    }
  for (int j : {4, 9, 15}) {
    double r = (j + 0.5) / table.size, alpha = FacetClampAlpha(r * r);
    for (int i : {2, 8, 15}) {
      double NoV = (i + 0.5) / table.size;
      glm::dvec3 v = test::view_at(NoV);
      double grid = test::albedo(v, [&](const glm::dvec3& l) {
        glm::dvec3 h = glm::normalize(v + l);
        return FacetD_GGX(h.z, alpha) * FacetV_SmithGGXCorrelated(NoV, l.z, alpha);
      });
      EXPECT_NEAR(table.at(i, j).y, grid, 1.5e-2) << "r " << r << " NoV " << NoV;
    }
  }
}

// docs/lighting-models.md: EnvBRDFApprox gives A = 0.452 at r = 1, NoV = 1 where the
// table has 0.307 (+47 %), and |dA| <= 0.40 over the table.
TEST(ReferenceIblTest, EnvBRDFApproxErrorMatchesItsDocumentedBudget) {
  glm::dvec2 ab = FacetEnvBRDFApproxAB(1.0, 1.0);
  glm::dvec2 dfg = FacetDFG_Integrate(1.0, 1.0, 4096);
  double A = dfg.y - dfg.x;  // f0 weight in f0 (y - x) + f90 x
  EXPECT_NEAR(ab.x, 0.452, 2e-3);
  EXPECT_NEAR(ab.x / A, 1.47, 0.02);
  double worst = 0.0;
  for (double r = 0.05; r <= 1.0; r += 0.1)
    for (double NoV = 0.05; NoV <= 1.0; NoV += 0.1) {
      glm::dvec2 d = FacetDFG_Integrate(NoV, r * r, 512);
      worst = std::max(worst, std::abs(FacetEnvBRDFApproxAB(r, NoV).x - (d.y - d.x)));
    }
  EXPECT_LE(worst, 0.41);
}

// L(d) = 0.7 + a.d lies in bands 0-1, whose irradiance convolution is exact:
// E(n) = pi 0.7 + (2 pi / 3) a.n.
TEST(ReferenceIblTest, SH9IrradianceIsExactForConstantAndLinearRadiance) {
  const glm::dvec3 a(0.2, -0.3, 0.25);
  std::array<double, 9> sh = project_sh9([&](const glm::dvec3& d) { return 0.7 + glm::dot(a, d); }, 2048);
  for (const glm::dvec3& n : {glm::dvec3(0, 0, 1), glm::normalize(glm::dvec3(1, 2, -3)), glm::dvec3(-1, 0, 0)}) {
    EXPECT_NEAR(FacetSH9Irradiance(n, sh.data()), kPi * 0.7 + 2.0 * kPi / 3.0 * glm::dot(a, n), 1e-6);
  }
  for (int k = 4; k < 9; ++k) EXPECT_NEAR(sh[k], 0.0, 1e-6) << k;
}

TEST(ReferenceIblTest, RoughnessToMipIsLinearAndUnityCurveEndsAtTheLastStep) {
  EXPECT_DOUBLE_EQ(FacetPerceptualRoughnessToMipLevel(0.5, 8.0), 4.0);
  EXPECT_DOUBLE_EQ(FacetPerceptualRoughnessToMipLevel(2.0, 8.0), 8.0);
  EXPECT_DOUBLE_EQ(FacetPerceptualRoughnessToMipLevelUnity(1.0, 6.0), 6.0);
  EXPECT_DOUBLE_EQ(FacetPerceptualRoughnessToMipLevelUnity(0.0, 6.0), 0.0);
}

TEST(ReferenceIblTest, RadicalInverseIsTheBitReversedFraction) {
  EXPECT_DOUBLE_EQ(FacetRadicalInverse(1), 0.5);
  EXPECT_DOUBLE_EQ(FacetRadicalInverse(2), 0.25);
  EXPECT_DOUBLE_EQ(FacetRadicalInverse(3), 0.75);
}

}  // namespace
}  // namespace facet::reference
