// A ShaderStore keeps shaders and their compiled variants from one render to
// the next, and forgets a shader whose file, or a file it includes, changed
// on disk: the next render loads and compiles it again.
#include <chrono>
#include <filesystem>
#include <fstream>

#include "render_test_support.h"

namespace facet::runtime {
namespace {

namespace fs = std::filesystem;
using test_support::pixel;

// An unlit cube in the colour TINT, which tint.cginc defines.
constexpr const char* kShader = R"(Shader "Tests/StoreTint" {
  SubShader { Pass {
    CGPROGRAM
    #pragma vertex vert
    #pragma fragment frag
    #pragma multi_compile __ HALF_TINT
    #include "UnityCG.cginc"
    #include "tint.cginc"
    float4 vert(float4 v : POSITION) : SV_POSITION { return UnityObjectToClipPos(v); }
    fixed4 frag() : SV_Target { return TINT; }
    ENDCG
  } }
}
)";

class ShaderStoreTest : public test_support::RenderTest {
 protected:
  void SetUp() override {
    RenderTest::SetUp();
    dir_ = test_support::test_dir() / ::testing::UnitTest::GetInstance()->current_test_info()->name();
    fs::create_directories(dir_);
    write("Tint.shader", kShader);
    write("tint.cginc", "#define TINT float4(1, 0, 0, 1)\n");
    std::string json = test_support::small_scene(R"([{"mesh": "cube", "material": {"shader": "Tint.shader"}}])");
    auto scene = parse_scene(json, (dir_ / "scene.json").string());
    ASSERT_TRUE(scene) << scene.error().message;
    scene_ = std::move(*scene);
  }

  // Rewrites a file of the test and moves its time on, as an editor's save does.
  void write(const std::string& name, const std::string& text) {
    fs::path path = dir_ / name;
    bool existed = fs::exists(path);
    fs::file_time_type before = existed ? fs::last_write_time(path) : fs::file_time_type{};
    std::ofstream(path, std::ios::trunc) << text;
    if (existed) fs::last_write_time(path, before + std::chrono::seconds(2));
  }

  Result<RenderedFrame, test_support::Printed> render_kept() {
    return render_scene(context(), scene_, test_support::with_compiler({.shaders = store_}));
  }

  RenderedFrame render_ok() {
    auto frame = render_kept();
    EXPECT_TRUE(frame) << frame.error().message;
    return frame ? std::move(*frame) : RenderedFrame{};
  }

  fs::path dir_;
  Scene scene_;
  std::shared_ptr<ShaderStore> store_ = make_shader_store();
};

TEST_F(ShaderStoreTest, AKeptShaderIsNeitherLoadedNorCompiledAgain) {
  RenderedFrame first = render_ok();
  EXPECT_EQ(first.stats.shaders_loaded, 1u);
  EXPECT_GE(first.stats.variants_compiled, 1u);
  RenderedFrame second = render_ok();
  EXPECT_EQ(second.stats.shaders_loaded, 0u);
  EXPECT_EQ(second.stats.variants_compiled, 0u);
  EXPECT_EQ(second.stats.shaders_reloaded, 0u);
  EXPECT_EQ(first.ldr, second.ldr);
  EXPECT_EQ(second.shader_files, first.shader_files) << "the depfile's inputs are the kept shader's";
}

TEST_F(ShaderStoreTest, AShaderWhoseFileChangedIsReloaded) {
  RenderedFrame red = render_ok();
  EXPECT_EQ(pixel(red, 32, 32), (std::array<int, 3>{255, 0, 0}));
  std::string green = kShader;
  green.replace(green.find("return TINT;"), 12, "return fixed4(0, 1, 0, 1);");
  write("Tint.shader", green);
  RenderedFrame after = render_ok();
  EXPECT_EQ(after.stats.shaders_reloaded, 1u);
  EXPECT_EQ(after.stats.shaders_loaded, 1u);
  EXPECT_GE(after.stats.variants_compiled, 1u);
  EXPECT_EQ(pixel(after, 32, 32), (std::array<int, 3>{0, 255, 0}));
}

TEST_F(ShaderStoreTest, AShaderWhoseIncludeChangedIsReloaded) {
  render_ok();
  write("tint.cginc", "#define TINT float4(0, 0, 1, 1)\n");
  RenderedFrame after = render_ok();
  EXPECT_EQ(after.stats.shaders_reloaded, 1u);
  EXPECT_EQ(pixel(after, 32, 32), (std::array<int, 3>{0, 0, 255}));
}

TEST_F(ShaderStoreTest, ABrokenEditIsALocatedErrorAndTheFixedFileRendersAgain) {
  render_ok();
  std::string broken = kShader;
  broken.replace(broken.find("SubShader {"), 11, "SubShader { Bogus");
  write("Tint.shader", broken);
  auto failed = render_kept();
  ASSERT_FALSE(failed);
  EXPECT_NE(failed.error().message.find("Tint.shader:2:"), std::string::npos) << failed.error().message;
  write("Tint.shader", kShader);
  RenderedFrame fixed = render_ok();
  EXPECT_EQ(pixel(fixed, 32, 32), (std::array<int, 3>{255, 0, 0}));
}

// A kept .shader whose draw needs a variant not compiled yet, in a render
// given no development layer: a located error, not a crash.
TEST_F(ShaderStoreTest, ANewVariantWithoutTheDevelopmentLayerIsAnError) {
  render_ok();
  scene_.objects[0].material.keywords = {"HALF_TINT"};
  auto frame = render_scene(context(), scene_, {.shaders = store_});
  ASSERT_FALSE(frame);
  EXPECT_NE(frame.error().message.find("needs the development layer"), std::string::npos) << frame.error().message;
  EXPECT_TRUE(render_kept()) << "with the layer again, the variant compiles";
}

TEST_F(ShaderStoreTest, AStoreRendersWithNoOtherContext) {
  render_ok();
  VkResultOf<std::unique_ptr<Context>> other = create_context({});
  ASSERT_TRUE(other) << describe(other.error());
  auto frame = render_scene(**other, scene_, test_support::with_compiler({.shaders = store_}));
  ASSERT_FALSE(frame);
  EXPECT_NE(frame.error().message.find("another Context"), std::string::npos) << frame.error().message;
}

}  // namespace
}  // namespace facet::runtime
