// The procedural sky's SH (facet/runtime/sky_sh.h) on the CPU: the flat case,
// an analytic projection, ShadeSH9 against a brute-force irradiance, and the
// environment cube's faces.
#include "facet/runtime/sky_sh.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "facet/runtime/environment.h"
#include "facet/runtime/material.h"

namespace facet::runtime {
namespace {

constexpr double kPi = std::numbers::pi;

// Directions spread evenly over the sphere (a Fibonacci lattice).
std::vector<glm::vec3> sphere_directions(int n) {
  std::vector<glm::vec3> out;
  double golden = kPi * (3 - std::sqrt(5.0));
  for (int i = 0; i < n; ++i) {
    double y = 1 - 2 * (i + 0.5) / n, r = std::sqrt(1 - y * y);
    out.push_back(glm::vec3(float(r * std::cos(golden * i)), float(y), float(r * std::sin(golden * i))));
  }
  return out;
}

// Irradiance / pi at normal n by brute force: a midpoint rule in (cos theta,
// phi) over the hemisphere around n, independent of the SH code.
glm::dvec3 reference_irradiance_over_pi(const SkyRadiance& sky, const glm::vec3& n) {
  glm::dvec3 nn(n), t = std::abs(n.y) < 0.9f ? glm::dvec3(0, 1, 0) : glm::dvec3(1, 0, 0);
  glm::dvec3 u = glm::normalize(glm::cross(t, nn)), v = glm::cross(nn, u);
  const int heights = 200, azimuths = 400;
  glm::dvec3 sum(0);
  for (int i = 0; i < heights; ++i) {
    double c = (i + 0.5) / heights, s = std::sqrt(1 - c * c);
    for (int k = 0; k < azimuths; ++k) {
      double phi = 2 * kPi * (k + 0.5) / azimuths;
      glm::dvec3 d = c * nn + s * std::cos(phi) * u + s * std::sin(phi) * v;
      sum += glm::dvec3(sky_radiance(sky, glm::vec3(d))) * c;
    }
  }
  return sum * (2 * kPi / (double(heights) * azimuths)) / kPi;
}

SkyRadiance typical_sky() {
  return linear_sky(SceneSky{.zenith = {0.2f, 0.45f, 0.9f}, .horizon = {0.8f, 0.8f, 0.75f},
                             .ground = {0.25f, 0.2f, 0.15f}, .intensity = 1.5f});
}

TEST(SkySh, FlatSkyGivesTheL0OnlyCoefficientsOfAFlatAmbient) {
  Vec3 c = {0.3f, 0.5f, 0.7f};
  UnitySh sky = pack_unity_sh(project_sh([&](const glm::vec3& d) {
    return sky_radiance(linear_sky(SceneSky{.zenith = c, .horizon = c, .ground = c}), d);
  }));
  glm::vec3 linear(float(srgb_to_linear(c[0])), float(srgb_to_linear(c[1])), float(srgb_to_linear(c[2])));
  UnitySh flat = flat_unity_sh(linear);
  for (int ch = 0; ch < 3; ++ch) {
    EXPECT_FLOAT_EQ(sky.a[ch].w, flat.a[ch].w) << "channel " << ch;
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(sky.a[ch][i], 0, 1e-7) << "A[" << ch << "][" << i << "]";
    for (int i = 0; i < 4; ++i) EXPECT_NEAR(sky.b[ch][i], 0, 1e-7) << "B[" << ch << "][" << i << "]";
    EXPECT_NEAR(sky.c[ch], 0, 1e-7);
  }
  EXPECT_EQ(flat.c, glm::vec4(0));
}

// Radiance max(0, y): L00 = Y0 pi, L(1,-1) = Y1 2pi/3, and band 2 is the
// y-zonal Y20 pi/2, which is -1/2 Y(2,0) - sqrt(3)/2 Y(2,2) in the z-zonal basis.
TEST(SkySh, ZenithOnlySkyMatchesTheAnalyticProjectionOfMaxZeroY) {
  SkyRadiance sky{.zenith = glm::vec3(1), .horizon = glm::vec3(0), .ground = glm::vec3(0)};
  ShCoefficients c = project_sh([&](const glm::vec3& d) { return sky_radiance(sky, d); });
  const double y0 = 0.28209479177387814, y1 = 0.4886025119029199, y20 = 0.31539156525252005;
  double zonal2 = y20 * kPi / 2;
  double expected[9] = {y0 * kPi, y1 * 2 * kPi / 3, 0, 0, 0, 0, -zonal2 / 2, 0, -std::sqrt(3.0) / 2 * zonal2};
  for (int i = 0; i < 9; ++i) EXPECT_NEAR(c[i].r, expected[i], 1e-5) << "coefficient " << i;
}

TEST(SkySh, ProjectionOfEachBasisFunctionIsThatUnitCoefficient) {
  for (int j = 0; j < 9; ++j) {
    ShCoefficients c = project_sh([&](const glm::vec3& d) { return glm::vec3(sh_basis(d)[j]); });
    for (int i = 0; i < 9; ++i) EXPECT_NEAR(c[i].g, i == j ? 1.0 : 0.0, 1e-5) << "basis " << j << " coefficient " << i;
  }
}

TEST(SkySh, ShadeSH9WithThePackedCoefficientsIsTheCosineConvolvedIrradianceWithin2Percent) {
  SkyRadiance sky = typical_sky();
  UnitySh sh = pack_unity_sh(project_sh([&](const glm::vec3& d) { return sky_radiance(sky, d); }));
  double worst = 0;
  for (const glm::vec3& n : sphere_directions(40)) {
    glm::dvec3 want = reference_irradiance_over_pi(sky, n);
    glm::vec3 got = eval_unity_sh(sh, n);
    for (int ch = 0; ch < 3; ++ch) {
      double rel = std::abs(got[ch] - want[ch]) / want[ch];
      worst = std::max(worst, rel);
      EXPECT_LT(rel, 0.02) << "n = (" << n.x << ", " << n.y << ", " << n.z << ") channel " << ch << ": " << got[ch]
                           << " vs " << want[ch];
    }
  }
  RecordProperty("worst_relative_error", std::to_string(worst));
}

TEST(SkySh, ALightInSHGivesItsColourTimesTheClampedCosineUpToTheL2Truncation) {
  glm::vec3 to_light = glm::normalize(glm::vec3(1, 2, -0.5f));
  glm::vec3 color(0.8f, 0.4f, 0.2f);
  UnitySh sh = pack_unity_sh(light_sh(to_light, color));
  // Bands 0..2 of max(0, cos): 1/4 + 1/2 + 5/16 facing the light, 1/4 - 1/2 + 5/16 behind it.
  glm::vec3 facing = eval_unity_sh(sh, to_light);
  glm::vec3 behind = eval_unity_sh(sh, -to_light);
  for (int ch = 0; ch < 3; ++ch) {
    EXPECT_NEAR(facing[ch], 1.0625f * color[ch], 1e-4f);
    EXPECT_NEAR(behind[ch], 0.0625f * color[ch], 1e-4f);
  }
  // Sideways the L2 sum is 1/4 - 5/32: still lit a little, as Unity's SH lights are.
  glm::vec3 side = glm::normalize(glm::cross(to_light, glm::vec3(0, 0, 1)));
  EXPECT_NEAR(eval_unity_sh(sh, side)[0], (0.25f - 5.0f / 32) * color[0], 1e-4f);
}

TEST(SkySh, PackingsAddUpAsTheirLightsDo) {
  UnitySh ambient = flat_unity_sh({0.1f, 0.2f, 0.3f});
  ShCoefficients light = light_sh({0, 1, 0}, {1, 1, 1});
  UnitySh sum = ambient + pack_unity_sh(light);
  glm::vec3 up = eval_unity_sh(sum, {0, 1, 0});
  EXPECT_NEAR(up.x, 0.1f + 1.0625f, 1e-4f);
  EXPECT_NEAR(up.z, 0.3f + 1.0625f, 1e-4f);
  EXPECT_NEAR(eval_unity_sh(sum, {0, -1, 0}).y, 0.2f + 0.0625f, 1e-4f);
}

TEST(SkySh, CubeFacesPointAlongTheirAxesAndTheTopFaceCentreIsTheZenith) {
  const glm::vec3 axes[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  for (int f = 0; f < 6; ++f) {
    glm::vec3 d = cube_direction(f, 0.5f, 0.5f);
    EXPECT_NEAR(glm::distance(d, axes[f]), 0, 1e-6) << "face " << f;
  }
  // Row 0 (t = 0) of a side face looks up (45 degrees at the edge), as
  // Vulkan's face selection has it; the last row looks down.
  for (int f : {0, 1, 4, 5}) {
    EXPECT_GT(cube_direction(f, 0.5f, 0.0f).y, 0.7f) << "face " << f;
    EXPECT_LT(cube_direction(f, 0.5f, 1.0f).y, -0.7f) << "face " << f;
  }
  SkyRadiance sky{.zenith = {1, 0, 0}, .horizon = {0, 1, 0}, .ground = {0, 0, 1}};
  std::vector<std::vector<float>> mips =
      cube_from_radiance([&](const glm::vec3& d) { return sky_radiance(sky, d); }, 16).mips;
  ASSERT_EQ(mips.size(), 5u);  // 16, 8, 4, 2, 1
  EXPECT_EQ(mips.back().size(), 6u * 4u);
  const float* top = &mips[0][((2 * 16 + 8) * 16 + 8) * 4];  // +Y face, near its centre
  EXPECT_GT(top[0], 0.95f);
  const float* bottom = &mips[0][((3 * 16 + 8) * 16 + 8) * 4];
  EXPECT_GT(bottom[2], 0.95f);
}

}  // namespace
}  // namespace facet::runtime

namespace facet::runtime {
namespace {

// The sun's SH is the delta of its power: facing it, ShadeSH9 gives its
// irradiance / pi (radiance x solid angle / pi) times L2's 1.0625; facing
// away, L2's 0.0625 ringing.
TEST(SkySh, TheSunsShIsTheDeltaOfItsPower) {
  SkySun sun{.to_sun = glm::normalize(glm::vec3(0, 1, 1)), .radiance = glm::vec3(50), .cos_radius = std::cos(0.02f)};
  const float solid_angle = 2 * std::numbers::pi_v<float> * (1 - sun.cos_radius);
  UnitySh sh = pack_unity_sh(sun_sh(sun));
  const float facing = 50 * solid_angle / std::numbers::pi_v<float>;
  EXPECT_NEAR(eval_unity_sh(sh, sun.to_sun).r, 1.0625f * facing, 1e-3f * facing);
  EXPECT_NEAR(eval_unity_sh(sh, -sun.to_sun).r, 0.0f, 0.07f * facing);
  // The disc itself: full radiance at its centre, none well outside.
  EXPECT_FLOAT_EQ(sun_radiance(sun, sun.to_sun).r, 50.0f);
  EXPECT_EQ(sun_radiance(sun, glm::vec3(1, 0, 0)).r, 0.0f);
}

}  // namespace
}  // namespace facet::runtime
