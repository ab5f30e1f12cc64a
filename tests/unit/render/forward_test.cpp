// The forward renderer on lavapipe: what it draws, what it compiles, and the
// pixels of a scene whose colour is known.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "facet/runtime/scene.h"
#include "render_test_support.h"

namespace facet::runtime {
namespace {

using test_support::count_draws;
using test_support::object_json;
using test_support::small_scene;
using test_support::pixel;

using ForwardTest = test_support::RenderTest;

bool any_compiled(const RenderedFrame& f, const std::string& text) {
  return std::any_of(f.compiled.begin(), f.compiled.end(),
                     [&](const std::string& c) { return c.find(text) != std::string::npos; });
}

constexpr const char* kSun = R"({"type": "directional", "rotation": [30, 20, 0]})";
constexpr const char* kPoint = R"({"type": "point", "position": [0.5, 0.5, -1.2], "range": 5, "intensity": 2})";

TEST_F(ForwardTest, UnlitSphereHasTheMaterialColourInTheCentreAndTheClearColourInTheCorner) {
  RenderedFrame f = render("unlit", small_scene("[" + object_json("sphere", "Unlit.shader") + "]"));
  ASSERT_EQ(f.ldr.size(), 64u * 64u * 4u);
  // _Color defaults to (1, 0.5, 0.25), authored in sRGB: the PNG gets it back (half floats cost one step).
  std::array<int, 3> centre = pixel(f, 32, 32);
  EXPECT_EQ(centre[0], 255);
  EXPECT_NEAR(centre[1], 128, 1);
  EXPECT_NEAR(centre[2], 64, 1);
  EXPECT_EQ(pixel(f, 1, 1), (std::array<int, 3>{0, 0, 0}));
  EXPECT_EQ(f.stats.draws, 1u);
  EXPECT_EQ(f.stats.variants_compiled, 1u);
}

TEST_F(ForwardTest, MaterialColourOverridesTheShaderDefault) {
  RenderedFrame f = render("unlit_green", small_scene("[" +
                                                      object_json("cube", "Unlit.shader",
                                                                  R"(, "properties": {"_Color": [0, 1, 0, 1]})") +
                                                      "]"));
  ASSERT_FALSE(f.ldr.empty());
  EXPECT_EQ(pixel(f, 32, 32), (std::array<int, 3>{0, 255, 0}));
}

TEST_F(ForwardTest, OneDirectionalLightIssuesNoAdditiveDrawAndCompilesNoForwardAddVariant) {
  RenderedFrame f = render("one_light",
                           small_scene("[" + object_json("sphere", "PhongMultiLight.shader") + "]", std::string("[") + kSun + "]"));
  EXPECT_EQ(f.stats.additive_draws, 0u);
  EXPECT_EQ(count_draws(f, "ForwardBase"), 1u);
  EXPECT_EQ(count_draws(f, "ForwardAdd"), 0u);
  EXPECT_FALSE(any_compiled(f, "FORWARD_DELTA")) << "compiled a ForwardAdd variant";
  EXPECT_EQ(f.stats.variants_compiled, 1u);
}

TEST_F(ForwardTest, APointLightAddsOneAdditiveDrawPerLitObjectWithThePointVariant) {
  std::string objects = "[" + object_json("sphere", "PhongMultiLight.shader", "", "[-0.6, 0, 0]") + ", " +
                        object_json("cube", "PhongMultiLight.shader", "", "[0.6, 0, 0]") + ", " +
                        // Far beyond the light's range: lit by the sun only.
                        object_json("sphere", "PhongMultiLight.shader", "", "[0, 0, 40]") + "]";
  RenderedFrame f = render("point_light", small_scene(objects, std::string("[") + kSun + ", " + kPoint + "]"));
  EXPECT_EQ(count_draws(f, "ForwardBase"), 3u);
  EXPECT_EQ(f.stats.additive_draws, 2u);
  std::vector<size_t> lit;
  for (const DrawRecord& d : f.draws) {
    if (!d.additive) continue;
    lit.push_back(d.object_index);
    EXPECT_EQ(d.keywords, (std::vector<std::string>{"POINT"}));
  }
  std::sort(lit.begin(), lit.end());
  EXPECT_EQ(lit, (std::vector<size_t>{0, 1}));
  EXPECT_TRUE(any_compiled(f, "FORWARD_DELTA: POINT"));
  EXPECT_EQ(f.stats.variants_compiled, 2u);  // one ForwardBase, one ForwardAdd POINT
}

TEST_F(ForwardTest, APointLightBrightensTheLitSideOfADiffuseObject) {
  std::string objects = "[" + object_json("sphere", "PhongMultiLight.shader", R"(, "properties": {"_SpecColor": [0, 0, 0]})") + "]";
  RenderedFrame dark = render("dark", small_scene(objects));
  RenderedFrame lit = render("lit", small_scene(objects, std::string("[") + kPoint + "]"));
  ASSERT_FALSE(dark.ldr.empty());
  ASSERT_FALSE(lit.ldr.empty());
  // The light is up and to the right of the camera; x grows to the right, y down.
  EXPECT_GT(pixel(lit, 40, 26)[0], pixel(dark, 40, 26)[0] + 20);
  EXPECT_GT(pixel(lit, 40, 26)[0], pixel(lit, 24, 40)[0]);
}

TEST_F(ForwardTest, TransparentQueueDrawsBackToFrontAndOpaqueFrontToBack) {
  std::string transparent = R"(, "queue": 3000)";
  std::string objects = "[" + object_json("quad", "Unlit.shader", transparent, "[0, 0, 1]") + ", " +
                        object_json("quad", "Unlit.shader", transparent, "[0, 0, 3]") + ", " +
                        object_json("quad", "Unlit.shader", "", "[0, 0, 3]") + ", " +
                        object_json("quad", "Unlit.shader", "", "[0, 0, 1]") + "]";
  RenderedFrame f = render("queues", small_scene(objects));
  std::vector<size_t> order;
  for (const DrawRecord& d : f.draws) order.push_back(d.object_index);
  EXPECT_EQ(order, (std::vector<size_t>{3, 2, 1, 0}));
}

TEST_F(ForwardTest, FogEnablesTheFogKeywordOnlyWhenTheSceneHasFog) {
  std::string objects = "[" + object_json("sphere", "TexturedAmbient.shader") + "]";
  RenderedFrame plain = render("nofog", small_scene(objects));
  std::string foggy_json = small_scene(objects);
  foggy_json.insert(1, R"("fog": {"mode": "exp2", "density": 0.2}, )");
  RenderedFrame foggy = render("fog", foggy_json);
  ASSERT_FALSE(plain.draws.empty());
  ASSERT_FALSE(foggy.draws.empty());
  auto has = [](const DrawRecord& d, const char* k) {
    return std::find(d.keywords.begin(), d.keywords.end(), k) != d.keywords.end();
  };
  EXPECT_FALSE(has(plain.draws[0], "FOG_EXP2"));
  EXPECT_TRUE(has(foggy.draws[0], "FOG_EXP2"));
  EXPECT_FALSE(any_compiled(plain, "FOG_"));
}

}  // namespace
}  // namespace facet::runtime
