// T1/T2: every assembled model on the hard-case grid of docs/stability.md
// (grazing and back-facing NoV/NoL, L = -V, L = V = N, NoH = 1, roughness 0
// and 1, f0 0 and 1, unnormalised and zero-length normals, denormals, light
// intensities 0 / 65504 / 1e6): finite, non-negative, representable in fp32,
// and no contribution from a light behind the surface.
#include <gtest/gtest.h>

#include <cfloat>
#include <functional>
#include <string>
#include <vector>

#include "facet/reference/lighting.h"

namespace facet::reference {
namespace {

struct Inputs {
  glm::dvec3 n, v, l;
  double roughness, f0;
};
// A model returns the light it reflects, f(v, l) <n.l>, for unit intensity.
using Model = std::function<glm::dvec3(const Inputs&)>;

glm::dvec3 dir(double c, double phi) {
  double s = std::sqrt(std::max(0.0, 1.0 - c * c));
  return {s * std::cos(phi), s * std::sin(phi), c};
}

std::vector<glm::dvec3> normals() {
  return {{0, 0, 1}, {0, 0, 0.98}, {0, 0, 1.02}, {0, 0, 0}, {0, 0, 1e-40}, {0, 0, 4.9e-324}, {1e-39, 0, 1}};
}

std::vector<std::pair<glm::dvec3, glm::dvec3>> view_light_pairs() {
  const double cosines[] = {-0.3, -1e-6, 0.0, 1e-7, 1e-4, 0.5, 1.0};
  std::vector<std::pair<glm::dvec3, glm::dvec3>> pairs;
  for (double cv : cosines)
    for (double cl : cosines) pairs.push_back({dir(cv, 0.0), dir(cl, 2.0)});
  for (double c : cosines) {
    glm::dvec3 v = dir(c, 0.7);
    pairs.push_back({v, -v});                         // L = -V: H = 0
    pairs.push_back({v, 2.0 * v.z * glm::dvec3(0, 0, 1) - v});  // mirror: NoH = 1
    pairs.push_back({v, v});                          // L = V
  }
  pairs.push_back({{0, 0, 1}, {0, 0, 1}});            // L = V = N
  pairs.push_back({{1e-40, 0, 1}, {0, 1e-310, 1}});   // denormal components
  return pairs;
}

// Tangent frame for the anisotropic models, safe for a zero normal.
void frame(const glm::dvec3& n, glm::dvec3& x, glm::dvec3& y) {
  glm::dvec3 nn = FacetSafeNormalize(n);
  x = FacetSafeNormalize(glm::cross(glm::dvec3(0, 1, 0), nn) + glm::dvec3(1e-3, 0, 0));
  y = glm::cross(nn, x);
}

std::vector<std::pair<std::string, Model>> models() {
  auto diffuse = [](double (*fd)(const FacetAngles&, double)) {
    return [fd](const Inputs& in) {
      FacetAngles a = FacetComputeAngles(in.n, in.v, in.l);
      return glm::dvec3(fd(a, in.roughness) * a.NoL);
    };
  };
  return {
      {"Cook-Torrance GGX", [](const Inputs& in) {
         FacetAngles a = FacetComputeAngles(in.n, in.v, in.l);
         return FacetBRDF_CookTorranceGGX(in.n, in.v, in.l, glm::dvec3(in.f0), in.roughness) * a.NoL;
       }},
      {"Cook-Torrance Beckmann", [](const Inputs& in) {
         FacetAngles a = FacetComputeAngles(in.n, in.v, in.l);
         return FacetBRDF_CookTorranceBeckmann(in.n, in.v, in.l, glm::dvec3(in.f0), in.roughness) * a.NoL;
       }},
      {"GGX FP16-safe D + Hammon V", [](const Inputs& in) {
         FacetAngles a = FacetComputeAngles(in.n, in.v, in.l);
         glm::dvec3 n = FacetSafeNormalize(in.n), h = FacetSafeNormalize(FacetSafeNormalize(in.v) + FacetSafeNormalize(in.l));
         double alpha = std::max(in.roughness * in.roughness, FACET_MIN_ALPHA_FP16);
         return FacetD_GGX_FP16Safe(n, h, alpha) * FacetV_SmithGGXCorrelatedFast(a.NoV, a.NoL, alpha) *
                FacetF_Schlick(glm::dvec3(in.f0), 1.0, a.LoH) * a.NoL;
       }},
      {"Lambert", diffuse([](const FacetAngles&, double) { return FacetFd_Lambert(); })},
      {"Burley", diffuse([](const FacetAngles& a, double r) { return FacetFd_Burley(a.NoV, a.NoL, a.LoH, r); })},
      {"Frostbite", diffuse([](const FacetAngles& a, double r) { return FacetFd_Frostbite(a.NoV, a.NoL, a.LoH, r * r); })},
      {"Oren-Nayar qualitative",
       diffuse([](const FacetAngles& a, double r) { return FacetFd_OrenNayarQualitative(a.NoV, a.NoL, a.LoV, r); })},
      {"Oren-Nayar full",
       diffuse([](const FacetAngles& a, double r) { return FacetFd_OrenNayar(a.NoV, a.NoL, a.LoV, r, 1.0); })},
      {"Phong normalized", diffuse([](const FacetAngles& a, double r) {
         return FacetPhongNormalized(2 * a.NoL * a.NoV - a.LoV, FacetAlphaToBlinnPhongExponent(FacetClampAlpha(r * r)));
       })},
      {"Blinn-Phong normalized", diffuse([](const FacetAngles& a, double r) {
         return FacetBlinnPhongNormalized(a.NoH, FacetAlphaToBlinnPhongExponent(FacetClampAlpha(r * r)));
       })},
      {"Ashikhmin-Shirley", [](const Inputs& in) {
         FacetAngles a = FacetComputeAngles(in.n, in.v, in.l);
         glm::dvec3 x, y;
         frame(in.n, x, y);
         glm::dvec3 h = FacetSafeNormalize(FacetSafeNormalize(in.v) + FacetSafeNormalize(in.l));
         double e = FacetAlphaToBlinnPhongExponent(FacetClampAlpha(in.roughness * in.roughness));
         return glm::dvec3((FacetSpecular_AshikhminShirley(a.NoV, a.NoL, a.NoH, a.LoH, glm::dot(h, x), glm::dot(h, y),
                                                           e, 2 * e, in.f0) +
                            FacetFd_AshikhminShirley(a.NoV, a.NoL, 1.0, in.f0)) * a.NoL);
       }},
      {"Ward", [](const Inputs& in) {
         FacetAngles a = FacetComputeAngles(in.n, in.v, in.l);
         glm::dvec3 x, y;
         frame(in.n, x, y);
         glm::dvec3 h = FacetSafeNormalize(FacetSafeNormalize(in.v) + FacetSafeNormalize(in.l));
         double alpha = FacetClampAlpha(in.roughness * in.roughness);
         return glm::dvec3(FacetSpecular_Ward(a.NoV, a.NoL, a.NoH, glm::dot(h, x), glm::dot(h, y), alpha, 2 * alpha) * a.NoL);
       }},
      // FacetBRDF_Disney needs an orthonormal frame, which a normal shorter
      // than FacetSafeNormalize's floor (1/128) cannot give: such a pixel
      // shades black, as every other model here makes it.
      {"Disney", [](const Inputs& in) {
         if (glm::length(FacetSafeNormalize(in.n)) < 0.5) return glm::dvec3(0.0);
         FacetDisneyMaterial m;
         m.roughness = in.roughness, m.metallic = in.f0, m.clearcoat = 1, m.sheen = 1, m.subsurface = 0.5;
         m.anisotropic = 0.5;
         glm::dvec3 x, y;
         frame(in.n, x, y);
         glm::dvec3 n = FacetSafeNormalize(in.n);
         return FacetBRDF_Disney(m, FacetSafeNormalize(in.l), FacetSafeNormalize(in.v), n, x, y) *
                saturate(glm::dot(n, FacetSafeNormalize(in.l)));
       }},
      {"GGX + energy compensation", [](const Inputs& in) {
         FacetAngles a = FacetComputeAngles(in.n, in.v, in.l);
         glm::dvec3 f0(in.f0);
         double E = std::max(FacetEnvBRDFApproxAB(in.roughness, a.NoV).x + FacetEnvBRDFApproxAB(in.roughness, a.NoV).y, 0.05);
         return FacetBRDF_CookTorranceGGX(in.n, in.v, in.l, f0, in.roughness) * FacetEnergyCompensation(f0, E) * a.NoL;
       }},
      {"translucency", [](const Inputs& in) {
         return glm::dvec3(FacetTranslucency(FacetSafeNormalize(in.n), FacetSafeNormalize(in.v), FacetSafeNormalize(in.l),
                                             0.3, 4.0 * in.roughness, 1.0, 0.0, 1.0));
       }},
  };
}

bool fp32_representable(double x) { return std::isfinite(x) && std::abs(x) <= double(FLT_MAX); }

TEST(ReferenceHardCasesTest, AssembledModelsAreFiniteNonNegativeAndFitFp32OnTheHardCaseGrid) {
  const double intensities[] = {0.0, 1.0, 65504.0, 1e6};
  int evaluations = 0;
  for (const auto& [name, model] : models()) {
    for (const glm::dvec3& n : normals())
      for (const auto& [v, l] : view_light_pairs())
        for (double r : {0.0, 0.045, 0.5, 1.0})
          for (double f0 : {0.0, 0.04, 1.0}) {
            glm::dvec3 out = model({n, v, l, r, f0});
            for (double intensity : intensities)
              for (int c = 0; c < 3; ++c) {
                double y = out[c] * intensity;
                ++evaluations;
                ASSERT_TRUE(fp32_representable(y) && y >= 0.0)
                    << name << ": " << y << " for n=(" << n.x << "," << n.y << "," << n.z << ") v.z=" << v.z
                    << " l.z=" << l.z << " r=" << r << " f0=" << f0 << " intensity=" << intensity;
              }
          }
  }
  EXPECT_GT(evaluations, 100000);
}

TEST(ReferenceHardCasesTest, LightBehindTheSurfaceContributesNothing) {
  for (const auto& [name, model] : models()) {
    if (name == "translucency") continue;  // light from behind is its purpose
    for (double cl : {-1.0, -0.3, -1e-6})
      for (double cv : {-0.3, 1e-4, 0.5, 1.0}) {
        glm::dvec3 out = model({{0, 0, 1}, dir(cv, 0.0), dir(cl, 1.0), 0.5, 0.5});
        EXPECT_EQ(out.x + out.y + out.z, 0.0) << name << " NoL " << cl << " NoV " << cv;
      }
  }
}

TEST(ReferenceHardCasesTest, ComputeAnglesAppliesTheNoVAndNoLClamps) {
  for (const glm::dvec3& n : normals())
    for (const auto& [v, l] : view_light_pairs()) {
      FacetAngles a = FacetComputeAngles(n, v, l);
      EXPECT_GE(a.NoV, FACET_MIN_NOV);
      EXPECT_TRUE(a.NoL >= 0.0 && a.NoL <= 1.0 && a.NoH >= 0.0 && a.NoH <= 1.0 && a.LoH >= 0.0 && a.LoH <= 1.0);
      EXPECT_TRUE(std::isfinite(a.LoV));
    }
}

// The fp16 form never exceeds the largest half for any h, down to the fp32
// clamp; the plain form does (its peak at alpha = 0.002025 is 77 625).
TEST(ReferenceHardCasesTest, FP16SafeGGXStaysBelowHalfMaxWherePlainGGXOverflowsIt) {
  double worst = 0.0;
  for (double alpha : {FACET_MIN_ALPHA, 0.005, FACET_MIN_ALPHA_FP16, 0.1})
    for (double t = 0.0; t <= 1.6; t += 1e-4) worst = std::max(worst, FacetD_GGX_FP16Safe({0, 0, 1}, dir(std::cos(t), 0), alpha));
  EXPECT_LE(worst, FACET_HALF_MAX);
  EXPECT_GT(FacetD_GGX(1.0, FACET_MIN_ALPHA), FACET_HALF_MAX);
  EXPECT_NEAR(FacetD_GGX(1.0, FACET_MIN_ALPHA), 77625, 1);
}

TEST(ReferenceHardCasesTest, SafeNormalizeMapsZeroToZero) {
  glm::dvec3 z = FacetSafeNormalize(glm::dvec3(0.0));
  EXPECT_EQ(z, glm::dvec3(0.0));
  EXPECT_NEAR(glm::length(FacetSafeNormalize({0, 3, 4})), 1.0, 1e-15);
}

}  // namespace
}  // namespace facet::reference
