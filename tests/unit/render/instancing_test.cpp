// GPU instancing: a material with instancing enabled draws its objects with
// the INSTANCING_ON variant, runs of them as one instanced draw of up to 128,
// and the image is the one drawn object by object (per-instance colours
// included); what breaks a run; the scene key.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>

#include "render_test_support.h"

namespace facet::runtime {
namespace {

using ::testing::HasSubstr;
using test_support::example_shader;

// `count` small cubes in a grid under one directional light, each with its
// own _Color when `colors`.
Scene grid(const std::string& shader, int count, bool instancing, bool colors = true) {
  Scene scene;
  scene.path = "instancing grid";
  scene.width = 96;
  scene.height = 96;
  scene.camera.transform.position = {0, 0, -12};
  scene.camera.transform.look_at = Vec3{0, 0, 0};
  scene.camera.fov = 45;
  SceneLight sun;
  sun.json_path = "lights[0]";
  sun.transform.rotation = {40, -30, 0};
  scene.lights.push_back(sun);
  const int side = int(std::ceil(std::sqrt(double(count))));
  const float step = 10.0f / float(side);
  for (int i = 0; i < count; ++i) {
    SceneObject o;
    o.json_path = "objects[" + std::to_string(i) + "]";
    o.mesh = "cube";
    o.transform.position = {(float(i % side) - float(side - 1) / 2) * step, (float(i / side) - float(side - 1) / 2) * step,
                            0};
    o.transform.rotation = {30, float(i * 7), 0};
    o.transform.scale = {step * 0.6f, step * 0.6f, step * 0.6f};
    o.material.shader = shader;
    o.material.json_path = o.json_path + ".material";
    o.material.instancing = instancing;
    if (colors) o.material.properties.push_back(
        {.name = "_Color",
         .json_path = o.material.json_path + ".properties._Color",
         .numbers = {0.5f + 0.5f * std::sin(float(i)), 0.5f + 0.5f * std::cos(float(i) * 1.3f), float(i % 5) / 4, 1}});
    scene.objects.push_back(std::move(o));
  }
  return scene;
}

class InstancingTest : public test_support::RenderTest {
 protected:
  static RenderedFrame render(const Scene& scene) {
    auto frame = render_scene(context(), scene, test_support::with_compiler({}));
    EXPECT_TRUE(frame) << frame.error().message;
    return frame ? std::move(*frame) : RenderedFrame{};
  }
};

TEST_F(InstancingTest, RunsOfObjectsAreInstancedDrawsOf128AndTheImageIsTheSame) {
  const std::string shader = example_shader("Instanced.shader");
  RenderedFrame separate = render(grid(shader, 150, false));
  RenderedFrame instanced = render(grid(shader, 150, true));
  EXPECT_EQ(separate.stats.draws, 150u);
  EXPECT_EQ(instanced.stats.draws, 2u) << "128 objects, then 22";
  EXPECT_EQ(instanced.stats.instanced_draws, 2u);
  EXPECT_EQ(instanced.stats.instanced_away, 148u);
  EXPECT_EQ(instanced.stats.triangles, separate.stats.triangles);
  ASSERT_EQ(instanced.draws.size(), 150u) << "every object keeps its record";
  EXPECT_THAT(instanced.draws[0].keywords, ::testing::Contains("INSTANCING_ON"));
  EXPECT_THAT(instanced.draws[0].why, HasSubstr("instanced: 128 objects in one draw"));
  EXPECT_THAT(instanced.draws[1].why, HasSubstr("instanced: drawn by draw of " + instanced.draws[0].object));
  EXPECT_THAT(separate.draws[0].keywords, ::testing::Not(::testing::Contains("INSTANCING_ON")));
  EXPECT_TRUE(instanced.ldr == separate.ldr) << "the instanced image differs from the one drawn object by object";
}

// Surface shaders' generated passes declare multi_compile_instancing and
// carry the instance ID themselves. Their _Color is a plain material value:
// objects of one colour share a draw, and another colour breaks the run.
TEST_F(InstancingTest, ASurfaceShaderDrawsInstancedToTheSameImage) {
  const std::string shader = example_shader("SurfaceStandard.shader");
  RenderedFrame separate = render(grid(shader, 40, false, false));
  RenderedFrame instanced = render(grid(shader, 40, true, false));
  EXPECT_EQ(instanced.stats.instanced_draws, 1u);
  EXPECT_EQ(instanced.stats.draws, 1u);
  EXPECT_EQ(separate.stats.draws, 40u);
  EXPECT_EQ(render(grid(shader, 40, true, true)).stats.instanced_draws, 0u) << "each object's own _Color";
  EXPECT_TRUE(instanced.ldr == separate.ldr) << "the instanced image differs from the one drawn object by object";
}

TEST_F(InstancingTest, AnotherMeshOrSharedValueIsNotInstancedWithTheRest) {
  Scene scene = grid(example_shader("SurfaceStandard.shader"), 12, true, false);
  scene.objects[4].mesh = "sphere";
  scene.objects[7].material.properties.push_back(
      {.name = "_Glossiness", .json_path = "objects[7].material.properties._Glossiness", .numbers = {0.9f}});
  RenderedFrame frame = render(scene);
  EXPECT_GE(frame.stats.draws, 3u);
  EXPECT_GE(frame.stats.instanced_draws, 1u);
  for (const DrawRecord& d : frame.draws) {
    if (d.object_index == 4 || d.object_index == 7) {
      EXPECT_THAT(d.why, ::testing::Not(HasSubstr("instanced"))) << d.object;
    }
  }
}

// 300 objects drawn one by one need more descriptor sets than one pool
// holds (256): the pools grow, and the image is the instanced one.
TEST_F(InstancingTest, ManyObjectsDrawnSeparatelyFillSeveralDescriptorPools) {
  const std::string shader = example_shader("Instanced.shader");
  RenderedFrame separate = render(grid(shader, 300, false));
  RenderedFrame instanced = render(grid(shader, 300, true));
  EXPECT_EQ(separate.stats.draws, 300u);
  EXPECT_EQ(instanced.stats.draws, 3u);
  EXPECT_TRUE(instanced.ldr == separate.ldr) << "the instanced image differs from the one drawn object by object";
}

TEST(InstancingScene, InstancingMustBeABoolean) {
  auto scene = parse_scene(R"({"camera": {}, "objects": [{"mesh": "cube", "material": {"shader": ")" +
                               example_shader("Instanced.shader") + R"(", "instancing": 1}}]})",
                           "s.json");
  ASSERT_FALSE(scene);
  EXPECT_THAT(scene.error().message, HasSubstr("objects[0].material.instancing: expected true or false"));
}

}  // namespace
}  // namespace facet::runtime
