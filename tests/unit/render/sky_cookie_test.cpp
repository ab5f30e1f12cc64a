// The procedural sky ambient and light cookies through the renderer on
// lavapipe, and the scene reader's errors for both.
#include <gtest/gtest.h>

#include <cmath>
#include <algorithm>
#include <fstream>
#include <sstream>

#include "facet/commands.h"
#include "facet/runtime/material.h"
#include "facet/runtime/scene.h"
#include "facet/runtime/sky_sh.h"
#include "render_test_support.h"

namespace facet::runtime {
namespace {

using test_support::example_shader;
using test_support::object_json;
using test_support::write_scene;

std::array<int, 3> pixel(const RenderedFrame& f, int x, int y) {
  const uint8_t* p = &f.ldr[(size_t(y) * f.width + x) * 4];
  return {p[0], p[1], p[2]};
}

// A 16 x 16 grey cookie (PGM): black where u < 0.5, white where u >= 0.5.
std::string half_cookie() {
  std::string path = (test_support::test_dir() / "half_cookie.pgm").string();
  std::ofstream out(path, std::ios::binary);
  out << "P5\n16 16\n255\n";
  for (int y = 0; y < 16; ++y)
    for (int x = 0; x < 16; ++x) out.put(char(x < 8 ? 0 : 255));
  return path;
}

// A Phong floor seen from straight above (image right = +X, up = +Z).
std::string floor_scene(const std::string& lights, const std::string& camera) {
  return R"({"width": 64, "height": 64, "ambient": [0, 0, 0], "camera": )" + camera + R"(, "lights": )" + lights +
         R"(, "objects": [{"mesh": "plane", "scale": 0.5, "material": {"shader": ")" +
         example_shader("PhongMultiLight.shader") +
         R"(", "properties": {"_Color": [0.8, 0.8, 0.8], "_SpecColor": [0, 0, 0]}}}]})";
}

constexpr const char* kTopCamera = R"({"position": [0, 3, 0], "look_at": [0, 0, 0], "fov": 40, "clear_color": [0, 0, 0]})";
constexpr const char* kTopOrtho =
    R"({"type": "orthographic", "size": 2, "position": [0, 3, 0], "look_at": [0, 0, 0], "clear_color": [0, 0, 0]})";

using SkyCookieTest = test_support::RenderTest;

int to_8bit(float linear) { return int(std::lround(linear_to_srgb(std::clamp(linear, 0.0f, 1.0f)) * 255.0)); }

TEST_F(SkyCookieTest, SkyAmbientOnADiffuseSphereIsShadeSH9OfTheSkyAtTheNormal) {
  const char* sky = R"({"sky": {"zenith": [0.3, 0.5, 0.9], "horizon": [0.7, 0.7, 0.65], "ground": [0.3, 0.2, 0.1]}})";
  std::string json = std::string(R"({"width": 64, "height": 64, "ambient": )") + sky +
                     R"(, "camera": {"position": [0, 0, -3], "look_at": [0, 0, 0], "fov": 40, "clear_color": [0, 0, 0]},
                     "objects": [)" + object_json("sphere", "Diffuse.shader") + "]}";
  RenderedFrame f = render("sky_sphere", json);
  ASSERT_FALSE(f.ldr.empty());
  SceneSky s{.zenith = {0.3f, 0.5f, 0.9f}, .horizon = {0.7f, 0.7f, 0.65f}, .ground = {0.3f, 0.2f, 0.1f}};
  SkyRadiance r = linear_sky(s);
  UnitySh sh = pack_unity_sh(project_sh([&](const glm::vec3& d) { return sky_radiance(r, d); }));
  glm::vec3 want = eval_unity_sh(sh, {0, 0, -1});  // the centre pixel faces the camera
  std::array<int, 3> got = pixel(f, 32, 32);
  for (int ch = 0; ch < 3; ++ch) EXPECT_NEAR(got[ch], to_8bit(want[ch]), 2) << "channel " << ch;
  // Upper half faces the blue zenith, lower half the brown ground.
  std::array<int, 3> up = pixel(f, 32, 24), down = pixel(f, 32, 40);
  EXPECT_GT(up[2] - up[0], down[2] - down[0] + 20);
}

TEST_F(SkyCookieTest, SpotCookieDarkensTheMaskedHalfAndLeavesTheOpenHalfAsWithoutACookie) {
  std::string spot = R"({"type": "spot", "position": [0, 2, 0], "rotation": [90, 0, 0], "range": 5,
                         "spot_angle": 60, "intensity": 2)";
  RenderedFrame plain = render("spot_plain", floor_scene("[" + spot + "}]", kTopCamera));
  RenderedFrame cookie =
      render("spot_cookie", floor_scene("[" + spot + R"(, "cookie": ")" + half_cookie() + "\"}]", kTopCamera));
  ASSERT_FALSE(plain.ldr.empty());
  ASSERT_FALSE(cookie.ldr.empty());
  // Floor x = -0.4 (pixel 20) is under the cookie's black half, x = +0.4 (pixel 44) under its white half.
  EXPECT_GT(pixel(plain, 20, 32)[0], 60);
  EXPECT_EQ(pixel(cookie, 20, 32), (std::array<int, 3>{0, 0, 0}));
  EXPECT_EQ(pixel(cookie, 44, 32), pixel(plain, 44, 32));
  bool spot_keyword = false;
  for (const DrawRecord& d : cookie.draws)
    for (const std::string& k : d.keywords) spot_keyword |= d.additive && k == "SPOT";
  EXPECT_TRUE(spot_keyword);
}

TEST_F(SkyCookieTest, DirectionalCookieRepeatsEveryCookieSizeAndIsDrawnAdditivelyWithDirectionalCookie) {
  std::string light = R"([{"type": "directional", "rotation": [90, 0, 0], "cookie_size": 2, "cookie": ")" +
                      half_cookie() + "\"}]";
  RenderedFrame f = render("dir_cookie", floor_scene(light, kTopOrtho));
  ASSERT_FALSE(f.ldr.empty());
  // 16 pixels per world unit: x = -0.47 (pixel 24) and 1.53 (pixel 56) are masked, x = 0.53 (pixel 40) is lit.
  EXPECT_EQ(pixel(f, 24, 32), (std::array<int, 3>{0, 0, 0}));
  EXPECT_EQ(pixel(f, 56, 32), (std::array<int, 3>{0, 0, 0}));
  EXPECT_GT(pixel(f, 40, 32)[0], 100);
  size_t cookie_draws = 0, base_draws = 0;
  for (const DrawRecord& d : f.draws) {
    if (!d.drawn) continue;
    bool has = std::find(d.keywords.begin(), d.keywords.end(), "DIRECTIONAL_COOKIE") != d.keywords.end();
    cookie_draws += d.additive && has;
    if (d.light_mode == "ForwardBase") {
      ++base_draws;
      EXPECT_TRUE(d.light.empty()) << "the cookie light must not be ForwardBase's main light";
      EXPECT_FALSE(has);
    }
  }
  EXPECT_EQ(cookie_draws, 1u);
  EXPECT_EQ(base_draws, 1u);
}

TEST_F(SkyCookieTest, DirectionalLightWithoutCookieCompilesNoDirectionalCookieVariant) {
  RenderedFrame f = render("dir_plain", floor_scene(R"([{"type": "directional", "rotation": [90, 0, 0]}])", kTopOrtho));
  for (const std::string& c : f.compiled) EXPECT_EQ(c.find("DIRECTIONAL_COOKIE"), std::string::npos) << c;
}

TEST_F(SkyCookieTest, CookieFileThatIsNotAnImageFailsNamingTheLightsCookie) {
  std::string path = (test_support::test_dir() / "not_an_image.png").string();
  std::ofstream(path) << "not a png";
  std::string json = floor_scene(R"([{"type": "spot", "position": [0, 2, 0], "rotation": [90, 0, 0], "cookie": ")" +
                                     path + "\"}]",
                                 kTopCamera);
  auto scene = parse_scene(json, write_scene("bad_cookie", json));
  ASSERT_TRUE(scene) << scene.error().message;
  auto frame = render_scene(context(), *scene, test_support::with_compiler({}));
  ASSERT_FALSE(frame);
  EXPECT_NE(frame.error().message.find("lights[0].cookie: "), std::string::npos)
      << frame.error().message;
}

// ---- errors -------------------------------------------------------------------

struct BadCase {
  const char* name;
  std::string fragment;  // replaces AMBIENT and LIGHTS below
  bool is_light;
  const char* message;
};

std::string bad_scene(const BadCase& c) {
  std::string ambient = c.is_light ? "[0.1, 0.1, 0.1]" : c.fragment;
  std::string lights = c.is_light ? "[" + c.fragment + "]" : "[]";
  return R"({"ambient": )" + ambient + R"(, "lights": )" + lights + R"(, "camera": {}, "objects": [)" +
         object_json("sphere", "Unlit.shader") + "]}";
}

class SkyCookieErrors : public testing::TestWithParam<BadCase> {};

TEST_P(SkyCookieErrors, NamesTheJsonPath) {
  const BadCase& c = GetParam();
  auto scene = parse_scene(bad_scene(c), write_scene(c.name, bad_scene(c)));
  ASSERT_FALSE(scene) << "accepted: " << c.fragment;
  EXPECT_NE(scene.error().message.find(c.message), std::string::npos) << scene.error().message;
}

INSTANTIATE_TEST_SUITE_P(
    Cases, SkyCookieErrors,
    testing::Values(
        BadCase{"sky_colour_type", R"({"sky": {"zenith": "blue"}})", false, "ambient.sky.zenith: expected 3 to 4 numbers"},
        BadCase{"sky_negative", R"({"sky": {"intensity": -1}})", false, "ambient.sky.intensity: expected a number >= 0"},
        BadCase{"sky_unknown_key", R"({"sky": {"zenit": [1, 1, 1]}})", false, "ambient.sky.zenit: unknown key"},
        BadCase{"ambient_unknown_key", R"({"skye": {}})", false, "ambient.skye: unknown key"},
        BadCase{"ambient_type", R"("blue")", false, "ambient: expected a colour"},
        BadCase{"point_cookie", R"({"type": "point", "cookie": "white"})", true,
                "lights[0].cookie: point lights take no cookie"},
        BadCase{"cookie_type", R"({"type": "spot", "cookie": 3})", true, "lights[0].cookie: expected a texture file"},
        BadCase{"cookie_missing", R"({"type": "spot", "cookie": "no_such.png"})", true,
                "lights[0].cookie: texture file"},
        BadCase{"cookie_size_spot", R"({"type": "spot", "cookie_size": 2})", true,
                "lights[0].cookie_size: only a directional light"},
        BadCase{"cookie_size_zero", R"({"type": "directional", "cookie_size": 0})", true,
                "lights[0].cookie_size: expected a number above 0"}),
    [](const testing::TestParamInfo<BadCase>& info) { return std::string(info.param.name); });

TEST(SkyCookieCli, BadSkyExitsWithOneAndNamesThePath) {
  BadCase c{"cli_sky", R"({"sky": {"intensity": -2}})", false, ""};
  std::string scene = write_scene(c.name, bad_scene(c));
  std::string png = (test_support::test_dir() / "cli_sky.png").string();
  std::vector<const char*> argv = {"render", scene.c_str(), "-o", png.c_str()};
  std::ostringstream out, err;
  EXPECT_EQ(tool::render_command(int(argv.size()), argv.data(), out, err), 1);
  EXPECT_NE(err.str().find("ambient.sky.intensity"), std::string::npos) << err.str();
}

}  // namespace
}  // namespace facet::runtime
