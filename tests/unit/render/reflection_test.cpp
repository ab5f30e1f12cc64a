// Image-based lighting on lavapipe: a scene's environment (an HDR
// equirectangular image or a uniform radiance) as the GGX-prefiltered
// unity_SpecCube0 every object reflects, its SH as the ambient, and the same
// environment behind the scene with camera.clear "sky"; bad environments
// refused with their JSON path.
#include <OpenImageIO/imageio.h>
#include <fmt/format.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <glm/glm.hpp>
#include <numbers>

#include "render_test_support.h"

namespace facet::runtime {
namespace {

using test_support::example_shader;
using ::testing::HasSubstr;

using ReflectionTest = test_support::RenderTest;

// The linear RGB of pixel (x, y) before tone mapping.
glm::vec3 hdr_at(const RenderedFrame& f, int x, int y) {
  const float* p = &f.hdr[(size_t(y) * f.width + size_t(x)) * 4];
  return {p[0], p[1], p[2]};
}

std::string reflective_sphere(double x, double roughness) {
  return fmt::format(R"({{"mesh": "sphere", "position": [{}, 0, 0], "scale": 0.9, "material": {{"shader": "{}",
      "properties": {{"_Roughness": {}}}}}}})",
                     x, example_shader("EnvironmentReflection.shader"), roughness);
}

// Three spheres (roughness 0, 0.5, 1) in front of a black clear colour.
std::string sphere_row(const std::string& environment, const std::string& camera_extra = "") {
  return R"({"width": 96, "height": 32,
    "camera": {"position": [0, 0, -6], "look_at": [0, 0, 0], "fov": 20, "clear_color": [0, 0, 0])" +
         camera_extra + R"(},
    "environment": )" + environment + R"(,
    "lights": [], "objects": [)" +
         reflective_sphere(-1, 0) + "," + reflective_sphere(0, 0.5) + "," + reflective_sphere(1, 1) + "]}";
}

// The Done-when furnace: reflectance 1, a uniform white environment: the
// probe's prefiltered radiance is 1 at every roughness (the prefilter's
// weights are normalised; the mip Unity's curve picks; the HDR decode).
TEST_F(ReflectionTest, ARoughMetalSphereInAUniformWhiteEnvironmentReflectsOne) {
  RenderedFrame f = render("ibl_furnace", sphere_row(R"({"color": [1, 1, 1]})"));
  ASSERT_FALSE(f.hdr.empty());
  size_t covered = 0;
  float lo = 10, hi = 0;
  for (int y = 0; y < f.height; ++y) {
    for (int x = 0; x < f.width; ++x) {
      glm::vec3 c = hdr_at(f, x, y);
      if (c.r <= 0) continue;  // the black background
      ++covered;
      for (int ch = 0; ch < 3; ++ch) lo = std::min(lo, c[ch]), hi = std::max(hi, c[ch]);
    }
  }
  EXPECT_GT(covered, size_t(96 * 32 / 8)) << "the spheres cover the frame";
  EXPECT_GE(lo, 0.98f);
  EXPECT_LE(hi, 1.02f);
  std::printf("[ ibl furnace ] %zu covered pixels reflect %.4f .. %.4f\n", covered, lo, hi);
}

// Unity's Standard BRDF scales the environment by surfaceReduction,
// 1 / (roughness^2 + 1): one half for a fully rough white metal, which has
// no diffuse term and a Fresnel of 1.
TEST_F(ReflectionTest, TheStandardShadersFullyRoughWhiteMetalReflectsHalfTheEnvironment) {
  std::string json = R"({"width": 32, "height": 32,
    "camera": {"position": [0, 0, -4], "look_at": [0, 0, 0], "fov": 20, "clear_color": [0, 0, 0]},
    "environment": {"color": [1, 1, 1]}, "lights": [], "objects": [
      {"mesh": "sphere", "scale": 1.2, "material": {"shader": ")" +
                     example_shader("SurfaceStandard.shader") + R"(",
        "properties": {"_Color": [1, 1, 1, 1], "_Glossiness": 0, "_Metallic": 1}}}]})";
  RenderedFrame f = render("ibl_standard_rough_metal", json);
  ASSERT_FALSE(f.hdr.empty());
  glm::vec3 centre = hdr_at(f, 16, 16);
  EXPECT_NEAR(centre.r, 0.5f, 0.01f);
  EXPECT_NEAR(centre.g, 0.5f, 0.01f);
  EXPECT_NEAR(centre.b, 0.5f, 0.01f);
}

// An equirectangular HDR image whose radiance tells directions apart:
// red towards +X, green towards +Z, blue towards -Z (2 at the axis), and a
// dim grey floor of light everywhere.
std::string write_direction_environment(const std::string& name) {
  const int w = 128, h = 64;
  std::vector<float> rgb(size_t(w) * h * 3);
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      double theta = std::numbers::pi * (y + 0.5) / h;
      double azimuth = (0.5 - (x + 0.5) / w) * 2 * std::numbers::pi;  // atan2(z, x), Skybox/Panoramic's u
      glm::dvec3 d(std::sin(theta) * std::cos(azimuth), std::cos(theta), std::sin(theta) * std::sin(azimuth));
      float* p = &rgb[(size_t(y) * w + size_t(x)) * 3];
      p[0] = float(0.05 + 2 * std::max(d.x, 0.0));
      p[1] = float(0.05 + 2 * std::max(d.z, 0.0));
      p[2] = float(0.05 + 2 * std::max(-d.z, 0.0));
    }
  }
  std::string path = (test_support::test_dir() / name).string();
  auto out = OIIO::ImageOutput::create(path);
  EXPECT_TRUE(out);
  OIIO::ImageSpec spec(w, h, 3, OIIO::TypeDesc::FLOAT);
  EXPECT_TRUE(out->open(path, spec) && out->write_image(OIIO::TypeDesc::FLOAT, rgb.data()) && out->close());
  return path;
}

// A mirror sphere seen along +Z: its centre reflects straight back (-Z,
// blue), its right edge reflects +X (red); the sky behind it is +Z (green).
TEST_F(ReflectionTest, AMirrorSphereReflectsTheHdrEnvironmentAndTheSkyShowsWhatLiesBehindIt) {
  std::string env = write_direction_environment("directions.hdr");
  std::string json = R"({"width": 64, "height": 64,
    "camera": {"position": [0, 0, -4], "look_at": [0, 0, 0], "fov": 30, "clear": "sky"},
    "environment": {"file": ")" + env + R"(", "resolution": 64}, "lights": [], "objects": [
      {"mesh": "sphere", "scale": 1.2, "material": {"shader": ")" +
                     example_shader("EnvironmentReflection.shader") + R"(", "properties": {"_Roughness": 0}}}]})";
  RenderedFrame f = render("ibl_mirror", json);
  ASSERT_FALSE(f.hdr.empty());
  glm::vec3 centre = hdr_at(f, 32, 32);
  EXPECT_GT(centre.b, 1.5f) << centre.r << " " << centre.g << " " << centre.b;
  EXPECT_LT(centre.g, 0.2f);
  // Near the sphere's right rim (screen right is +X) the reflection turns to +X.
  glm::vec3 rim = hdr_at(f, 45, 32);
  EXPECT_GT(rim.r, rim.b) << rim.r << " " << rim.g << " " << rim.b;
  EXPECT_GT(rim.r, 1.0f);
  glm::vec3 sky = hdr_at(f, 32, 2);  // above the sphere: the sky, looking nearly along +Z
  EXPECT_GT(sky.g, 1.5f) << sky.r << " " << sky.g << " " << sky.b;
  EXPECT_LT(sky.b, 0.2f);
}

TEST_F(ReflectionTest, RotationTurnsTheEnvironmentAboutUp) {
  std::string env = write_direction_environment("directions_rotated.hdr");
  std::string json = R"({"width": 32, "height": 32,
    "camera": {"position": [0, 0, -4], "look_at": [0, 0, 0], "fov": 30, "clear": "sky"},
    "environment": {"file": ")" + env + R"(", "resolution": 32, "rotation": 180}, "lights": [], "objects": []})";
  RenderedFrame f = render("ibl_rotated", json);
  ASSERT_FALSE(f.hdr.empty());
  glm::vec3 ahead = hdr_at(f, 16, 16);  // +Z turned half a turn: what lay behind (-Z, blue)
  EXPECT_GT(ahead.b, 1.5f) << ahead.r << " " << ahead.g << " " << ahead.b;
  EXPECT_LT(ahead.g, 0.2f);
}

// The environment is the ambient too (Unity's Environment Lighting Source
// "Skybox"): a white Lambert-like Standard dielectric lit only by it is
// brighter on the side facing the bright half of the environment.
TEST_F(ReflectionTest, TheEnvironmentsShIsTheAmbientUnlessTheSceneGivesOne) {
  std::string env = write_direction_environment("directions_ambient.hdr");
  auto scene = [&](const std::string& ambient) {
    return R"({"width": 64, "height": 32,
      "camera": {"position": [0, 0, -4], "look_at": [0, 0, 0], "fov": 30, "clear_color": [0, 0, 0]},
      "environment": {"file": ")" + env + R"(", "resolution": 16})" + ambient + R"(, "lights": [], "objects": [
        {"mesh": "sphere", "scale": 1.2, "material": {"shader": ")" +
           example_shader("SurfaceStandard.shader") + R"(",
          "properties": {"_Color": [1, 1, 1, 1], "_Glossiness": 0, "_Metallic": 0}}}]})";
  };
  RenderedFrame lit = render("ibl_ambient", scene(""));
  ASSERT_FALSE(lit.hdr.empty());
  // Facing the camera (-Z): blue dominates; the right side (+X) turns red.
  glm::vec3 front = hdr_at(lit, 32, 16), right = hdr_at(lit, 39, 16);
  EXPECT_GT(front.b, front.r) << front.r << " " << front.g << " " << front.b;
  EXPECT_GT(right.r, front.r);
  RenderedFrame flat = render("ibl_ambient_given", scene(R"(, "ambient": [0, 0, 0])"));
  ASSERT_FALSE(flat.hdr.empty());
  glm::vec3 dark = hdr_at(flat, 32, 16);
  EXPECT_LT(dark.b, front.b * 0.5f) << "a given ambient replaces the environment's SH";
}

std::string unlit_color(const char* name, const std::string& position, const std::string& rotation,
                        const std::string& scale, const std::string& color) {
  return fmt::format(R"({{"name": "{}", "mesh": "quad", "position": {}, "rotation": {}, "scale": {},
      "material": {{"shader": "{}", "properties": {{"_Color": {}}}}}}})",
                     name, position, rotation, scale, std::string(FACET_SOURCE_DIR) + "/stdlib/Shaders/Unlit/Color.shader",
                     color);
}

// A room 6 wide: red wall at +X, blue at -X, and behind the camera a front
// wall (at z = -3, facing +Z) yellow for x < 1 and cyan for x > 1; a mirror
// sphere at (sphere_x, 1, 0); a probe at (0, 1, 0) whose box is the room.
// The mirror is EnvironmentReflection.shader (the probe read as
// Unity_GlossyEnvironment reads it), or with `standard` the Standard
// surface shader's white smooth metal, whose reflection goes through
// UnityGI_IndirectSpecular: box projection and probe blending.
std::string probe_room(float sphere_x, const std::string& probes, bool standard = false) {
  const std::string mirror =
      standard ? fmt::format(R"({{"shader": "{}", "properties": {{"_Color": [1, 1, 1, 1], "_Glossiness": 1, "_Metallic": 1}}}})",
                             example_shader("SurfaceStandard.shader"))
               : fmt::format(R"({{"shader": "{}", "properties": {{"_Roughness": 0}}}})",
                             example_shader("EnvironmentReflection.shader"));
  std::string walls = unlit_color("red wall", "[3, 1, 0]", "[0, 90, 0]", "[6, 3, 1]", "[1, 0, 0, 1]") + "," +
                      unlit_color("blue wall", "[-3, 1, 0]", "[0, -90, 0]", "[6, 3, 1]", "[0, 0, 1, 1]") + "," +
                      unlit_color("yellow front", "[-1, 1, -3]", "[0, 180, 0]", "[4, 3, 1]", "[1, 1, 0, 1]") + "," +
                      unlit_color("cyan front", "[2, 1, -3]", "[0, 180, 0]", "[2, 3, 1]", "[0, 1, 1, 1]");
  return fmt::format(R"({{"width": 48, "height": 48,
    "camera": {{"position": [{0}, 1, -1.6], "look_at": [{0}, 1, 0], "fov": 30, "clear_color": [0, 0, 0]}},
    "environment": {{"color": [0.2, 0.2, 0.2]}}, "lights": [], {1}
    "objects": [{2}, {{"name": "mirror", "mesh": "sphere", "position": [{0}, 1, 0], "scale": 0.8,
      "material": {3}}}]}})",
                     sphere_x, probes, walls, mirror);
}

// The probe sees the room: the mirror's centre reflects what is behind the
// camera (the front wall), its sides the side walls, where without a probe
// it reflects the grey environment.
TEST_F(ReflectionTest, AReflectionProbeCapturesTheRoomTheMirrorReflects) {
  RenderedFrame none = render("probe_none", probe_room(0, ""));
  RenderedFrame probed = render(
      "probe_room", probe_room(0, R"("reflection_probes": [{"position": [0, 1, 0], "size": [6, 3, 6.2], "resolution": 32}],)"));
  ASSERT_FALSE(probed.hdr.empty());
  glm::vec3 plain = hdr_at(none, 24, 24), centre = hdr_at(probed, 24, 24);
  EXPECT_NEAR(plain.r, 0.2f, 0.02f) << "without a probe: the environment";
  EXPECT_GT(centre.r, 0.7f) << centre.r << " " << centre.g << " " << centre.b << ": the yellow front wall";
  EXPECT_GT(centre.g, 0.7f);
  EXPECT_LT(centre.b, 0.2f);
  glm::vec3 right = hdr_at(probed, 42, 24), left = hdr_at(probed, 6, 24);
  EXPECT_GT(right.r, 0.6f) << "right rim: the red wall";
  EXPECT_GT(left.b, 0.6f) << "left rim: the blue wall";
}

// Box projection: at x = 2 the mirror's centre reflects the front wall at
// x = 2 (cyan) when the probe projects onto its box, the wall straight
// ahead of the probe (yellow) when it does not.
TEST_F(ReflectionTest, BoxProjectionReflectsWhatLiesAheadOfTheObjectNotOfTheProbe) {
  auto probe = [](bool box) {
    return fmt::format(
        R"("reflection_probes": [{{"position": [0, 1, 0], "size": [6, 3, 6.2], "resolution": 32, "box_projection": {}}}],)",
        box ? "true" : "false");
  };
  RenderedFrame flat = render("probe_no_box", probe_room(2, probe(false), true));
  RenderedFrame boxed = render("probe_box", probe_room(2, probe(true), true));
  ASSERT_FALSE(boxed.hdr.empty());
  glm::vec3 f = hdr_at(flat, 24, 24), b = hdr_at(boxed, 24, 24);
  EXPECT_GT(f.r, 0.7f) << f.r << " " << f.g << " " << f.b << ": yellow without box projection";
  EXPECT_LT(f.b, 0.2f);
  EXPECT_LT(b.r, 0.2f) << b.r << " " << b.g << " " << b.b << ": cyan with box projection";
  EXPECT_GT(b.b, 0.7f);
}

// An object whose centre is outside every probe's box reflects the
// environment; 0.5 inside a face of a box with blend distance 1, half the
// probe and half the environment.
TEST_F(ReflectionTest, AnObjectReflectsTheProbesHoldingItsCentreFadingOverTheBlendDistance) {
  auto probe = [](float width) {
    return fmt::format(
        R"("reflection_probes": [{{"position": [0, 1, 0], "size": [{}, 3, 6.2], "resolution": 32, "blend_distance": 1}}],)",
        width);
  };
  RenderedFrame outside = render("probe_outside", probe_room(2, probe(3.0f), true));  // the box ends at x = 1.5
  RenderedFrame inside = render("probe_inside", probe_room(2, probe(6.0f), true));    // 1 inside: weight 1
  RenderedFrame half = render("probe_half", probe_room(2, probe(5.0f), true));        // 0.5 inside: weight 0.5
  ASSERT_FALSE(half.hdr.empty());
  glm::vec3 o = hdr_at(outside, 24, 24), i = hdr_at(inside, 24, 24), h = hdr_at(half, 24, 24);
  EXPECT_NEAR(o.r, 0.2f, 0.02f) << "outside: the grey environment";
  EXPECT_NEAR(o.g, 0.2f, 0.02f);
  EXPECT_GT(i.g, 0.7f) << "inside: the probe (the yellow front wall)";
  for (int c = 0; c < 3; ++c) {
    EXPECT_NEAR(h[c], 0.5f * (i[c] + 0.2f), 0.05f) << "channel " << c << ": half probe, half environment";
  }
}

TEST_F(ReflectionTest, BadEnvironmentsAreRefusedWithTheirJsonPath) {
  auto error_of = [&](const std::string& name, const std::string& environment) {
    std::string json = R"({"camera": {"position": [0, 0, -4]}, "environment": )" + environment +
                       R"(, "objects": []})";
    std::string path = test_support::write_scene(name, json);
    auto scene = parse_scene(json, path);
    if (!scene) return scene.error().message;
    auto frame = render_scene(context(), *scene, test_support::with_compiler({}));
    return frame ? std::string("rendered") : frame.error().message;
  };
  EXPECT_THAT(error_of("env_missing", R"({"file": "nowhere.hdr"})"),
              HasSubstr("environment.file: " + (test_support::test_dir() / "nowhere.hdr").string()));
  EXPECT_THAT(error_of("env_both", R"({"file": "a.hdr", "color": [1, 1, 1]})"),
              HasSubstr("environment: expected exactly one of 'file' and 'color'"));
  EXPECT_THAT(error_of("env_resolution", R"({"color": [1, 1, 1], "resolution": 100})"),
              HasSubstr("environment.resolution: expected a power of two"));
  EXPECT_THAT(error_of("env_negative", R"({"color": [1, -1, 1]})"), HasSubstr("environment.color[1]"));
  // An 8-bit image holds no light brighter than white.
  std::string png = (test_support::test_dir() / "ldr.png").string();
  {
    auto out = OIIO::ImageOutput::create(png);
    ASSERT_TRUE(out);
    std::vector<uint8_t> grey(8 * 4 * 3, 128);
    OIIO::ImageSpec spec(8, 4, 3, OIIO::TypeDesc::UINT8);
    ASSERT_TRUE(out->open(png, spec) && out->write_image(OIIO::TypeDesc::UINT8, grey.data()) && out->close());
  }
  EXPECT_THAT(error_of("env_ldr", R"({"file": "ldr.png"})"), HasSubstr("must be a linear HDR image"));
}

}  // namespace
}  // namespace facet::runtime
