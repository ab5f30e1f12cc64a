// The deferred path on lavapipe: the same scene rendered forward and
// deferred agrees within the G-buffer's quantisation (docs/rendering.md
// records the measured figures); what goes into the G-buffer, what stays
// forward, and the scene key's errors.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "render_test_support.h"

namespace facet::runtime {
namespace {

using ::testing::HasSubstr;
using test_support::count_draws;
using test_support::example_shader;
using test_support::pixel;

Scene example_scene() {
  auto scene = load_scene(std::string(FACET_SOURCE_DIR) + "/examples/scenes/deferred.json");
  EXPECT_TRUE(scene) << scene.error().message;
  return scene ? std::move(*scene) : Scene{};
}

class DeferredTest : public test_support::RenderTest {
 protected:
  static RenderedFrame render_path(const Scene& scene, bool deferred) {
    Scene s = scene;
    s.camera.deferred = deferred;
    auto frame = render_scene(context(), s, test_support::with_compiler({.width = 160, .height = 90}));
    EXPECT_TRUE(frame) << frame.error().message;
    return frame ? std::move(*frame) : RenderedFrame{};
  }
};

struct Difference {
  int max = 0;        // of any channel, in 8-bit steps
  double mean = 0;    // over every channel of every pixel
};

Difference difference(const RenderedFrame& a, const RenderedFrame& b) {
  Difference d;
  if (a.ldr.size() != b.ldr.size() || a.ldr.empty()) return {255, 255};
  double sum = 0;
  size_t n = 0;
  for (size_t i = 0; i < a.ldr.size(); ++i) {
    if (i % 4 == 3) continue;
    int delta = std::abs(int(a.ldr[i]) - int(b.ldr[i]));
    d.max = std::max(d.max, delta);
    sum += delta;
    ++n;
  }
  d.mean = sum / double(n);
  return d;
}

// Directional (soft shadows), point (cube shadows) and spot (shadows)
// lights on Standard spheres of three smoothnesses, dielectric and metal, a
// surface shader of the Standard model (its generated Deferred pass) and
// one of a custom model without a _Deferred function (drawn forward), a
// transparent cube drawn forward over them, the procedural sky behind:
// the deferred image is the forward one but for the G-buffer's 8-bit
// smoothness and 10-bit normals, which move the sharpest highlights.
TEST_F(DeferredTest, ForwardAndDeferredImagesAgreeWithinTheGBuffersQuantisation) {
  Scene scene = example_scene();
  RenderedFrame forward = render_path(scene, false);
  RenderedFrame deferred = render_path(scene, true);
  ASSERT_FALSE(forward.ldr.empty());
  ASSERT_FALSE(deferred.ldr.empty());
  EXPECT_EQ(forward.stats.gbuffer_draws, 0u);
  EXPECT_EQ(deferred.stats.gbuffer_draws, 8u);  // the floor, six Standard spheres, the surface Standard one
  EXPECT_EQ(deferred.stats.deferred_lights, 3u);
  Difference d = difference(forward, deferred);
  std::cout << "forward vs deferred: max " << d.max << "/255, mean " << d.mean << "/255\n";
  EXPECT_LE(d.max, 24);
  EXPECT_LT(d.mean, 0.5);
  // Not the same image by accident: the objects are lit and shadowed.
  EXPECT_NE(pixel(deferred, 80, 60), pixel(deferred, 80, 5));
}

TEST_F(DeferredTest, OpaqueDeferredPassesGoToTheGBufferAndTheRestStaysForward) {
  RenderedFrame f = render_path(example_scene(), true);
  ASSERT_FALSE(f.ldr.empty());
  EXPECT_EQ(count_draws(f, "Deferred"), 8u);
  // The deferred objects' forward passes are skipped, with the reason.
  EXPECT_EQ(count_draws(f, "ForwardBase", false), 8u);
  auto skipped = std::find_if(f.draws.begin(), f.draws.end(), [](const DrawRecord& d) {
    return !d.drawn && d.light_mode == "ForwardAdd";
  });
  ASSERT_NE(skipped, f.draws.end());
  EXPECT_THAT(skipped->why, HasSubstr("drawn deferred"));
  // The transparent cube (queue 3000) and the Cook-Torrance sphere (no
  // LightingCookTorrance_Deferred, so no Deferred pass) are drawn forward:
  // each its base pass and one additive pass for the point and the spot light.
  EXPECT_EQ(count_draws(f, "ForwardBase"), 2u);
  EXPECT_EQ(count_draws(f, "ForwardAdd"), 4u);
  // One light draw a light, each with its light and shadow keywords.
  std::vector<std::string> light_variants;
  for (const DrawRecord& d : f.draws) {
    if (d.shader != "Hidden/Internal-DeferredShading") continue;
    std::string keys;
    for (const std::string& k : d.keywords) keys += (keys.empty() ? "" : " ") + k;
    light_variants.push_back(keys);
  }
  EXPECT_THAT(light_variants, ::testing::UnorderedElementsAre("DIRECTIONAL SHADOWS_SCREEN UNITY_HDR_ON",
                                                              "POINT SHADOWS_CUBE UNITY_HDR_ON",
                                                              "SPOT SHADOWS_DEPTH UNITY_HDR_ON"));
}

// A shader without a Deferred pass (an unlit one) is drawn forward even by
// a deferred camera, after the lights, and looks as it does forward.
TEST_F(DeferredTest, AShaderWithoutADeferredPassIsDrawnForward) {
  std::string scene = test_support::small_scene(
      "[" + test_support::object_json("sphere", "Unlit.shader") + "]",
      R"([{"type": "directional", "rotation": [30, 20, 0]}])");
  scene.replace(scene.find("\"camera\": {"), 11, R"("camera": {"rendering_path": "deferred", )");
  RenderedFrame f = render("deferred_unlit", scene);
  ASSERT_FALSE(f.ldr.empty());
  EXPECT_EQ(f.stats.gbuffer_draws, 0u);
  EXPECT_EQ(pixel(f, 32, 32)[0], 255);
}

TEST_F(DeferredTest, AnUnknownRenderingPathIsAnErrorAtItsKey) {
  auto scene = parse_scene(R"({"camera": {"rendering_path": "legacy"}, "objects": []})", "bad.json");
  ASSERT_FALSE(scene);
  EXPECT_THAT(scene.error().message, HasSubstr("camera.rendering_path"));
  EXPECT_THAT(scene.error().message, HasSubstr("deferred"));
}

TEST_F(DeferredTest, AnOrthographicDeferredCameraIsRefused) {
  Scene scene = example_scene();
  scene.camera.projection = Projection::orthographic;
  auto frame = render_scene(context(), scene, test_support::with_compiler({.width = 32, .height = 18}));
  ASSERT_FALSE(frame);
  EXPECT_THAT(frame.error().message, HasSubstr("perspective"));
}

}  // namespace
}  // namespace facet::runtime
