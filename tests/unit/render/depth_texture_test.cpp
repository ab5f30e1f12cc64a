// The camera depth texture for scene objects: a shader that samples
// _CameraDepthTexture gets the opaque objects' ShadowCaster depth from the
// camera (as in Unity), made only when some drawn variant samples it.
#include <gtest/gtest.h>

#include <algorithm>

#include "facet/runtime/scene.h"
#include "render_test_support.h"

namespace facet::runtime {
namespace {

using test_support::example_shader;
using test_support::pixel;

// A grey floor 0.5 below a water plane that fades over `fade` world units of
// depth behind it, seen from above at an angle.
std::string water_scene(float fade, bool water = true) {
  std::string standard = example_shader("SurfaceStandard.shader");
  std::string json = R"({"width": 64, "height": 48, "ambient": [0.5, 0.5, 0.5],
    "camera": {"position": [0, 3, -2], "look_at": [0, 0, 0], "fov": 40, "clear_color": [0, 0, 0]},
    "objects": [
      {"name": "floor", "mesh": "plane", "scale": 0.5, "material": {"shader": ")" + standard +
                     R"(", "properties": {"_Color": [0.8, 0.8, 0.8]}}},
      {"name": "ball", "mesh": "sphere", "position": [1.2, 0.3, 0.5], "material": {"shader": ")" + standard + "\"}}";
  if (water) {
    json += R"(, {"name": "water", "mesh": "plane", "position": [0, 0.5, 0], "scale": 0.5, "material": {"shader": ")" +
            example_shader("DepthFade.shader") + R"(", "properties": {"_Color": [0, 0, 1, 1], "_FadeDistance": )" +
            std::to_string(fade) + "}}}";
  }
  return json + "]}";
}

using DepthTextureTest = test_support::RenderTest;

TEST_F(DepthTextureTest, ASamplingShaderGetsTheOpaqueCastersDepthFromTheCamera) {
  RenderedFrame f = render("water", water_scene(0.5f));
  EXPECT_EQ(f.stats.depth_texture_draws, 2u);  // floor and ball; the transparent water is not in it
  EXPECT_EQ(f.stats.shadow_maps, 0u);
  size_t into_depth = size_t(std::count_if(f.draws.begin(), f.draws.end(), [](const DrawRecord& d) {
    return d.drawn && d.light_mode == "ShadowCaster" && d.why.find("camera depth texture") != std::string::npos;
  }));
  EXPECT_EQ(into_depth, 2u);
}

TEST_F(DepthTextureTest, NoShaderSamplingItMeansNoDepthTexture) {
  RenderedFrame f = render("dry", water_scene(0.5f, false));
  EXPECT_EQ(f.stats.depth_texture_draws, 0u);
  for (const std::string& c : f.compiled) EXPECT_EQ(c.find("ShadowCaster"), std::string::npos) << c;
}

TEST_F(DepthTextureTest, TheFadeFollowsTheDepthBehindTheSurface) {
  // The floor is 0.5 below the water (more along the view ray): with a fade
  // distance of 0.05 the water is opaque blue there, with 50 it is nearly
  // clear. Without a depth texture (far everywhere) both would be opaque.
  RenderedFrame opaque = render("short_fade", water_scene(0.05f));
  RenderedFrame clear = render("long_fade", water_scene(50.0f));
  ASSERT_FALSE(clear.ldr.empty());
  std::array<int, 3> a = pixel(opaque, 20, 30), b = pixel(clear, 20, 30);
  EXPECT_GT(a[2], b[2] + 10);
  EXPECT_LT(a[0] + 60, b[0]);  // the clear water shows the grey floor's red channel
}

}  // namespace
}  // namespace facet::runtime
