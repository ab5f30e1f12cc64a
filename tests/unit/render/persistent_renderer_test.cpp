// Renderer: the frame kept between renders. Each render draws what
// render_scene draws for the same scene, pixel for pixel, and says what it
// kept: a scene drawn again creates nothing; changed values, transforms,
// keywords, lights and camera update the kept frame, creating GPU objects only
// for draws not seen before; anything else prepares anew and says why.
#include <gtest/gtest.h>

#include <cmath>

#include "facet/runtime/renderer.h"
#include "facet/runtime/scene.h"
#include "render_test_support.h"

namespace facet::runtime {
namespace {

class PersistentRendererTest : public test_support::RendererTest {
 protected:
  static RenderedFrame draw(Renderer& renderer, const Scene& scene, FrameOptions options = {}) {
    RenderedFrame frame;
    auto drawn = test_support::render(renderer, scene, frame, options);
    EXPECT_TRUE(drawn) << drawn.error().message;
    return frame;
  }
  static void expect_created_nothing(const RenderStats& stats) {
    EXPECT_EQ(stats.pipelines, 0u);
    EXPECT_EQ(stats.descriptor_pools_created, 0u);
    EXPECT_EQ(stats.uniform_buffers_created, 0u);
    EXPECT_EQ(stats.meshes_loaded, 0u);
    EXPECT_EQ(stats.textures_loaded, 0u);
    EXPECT_EQ(stats.variants_compiled, 0u);
    EXPECT_EQ(stats.shaders_loaded, 0u);
  }
  static Scene keyword_grid(int count) { return test_support::lit_cubes("Keywords.shader", count, 64, 48); }
  // Frame `f` of an engine's loop: every colour changes, _EMISSION moves along the grid.
  static void animate(Scene& scene, int f) {
    for (size_t i = 0; i < scene.objects.size(); ++i) {
      SceneMaterial& m = scene.objects[i].material;
      const float phase = float(i) * 0.3f + float(f) * 0.2f;
      m.properties = {{.name = "_Color",
                       .json_path = m.json_path + ".properties._Color",
                       .numbers = {0.5f + 0.5f * std::sin(phase), 0.5f + 0.5f * std::cos(phase), 0.6f, 1}}};
      m.keywords.clear();
      if ((i + size_t(f)) % 3 == 0) {
        m.keywords.push_back("_EMISSION");
        m.properties.push_back(
            {.name = "_EmissionColor", .json_path = m.json_path + ".properties._EmissionColor", .numbers = {0.8f, 0.6f, 0.1f, 1}});
      }
    }
  }
};

TEST_F(PersistentRendererTest, TheSameSceneAgainIsRepeatedAndCreatesNothing) {
  auto renderer = make_renderer();
  ASSERT_TRUE(renderer);
  Scene scene = test_support::example_scene("phong_lights.json");
  RenderedFrame first = draw(*renderer, scene);
  EXPECT_EQ(first.stats.frame_path, FramePath::prepared);
  EXPECT_EQ(first.stats.prepared_because, "");
  EXPECT_GT(first.stats.pipelines, 0u);
  EXPECT_GT(first.stats.uniform_buffers_created, 0u);
  RenderedFrame second = draw(*renderer, scene);
  EXPECT_EQ(second.stats.frame_path, FramePath::repeated);
  expect_created_nothing(second.stats);
  EXPECT_EQ(second.hdr, first.hdr);
  EXPECT_EQ(second.stats.draws, first.stats.draws);
  EXPECT_EQ(second.draws.size(), first.draws.size());
  EXPECT_EQ(fresh(scene).hdr, first.hdr);
}

TEST_F(PersistentRendererTest, AChangedTimeIsRepeatedAndDrawsTheNewTime) {
  auto renderer = make_renderer();
  ASSERT_TRUE(renderer);
  Scene scene = test_support::example_scene("phong_lights.json");
  draw(*renderer, scene);
  scene.time = 3.5f;
  RenderedFrame later = draw(*renderer, scene);
  EXPECT_EQ(later.stats.frame_path, FramePath::repeated);
  EXPECT_EQ(later.hdr, fresh(scene).hdr);
}

TEST_F(PersistentRendererTest, ChangedValuesTransformsLightsAndCameraUpdateInPlace) {
  auto renderer = make_renderer();
  ASSERT_TRUE(renderer);
  Scene scene = test_support::example_scene("phong_lights.json");
  draw(*renderer, scene);
  scene.objects[1].transform.position = {-0.3f, 0.7f, 0.2f};
  scene.objects[2].material.properties[0].numbers = {0.2f, 0.8f, 0.4f};
  scene.lights[1].color = {0.2f, 1, 0.3f};
  scene.lights[2].transform.position = {-1, 2, -1};
  scene.camera.transform.position = {0.5f, 1.8f, -3.5f};
  RenderedFrame updated = draw(*renderer, scene);
  EXPECT_EQ(updated.stats.frame_path, FramePath::updated) << updated.stats.prepared_because;
  expect_created_nothing(updated.stats);
  RenderedFrame reference = fresh(scene);
  EXPECT_EQ(updated.hdr, reference.hdr);
  EXPECT_EQ(updated.stats.draws, reference.stats.draws);
  ASSERT_EQ(updated.draws.size(), reference.draws.size());
  for (size_t i = 0; i < updated.draws.size(); ++i) EXPECT_EQ(updated.draws[i].object, reference.draws[i].object);
}

TEST_F(PersistentRendererTest, AddedAndRemovedObjectsUpdateInPlace) {
  auto renderer = make_renderer();
  ASSERT_TRUE(renderer);
  Scene scene = test_support::example_scene("phong_lights.json");
  draw(*renderer, scene);
  SceneObject copy = scene.objects[1];
  copy.transform.position = {0.2f, 1.2f, -0.8f};
  scene.objects.push_back(copy);
  RenderedFrame added = draw(*renderer, scene);
  EXPECT_EQ(added.stats.frame_path, FramePath::updated) << added.stats.prepared_because;
  EXPECT_EQ(added.hdr, fresh(scene).hdr);
  scene.objects.erase(scene.objects.begin());
  RenderedFrame removed = draw(*renderer, scene);
  EXPECT_EQ(removed.stats.frame_path, FramePath::updated) << removed.stats.prepared_because;
  EXPECT_EQ(removed.hdr, fresh(scene).hdr);
}

TEST_F(PersistentRendererTest, KeywordAndColourChangesEveryFrameCreateNothingOnceEachVariantWasDrawn) {
  auto renderer = make_renderer();
  ASSERT_TRUE(renderer);
  Scene scene = keyword_grid(12);
  for (int f = 0; f < 8; ++f) {
    animate(scene, f);
    RenderedFrame frame = draw(*renderer, scene, {.records = false});
    EXPECT_TRUE(frame.draws.empty());
    EXPECT_EQ(frame.stats.draws, 12u);
    if (f == 0) continue;
    EXPECT_EQ(frame.stats.frame_path, FramePath::updated) << "frame " << f << ": " << frame.stats.prepared_because;
    // Frame 0 drew both variants (with and without _EMISSION) and as many
    // sets and uniform bytes as any later frame needs.
    expect_created_nothing(frame.stats);
    if (f % 3 == 2) {
      EXPECT_EQ(frame.hdr, fresh(scene).hdr) << "frame " << f;
    }
  }
}

TEST_F(PersistentRendererTest, AnUnseenVariantIsCompiledOnUpdate) {
  auto renderer = make_renderer();
  ASSERT_TRUE(renderer);
  Scene scene = keyword_grid(2);
  draw(*renderer, scene);
  scene.objects[0].material.keywords = {"_EMISSION"};
  RenderedFrame frame = draw(*renderer, scene);
  EXPECT_EQ(frame.stats.frame_path, FramePath::updated) << frame.stats.prepared_because;
  EXPECT_EQ(frame.stats.variants_compiled, 1u);
  EXPECT_EQ(frame.compiled.size(), 1u);
  EXPECT_GT(frame.stats.pipelines, 0u);
  EXPECT_EQ(frame.hdr, fresh(scene).hdr);
}

TEST_F(PersistentRendererTest, WhatAnUpdateCannotCoverIsPreparedAnewWithTheReason) {
  auto renderer = make_renderer();
  ASSERT_TRUE(renderer);
  Scene scene = test_support::example_scene("phong_lights.json");
  draw(*renderer, scene);
  RenderedFrame resized = draw(*renderer, scene, {.width = 40, .height = 30});
  EXPECT_EQ(resized.stats.frame_path, FramePath::prepared);
  EXPECT_EQ(resized.stats.prepared_because, "the image size changed");
  EXPECT_EQ(resized.width, 40);
  scene.lights[0].shadows = ShadowMode::hard;
  RenderedFrame shadowed = draw(*renderer, scene, {.width = 40, .height = 30});
  EXPECT_EQ(shadowed.stats.frame_path, FramePath::prepared);
  EXPECT_EQ(shadowed.stats.prepared_because, "a light casts shadows");
  scene.lights[0].color = {1, 0.5f, 0.5f};
  RenderedFrame still_shadowed = draw(*renderer, scene, {.width = 40, .height = 30});
  EXPECT_EQ(still_shadowed.stats.frame_path, FramePath::prepared);
  EXPECT_EQ(still_shadowed.stats.prepared_because, "the frame has shadows");
  EXPECT_EQ(still_shadowed.hdr, render_scene(context(), scene, test_support::with_compiler({.width = 40, .height = 30}))->hdr);
  RenderedFrame again = draw(*renderer, scene, {.width = 40, .height = 30});
  EXPECT_EQ(again.stats.frame_path, FramePath::repeated);
  EXPECT_EQ(again.hdr, still_shadowed.hdr);
}

TEST_F(PersistentRendererTest, TheSkysSunLightingTheAmbientPreparesAnewWhenItTurns) {
  auto renderer = make_renderer();
  ASSERT_TRUE(renderer);
  Scene scene = test_support::example_scene("phong_lights.json");
  scene.sky = SceneSky{.sun = SceneSkySun{.light = 0}};
  draw(*renderer, scene);
  scene.lights[0].transform.rotation = {20, 60, 0};
  RenderedFrame turned = draw(*renderer, scene);
  EXPECT_EQ(turned.stats.frame_path, FramePath::prepared);
  EXPECT_EQ(turned.stats.prepared_because, "the sky's sun changed");
  EXPECT_EQ(turned.hdr, fresh(scene).hdr);
  scene.lights[1].color = {0.3f, 0.3f, 1};  // not the sun: an update
  RenderedFrame other = draw(*renderer, scene);
  EXPECT_EQ(other.stats.frame_path, FramePath::updated) << other.stats.prepared_because;
  EXPECT_EQ(other.hdr, fresh(scene).hdr);
}

TEST_F(PersistentRendererTest, AFailedRenderDropsTheKeptFrame) {
  auto renderer = make_renderer();
  ASSERT_TRUE(renderer);
  Scene scene = test_support::example_scene("phong_lights.json");
  draw(*renderer, scene);
  Scene broken = scene;
  broken.objects[0].material.shader = "/nonexistent/Missing.shader";
  RenderedFrame frame;
  auto failed = test_support::render(*renderer, broken, frame);
  ASSERT_FALSE(failed);
  EXPECT_NE(failed.error().message.find("objects[0].material.shader"), std::string::npos) << failed.error().message;
  RenderedFrame after = draw(*renderer, scene);
  EXPECT_EQ(after.stats.frame_path, FramePath::prepared);
  EXPECT_EQ(after.hdr, fresh(scene).hdr);
}

TEST_F(PersistentRendererTest, ARendererForOneRenderKeepsNoSceneAndPreparesEachRender) {
  auto renderer = test_support::create_renderer(
      context(), {.shader_compiler = test_support::with_compiler({}).shader_compiler, .one_render = true});
  ASSERT_TRUE(renderer);
  Scene scene = test_support::example_scene("unlit.json");
  RenderedFrame first = draw(**renderer, scene);
  RenderedFrame second = draw(**renderer, scene);
  EXPECT_EQ(second.stats.frame_path, FramePath::prepared);
  EXPECT_EQ(second.stats.prepared_because, "the renderer keeps no scene (RendererOptions::one_render)");
  EXPECT_EQ(second.hdr, first.hdr);
}

TEST_F(PersistentRendererTest, TheFrameBuffersOfTheCallerAreReused) {
  auto renderer = make_renderer();
  ASSERT_TRUE(renderer);
  Scene scene = test_support::example_scene("unlit.json");
  RenderedFrame frame;
  ASSERT_TRUE(test_support::render(*renderer, scene, frame));
  const float* hdr = frame.hdr.data();
  const uint8_t* ldr = frame.ldr.data();
  ASSERT_TRUE(test_support::render(*renderer, scene, frame));
  EXPECT_EQ(frame.hdr.data(), hdr);
  EXPECT_EQ(frame.ldr.data(), ldr);
  EXPECT_EQ(frame.stats.frame_ms.size(), 1u);
}

}  // namespace
}  // namespace facet::runtime
