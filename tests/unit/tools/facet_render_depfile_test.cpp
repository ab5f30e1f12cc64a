// `facet render --depfile FILE` writes the make rule of the image (every file
// the render read, includes of its shaders too) and `-I` gives the scene's
// shaders their include folders. These renders run on the default device
// (lavapipe).
#include "facetc_test_util.h"

namespace facet::tools::testing {
namespace {

using ::testing::HasSubstr;
using ::testing::Not;

constexpr const char* kScene = R"({
  "width": 8, "height": 8,
  "camera": { "position": [0, 0, -3], "look_at": [0, 0, 0] },
  "objects": [
    { "mesh": "tri.obj",
      "material": { "shader": "Tinted.shader", "properties": { "_MainTex": { "texture": "checker.png" } } } }
  ]
}
)";
constexpr const char* kMesh = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
constexpr const char* kShader = R"(Shader "Test/Tinted" {
  Properties { _MainTex ("Tex", 2D) = "white" {} }
  SubShader { Pass {
    CGPROGRAM
    #pragma vertex vert
    #pragma fragment frag
    #include "UnityCG.cginc"
    #include "Tint.cginc"
    sampler2D _MainTex;
    float4 vert(float4 v : POSITION) : SV_POSITION { return UnityObjectToClipPos(v); }
    float4 frag() : SV_Target { return tint(tex2D(_MainTex, float2(0.5, 0.5))); }
    ENDCG
  } }
}
)";

class FacetRenderDepfileTest : public FacetcTest {
 protected:
  void SetUp() override {
    FacetcTest::SetUp();
    write_all(dir_ / "scene.json", kScene);
    write_all(dir_ / "tri.obj", kMesh);
    write_all(dir_ / "Tinted.shader", kShader);
    fs::create_directory(dir_ / "lib");
    write_all(dir_ / "lib" / "Tint.cginc", "float4 tint(float4 c) { return c * float4(1, 0.5, 0.5, 1); }\n");
    fs::copy_file(fs::path(FACET_SOURCE_DIR) / "examples" / "textures" / "checker.png", dir_ / "checker.png");
  }

  FacetcRun render(const std::vector<std::string>& args) const { return facet_render(args); }
};

TEST_F(FacetRenderDepfileTest, TheDepfileListsTheSceneItsFilesAndEveryIncludeOfItsShaders) {
  FacetcRun run = render({"scene.json", "-o", "out.png", "-I", "lib", "--depfile", "out.png.d"});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  std::string rule = read_all(dir_ / "out.png.d");
  EXPECT_EQ(rule.rfind("out.png:", 0), 0u) << rule;
  for (const char* file : {"scene.json", "tri.obj", "Tinted.shader", "checker.png", "lib/Tint.cginc", "UnityCG.cginc",
                           "UnityShaderVariables.cginc"}) {
    EXPECT_THAT(rule, HasSubstr(file)) << rule;
  }
  EXPECT_TRUE(fs::exists(dir_ / "out.png"));
}

TEST_F(FacetRenderDepfileTest, WithoutTheIncludeFolderTheShaderFailsWithTheLocatedError) {
  FacetcRun run = render({"scene.json", "-o", "out.png", "--depfile", "out.png.d"});
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_THAT(run.err, HasSubstr("Tinted.shader:8:14: error: include file 'Tint.cginc' not found"));
  EXPECT_FALSE(fs::exists(dir_ / "out.png"));
  EXPECT_FALSE(fs::exists(dir_ / "out.png.d"));
}

TEST_F(FacetRenderDepfileTest, ADepfileNamingAFileTheRenderReadIsRefusedAndNothingIsWritten) {
  std::string scene = read_all(dir_ / "scene.json");
  FacetcRun run = render({"scene.json", "-o", "out.png", "-I", "lib", "--depfile", "scene.json"});
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_THAT(run.err, HasSubstr("output 'scene.json' is also an input of this render (the scene)"));
  EXPECT_EQ(read_all(dir_ / "scene.json"), scene);

  // An include is known only once the shaders compiled: still refused before any write.
  std::string include = read_all(dir_ / "lib" / "Tint.cginc");
  run = render({"scene.json", "-o", "out.png", "-I", "lib", "--depfile", "lib/Tint.cginc"});
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_THAT(run.err, HasSubstr("output 'lib/Tint.cginc' is also an input of this render (a file a shader of the "
                                 "scene read); nothing was written"));
  EXPECT_EQ(read_all(dir_ / "lib" / "Tint.cginc"), include);
  EXPECT_FALSE(fs::exists(dir_ / "out.png"));
  EXPECT_THAT(run.err, Not(HasSubstr("cannot write")));
}

// The image too: an include is an input of the render, whichever output names it.
TEST_F(FacetRenderDepfileTest, AnImageNamingAnIncludeOfTheShadersIsRefusedAndNothingIsWritten) {
  std::string include = read_all(dir_ / "lib" / "Tint.cginc");
  FacetcRun run = render({"scene.json", "-o", "lib/Tint.cginc", "-I", "lib"});
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_THAT(run.err, HasSubstr("output 'lib/Tint.cginc' is also an input of this render (a file a shader of the "
                                 "scene read)"));
  EXPECT_EQ(read_all(dir_ / "lib" / "Tint.cginc"), include);
}

TEST_F(FacetRenderDepfileTest, TwoOutputsNamingOneFileAreRefusedBeforeRendering) {
  for (const std::vector<std::string>& args : std::vector<std::vector<std::string>>{
           {"scene.json", "-o", "z.png", "-I", "lib", "--depfile", "z.png"},
           {"scene.json", "-o", "y.png", "-I", "lib", "--exr", "./y.png"},
           {"scene.json", "-o", "w.png", "-I", "lib", "--depfile", "d.txt", "--emit-variants", "d.txt"}}) {
    FacetcRun run = render(args);
    EXPECT_EQ(run.exit_code, 1) << args[2];
    EXPECT_THAT(run.err, HasSubstr("are the same file; nothing was written")) << args[2];
    EXPECT_FALSE(fs::exists(dir_ / args[2])) << args[2];
    EXPECT_FALSE(fs::exists(dir_ / "d.txt"));
  }
}

}  // namespace
}  // namespace facet::tools::testing
