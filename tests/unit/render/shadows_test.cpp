// Shadow maps on lavapipe: a shadowed light renders one depth map (a point
// light one distance cube) from the ShadowCaster passes, receivers' variants
// sample it (SHADOWS_SCREEN, SHADOWS_DEPTH, SHADOWS_CUBE), and nothing of it
// exists when no light casts shadows.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>

#include "facet/runtime/frame_capture.h"
#include "facet/runtime/scene.h"
#include "render_test_support.h"

namespace facet::runtime {
namespace {

using test_support::example_shader;

int grey(const RenderedFrame& f, int x, int y) { return f.ldr[(size_t(y) * f.width + x) * 4 + 1]; }

// A floor and a ball 1 above it, seen straight from above (orthographic: 16
// px per unit, image right = +X, up = +Z). A light tilted 60 degrees towards
// +Z throws the ball's shadow 0.58 towards +Z: pixel (32, 23); (32, 41) is
// the floor on the other side, lit.
std::string ball_scene(const std::string& lights, const std::string& extra_objects = "",
                       const std::string& settings = "", const std::string& ball_shader = "") {
  std::string standard = example_shader("SurfaceStandard.shader");
  std::string ball = ball_shader.empty() ? standard : ball_shader;
  return R"({"width": 64, "height": 64, "ambient": [0.05, 0.05, 0.05], )" + settings +
         R"("camera": {"type": "orthographic", "size": 2, "position": [0, 4, 0], "look_at": [0, 0, 0],
                       "clear_color": [0, 0, 0]},
           "lights": )" + lights + R"(,
           "objects": [
             {"name": "floor", "mesh": "plane", "scale": 0.5, "material": {"shader": ")" + standard +
         R"(", "properties": {"_Color": [0.8, 0.8, 0.8], "_Glossiness": 0}}},
             {"name": "ball", "mesh": "sphere", "position": [0, 1, 0], "scale": 0.6, "material": {"shader": ")" +
         ball + R"(", "properties": {"_Color": [0.8, 0.2, 0.2], "_Glossiness": 0}}})" + extra_objects + "]}";
}

std::string sun(const std::string& shadows) {
  return R"([{"type": "directional", "rotation": [60, 0, 0], "intensity": 1.5)" + shadows + "}]";
}

using ShadowsTest = test_support::RenderTest;

size_t count_if(const RenderedFrame& f, const std::function<bool(const DrawRecord&)>& pred) {
  return size_t(std::count_if(f.draws.begin(), f.draws.end(), pred));
}

bool has_keyword(const DrawRecord& d, const std::string& k) {
  return std::find(d.keywords.begin(), d.keywords.end(), k) != d.keywords.end();
}

TEST_F(ShadowsTest, ADirectionalLightsShadowDarkensTheFloorBehindTheBall) {
  RenderedFrame plain = render("plain", ball_scene(sun("")));
  RenderedFrame shadowed = render("shadowed", ball_scene(sun(R"(, "shadows": "hard")")));
  ASSERT_FALSE(shadowed.ldr.empty());
  EXPECT_LT(std::abs(grey(plain, 32, 23) - grey(plain, 32, 41)), 8);
  EXPECT_LT(grey(shadowed, 32, 23) + 60, grey(shadowed, 32, 41));
  EXPECT_LT(std::abs(grey(shadowed, 32, 41) - grey(plain, 32, 41)), 3);  // lit floor unchanged: no acne
  EXPECT_LT(std::abs(grey(shadowed, 32, 32) - grey(plain, 32, 32)), 3);  // the ball's lit top unchanged
}

// A ball shader with a ForwardBase pass and no ShadowCaster of its own:
// whatever shadow it casts comes from its Fallback, or from `extra_pass`
// (a UsePass) written after the ForwardBase pass.
std::string ball_shader_falling_back_to(const std::string& fallback, const std::string& extra_pass = "") {
  std::filesystem::path path = test_support::test_dir() /
                               ("ball_fallback_" + std::to_string(fallback.size() + 100 * extra_pass.size()) + ".shader");
  std::ofstream(path) << R"(Shader "Test/BallWithFallback" {
    Properties { _Color ("Color", Color) = (1, 1, 1, 1) _Glossiness ("Smoothness", Float) = 0 }
    SubShader {
        Pass {
            Tags { "LightMode" = "ForwardBase" }
            CGPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            #include "UnityCG.cginc"
            float4 vert(float4 v : POSITION) : SV_POSITION { return UnityObjectToClipPos(v); }
            fixed4 _Color;
            fixed4 frag() : SV_Target { return _Color; }
            ENDCG
        }
        )" << extra_pass << R"(
    }
    Fallback )" << fallback << "\n}\n";
  return path.string();
}

TEST_F(ShadowsTest, AShaderCastsTheShadowOfItsFallbackDiffuse) {
  const std::string lights = sun(R"(, "shadows": "hard")");
  RenderedFrame diffuse = render("fallback_diffuse", ball_scene(lights, "", "", ball_shader_falling_back_to("\"Diffuse\"")));
  RenderedFrame off = render("fallback_off", ball_scene(lights, "", "", ball_shader_falling_back_to("Off")));
  ASSERT_FALSE(diffuse.ldr.empty());
  ASSERT_FALSE(off.ldr.empty());
  EXPECT_LT(grey(diffuse, 32, 23) + 60, grey(diffuse, 32, 41));  // the floor behind the ball is in its shadow
  EXPECT_LT(std::abs(grey(off, 32, 23) - grey(off, 32, 41)), 8);  // no caster, no shadow
  // Into the light's map (the camera depth texture the screen-space pass reads draws it too).
  auto is_ball_caster = [](const DrawRecord& d) {
    return d.light_mode == "ShadowCaster" && d.object_index == 1 && d.drawn && d.light == "lights[0] (directional)";
  };
  EXPECT_EQ(count_if(diffuse, is_ball_caster), 1u);
  EXPECT_EQ(count_if(off, is_ball_caster), 0u);
}

TEST_F(ShadowsTest, AUsePassOfLegacyVertexLitsCasterCastsTheShadow) {
  const std::string lights = sun(R"(, "shadows": "hard")");
  std::string shader = ball_shader_falling_back_to("Off", "UsePass \"Legacy Shaders/VertexLit/SHADOWCASTER\"");
  RenderedFrame frame = render("usepass_caster", ball_scene(lights, "", "", shader));
  ASSERT_FALSE(frame.ldr.empty());
  EXPECT_LT(grey(frame, 32, 23) + 60, grey(frame, 32, 41));
}

TEST_F(ShadowsTest, ZeroStrengthDrawsTheSameImageAsNoShadows) {
  RenderedFrame plain = render("plain0", ball_scene(sun("")));
  RenderedFrame none = render("strength0", ball_scene(sun(R"(, "shadows": "hard", "shadow_strength": 0)")));
  ASSERT_EQ(plain.hdr.size(), none.hdr.size());
  float worst = 0;
  for (size_t i = 0; i < plain.hdr.size(); ++i) worst = std::max(worst, std::abs(plain.hdr[i] - none.hdr[i]));
  EXPECT_LT(worst, 1e-3f);
  EXPECT_EQ(none.stats.shadow_maps, 1u);
}

TEST_F(ShadowsTest, NoShadowedLightMeansNoShadowMapNoCasterDrawAndNoShadowVariant) {
  RenderedFrame f = render("no_shadows", ball_scene(sun("")));
  EXPECT_EQ(f.stats.shadow_maps, 0u);
  EXPECT_EQ(f.stats.shadow_draws, 0u);
  for (const std::string& c : f.compiled) EXPECT_EQ(c.find("SHADOW"), std::string::npos) << c;
  EXPECT_EQ(count_if(f, [](const DrawRecord& d) { return d.drawn && d.light_mode == "ShadowCaster"; }), 0u);
}

TEST_F(ShadowsTest, AShadowedLightRendersOneMapWithOneCasterDrawPerCaster) {
  std::string phong = R"(, {"name": "box", "mesh": "cube", "position": [1.5, 0.5, 0], "scale": 0.5,
                          "material": {"shader": ")" + example_shader("PhongMultiLight.shader") + "\"}}";
  RenderedFrame f = render("casters", ball_scene(sun(R"(, "shadows": "hard")"), phong));
  EXPECT_EQ(f.stats.shadow_maps, 1u);
  EXPECT_EQ(f.stats.shadow_draws, 2u);  // floor and ball: the Phong box's shader has no ShadowCaster pass
  EXPECT_EQ(count_if(f, [](const DrawRecord& d) {
              return d.drawn && d.light_mode == "ShadowCaster" && d.light == "lights[0] (directional)" &&
                     has_keyword(d, "SHADOWS_DEPTH");
            }),
            2u);
  // Skipped for the light's map and for the camera depth texture (the screen-space pass's input).
  EXPECT_EQ(count_if(f, [](const DrawRecord& d) {
              return !d.drawn && d.object == "objects[2] (box)" && d.why.find("no ShadowCaster pass") != std::string::npos;
            }),
            2u);
  EXPECT_EQ(count_if(f, [](const DrawRecord& d) {
              return d.drawn && d.light_mode == "ForwardBase" && has_keyword(d, "SHADOWS_SCREEN");
            }),
            3u);
  // Casters are submitted first: they fill the map the receivers sample.
  ASSERT_FALSE(f.draws.empty());
  EXPECT_EQ(f.draws[0].light_mode, "ShadowCaster");
}

// Unity's screen-space shadows: the directional light's receivers read one
// mask the size of the frame, made from the camera depth texture by one
// full-screen draw; the mask is what they would have looked up themselves
// (the shadow tests above pass through it).
TEST_F(ShadowsTest, ADirectionalLightsReceiversReadOneScreenSpaceMask) {
  RenderedFrame f = render("screen_mask", ball_scene(sun(R"(, "shadows": "soft")")));
  ASSERT_FALSE(f.ldr.empty());
  EXPECT_EQ(f.stats.screen_shadow_masks, 1u);
  EXPECT_EQ(f.stats.depth_texture_draws, 2u);  // floor and ball, from the camera
  EXPECT_EQ(count_if(f, [](const DrawRecord& d) {
              return d.drawn && d.shader == "Hidden/Internal-ScreenSpaceShadows" && d.light == "lights[0] (directional)";
            }),
            1u);
  EXPECT_EQ(count_if(f, [](const DrawRecord& d) {
              return d.drawn && d.light_mode == "ForwardBase" && has_keyword(d, "SHADOWS_SCREEN");
            }),
            2u);
  EXPECT_LT(grey(f, 32, 23) + 60, grey(f, 32, 41));
}

// As in Unity the mask holds the opaque objects only, so a transparent
// object gets no SHADOWS_SCREEN (and says why); a scene without directional
// shadows makes no mask and no camera depth texture.
TEST_F(ShadowsTest, ATransparentObjectReceivesNoDirectionalShadowAndNoShadowNoMask) {
  std::string glass = R"(, {"name": "glass", "mesh": "cube", "position": [0, 0.2, 1.2], "scale": 0.4,
                          "material": {"shader": ")" + example_shader("SurfaceAlpha.shader") + "\"}}";
  RenderedFrame f = render("transparent_receiver", ball_scene(sun(R"(, "shadows": "hard")"), glass));
  ASSERT_FALSE(f.ldr.empty());
  auto glass_base = std::find_if(f.draws.begin(), f.draws.end(), [](const DrawRecord& d) {
    return d.drawn && d.light_mode == "ForwardBase" && d.object == "objects[2] (glass)";
  });
  ASSERT_NE(glass_base, f.draws.end());
  EXPECT_FALSE(has_keyword(*glass_base, "SHADOWS_SCREEN"));
  EXPECT_NE(glass_base->why.find("no shadows: transparent"), std::string::npos) << glass_base->why;
  RenderedFrame plain = render("no_mask", ball_scene(sun("")));
  EXPECT_EQ(plain.stats.screen_shadow_masks, 0u);
  EXPECT_EQ(plain.stats.depth_texture_draws, 0u);
}

TEST_F(ShadowsTest, ASpotLightsShadowComesThroughItsForwardAddDraw) {
  std::string spot = R"([{"type": "spot", "position": [0, 3, -1.7], "look_at": [0, 0, 0.4], "range": 8,
                        "spot_angle": 70, "intensity": 3)";
  RenderedFrame plain = render("spot_plain", ball_scene(spot + "}]"));
  RenderedFrame shadowed = render("spot_shadowed", ball_scene(spot + R"(, "shadows": "hard"}])"));
  ASSERT_FALSE(shadowed.ldr.empty());
  EXPECT_EQ(shadowed.stats.shadow_maps, 1u);
  EXPECT_EQ(count_if(shadowed, [](const DrawRecord& d) { return d.additive && has_keyword(d, "SHADOWS_DEPTH"); }), 2u);
  // The spot stands at -Z and above: the ball's shadow falls towards +Z, at about z = 0.8 (pixel row 19).
  EXPECT_LT(grey(shadowed, 32, 19) + 40, grey(plain, 32, 19));
  EXPECT_LT(std::abs(grey(shadowed, 32, 45) - grey(plain, 32, 45)), 3);
}

// A point light at the origin, a ball 1.5 along `axis` and a wall 3 along it
// facing the light, seen from beside the light so that the wall's centre is
// the image's centre: the ball's shadow falls there, through the cube face
// of `axis`.
std::string point_light_wall(const std::array<int, 3>& axis, const std::string& rotation, const std::string& shadows) {
  std::string standard = example_shader("SurfaceStandard.shader");
  auto at = [&](float t) { return fmt::format("[{}, {}, {}]", axis[0] * t, axis[1] * t, axis[2] * t); };
  // Beside the light: 2.5 along an axis across `axis`, half a unit back.
  std::array<int, 3> across = axis[0] != 0 ? std::array<int, 3>{0, 0, 1} : std::array<int, 3>{1, 0, 0};
  std::string camera = fmt::format("[{}, {}, {}]", 2.5f * across[0] - 0.5f * axis[0], 2.5f * across[1] - 0.5f * axis[1],
                                   2.5f * across[2] - 0.5f * axis[2]);
  return R"({"width": 64, "height": 64, "ambient": [0.02, 0.02, 0.02],
    "camera": {"position": )" + camera + R"(, "look_at": )" + at(3) + R"(, "fov": 50, "clear_color": [0, 0, 0]},
    "lights": [{"type": "point", "position": [0, 0, 0], "range": 8, "intensity": 3)" + shadows + R"(}],
    "objects": [
      {"name": "wall", "mesh": "plane", "position": )" + at(3) + R"(, "rotation": )" + rotation +
         R"(, "scale": 0.4, "material": {"shader": ")" + standard +
         R"(", "properties": {"_Color": [0.8, 0.8, 0.8], "_Glossiness": 0}}},
      {"name": "ball", "mesh": "sphere", "position": )" + at(1.5f) + R"(, "scale": 0.6, "material": {"shader": ")" +
         standard + R"(", "properties": {"_Color": [0.8, 0.2, 0.2], "_Glossiness": 0}}}]})";
}

// The Done-when item: from every cube face. Each wall is turned so that its
// lit side (+Y of the plane) faces the light.
TEST_F(ShadowsTest, APointLightsShadowDarkensTheWallBehindABallThroughEveryCubeFace) {
  struct Face {
    const char* name;
    std::array<int, 3> axis;
    const char* rotation;
  };
  const Face faces[6] = {{"+X", {1, 0, 0}, "[0, 0, 90]"},  {"-X", {-1, 0, 0}, "[0, 0, -90]"},
                         {"+Y", {0, 1, 0}, "[180, 0, 0]"}, {"-Y", {0, -1, 0}, "[0, 0, 0]"},
                         {"+Z", {0, 0, 1}, "[-90, 0, 0]"}, {"-Z", {0, 0, -1}, "[90, 0, 0]"}};
  for (const Face& face : faces) {
    std::string name = std::string("point_face_") + (face.name[0] == '+' ? "pos" : "neg") + face.name[1];
    RenderedFrame plain = render(name + "_plain", point_light_wall(face.axis, face.rotation, ""));
    RenderedFrame shadowed = render(name, point_light_wall(face.axis, face.rotation, R"(, "shadows": "hard")"));
    ASSERT_FALSE(shadowed.ldr.empty()) << face.name;
    EXPECT_EQ(shadowed.stats.shadow_maps, 1u) << face.name << ": one cube";
    EXPECT_EQ(count_if(shadowed, [](const DrawRecord& d) { return d.additive && has_keyword(d, "SHADOWS_CUBE"); }), 2u)
        << face.name;
    // The wall is lit where the ball does not hide it...
    EXPECT_GT(grey(plain, 32, 32), 60) << face.name << ": the wall faces the light";
    // ... and dark behind the ball, through this face only.
    EXPECT_LT(grey(shadowed, 32, 32) + 40, grey(plain, 32, 32)) << face.name;
    int lit_same = 0, lit_total = 0;
    for (int y = 0; y < 64; y += 4) {
      for (int x = 0; x < 64; x += 4) {
        if (std::abs(x - 32) < 14 && std::abs(y - 32) < 14) continue;  // around the shadow
        if (grey(plain, x, y) < 30) continue;                            // not the lit wall
        ++lit_total;
        lit_same += std::abs(grey(shadowed, x, y) - grey(plain, x, y)) <= 2;
      }
    }
    EXPECT_GT(lit_total, 20) << face.name;
    EXPECT_EQ(lit_same, lit_total) << face.name << ": the rest of the wall stays lit (no acne, no stray shadow)";
  }
}

// A long floor under a steep sun, a small ball near the camera and a large
// one far away; `cascades` and `resolution` as the scene's shadow settings.
std::string cascade_scene(int cascades, int resolution, bool shadows = true) {
  std::string standard = example_shader("SurfaceStandard.shader");
  return fmt::format(R"({{"width": 192, "height": 128, "ambient": [0.05, 0.05, 0.05],
    "shadow_cascades": {}, "shadow_resolution": {}, "shadow_distance": 15,
    "camera": {{"position": [0, 1.2, -3], "look_at": [0, 0, 2], "clear_color": [0, 0, 0]}},
    "lights": [{{"type": "directional", "rotation": [55, -40, 0], "intensity": 1.5{}}}],
    "objects": [
      {{"name": "floor", "mesh": "plane", "scale": 4, "material": {{"shader": "{}",
        "properties": {{"_Color": [0.8, 0.8, 0.8], "_Glossiness": 0}}}}}},
      {{"name": "near ball", "mesh": "sphere", "position": [0, 0.3, -1], "scale": 0.3, "material": {{"shader": "{}",
        "properties": {{"_Color": [0.8, 0.2, 0.2], "_Glossiness": 0}}}}}},
      {{"name": "far ball", "mesh": "sphere", "position": [2.5, 1.2, 8], "scale": 2.4, "material": {{"shader": "{}",
        "properties": {{"_Color": [0.2, 0.2, 0.8], "_Glossiness": 0}}}}}}]}})",
                     cascades, resolution, shadows ? R"(, "shadows": "hard")" : "", standard, standard, standard);
}

// Pixels of the lower half (the floor near the camera) and of the upper
// half (far away) darker than without shadows.
std::pair<int, int> shadowed_pixels(const RenderedFrame& plain, const RenderedFrame& shadowed) {
  int near = 0, far = 0;
  for (int y = 0; y < plain.height; ++y)
    for (int x = 0; x < plain.width; ++x)
      if (grey(shadowed, x, y) + 30 < grey(plain, x, y)) (y >= 80 ? near : far) += 1;
  return {near, far};
}

// Unity's cascades: the view split at its default ratios, a map of each
// slice in one atlas, so a small ball near the camera casts a shadow that a
// single coarse map over the whole floor smears. Against a 4096-texel single
// map, the 512-texel atlas of 4 cascades (256 a cascade) gives the near
// shadow's area within 25 % (measured: 82 px against 86), 2 cascades closer
// than one map (74 and 52 px); the far ball's shadow is there in every case.
TEST_F(ShadowsTest, TwoAndFourCascadesResolveTheNearShadowThatOneCoarseMapSmears) {
  RenderedFrame plain = render("cascades_plain", cascade_scene(1, 512, false));
  RenderedFrame reference = render("cascades_reference", cascade_scene(1, 4096));
  ASSERT_FALSE(reference.ldr.empty());
  auto [ref_near, ref_far] = shadowed_pixels(plain, reference);
  ASSERT_GT(ref_near, 20) << "the near ball's shadow is on the floor";
  ASSERT_GT(ref_far, 20) << "the far ball's shadow is on the floor";
  std::map<int, std::pair<int, int>> measured;
  for (int cascades : {1, 2, 4}) {
    RenderedFrame f = render("cascades_" + std::to_string(cascades), cascade_scene(cascades, 512));
    ASSERT_FALSE(f.ldr.empty()) << cascades;
    EXPECT_EQ(f.stats.shadow_maps, 1u) << cascades << " cascades: one atlas";
    EXPECT_EQ(f.stats.shadow_draws, 3u * unsigned(cascades)) << "each cascade draws every caster";
    measured[cascades] = shadowed_pixels(plain, f);
    EXPECT_GT(measured[cascades].second, ref_far / 2) << cascades << " cascades: the far shadow";
    std::printf("[ cascades ] %d: near shadow %d px, far %d px (reference %d, %d)\n", cascades,
                measured[cascades].first, measured[cascades].second, ref_near, ref_far);
  }
  auto near_error = [&](int cascades) { return std::abs(measured[cascades].first - ref_near) / double(ref_near); };
  EXPECT_LT(near_error(4), 0.25);
  EXPECT_LT(near_error(2), near_error(1));
  EXPECT_LT(near_error(4), near_error(1));
  EXPECT_GT(near_error(1), 0.25) << "the single coarse map smears the near shadow (else the scene tests nothing)";
}

TEST_F(ShadowsTest, ThreeCascadesAreRefusedWithTheJsonPath) {
  auto scene = parse_scene(cascade_scene(3, 512), "s.json");
  ASSERT_FALSE(scene);
  EXPECT_NE(scene.error().message.find("shadow_cascades: expected 1, 2 or 4"), std::string::npos) << scene.error().message;
}

// Along the column x = 32, count the pixels between shadow and light.
int penumbra(const RenderedFrame& f) {
  int dark = grey(f, 32, 23), lit = grey(f, 32, 45), n = 0;
  for (int y = 0; y < 64; ++y) {
    int g = grey(f, 32, y);
    n += g > dark + 12 && g < lit - 12;
  }
  return n;
}

TEST_F(ShadowsTest, SoftShadowsHaveAWiderPenumbraThanHardOnes) {
  std::string coarse = R"("shadow_resolution": 64, )";
  RenderedFrame hard = render("hard", ball_scene(sun(R"(, "shadows": "hard")"), "", coarse));
  RenderedFrame soft = render("soft", ball_scene(sun(R"(, "shadows": "soft")"), "", coarse));
  ASSERT_FALSE(soft.ldr.empty());
  EXPECT_GT(penumbra(soft), penumbra(hard) + 2);
  // Soft is filtering, not another variant.
  EXPECT_EQ(soft.compiled, hard.compiled);
}

TEST_F(ShadowsTest, LaterFramesWithShadowsDrawTheSameImage) {
  std::string json = ball_scene(sun(R"(, "shadows": "soft")"));
  RenderedFrame one = render("frames1", json);
  RenderedFrame three = render("frames3", json, {.frames = 3});
  EXPECT_EQ(one.hdr, three.hdr);
}

// A lit floor that only shadows itself: a shadowed light must draw exactly
// the image of an unshadowed one (no acne), at a steep and at grazing angles.
TEST_F(ShadowsTest, TheDefaultBiasesLeaveNoAcneOnALitPlane) {
  std::string standard = example_shader("SurfaceStandard.shader");
  auto floor_scene = [&](float elevation, const std::string& shadows) {
    return R"({"width": 96, "height": 64, "ambient": [0.05, 0.05, 0.05],
             "camera": {"position": [0, 2.5, -3.5], "look_at": [0, 0, 0], "clear_color": [0, 0, 0]},
             "lights": [{"type": "directional", "rotation": [)" +
           std::to_string(elevation) + R"(, 30, 0], "intensity": 1.5)" + shadows + R"(}],
             "objects": [{"name": "floor", "mesh": "plane", "scale": 0.5, "material": {"shader": ")" + standard +
           R"(", "properties": {"_Color": [0.8, 0.8, 0.8], "_Glossiness": 0}}}]})";
  };
  for (float elevation : {70.0f, 35.0f, 15.0f}) {
    for (const char* mode : {"hard", "soft"}) {
      std::string name = "acne_" + std::to_string(int(elevation)) + "_" + mode;
      RenderedFrame plain = render(name + "_plain", floor_scene(elevation, ""));
      RenderedFrame shadowed =
          render(name, floor_scene(elevation, std::string(R"(, "shadows": ")") + mode + "\""));
      ASSERT_EQ(plain.ldr.size(), shadowed.ldr.size());
      ASSERT_EQ(shadowed.stats.shadow_maps, 1u) << name;
      ASSERT_EQ(shadowed.stats.shadow_draws, 1u) << name << ": the floor casts into the map";
      size_t floor_pixels = 0, acne = 0;
      for (int y = 0; y < plain.height; ++y) {
        for (int x = 0; x < plain.width; ++x) {
          if (grey(plain, x, y) < 8) continue;  // not the floor
          ++floor_pixels;
          acne += grey(shadowed, x, y) + 2 < grey(plain, x, y);
        }
      }
      EXPECT_GT(floor_pixels, 1000u) << name;
      EXPECT_EQ(acne, 0u) << name << ": " << acne << " of " << floor_pixels << " floor pixels darkened";
    }
  }
}

TEST_F(ShadowsTest, AFrameCaptureRefusesShadowMaps) {
  FrameCapture capture;
  auto f = try_render("capture", ball_scene(sun(R"(, "shadows": "hard")")), {.capture = &capture});
  ASSERT_FALSE(f);
  EXPECT_NE(f.error().message.find("shadow maps"), std::string::npos);
}

TEST(ShadowScene, BadShadowSettingsNameTheirJsonPath) {
  struct Case {
    std::string light_extra, settings, expected;
  };
  const std::vector<Case> cases = {
      {R"(, "shadows": "maybe")", "", "lights[0].shadows: unknown value 'maybe' (expected one of: none, hard, soft)"},
      {R"(, "shadows": true)", "", "lights[0].shadows: expected a string"},
      {R"(, "shadow_strength": 1.5)", "", "lights[0].shadow_strength: expected a number from 0 to 1"},
      {R"(, "shadow_bias": -1)", "", "lights[0].shadow_bias: expected a number from 0 to 10"},
      {"", R"("shadow_resolution": 8, )", "shadow_resolution: expected an integer from 16 to 8192"},
      {"", R"("shadow_distance": 0, )", "shadow_distance: expected a number above 0"},
  };
  for (const Case& c : cases) {
    std::string json = ball_scene(sun(c.light_extra), "", c.settings);
    auto scene = parse_scene(json, "bad.json");
    ASSERT_FALSE(scene) << c.expected;
    EXPECT_NE(scene.error().message.find(c.expected), std::string::npos) << scene.error().message;
  }
}

}  // namespace
}  // namespace facet::runtime
