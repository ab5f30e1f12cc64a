// Every example scene rendered on lavapipe (validation on, zero messages) and
// compared with its reviewed golden in tests/golden/; and the comparison
// itself: rasteriser-sized differences pass, real changes fail.
// FACET_UPDATE_GOLDENS=1 rewrites the goldens instead of comparing.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iostream>

#include "facet/runtime/scene.h"
#include "golden_support.h"
#include "render_test_support.h"

namespace facet::runtime {
namespace {

using test_support::compare_images;
using test_support::compare_with_golden;
using test_support::GoldenComparison;

std::filesystem::path scenes_dir() { return std::filesystem::path(FACET_SOURCE_DIR) / "examples" / "scenes"; }

std::vector<std::string> example_scene_names() {
  std::vector<std::string> names;
  for (const auto& entry : std::filesystem::directory_iterator(scenes_dir()))
    if (entry.path().extension() == ".json") names.push_back(entry.path().stem().string());
  std::sort(names.begin(), names.end());
  return names;
}

class GoldenTest : public test_support::LavapipeTest {
 protected:
  static Scene load(const std::string& name) {
    auto scene = load_scene((scenes_dir() / (name + ".json")).string());
    EXPECT_TRUE(scene) << scene.error().message;
    return scene ? std::move(*scene) : Scene{};
  }
  static RenderedFrame render(const Scene& scene) {
    RenderOptions options{.width = test_support::kGoldenWidth, .height = test_support::kGoldenHeight};
    auto frame = render_scene(context(), scene, test_support::with_compiler(options));
    EXPECT_TRUE(frame) << frame.error().message;
    return frame ? std::move(*frame) : RenderedFrame{};
  }
};

class ExampleSceneGolden : public GoldenTest, public ::testing::WithParamInterface<std::string> {};

TEST_P(ExampleSceneGolden, MatchesItsGoldenWithinTheRasteriserTolerance) {
  RenderedFrame frame = render(load(GetParam()));
  ASSERT_FALSE(frame.ldr.empty());
  if (test_support::updating_goldens()) {
    auto written = test_support::update_golden(frame, GetParam());
    ASSERT_TRUE(written) << written.error().message;
    std::cout << "updated tests/golden/" << GetParam() << ".png: review it before committing\n";
    return;
  }
  GoldenComparison c = compare_with_golden(frame, GetParam());
  EXPECT_TRUE(c.ok) << c.message;
}

INSTANTIATE_TEST_SUITE_P(Examples, ExampleSceneGolden, ::testing::ValuesIn(example_scene_names()),
                         [](const ::testing::TestParamInfo<std::string>& info) { return info.param; });

TEST(GoldenFiles, EveryGoldenBelongsToAnExampleScene) {
  std::vector<std::string> scenes = example_scene_names();
  for (const auto& entry : std::filesystem::directory_iterator(test_support::golden_dir())) {
    if (entry.path().extension() != ".png") continue;
    EXPECT_TRUE(std::count(scenes.begin(), scenes.end(), entry.path().stem().string()))
        << entry.path() << " has no scene examples/scenes/" << entry.path().stem().string() << ".json";
  }
}

// The property `name` of object `index`, scaled by `factor` (colour channels only).
void scale_colour(Scene& scene, size_t index, const std::string& name, float factor) {
  for (SceneProperty& p : scene.objects.at(index).material.properties)
    if (p.name == name)
      for (size_t i = 0; i < std::min<size_t>(p.numbers.size(), 3); ++i) p.numbers[i] *= factor;
}

// The size of one pixel at the camera's look-at point, in world units.
float pixel_size(const Scene& scene) {
  const SceneCamera& cam = scene.camera;
  Vec3 d{};
  for (int i = 0; i < 3; ++i) d[i] = cam.transform.look_at.value()[i] - cam.transform.position[i];
  float distance = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
  return 2 * distance * std::tan(cam.fov * 3.14159265f / 360) / test_support::kGoldenHeight;
}

TEST_F(GoldenTest, ASubPixelCameraShiftPasses) {
  // Moving every silhouette by a tenth of a pixel changes coverage along the
  // edges, as a rasteriser with other sub-pixel precision or tie-breaking
  // would: noise the goldens must accept.
  Scene scene = load("phong_lights");
  float shift = pixel_size(scene) / 10;
  scene.camera.transform.position[0] += shift;
  scene.camera.transform.look_at.value()[0] += shift;
  GoldenComparison c = compare_with_golden(render(scene), "phong_lights");
  EXPECT_TRUE(c.ok) << c.message;
  EXPECT_GT(c.max_error, 0) << "the shift changed nothing: the test does not exercise the tolerance";
}

TEST_F(GoldenTest, AMaterialColourTenPercentDarkerFails) {
  Scene scene = load("diffuse");
  scale_colour(scene, 1, "_Color", 0.9f);  // the ball
  GoldenComparison c = compare_with_golden(render(scene), "diffuse");
  EXPECT_FALSE(c.ok) << c.message;
}

TEST_F(GoldenTest, ALightFivePercentDimmerFails) {
  // Each pixel moves by a few levels only: the mean error has to catch it.
  Scene scene = load("phong_lights");
  scene.lights.at(0).intensity *= 0.95f;
  GoldenComparison c = compare_with_golden(render(scene), "phong_lights");
  EXPECT_FALSE(c.ok) << c.message;
}

TEST_F(GoldenTest, AMissingGoldenFailsAndSaysHowToCreateIt) {
  GoldenComparison c = compare_with_golden(render(load("unlit")), "no_such_golden");
  EXPECT_FALSE(c.ok);
  EXPECT_NE(c.message.find("FACET_UPDATE_GOLDENS=1"), std::string::npos) << c.message;
}

OIIO::ImageBuf flat_image(int width, int height, float grey) {
  OIIO::ImageBuf image(OIIO::ImageSpec(width, height, 3, OIIO::TypeDesc::UINT8));
  float value[3] = {grey, grey, grey};
  OIIO::ImageBufAlgo::fill(image, value);
  return image;
}

TEST(GoldenCompare, AFewWrongEdgePixelsPassButAWrongSquareFails) {
  OIIO::ImageBuf golden = flat_image(96, 72, 0.5f);
  OIIO::ImageBuf noisy = flat_image(96, 72, 0.5f);
  float white[3] = {1, 1, 1};
  for (int x = 0; x < 40; x += 2) noisy.setpixel(x, 30, white);  // 20 pixels, 0.3 % of the image
  EXPECT_TRUE(compare_images(noisy, golden).ok) << compare_images(noisy, golden).message;
  OIIO::ImageBuf wrong = flat_image(96, 72, 0.5f);
  OIIO::ImageBufAlgo::fill(wrong, white, OIIO::ROI(10, 22, 10, 22));  // 144 pixels, 2 %
  GoldenComparison c = compare_images(wrong, golden);
  EXPECT_FALSE(c.ok) << c.message;
  EXPECT_EQ(c.failing_pixels, 144);
}

TEST(GoldenCompare, ADifferentSizeFails) {
  GoldenComparison c = compare_images(flat_image(96, 72, 0.5f), flat_image(64, 64, 0.5f));
  EXPECT_FALSE(c.ok);
  EXPECT_NE(c.message.find("96x72"), std::string::npos) << c.message;
}

}  // namespace
}  // namespace facet::runtime
