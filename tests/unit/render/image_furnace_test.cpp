// T18 of docs/stability.md ("Rendered furnace"), rendered: a sphere grid (smoothness x metallic) of
// the Standard surface shader in a uniform white environment (ambient 1, no
// lights), and a plane seen at a grazing angle, scanned for NaN/Inf and for
// light beyond the environment's by more than the Standard model's known
// additive excess (docs/stability.md, "Rendered furnace").
#include <gtest/gtest.h>

#include <cmath>
#include <fmt/format.h>

#include <string>

#include "facet/runtime/scene.h"
#include "render_test_support.h"

namespace facet::runtime {
namespace {

using test_support::example_shader;

struct Scan {
  size_t non_finite = 0, negative = 0, covered = 0;
  float max = 0;
};

// Pixels the objects cover: the background is black, the environment white.
Scan scan(const RenderedFrame& f) {
  Scan s;
  for (size_t i = 0; i + 3 < f.hdr.size(); i += 4) {
    for (int c = 0; c < 3; ++c) {
      float v = f.hdr[i + size_t(c)];
      if (!std::isfinite(v)) ++s.non_finite;
      else if (v < 0) ++s.negative;
      else s.max = std::max(s.max, v);
    }
    s.covered += f.hdr[i] > 0 || f.hdr[i + 1] > 0 || f.hdr[i + 2] > 0;
  }
  return s;
}

std::string sphere(double x, double y, double smoothness, double metallic) {
  return fmt::format(R"({{"mesh": "sphere", "position": [{}, {}, 0], "scale": 0.9, "material": {{"shader": "{}",
      "properties": {{"_Color": [1, 1, 1, 1], "_Glossiness": {}, "_Metallic": {}}}}}}})",
                     x, y, example_shader("SurfaceStandard.shader"), smoothness, metallic);
}

using ImageFurnaceTest = test_support::RenderTest;

std::string grid_scene(int metallic) {
  std::string objects;
  for (int s = 0; s < 4; ++s) {
    if (!objects.empty()) objects += ",";
    objects += sphere(-1.5 + s, 0, s / 3.0, metallic);
  }
  return R"({"width": 96, "height": 32, "ambient": [1, 1, 1],
    "camera": {"position": [0, 0, -6], "look_at": [0, 0, 0], "fov": 20, "clear_color": [0, 0, 0]},
    "lights": [], "objects": [)" + objects + "]}";
}

// A white metal (f0 = 1, no diffuse) reflects at most the environment:
// Unity's specular environment term is surfaceReduction x FresnelLerp <= 1.
TEST_F(ImageFurnaceTest, MetalSphereRowInAWhiteEnvironmentStaysFiniteAndBelowTheEnvironment) {
  RenderedFrame f = render("furnace_metal", grid_scene(1));
  ASSERT_FALSE(f.hdr.empty());
  Scan s = scan(f);
  EXPECT_EQ(s.non_finite, 0u);
  EXPECT_EQ(s.negative, 0u);
  EXPECT_GT(s.covered, size_t(96 * 32 / 8)) << "the spheres cover the frame";
  EXPECT_LE(s.max, 1.01f);
  std::printf("[ image furnace ] metal row: max %.4f over %zu covered pixels\n", s.max, s.covered);
}

// A white dielectric: Unity's Standard model adds its diffuse and specular
// environment terms without coupling them, (1 - 0.04) x albedo plus up to 1
// at grazing views, so it may exceed the environment (a known violator);
// the analytic bound is 2, and the measured excess is reported.
TEST_F(ImageFurnaceTest, DielectricSphereRowStaysFiniteAndWithinTheStandardModelsBound) {
  RenderedFrame f = render("furnace_dielectric", grid_scene(0));
  ASSERT_FALSE(f.hdr.empty());
  Scan s = scan(f);
  EXPECT_EQ(s.non_finite, 0u);
  EXPECT_EQ(s.negative, 0u);
  EXPECT_GT(s.covered, size_t(96 * 32 / 8));
  EXPECT_GT(s.max, 0.9f) << "a white diffuse sphere is about as bright as the environment";
  EXPECT_LE(s.max, 2.0f);
  std::printf("[ image furnace ] dielectric row: max %.4f over %zu covered pixels\n", s.max, s.covered);
}

// A mirror-smooth white metal plane seen from just above it: NoV falls to
// ~0.02 in the distance, where the clamps on NoV keep every term finite.
TEST_F(ImageFurnaceTest, GrazingPlaneInAWhiteEnvironmentStaysFiniteAndBounded) {
  std::string json = fmt::format(R"({{"width": 96, "height": 48, "ambient": [1, 1, 1],
    "camera": {{"position": [0, 0.3, -9], "look_at": [0, 0, 10], "fov": 60, "clear_color": [0, 0, 0]}},
    "lights": [], "objects": [{{"mesh": "plane", "scale": 2, "material": {{"shader": "{}",
      "properties": {{"_Color": [1, 1, 1, 1], "_Glossiness": 1, "_Metallic": 1}}}}}}]}})",
                                 example_shader("SurfaceStandard.shader"));
  RenderedFrame f = render("furnace_plane", json);
  ASSERT_FALSE(f.hdr.empty());
  Scan s = scan(f);
  EXPECT_EQ(s.non_finite, 0u);
  EXPECT_EQ(s.negative, 0u);
  EXPECT_GT(s.covered, size_t(96 * 48 / 8));
  EXPECT_LE(s.max, 1.01f);
  std::printf("[ image furnace ] grazing plane: max %.4f over %zu covered pixels\n", s.max, s.covered);
}

}  // namespace
}  // namespace facet::runtime
