// MaterialInstance edits and an engine's own meshes, drawn by a Renderer's
// update: each render draws what render_scene draws for the edited scene.
#include <gtest/gtest.h>

#include "facet/runtime/material.h"
#include "facet/runtime/material_instance.h"
#include "facet/runtime/renderer.h"
#include "facet/runtime/scene.h"
#include "render_test_support.h"

namespace facet::runtime {
namespace {

class MaterialInstanceTest : public test_support::RendererTest {
 protected:
  // Two cubes of examples/shaders/Keywords.shader (its `Cull [_Cull]`).
  static Scene cubes() { return test_support::lit_cubes("Keywords.shader", 2, 48, 32); }
};

TEST_F(MaterialInstanceTest, EditsReplaceTheNamedPropertyAndKeywordsOnce) {
  SceneMaterial m;
  m.json_path = "objects[0].material";
  MaterialInstance(m).set_float("_Cull", 1).set_color("_Color", {1, 0, 0, 1}).set_float("_Cull", 0);
  MaterialInstance(m).enable_keyword("_EMISSION").enable_keyword("_EMISSION").disable_keyword("FOG_LINEAR");
  ASSERT_EQ(m.properties.size(), 2u);
  EXPECT_EQ(m.properties[0].name, "_Cull");
  EXPECT_EQ(m.properties[0].numbers, std::vector<float>{0});
  EXPECT_EQ(m.properties[1].json_path, "objects[0].material.properties._Color");
  EXPECT_EQ(m.keywords, std::vector<std::string>{"_EMISSION"});
  MaterialInstance(m).disable_keyword("_EMISSION").set_queue(3000);
  EXPECT_TRUE(m.keywords.empty());
  EXPECT_EQ(m.queue, 3000);
  SceneTexture white{.name = "white", .builtin = true};
  MaterialInstance(m).set_texture("_Color", white);
  EXPECT_TRUE(m.properties[1].numbers.empty());
  ASSERT_TRUE(m.properties[1].texture);
}

TEST_F(MaterialInstanceTest, AMatrixOfNoPropertyReachesTheMaterialsUniforms) {
  Scene scene = cubes();
  std::array<float, 16> matrix{};
  for (size_t i = 0; i < 16; ++i) matrix[i] = float(i);
  MaterialInstance(scene.objects[0].material).set_matrix("_Projector", matrix);
  SourceMap sources;
  Diagnostics diags;
  auto shader = test_support::with_compiler({}).shader_compiler->load(scene.objects[0].material.shader, sources, diags);
  ASSERT_TRUE(shader) << render_text(diags, sources);
  auto material = make_material(shader->shader, scene.objects[0].material, scene.path, sources, diags);
  ASSERT_TRUE(material) << render_text(diags, sources);
  const std::vector<float>* value = material->uniforms.find("_Projector");
  ASSERT_NE(value, nullptr);
  EXPECT_EQ(*value, std::vector<float>(matrix.begin(), matrix.end()));
}

TEST_F(MaterialInstanceTest, ColourKeywordAndCullEditsAreDrawnByAnUpdate) {
  auto renderer = make_renderer();
  ASSERT_TRUE(renderer);
  Scene scene = cubes();
  RenderedFrame frame;
  ASSERT_TRUE(test_support::render(*renderer, scene, frame));
  EXPECT_NE(frame.draws[0].state.find("Cull Back"), std::string::npos) << frame.draws[0].state;
  MaterialInstance(scene.objects[0].material)
      .set_color("_Color", {0.2f, 0.9f, 0.3f, 1})
      .set_float("_Cull", 1)  // UnityEngine.Rendering.CullMode.Front
      .enable_keyword("_EMISSION")
      .set_color("_EmissionColor", {0.5f, 0.1f, 0.1f, 1});
  ASSERT_TRUE(test_support::render(*renderer, scene, frame));
  EXPECT_EQ(frame.stats.frame_path, FramePath::updated) << frame.stats.prepared_because;
  RenderedFrame reference = fresh(scene);
  EXPECT_EQ(frame.hdr, reference.hdr);
  bool culled_front = false;
  for (const DrawRecord& d : frame.draws) {
    if (d.object_index == 0) {
      culled_front = d.state.find("Cull Front") != std::string::npos;
      EXPECT_NE(std::find(d.keywords.begin(), d.keywords.end(), "_EMISSION"), d.keywords.end());
    }
  }
  EXPECT_TRUE(culled_front) << "the [_Cull] state is resolved again";
}

TEST_F(MaterialInstanceTest, ATextureFileBroughtByAnUpdateIsLoadedOnceAndCounted) {
  auto renderer = make_renderer();
  ASSERT_TRUE(renderer);
  Scene scene = cubes();
  RenderedFrame frame;
  ASSERT_TRUE(test_support::render(*renderer, scene, frame));
  SceneTexture checker{.name = std::string(FACET_SOURCE_DIR) + "/examples/textures/checker.png"};
  MaterialInstance(scene.objects[0].material).set_texture("_MainTex", checker);
  ASSERT_TRUE(test_support::render(*renderer, scene, frame));
  EXPECT_EQ(frame.stats.frame_path, FramePath::updated) << frame.stats.prepared_because;
  EXPECT_EQ(frame.stats.textures_loaded, 1u);
  EXPECT_EQ(frame.hdr, fresh(scene).hdr);
  MaterialInstance(scene.objects[1].material).set_texture("_MainTex", checker);
  ASSERT_TRUE(test_support::render(*renderer, scene, frame));
  EXPECT_EQ(frame.stats.textures_loaded, 0u) << "the file is loaded already";
  EXPECT_EQ(frame.hdr, fresh(scene).hdr);
}

TEST_F(MaterialInstanceTest, AnUndeclaredPropertyIsTheRendersErrorWithItsPath) {
  auto renderer = make_renderer();
  ASSERT_TRUE(renderer);
  Scene scene = cubes();
  RenderedFrame frame;
  ASSERT_TRUE(test_support::render(*renderer, scene, frame));
  MaterialInstance(scene.objects[1].material).set_float("_Colr", 1);
  auto failed = test_support::render(*renderer, scene, frame);
  ASSERT_FALSE(failed);
  EXPECT_NE(failed.error().message.find("objects[1].material.properties._Colr"), std::string::npos)
      << failed.error().message;
}

TEST_F(MaterialInstanceTest, AnEnginesMeshDrawsAsTheSameMeshFromAName) {
  Scene named = cubes();
  Scene given = named;
  auto cube = std::make_shared<MeshData>(*builtin_mesh("cube"));
  for (SceneObject& o : given.objects) o.mesh_data = cube;
  given.objects[0].mesh = "my cube";
  auto renderer = make_renderer();
  ASSERT_TRUE(renderer);
  RenderedFrame frame;
  ASSERT_TRUE(test_support::render(*renderer, given, frame));
  EXPECT_EQ(frame.stats.meshes_loaded, 1u) << "one upload for the two objects";
  EXPECT_EQ(frame.hdr, fresh(named).hdr);
  // Another MeshData is another mesh: uploaded by the update that brings it.
  auto sphere = std::make_shared<MeshData>(*builtin_mesh("sphere"));
  given.objects[1].mesh_data = sphere;
  named.objects[1].mesh = "sphere";
  ASSERT_TRUE(test_support::render(*renderer, given, frame));
  EXPECT_EQ(frame.stats.frame_path, FramePath::updated) << frame.stats.prepared_because;
  EXPECT_EQ(frame.stats.meshes_loaded, 1u);
  EXPECT_EQ(frame.hdr, fresh(named).hdr);
  // A mesh no object draws any more is let go (a loop giving new geometry
  // each frame does not pile up the old).
  EXPECT_GT(cube.use_count(), 1);
  given.objects[0].mesh_data = sphere;
  ASSERT_TRUE(test_support::render(*renderer, given, frame));
  EXPECT_EQ(frame.stats.frame_path, FramePath::updated);
  EXPECT_EQ(frame.stats.meshes_loaded, 0u);
  given.objects.clear();
  given.objects.push_back(named.objects[1]);
  ASSERT_TRUE(test_support::render(*renderer, given, frame));
  EXPECT_EQ(cube.use_count(), 1) << "only the test holds the cube";
  EXPECT_EQ(sphere.use_count(), 1) << "and the sphere";
}

TEST_F(MaterialInstanceTest, AnEnginesMeshWithBadIndicesIsAnError) {
  Scene scene = cubes();
  auto broken = std::make_shared<MeshData>(*builtin_mesh("cube"));
  broken->indices[4] = uint32_t(broken->vertices.size());
  scene.objects[1].mesh_data = broken;
  auto failed = render_scene(context(), scene, test_support::with_compiler({}));
  ASSERT_FALSE(failed);
  EXPECT_NE(failed.error().message.find("objects[1].mesh_data: index 4 is 24, but there are 24 vertices"),
            std::string::npos)
      << failed.error().message;
  broken->indices.pop_back();
  failed = render_scene(context(), scene, test_support::with_compiler({}));
  ASSERT_FALSE(failed);
  EXPECT_NE(failed.error().message.find("not whole triangles"), std::string::npos) << failed.error().message;
  scene.objects[1].mesh_data = std::make_shared<MeshData>();
  failed = render_scene(context(), scene, test_support::with_compiler({}));
  ASSERT_FALSE(failed);
  EXPECT_NE(failed.error().message.find("no vertices or no indices"), std::string::npos);
}

}  // namespace
}  // namespace facet::runtime
