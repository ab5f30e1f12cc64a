// Unity's forward light scheduling on lavapipe: which lights of a scene are
// pixel lights, per-vertex lights (VERTEXLIGHT_ON) and SH lights of an
// object, what --explain says of them, and that each kind lights the pixels.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "render_test_support.h"

namespace facet::runtime {
namespace {

using test_support::object_json;
using test_support::pixel;
using test_support::small_scene;

using LightScheduleTest = test_support::RenderTest;

constexpr const char* kSun = R"({"type": "directional", "rotation": [30, 20, 0], "intensity": 0.5})";

// `count` point lights around the origin in range of it, brightest first,
// each with `extra` keys.
std::string point_lights(int count, const std::string& extra = "") {
  std::string list;
  for (int i = 0; i < count; ++i) {
    float angle = 0.9f * float(i);
    list += (list.empty() ? "" : ", ") +
            std::string(R"({"type": "point", "range": 8, "intensity": )") + std::to_string(count - i) +
            R"(, "position": [)" + std::to_string(1.5f * std::cos(angle)) + ", " +
            std::to_string(1.5f * std::sin(angle)) + ", -1]" + extra + "}";
  }
  return list;
}

std::string with_pixel_lights(std::string scene, int count) {
  scene.insert(1, "\"pixel_light_count\": " + std::to_string(count) + ", ");
  return scene;
}

const DrawRecord* base_draw(const RenderedFrame& f) {
  for (const DrawRecord& d : f.draws) {
    if (d.drawn && d.light_mode == "ForwardBase") return &d;
  }
  return nullptr;
}

bool has(const std::vector<std::string>& keywords, const char* k) {
  return std::find(keywords.begin(), keywords.end(), k) != keywords.end();
}

std::vector<std::string> additive_lights(const RenderedFrame& f) {
  std::vector<std::string> out;
  for (const DrawRecord& d : f.draws) {
    if (d.drawn && d.additive) out.push_back(d.light);
  }
  return out;
}

std::string surface_object() { return "[" + object_json("sphere", "SurfaceLambertVertex.shader") + "]"; }

TEST_F(LightScheduleTest, WithSixLightsTheFifthAndSixthBecomeVertexLightsAndTheKeywordSetShowsIt) {
  RenderedFrame f =
      render("six_lights", small_scene(surface_object(), std::string("[") + kSun + ", " + point_lights(5) + "]"));
  // Four pixel lights: the sun in ForwardBase, the three brightest points additively.
  EXPECT_EQ(additive_lights(f),
            (std::vector<std::string>{"lights[1] (point)", "lights[2] (point)", "lights[3] (point)"}));
  const DrawRecord* base = base_draw(f);
  ASSERT_NE(base, nullptr);
  EXPECT_TRUE(has(base->keywords, "VERTEXLIGHT_ON")) << ::testing::PrintToString(base->keywords);
  EXPECT_TRUE(base->exact);
  EXPECT_NE(base->why.find("per vertex (VERTEXLIGHT_ON): lights[4] (point), lights[5] (point)"), std::string::npos)
      << base->why;
  EXPECT_EQ(base->why.find("into SH"), std::string::npos) << base->why;
  // Four lights or fewer: no vertex lights, and the variant without the keyword.
  RenderedFrame four =
      render("four_lights", small_scene(surface_object(), std::string("[") + kSun + ", " + point_lights(3) + "]"));
  ASSERT_NE(base_draw(four), nullptr);
  EXPECT_FALSE(has(base_draw(four)->keywords, "VERTEXLIGHT_ON"));
  EXPECT_EQ(additive_lights(four).size(), 3u);
}

TEST_F(LightScheduleTest, PointLightsBeyondTheFourVertexLightsAndOtherLightsGoIntoTheSH) {
  std::string lights = std::string("[") + kSun + ", " + point_lights(6) + R"(, {"type": "spot", "position": [0, 2, -1],
      "look_at": [0, 0, 0], "range": 8, "intensity": 0.1}])";
  RenderedFrame f = render("sh_lights", with_pixel_lights(small_scene(surface_object(), lights), 1));
  EXPECT_TRUE(additive_lights(f).empty());
  const DrawRecord* base = base_draw(f);
  ASSERT_NE(base, nullptr);
  EXPECT_TRUE(has(base->keywords, "VERTEXLIGHT_ON"));
  EXPECT_NE(base->why.find("per vertex (VERTEXLIGHT_ON): lights[1] (point), lights[2] (point), lights[3] (point), "
                           "lights[4] (point); into SH: lights[5] (point), lights[6] (point), lights[7] (spot)"),
            std::string::npos)
      << base->why;
}

TEST_F(LightScheduleTest, AnImportantLightIsAPixelLightBeyondTheCountAndANotImportantOneNever) {
  std::string objects = surface_object();
  auto lights = [&](const char* mode) {
    return std::string("[") + kSun + ", " + point_lights(1, std::string(R"(, "render_mode": ")") + mode + "\"") + "]";
  };
  RenderedFrame important = render("important", with_pixel_lights(small_scene(objects, lights("important")), 1));
  EXPECT_EQ(additive_lights(important), (std::vector<std::string>{"lights[1] (point)"}));
  for (const DrawRecord& d : important.draws) {
    if (d.additive) {
      EXPECT_NE(d.why.find("(important: always a pixel light)"), std::string::npos) << d.why;
    }
  }
  ASSERT_NE(base_draw(important), nullptr);
  EXPECT_FALSE(has(base_draw(important)->keywords, "VERTEXLIGHT_ON"));

  RenderedFrame automatic = render("auto", with_pixel_lights(small_scene(objects, lights("auto")), 1));
  EXPECT_TRUE(additive_lights(automatic).empty());
  ASSERT_NE(base_draw(automatic), nullptr);
  EXPECT_TRUE(has(base_draw(automatic)->keywords, "VERTEXLIGHT_ON"));

  RenderedFrame unimportant = render("not_important", small_scene(objects, lights("not_important")));
  EXPECT_TRUE(additive_lights(unimportant).empty()) << "a pixel-light slot was free, but the light is not important";
  ASSERT_NE(base_draw(unimportant), nullptr);
  EXPECT_TRUE(has(base_draw(unimportant)->keywords, "VERTEXLIGHT_ON"));
}

TEST_F(LightScheduleTest, ANotImportantDirectionalLightIsNeverTheMainLight) {
  std::string lights = R"([{"type": "directional", "intensity": 3, "render_mode": "not_important"},
                           {"type": "directional", "intensity": 0.2}])";
  RenderedFrame f = render("not_main", small_scene(surface_object(), lights));
  const DrawRecord* base = base_draw(f);
  ASSERT_NE(base, nullptr);
  EXPECT_EQ(base->light, "lights[1] (directional)");
  EXPECT_NE(base->why.find("or not important (lights[0] (directional)): into SH: lights[0] (directional)"),
            std::string::npos)
      << base->why;
}

TEST_F(LightScheduleTest, AVertexLightBrightensTheSideOfTheObjectItIsOn) {
  // The main light alone is a pixel light; the point light on the right lights per vertex.
  std::string objects = "[" + object_json("sphere", "SurfaceLambertVertex.shader") + "]";
  std::string right = R"({"type": "point", "position": [1.4, 0, -0.6], "range": 6, "intensity": 3})";
  RenderedFrame dark = render("no_vertex_light", with_pixel_lights(small_scene(objects, std::string("[") + kSun + "]"), 1));
  RenderedFrame lit = render("vertex_light",
                             with_pixel_lights(small_scene(objects, std::string("[") + kSun + ", " + right + "]"), 1));
  ASSERT_FALSE(dark.ldr.empty());
  ASSERT_FALSE(lit.ldr.empty());
  ASSERT_TRUE(additive_lights(lit).empty());
  ASSERT_TRUE(base_draw(lit) && has(base_draw(lit)->keywords, "VERTEXLIGHT_ON"));
  // Right of the centre (x grows to the right) against the left side.
  int gain_right = pixel(lit, 44, 32)[0] - pixel(dark, 44, 32)[0];
  int gain_left = pixel(lit, 20, 32)[0] - pixel(dark, 20, 32)[0];
  EXPECT_GT(gain_right, 30);
  EXPECT_LT(gain_left, gain_right / 3);
}

TEST_F(LightScheduleTest, AnSHLightBrightensTheSideFacingItAndTheBackOnlyByTheL2Ringing) {
  std::string objects = "[" + object_json("sphere", "SurfaceLambertVertex.shader") + "]";
  // Shines along -X: from the right of the image towards the left.
  std::string side = R"({"type": "directional", "rotation": [0, -90, 0], "intensity": 1.5, "render_mode": "not_important"})";
  RenderedFrame dark = render("no_sh_light", small_scene(objects));
  RenderedFrame lit = render("sh_light", small_scene(objects, "[" + side + "]"));
  ASSERT_FALSE(dark.ldr.empty());
  ASSERT_FALSE(lit.ldr.empty());
  ASSERT_TRUE(base_draw(lit));
  EXPECT_NE(base_draw(lit)->why.find("into SH: lights[0] (directional)"), std::string::npos);
  EXPECT_FALSE(has(base_draw(lit)->keywords, "VERTEXLIGHT_ON"));
  int gain_right = pixel(lit, 46, 32)[0] - pixel(dark, 46, 32)[0];
  int gain_left = pixel(lit, 18, 32)[0] - pixel(dark, 18, 32)[0];
  EXPECT_GT(gain_right, 40);
  EXPECT_LT(gain_left, gain_right / 3);
}

}  // namespace
}  // namespace facet::runtime
