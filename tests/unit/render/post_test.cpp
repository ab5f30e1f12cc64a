// The image-effect chain (scene "post"): steps drawn after the scene with
// the previous image as _MainTex, the camera depth texture, bad steps.
#include <gtest/gtest.h>

#include "facet/runtime/scene.h"
#include "render_test_support.h"

namespace facet::runtime {
namespace {

using test_support::example_shader;
using test_support::object_json;
using test_support::write_scene;

class PostTest : public test_support::LavapipeTest {
 protected:
  Result<RenderedFrame, test_support::Printed> render(const std::string& name, const std::string& post) {
    std::string json = R"({"width": 48, "height": 32, "camera": {"position": [0, 0, -3], "look_at": [0, 0, 0],
      "fov": 40, "near": 1, "far": 5, "clear_color": [1, 0, 0]}, "objects": [)" +
                       object_json("sphere", "Unlit.shader", R"(, "properties": {"_Color": [0, 0, 1]})") +
                       "], \"post\": " + post + "}";
    auto scene = parse_scene(json, write_scene(name, json));
    EXPECT_TRUE(scene) << scene.error().message;
    if (!scene) return unexpected(scene.error());
    return render_scene(context(), *scene, test_support::with_compiler({}));
  }
  static std::string step(int pass, const std::string& properties = "{}") {
    return R"({"shader": ")" + example_shader("ImageEffects.shader") + R"(", "pass": )" + std::to_string(pass) +
           R"(, "properties": )" + properties + "}";
  }
};

std::array<int, 3> pixel(const RenderedFrame& f, int x, int y) {
  const uint8_t* p = &f.ldr[(size_t(y) * f.width + x) * 4];
  return {p[0], p[1], p[2]};
}

TEST_F(PostTest, GreyscaleStepReadsTheSceneAsMainTexAndAddsOneDraw) {
  auto f = render("grey", "[" + step(0) + "]");
  ASSERT_TRUE(f) << f.error().message;
  EXPECT_EQ(f->stats.draws, 2u);
  EXPECT_EQ(f->draws.at(1).object, "post[0] (image effect)");
  // Red clear colour and the blue ball both become grey: r = g = b, not black.
  for (auto [x, y] : {std::pair{2, 2}, std::pair{24, 16}}) {
    std::array<int, 3> c = pixel(*f, x, y);
    EXPECT_NEAR(c[0], c[1], 1) << x << "," << y;
    EXPECT_NEAR(c[1], c[2], 1) << x << "," << y;
    EXPECT_GT(c[0], 20) << x << "," << y;
  }
  EXPECT_NE(pixel(*f, 2, 2), pixel(*f, 24, 16));
}

TEST_F(PostTest, TwoStepsChainThroughThePreviousImage) {
  // Greyscale at amount 0 is the identity: the chain must end with the scene's colours.
  auto f = render("chain", "[" + step(0, R"({"_Amount": 0})") + ", " + step(0, R"({"_Amount": 0})") + "]");
  ASSERT_TRUE(f) << f.error().message;
  EXPECT_EQ(pixel(*f, 2, 2), (std::array<int, 3>{255, 0, 0}));
  EXPECT_EQ(pixel(*f, 24, 16), (std::array<int, 3>{0, 0, 255}));
}

TEST_F(PostTest, DepthStepSeesTheCameraDepthTexture) {
  auto f = render("depth", "[" + step(2) + "]");
  ASSERT_TRUE(f) << f.error().message;
  // Linear01Depth: the background at the far plane is 1 (white); the ball's
  // front, 2.5 of the 5 units away, about 0.5: darker, but not black.
  EXPECT_EQ(pixel(*f, 2, 2)[0], 255);
  int ball = pixel(*f, 24, 16)[0];
  EXPECT_GT(ball, 150);
  EXPECT_LT(ball, 215);
}

TEST_F(PostTest, APassIndexBeyondTheShadersPassesIsAnErrorNamingIt) {
  auto f = render("bad_pass", "[" + step(7) + "]");
  ASSERT_FALSE(f);
  EXPECT_NE(f.error().message.find("post[0].pass: the shader 'Hidden/Examples/ImageEffects' has no pass 7 (its passes: 0, 1, 2, 3)"),
            std::string::npos)
      << f.error().message;
}

TEST(PostScene, UnknownKeyInAStepIsAnErrorNamingIt) {
  std::string json = R"({"camera": {}, "objects": [], "post": [{"shader": "x.shader", "passs": 1}]})";
  auto scene = parse_scene(json, "s.json");
  ASSERT_FALSE(scene);
  EXPECT_TRUE(test_support::has_error_at(scene.error().message, "s.json", "post[0].passs: unknown key"))
      << scene.error().message;
}

}  // namespace
}  // namespace facet::runtime
