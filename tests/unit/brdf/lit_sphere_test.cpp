// The lit sphere against the albedo view. In the furnace (uniform white
// environment of radiance 1) a pixel whose view cosine is mu shows E(mu), the
// directional albedo; for GGX with f0 = 1 and multiscatter compensation
// (ggx-ms: FacetEnergyCompensation with E from FacetDFG_Integrate, an
// importance-sampled integral independent of the views' grid quadrature)
// E = 1, so the sphere vanishes into the background (T7/T18).
#include <gtest/gtest.h>

#include <cmath>

#include "facet/reference/hlsl_math.h"
#include "facet/runtime/brdf.h"

namespace facet::brdf {
namespace {

constexpr int kSize = 24;

// E at view angle theta (degrees) from the albedo curve, linearly interpolated.
double albedo_at(const std::vector<AlbedoPoint>& curve, double theta) {
  for (size_t i = 1; i < curve.size(); ++i) {
    if (theta <= curve[i].theta_deg) {
      double t = (theta - curve[i - 1].theta_deg) / (curve[i].theta_deg - curve[i - 1].theta_deg);
      return reference::lerp(curve[i - 1].albedo.g, curve[i].albedo.g, t);
    }
  }
  return curve.back().albedo.g;
}

TEST(BrdfLitSphere, CompensatedGgxInTheFurnaceIsItsAlbedoWhichIsOne) {
  for (const char* spec : {"ggx-ms:roughness=0.5,f0=1", "ggx-ms:roughness=1,f0=1"}) {
    SCOPED_TRACE(spec);
    Result<Model> m = parse_model(spec);
    ASSERT_TRUE(m.has_value());
    Image im = render_lit_sphere(*m, {.size = kSize, .furnace = true, .quadrature = 48});
    std::vector<AlbedoPoint> curve = albedo_curve(*m, 19, 84.0, 96);
    int checked = 0;
    for (int y = 0; y < kSize; ++y) {
      for (int x = 0; x < kSize; ++x) {
        glm::dvec3 n, v;
        if (!lit_sphere_pixel(x, y, kSize, n, v) || v.z < 0.1) continue;
        double pixel = im.at(x, y).g;
        EXPECT_NEAR(pixel, albedo_at(curve, std::acos(v.z) * 180.0 / reference::kPi), 3e-3) << x << "," << y;
        EXPECT_NEAR(pixel, 1.0, 0.01) << x << "," << y;  // T7: +-1 %
        ++checked;
      }
    }
    EXPECT_GT(checked, 300);
  }
}

TEST(BrdfLitSphere, UncompensatedGgxDarkensInTheFurnace) {
  // Without compensation the same sphere is visible: E(1) = 1 - ln 2 at alpha = 1.
  Result<Model> m = parse_model("ggx:roughness=1,f0=1");
  ASSERT_TRUE(m.has_value());
  Image im = render_lit_sphere(*m, {.size = 9, .furnace = true, .quadrature = 64});
  EXPECT_NEAR(im.at(4, 4).g, 1.0 - std::log(2.0), 0.01);
}

TEST(BrdfLitSphere, DirectionalLightOnLambertFollowsTheCosine) {
  Result<Model> m = parse_model("lambert:albedo=0.6");
  ASSERT_TRUE(m.has_value());
  const double incidence = 30.0 * reference::kPi / 180.0;
  const glm::dvec3 l(-std::sin(incidence), 0.0, std::cos(incidence));
  Image im = render_lit_sphere(*m, {.size = kSize, .incidence_deg = 30.0});
  for (int y = 0; y < kSize; ++y) {
    for (int x = 0; x < kSize; ++x) {
      glm::dvec3 n, v;
      double expected = lit_sphere_pixel(x, y, kSize, n, v) ? 0.6 * std::max(glm::dot(n, l), 0.0) : 0.0;
      EXPECT_NEAR(im.at(x, y).r, expected, 1e-6) << x << "," << y;
    }
  }
}

}  // namespace
}  // namespace facet::brdf
