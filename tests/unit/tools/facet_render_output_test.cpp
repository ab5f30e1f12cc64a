// `facet render` refuses an image output that is one of the files the
// render reads (the scene, a texture, a mesh, a shader): exit 1, a clear
// error, the input's bytes untouched. The check runs before any GPU work,
// so these tests need no device. They run the `facet` binary the build made.
#include "facetc_test_util.h"

namespace facet::tools::testing {
namespace {

using ::testing::HasSubstr;

fs::path facet_binary() { return FACET_PATH; }

constexpr const char* kScene = R"({
  "width": 8, "height": 8,
  "camera": { "position": [0, 0, -3], "look_at": [0, 0, 0] },
  "objects": [
    { "mesh": "tri.obj",
      "material": { "shader": "Diffuse.shader", "properties": { "_MainTex": { "texture": "checker.png" } } } }
  ]
}
)";
constexpr const char* kMesh = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";

class FacetRenderOutputTest : public FacetcTest {
 protected:
  void SetUp() override {
    FacetcTest::SetUp();
    ASSERT_TRUE(fs::exists(facet_binary())) << "the facet binary is missing: " << facet_binary();
    write_all(dir_ / "scene.json", kScene);
    write_all(dir_ / "tri.obj", kMesh);
    fs::copy_file(example("Diffuse.shader"), dir_ / "Diffuse.shader");
    fs::copy_file(fs::path(FACET_SOURCE_DIR) / "examples" / "textures" / "checker.png", dir_ / "checker.png");
  }

  FacetcRun render(const std::vector<std::string>& args) const { return facet_render(args); }

  // The render fails, names `output` as `what`, and `file` keeps its bytes.
  void expect_refused(const std::vector<std::string>& args, const std::string& output, const std::string& what,
                      const std::string& file) {
    std::string before = read_all(dir_ / file);
    FacetcRun run = render(args);
    EXPECT_EQ(run.exit_code, 1) << run.err;
    EXPECT_THAT(run.err, HasSubstr("facet render: error: output '" + output + "' is also an input of this render (" +
                                   what + "); nothing was written"));
    EXPECT_TRUE(read_all(dir_ / file) == before) << file << " was replaced";
  }
};

TEST_F(FacetRenderOutputTest, OutputNamingTheSceneIsRefused) {
  expect_refused({"scene.json", "-o", "scene.json"}, "scene.json", "the scene", "scene.json");
  fs::create_directory(dir_ / "x");
  expect_refused({"scene.json", "-o", "./x/../scene.json"}, "./x/../scene.json", "the scene", "scene.json");
}

TEST_F(FacetRenderOutputTest, OutputNamingATextureIsRefused) {
  expect_refused({"scene.json", "-o", "checker.png"}, "checker.png", "a texture of the scene", "checker.png");
}

TEST_F(FacetRenderOutputTest, OutputsNamingAMeshOrAShaderAreRefused) {
  expect_refused({"scene.json", "-o", "tri.obj"}, "tri.obj", "a mesh of the scene", "tri.obj");
  fs::create_hard_link(dir_ / "Diffuse.shader", dir_ / "link.exr");
  expect_refused({"scene.json", "--exr", "link.exr"}, "link.exr", "a shader of the scene", "Diffuse.shader");
}

TEST_F(FacetRenderOutputTest, OutputsNamingTheEnvironmentImageAreRefused) {
  fs::copy_file(fs::path(FACET_SOURCE_DIR) / "examples" / "textures" / "studio.exr", dir_ / "studio.exr");
  std::string scene = kScene;
  scene.insert(scene.rfind('}'), R"(, "environment": { "file": "studio.exr" })");
  write_all(dir_ / "lit.json", scene);
  const std::string what = "the environment image of the scene";
  expect_refused({"lit.json", "-o", "studio.exr"}, "studio.exr", what, "studio.exr");
  expect_refused({"lit.json", "-o", "x.png", "--exr", "studio.exr"}, "studio.exr", what, "studio.exr");
  expect_refused({"lit.json", "-o", "x.png", "--depfile", "studio.exr"}, "studio.exr", what, "studio.exr");
  expect_refused({"lit.json", "-o", "x.png", "--emit-variants", "studio.exr"}, "studio.exr", what, "studio.exr");
  EXPECT_FALSE(fs::exists(dir_ / "x.png"));
}

}  // namespace
}  // namespace facet::tools::testing
