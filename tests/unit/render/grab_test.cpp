// GrabPass on lavapipe: the screen copied into _GrabTexture before each
// object with `GrabPass { }`, into a named texture once a frame, and a
// program that samples a grab texture nothing filled refused.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "render_test_support.h"

namespace facet::runtime {
namespace {

using test_support::example_shader;
using test_support::pixel;
using ::testing::HasSubstr;

using GrabTest = test_support::RenderTest;

std::string stdlib_shader(const std::string& name) {
  return std::string(FACET_SOURCE_DIR) + "/stdlib/Shaders/" + name;
}

// A red backdrop filling the view, and `objects` (JSON, each with a leading comma) in front of it.
std::string backdrop_scene(const std::string& objects) {
  return R"({"width": 64, "height": 64,
    "camera": {"position": [0, 0, -3], "look_at": [0, 0, 0], "fov": 40, "clear_color": [0, 0, 0]},
    "lights": [], "objects": [
      {"name": "backdrop", "mesh": "quad", "position": [0, 0, 2], "scale": 6,
       "material": {"shader": ")" + stdlib_shader("Unlit/Color.shader") + R"(", "properties": {"_Color": [0.8, 0.1, 0.1]}}})" +
         objects + "]}";
}

std::string glass(const std::string& position, const std::string& properties, const std::string& shader = "") {
  return R"(, {"mesh": "sphere", "position": )" + position + R"(, "scale": 0.8, "material": {"shader": ")" +
         (shader.empty() ? example_shader("GrabRefraction.shader") : shader) + R"(", "properties": )" + properties +
         "}}";
}

// A copy of GrabRefraction with its GrabPass named `_SharedGrab` (and the sampler renamed).
std::string named_grab_shader() {
  std::ifstream in(example_shader("GrabRefraction.shader"));
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  text.replace(text.rfind("GrabPass { }"), 12, "GrabPass { \"_SharedGrab\" }");  // not the comment's
  for (size_t at; (at = text.find("_GrabTexture")) != std::string::npos;) text.replace(at, 12, "_SharedGrab");
  std::filesystem::path path = test_support::test_dir() / "NamedGrab.shader";
  std::ofstream(path) << text;
  return path.string();
}

int diff(const std::array<int, 3>& a, const std::array<int, 3>& b) {
  return std::abs(a[0] - b[0]) + std::abs(a[1] - b[1]) + std::abs(a[2] - b[2]);
}

TEST_F(GrabTest, ARefractionShowsTheBackgroundBehindTheObject) {
  RenderedFrame backdrop = render("grab_backdrop", backdrop_scene(""));
  RenderedFrame clear = render("grab_clear", backdrop_scene(glass("[0, 0, 0]", R"({"_Distortion": 0, "_Tint": [1, 1, 1, 1]})")));
  RenderedFrame tinted = render("grab_tinted", backdrop_scene(glass("[0, 0, 0]", R"({"_Distortion": 0, "_Tint": [0.5, 1, 1, 1]})")));
  ASSERT_FALSE(clear.ldr.empty());
  ASSERT_FALSE(tinted.ldr.empty());
  // An undistorted, untinted glass shows exactly the backdrop behind it.
  EXPECT_GT(pixel(backdrop, 32, 32)[0], 150);
  EXPECT_LE(diff(pixel(clear, 32, 32), pixel(backdrop, 32, 32)), 3);
  // A tint multiplies what it shows: red halved in linear light.
  EXPECT_LT(pixel(tinted, 32, 32)[0] + 30, pixel(backdrop, 32, 32)[0]);
  EXPECT_EQ(clear.stats.grabs, 1u);
  const DrawRecord* glass_draw = nullptr;
  for (const DrawRecord& d : clear.draws) {
    if (d.object_index == 1 && d.drawn) glass_draw = &d;
  }
  ASSERT_NE(glass_draw, nullptr);
  EXPECT_THAT(glass_draw->why, HasSubstr("after GrabPass: the screen copied into _GrabTexture"));
}

TEST_F(GrabTest, ADistortedRefractionBendsTheBackdropsEdge) {
  // A sphere over the border of a green quad on the red backdrop, left of
  // its centre: the distorted glass samples further out from its centre, so
  // pixels right of the border show the green on its left.
  std::string scene_objects = R"(, {"mesh": "quad", "position": [-1.8, 0, 1], "scale": 3,
       "material": {"shader": ")" + stdlib_shader("Unlit/Color.shader") + R"(", "properties": {"_Color": [0, 0.8, 0]}}})";
  RenderedFrame flat = render("grab_edge_flat", backdrop_scene(scene_objects + glass("[0, 0, 0]", R"({"_Distortion": 0, "_Tint": [1, 1, 1, 1]})")));
  RenderedFrame bent = render("grab_edge_bent", backdrop_scene(scene_objects + glass("[0, 0, 0]", R"({"_Distortion": 0.25, "_Tint": [1, 1, 1, 1]})")));
  ASSERT_FALSE(bent.ldr.empty());
  size_t changed = 0;
  for (int y = 24; y < 40; ++y) {
    for (int x = 20; x < 44; ++x) changed += diff(pixel(flat, x, y), pixel(bent, x, y)) > 30;
  }
  EXPECT_GT(changed, 20u);
}

TEST_F(GrabTest, AnUnnamedGrabHappensBeforeEachObjectAndANamedOneOnceAFrame) {
  const std::string props = R"({"_Distortion": 0, "_Tint": [1, 1, 1, 1]})";
  RenderedFrame unnamed = render("grab_unnamed", backdrop_scene(glass("[-0.6, 0, 0]", props) + glass("[0.6, 0, 0]", props)));
  EXPECT_EQ(unnamed.stats.grabs, 2u);
  std::string named = named_grab_shader();
  RenderedFrame once = render("grab_named", backdrop_scene(glass("[-0.6, 0, 0]", props, named) + glass("[0.6, 0, 0]", props, named)));
  EXPECT_EQ(once.stats.grabs, 1u);
  ASSERT_FALSE(once.ldr.empty());
  // Both glasses show the backdrop, the second through the copy made for the first.
  EXPECT_LE(diff(pixel(once, 32 - 13, 32), pixel(unnamed, 32 - 13, 32)), 3);
  EXPECT_LE(diff(pixel(once, 32 + 13, 32), pixel(unnamed, 32 + 13, 32)), 3);
  EXPECT_GT(pixel(once, 32 + 13, 32)[0], 150);
}

TEST_F(GrabTest, SamplingAGrabTextureThatNoGrabPassFilledIsAnError) {
  std::filesystem::path path = test_support::test_dir() / "NoGrab.shader";
  std::ifstream in(example_shader("GrabRefraction.shader"));
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  text.replace(text.rfind("GrabPass { }"), 12, "");  // not the comment's
  std::ofstream(path) << text;
  auto frame = try_render("grab_missing", backdrop_scene(glass("[0, 0, 0]", "{}", path.string())));
  ASSERT_FALSE(frame);
  EXPECT_THAT(frame.error().message, HasSubstr("samples _GrabTexture, but no GrabPass copied the screen into it"));
}

}  // namespace
}  // namespace facet::runtime
