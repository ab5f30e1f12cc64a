// Pipeline stages and state on lavapipe with validation on: geometry and
// tessellation stages draw, `ZClip False` clamps depth instead of clipping
// at the far plane, and Stencil blocks mask one object by another.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "render_test_support.h"

namespace facet::runtime {
namespace {

using test_support::example_shader;

using StagesTest = test_support::RenderTest;

// Pixels brighter than the black clear colour.
size_t covered(const RenderedFrame& f) {
  size_t n = 0;
  for (size_t p = 0; p < size_t(f.width) * f.height; ++p) {
    n += f.ldr[p * 4] + f.ldr[p * 4 + 1] + f.ldr[p * 4 + 2] > 24;
  }
  return n;
}

std::string one_object(const std::string& shader, const std::string& properties, const std::string& camera_extra = "") {
  return R"({"width": 64, "height": 64, "ambient": [0.3, 0.3, 0.3],
    "camera": {"position": [0, 0, -3], "look_at": [0, 0, 0], "fov": 40, "clear_color": [0, 0, 0])" + camera_extra + R"(},
    "lights": [{"type": "directional", "rotation": [30, 20, 0], "intensity": 1}],
    "objects": [{"mesh": "sphere", "material": {"shader": ")" + shader + R"(", "properties": )" + properties + "}}]}";
}

const DrawRecord* first_drawn(const RenderedFrame& f) {
  for (const DrawRecord& d : f.draws) {
    if (d.drawn) return &d;
  }
  return nullptr;
}

TEST_F(StagesTest, AGeometryStageDrawsWhatItEmits) {
  const std::string shader = example_shader("GeometryExtrude.shader");
  RenderedFrame flat = render("geometry_flat", one_object(shader, R"({"_Extrude": 0})"));
  RenderedFrame extruded = render("geometry_extruded", one_object(shader, R"({"_Extrude": 0.4})"));
  ASSERT_FALSE(extruded.ldr.empty());
  ASSERT_NE(first_drawn(extruded), nullptr);
  EXPECT_GT(covered(flat), 400u);
  // Tiles pushed out 0.4 along their normals widen the silhouette.
  EXPECT_GT(covered(extruded), covered(flat) + 150);
}

TEST_F(StagesTest, HullAndDomainStagesTessellateAndDisplace) {
  const std::string shader = example_shader("SurfaceTessellation.shader");
  RenderedFrame still = render("tessellated_flat", one_object(shader, R"({"_Displacement": 0})"));
  RenderedFrame displaced = render("tessellated_displaced", one_object(shader, R"({"_Displacement": 0.4, "_HeightTex": "white"})"));
  ASSERT_FALSE(displaced.ldr.empty());
  EXPECT_GT(covered(still), 400u);
  EXPECT_GT(covered(displaced), covered(still) + 100);
}

TEST_F(StagesTest, ZClipFalseClampsDepthInsteadOfClippingAtTheFarPlane) {
  std::ifstream in(example_shader("Unlit.shader"));
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::filesystem::path path = test_support::test_dir() / "UnlitNoZClip.shader";
  std::string clamped = text;
  clamped.replace(clamped.find("Pass {"), 6, "Pass {\n            ZClip False");
  std::ofstream(path) << clamped;
  // The sphere (radius 0.5, centre 3 away) reaches from depth 2.5 to 2.92 at
  // its outline: a far plane at 2.6 keeps only the disk within 0.3 of its
  // centre, about a third of it.
  const std::string far = R"(, "far": 2.6)";
  RenderedFrame clipped = render("zclip_on", one_object(example_shader("Unlit.shader"), "{}", far));
  RenderedFrame kept = render("zclip_off", one_object(path.string(), "{}", far));
  ASSERT_FALSE(kept.ldr.empty());
  RenderedFrame whole = render("zclip_whole", one_object(example_shader("Unlit.shader"), "{}"));
  EXPECT_LT(covered(clipped) * 2, covered(whole));
  EXPECT_EQ(covered(kept), covered(whole));
}

// Examples/Unlit with `block` added to its Pass, written as `name`.
std::string unlit_with(const std::string& name, const std::string& block) {
  std::ifstream in(example_shader("Unlit.shader"));
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  text.replace(text.find("Pass {"), 6, "Pass {\n            " + block);
  std::filesystem::path path = test_support::test_dir() / name;
  std::ofstream(path) << text;
  return path.string();
}

TEST_F(StagesTest, AStencilMaskDrawsTheSecondObjectOnlyWhereTheFirstWroteTheReference) {
  // A sphere in front writes stencil 1 and no colour; a large quad
  // behind it (drawn later: queue 2001) passes only where the stencil is 1.
  const std::string mask = unlit_with("StencilMask.shader",
                                      "ColorMask 0 ZWrite Off Stencil { Ref 1 Comp Always Pass Replace }");
  const std::string masked = unlit_with("StencilMasked.shader", "Stencil { Ref 1 Comp Equal }");
  auto scene = [&](const std::string& quad_shader, const std::string& camera = "", const std::string& more = "") {
    return R"({"width": 64, "height": 64,
      "camera": {"position": [0, 0, -3], "look_at": [0, 0, 0], "fov": 40, "clear_color": [0, 0, 0])" + camera + R"(},
      "lights": [], "objects": [
        {"mesh": "sphere", "material": {"shader": ")" + mask + R"("}},
        {"mesh": "quad", "position": [0, 0, 1], "scale": 4,
         "material": {"shader": ")" + quad_shader + R"(", "queue": 2001}})" + more + "]}";
  };
  RenderedFrame plain = render("stencil_plain", scene(example_shader("Unlit.shader")));
  RenderedFrame stenciled = render("stencil_masked", scene(masked));
  ASSERT_FALSE(stenciled.ldr.empty());
  EXPECT_EQ(covered(plain), 64u * 64u);  // the quad fills the view
  EXPECT_GT(covered(stenciled), 300u);  // the sphere's disk, about 430 pixels
  EXPECT_LT(covered(stenciled), 64u * 64u / 4);
  // A deferred frame samples its depth (D32S8 through a depth-only view):
  // its stencil still masks the forward part.
  const std::string standard = std::string(FACET_SOURCE_DIR) + "/stdlib/Shaders/Standard.shader";
  RenderedFrame deferred = render("stencil_deferred",
                                  scene(masked, R"(, "rendering_path": "deferred")",
                                        R"(, {"mesh": "cube", "position": [5, 5, 5], "material": {"shader": ")" +
                                            standard + R"("}})"));
  ASSERT_FALSE(deferred.ldr.empty());
  EXPECT_EQ(deferred.stats.gbuffer_draws, 1u);
  EXPECT_EQ(covered(deferred), covered(stenciled));
}

}  // namespace
}  // namespace facet::runtime
