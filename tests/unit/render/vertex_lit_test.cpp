// Vertex-lit passes (LightMode Vertex): Unity's per-vertex lights reach the
// shader, a fixed-function lit pass renders like the same lighting written
// by hand, and the draw list says which lights and why.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "facet/runtime/scene.h"
#include "golden_support.h"
#include "render_test_support.h"

namespace facet::runtime {
namespace {

using test_support::compare_images;
using test_support::frame_image;
using test_support::object_json;
using test_support::small_scene;

std::filesystem::path example_scene() {
  return std::filesystem::path(FACET_SOURCE_DIR) / "examples" / "scenes" / "vertex_lit.json";
}

std::string read_text(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  for (size_t at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size())) {
    text.replace(at, from.size(), to);
  }
  return text;
}

class VertexLitTest : public test_support::RenderTest {
 protected:
  // The example scene rendered at the golden size from a text beside the
  // original (so that its relative paths resolve).
  static RenderedFrame render_example_text(const std::string& name, const std::string& json) {
    std::filesystem::path path = example_scene().parent_path() / (name + ".json");
    auto scene = parse_scene(json, path.string());
    EXPECT_TRUE(scene) << scene.error().message;
    if (!scene) return {};
    RenderOptions options{.width = test_support::kGoldenWidth, .height = test_support::kGoldenHeight};
    auto frame = render_scene(context(), *scene, test_support::with_compiler(options));
    EXPECT_TRUE(frame) << frame.error().message;
    return frame ? std::move(*frame) : RenderedFrame{};
  }
};

TEST_F(VertexLitTest, AFixedFunctionLitPassRendersLikeTheSameLightingWrittenByHand) {
  std::string json = read_text(example_scene());
  ASSERT_NE(json.find("FixedFunctionVertexLit.shader"), std::string::npos);
  RenderedFrame fixed = render_example_text("vertex_lit_fixed", json);
  RenderedFrame by_hand =
      render_example_text("vertex_lit_by_hand", replaced(json, "FixedFunctionVertexLit.shader", "VertexLitByHand.shader"));
  ASSERT_FALSE(fixed.ldr.empty());
  ASSERT_FALSE(by_hand.ldr.empty());
  test_support::GoldenComparison same = compare_images(frame_image(fixed), frame_image(by_hand));
  EXPECT_TRUE(same.ok) << same.message;

  // The lights matter: without them the same objects look different, so
  // the agreement above is about the lighting, not about two black images.
  std::string dark = json.substr(0, json.find("\"lights\"")) + "\"lights\": []," +
                     json.substr(json.find("\"objects\""));
  RenderedFrame unlit = render_example_text("vertex_lit_no_lights", dark);
  EXPECT_FALSE(compare_images(frame_image(fixed), frame_image(unlit)).ok) << "the lights changed nothing";
}

TEST_F(VertexLitTest, AVertexPassIsDrawnOnceWithAtMostEightLightsDirectionalFirst) {
  std::string lights = "[";
  for (int i = 0; i < 9; ++i) {
    lights += R"({"type": "point", "position": [0, 0, -1.5], "range": 10, "intensity": )" + std::to_string(1 + i) + "}, ";
  }
  lights += R"({"type": "directional", "rotation": [30, 20, 0], "intensity": 0.1}])";
  RenderedFrame f = render("vertex_eight", small_scene("[" + object_json("sphere", "FixedFunctionVertexLit.shader") + "]", lights));
  ASSERT_EQ(test_support::count_draws(f, "Vertex"), 1u);
  const DrawRecord& d = f.draws[0];
  EXPECT_EQ(d.light.rfind("lights[9] (directional), lights[8] (point), lights[7] (point)", 0), 0u) << d.light;
  EXPECT_EQ(std::count(d.light.begin(), d.light.end(), ','), 7) << d.light;
  EXPECT_NE(d.why.find("8 of the scene's lights"), std::string::npos) << d.why;
}

TEST_F(VertexLitTest, APointLightBrightensTheVertexLitSideFacingIt) {
  std::string left = R"([{"type": "point", "position": [-1.2, 0, -1], "range": 6, "intensity": 3}])";
  RenderedFrame f = render("vertex_point", small_scene("[" + object_json("sphere", "FixedFunctionVertexLit.shader") + "]", left));
  ASSERT_EQ(f.ldr.size(), 64u * 64u * 4u);
  auto red = [&](int x, int y) { return int(f.ldr[(size_t(y) * 64 + x) * 4]); };
  // The camera looks along +Z from z = -3, so world -X is on the image's left.
  EXPECT_GT(red(22, 32), red(42, 32) + 40);
}

TEST_F(VertexLitTest, AVertexPassIsSkippedWhenTheShaderHasForwardPasses) {
  const char* shader = R"(Shader "Test/BothPaths" {
    SubShader {
      Pass { Tags { "LightMode" = "ForwardBase" } Color (1, 0, 0, 1) }
      Pass { Tags { "LightMode" = "Vertex" } Lighting On Material { Diffuse (1, 1, 1, 1) } }
    }
  })";
  std::filesystem::path path = test_support::test_dir() / "BothPaths.shader";
  std::ofstream(path) << shader;
  std::string object = R"({"mesh": "sphere", "material": {"shader": ")" + path.string() + "\"}}";
  RenderedFrame f = render("vertex_skipped", small_scene("[" + object + "]"));
  EXPECT_EQ(test_support::count_draws(f, "ForwardBase"), 1u);
  EXPECT_EQ(test_support::count_draws(f, "Vertex"), 0u);
  ASSERT_EQ(test_support::count_draws(f, "Vertex", false), 1u);
  for (const DrawRecord& d : f.draws) {
    if (d.light_mode == "Vertex") {
      EXPECT_NE(d.why.find("forward passes"), std::string::npos) << d.why;
    }
  }
}

TEST_F(VertexLitTest, LightmappedVertexPassesAreSkippedWithTheReason) {
  const char* shader = R"(Shader "Test/Lightmapped" {
    SubShader {
      Pass { Tags { "LightMode" = "Vertex" } Lighting On Material { Diffuse (1, 1, 1, 1) } }
      Pass { Tags { "LightMode" = "VertexLM" } Color (1, 1, 1, 1) }
    }
  })";
  std::filesystem::path path = test_support::test_dir() / "Lightmapped.shader";
  std::ofstream(path) << shader;
  std::string object = R"({"mesh": "sphere", "material": {"shader": ")" + path.string() + "\"}}";
  RenderedFrame f = render("vertex_lm", small_scene("[" + object + "]"));
  EXPECT_EQ(test_support::count_draws(f, "Vertex"), 1u);
  for (const DrawRecord& d : f.draws) {
    if (d.light_mode == "VertexLM") {
      EXPECT_FALSE(d.drawn);
      EXPECT_NE(d.why.find("lightmapped"), std::string::npos) << d.why;
    }
  }
}

}  // namespace
}  // namespace facet::runtime
