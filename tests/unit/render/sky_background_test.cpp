// The camera's sky background (camera "clear": "sky"): the ambient's
// procedural sky drawn behind the scene, only when asked for.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "facet/runtime/material.h"
#include "facet/runtime/scene.h"
#include "render_test_support.h"

namespace facet::runtime {
namespace {

std::array<int, 3> pixel(const RenderedFrame& f, int x, int y) {
  const uint8_t* p = &f.ldr[(size_t(y) * f.width + x) * 4];
  return {p[0], p[1], p[2]};
}

constexpr const char* kSky =
    R"({"sky": {"zenith": [0.2, 0.4, 0.9], "horizon": [0.9, 0.8, 0.6], "ground": [0.3, 0.2, 0.1], "intensity": 1}})";

std::string sky_scene(const std::string& camera, const std::string& clear = R"(, "clear": "sky")") {
  return R"({"width": 32, "height": 32, "ambient": )" + std::string(kSky) + R"(, "camera": {)" + camera + clear +
         R"(}, "objects": []})";
}

// The sky's radiance towards `y` (the direction's height), as the shader
// blends it, then encoded as facet's 8-bit output (no tone mapping).
std::array<int, 3> expected(float y) {
  const float zenith[3] = {0.2f, 0.4f, 0.9f}, horizon[3] = {0.9f, 0.8f, 0.6f}, ground[3] = {0.3f, 0.2f, 0.1f};
  std::array<int, 3> out{};
  for (int c = 0; c < 3; ++c) {
    double h = srgb_to_linear(horizon[c]);
    double other = srgb_to_linear(y >= 0 ? zenith[c] : ground[c]);
    double linear = h + (other - h) * std::abs(y);
    out[size_t(c)] = int(std::lround(linear_to_srgb(std::clamp(linear, 0.0, 1.0)) * 255.0));
  }
  return out;
}

void expect_near(const std::array<int, 3>& got, const std::array<int, 3>& want, int tolerance) {
  for (size_t c = 0; c < 3; ++c) EXPECT_NEAR(got[c], want[c], tolerance) << "channel " << c;
}

using SkyBackgroundTest = test_support::RenderTest;

TEST_F(SkyBackgroundTest, TheSkyIsTheZenithStraightUpAndTheHorizonStraightAhead) {
  RenderedFrame up = render("sky_up", sky_scene(R"("position": [0, 0, 0], "rotation": [-90, 0, 0], "fov": 10)"));
  RenderedFrame ahead = render("sky_ahead", sky_scene(R"("position": [0, 0, 0], "fov": 10)"));
  ASSERT_FALSE(up.ldr.empty());
  expect_near(pixel(up, 16, 16), expected(1), 3);
  expect_near(pixel(ahead, 16, 16), expected(0), 3);
}

TEST_F(SkyBackgroundTest, LookingAlongTheHorizonTheTopIsBluerThanTheBottom) {
  RenderedFrame f = render("sky_rows", sky_scene(R"("position": [0, 0, 0], "fov": 90)"));
  ASSERT_FALSE(f.ldr.empty());
  EXPECT_GT(pixel(f, 16, 1)[2] - pixel(f, 16, 1)[0], pixel(f, 16, 16)[2] - pixel(f, 16, 16)[0] + 20);
  EXPECT_LT(pixel(f, 16, 30)[2], pixel(f, 16, 16)[2] - 20);  // below the horizon: the darker ground
}

TEST_F(SkyBackgroundTest, AFlatClearDrawsAndCompilesNoSky) {
  RenderedFrame f = render("flat", sky_scene(R"("position": [0, 0, 0], "clear_color": [1, 0, 0])", ""));
  EXPECT_EQ(f.stats.draws, 0u);
  EXPECT_TRUE(f.compiled.empty());
  EXPECT_EQ(pixel(f, 16, 16), (std::array<int, 3>{255, 0, 0}));
}

TEST_F(SkyBackgroundTest, TheSkyIsOneDrawBeforeTheScene) {
  RenderedFrame f = render("sky_first", sky_scene(R"("position": [0, 0, 0])"));
  ASSERT_EQ(f.stats.draws, 1u);
  EXPECT_EQ(f.draws[0].object, "camera.clear (procedural sky)");
  EXPECT_EQ(f.draws[0].shader, "Hidden/Facet/ProceduralSky");
}

TEST(SkyBackgroundScene, BadClearSettingsNameTheirJsonPath) {
  auto no_sky = parse_scene(R"({"camera": {"clear": "sky"}, "objects": []})", "s.json");
  ASSERT_FALSE(no_sky);
  EXPECT_NE(no_sky.error().message.find("camera.clear: \"sky\" needs something to draw: an environment, or ambient as a procedural sky"), std::string::npos)
      << no_sky.error().message;
  auto bad_word = parse_scene(R"({"camera": {"clear": "blue"}, "objects": []})", "s.json");
  ASSERT_FALSE(bad_word);
  EXPECT_NE(bad_word.error().message.find("camera.clear: unknown value 'blue' (expected one of: color, sky)"),
            std::string::npos)
      << bad_word.error().message;
}

}  // namespace
}  // namespace facet::runtime

namespace facet::runtime {
namespace {

using SkySunTest = test_support::RenderTest;

// A sky with a sun shining as lights[0] (from 40 degrees up, towards +Z):
// the camera looking at the sun sees its disc, bright beyond the sky's 1;
// a mirror ball reflects it from the environment cube; facing the sun, the
// ambient SH is brighter than facing away.
std::string sun_scene(const std::string& camera, const std::string& objects = "") {
  return R"({"width": 48, "height": 48,
    "ambient": {"sky": {"zenith": [0.2, 0.4, 0.9], "horizon": [0.9, 0.8, 0.6], "ground": [0.3, 0.2, 0.1],
                        "sun": {"light": 0, "size": 4, "intensity": 10}}},
    "lights": [{"type": "directional", "rotation": [40, 180, 0], "intensity": 1}],
    "camera": {)" + camera + R"(, "clear": "sky"}, "objects": [)" + objects + "]}";
}

TEST_F(SkySunTest, TheSunsDiscShowsInTheSkyWhereItsLightComesFrom) {
  // The light shines along pitch 40, yaw 180: from +Z and above, towards -Z.
  RenderedFrame f = render("sun_sky", sun_scene(R"("position": [0, 0, 0], "rotation": [-40, 0, 0], "fov": 30)"));
  ASSERT_FALSE(f.hdr.empty());
  const float* centre = &f.hdr[(24 * 48 + 24) * 4];
  const float* beside = &f.hdr[(24 * 48 + 2) * 4];
  EXPECT_GT(centre[0], 5.0f) << "the disc: the light's colour x intensity 10";
  EXPECT_LT(beside[0], 1.0f) << "the sky beside it";
}

TEST(SkySunScene, ASunMustShineAsADirectionalLight) {
  auto scene = parse_scene(R"({"camera": {}, "objects": [], "lights": [{"type": "point"}],
    "ambient": {"sky": {"sun": {"light": 0}}}})", "s.json");
  ASSERT_FALSE(scene);
  EXPECT_NE(scene.error().message.find("ambient.sky.sun.light: expected the index of a directional light"),
            std::string::npos)
      << scene.error().message;
}

}  // namespace
}  // namespace facet::runtime
