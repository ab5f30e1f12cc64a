// The renderer's pure parts: uniform blocks laid out from reflection, render
// state resolved against materials, built-in meshes.
#include <gtest/gtest.h>
#include <fmt/format.h>

#include <cstring>
#include <glm/glm.hpp>

#include "facet/runtime/material.h"
#include "facet/runtime/mesh.h"
#include "facet/runtime/render_state.h"
#include "facet/runtime/uniforms.h"

namespace facet::runtime {
namespace {

float read_float(const std::vector<std::byte>& bytes, size_t offset) {
  float f;
  std::memcpy(&f, bytes.data() + offset, 4);
  return f;
}

TEST(Uniforms, ColumnMajorMatrixIsWrittenColumnByColumnAtTheMatrixStride) {
  BlockMember m{.name = "M", .type = "float4x4", .offset = 16, .size = 64, .matrix_stride = 16};
  UniformBlock block{.name = "b", .size = 80, .members = {m}};
  UniformValues values;
  float data[16];
  for (int i = 0; i < 16; ++i) data[i] = float(i);  // glm: column c, row r at 4c + r
  values.set_matrix("M", data);
  std::vector<std::byte> bytes(80);
  EXPECT_TRUE(fill_block(bytes, block, {&values}).empty());
  EXPECT_EQ(read_float(bytes, 16 + 1 * 16 + 2 * 4), 6.0f);  // column 1, row 2
  EXPECT_EQ(read_float(bytes, 0), 0.0f);
}

TEST(Uniforms, RowMajorMatrixIsTransposedInMemory) {
  BlockMember m{.name = "M", .type = "float4x4", .offset = 0, .size = 64, .matrix_stride = 16, .row_major = true};
  UniformValues values;
  float data[16];
  for (int i = 0; i < 16; ++i) data[i] = float(i);
  values.set_matrix("M", data);
  std::vector<std::byte> bytes(64);
  write_member(bytes, m, *values.find("M"));
  EXPECT_EQ(read_float(bytes, 2 * 16 + 1 * 4), 6.0f);  // row 2, column 1 = glm[1][2]
}

TEST(Uniforms, VectorsArraysAndMissingMembers) {
  BlockMember color{.name = "_Color", .type = "float3", .offset = 0, .size = 12};
  BlockMember scalar{.name = "_Gloss", .type = "float", .offset = 12, .size = 4};
  BlockMember array{.name = "arr", .type = "float4", .offset = 16, .size = 32, .array_dims = {2}, .array_stride = 16};
  BlockMember missing{.name = "_Other", .type = "float4", .offset = 48, .size = 16};
  UniformBlock block{.name = "$Globals", .size = 64, .members = {color, scalar, array, missing}};
  UniformValues values;
  values.set_vector("_Color", 0.1f, 0.2f, 0.3f, 0.9f);
  values.set_vector("_Gloss", 0.5f);
  values.set_elements("arr", {1, 2, 3, 4, 5, 6, 7, 8});
  std::vector<std::byte> bytes(64, std::byte{0xff});
  std::vector<std::string> unfilled = fill_block(bytes, block, {nullptr, &values});
  EXPECT_EQ(unfilled, (std::vector<std::string>{"_Other"}));
  EXPECT_EQ(read_float(bytes, 8), 0.3f);
  EXPECT_EQ(read_float(bytes, 12), 0.5f);  // float3's alpha did not spill into _Gloss
  EXPECT_EQ(read_float(bytes, 32), 5.0f);
  EXPECT_EQ(read_float(bytes, 48), 0.0f);  // unfilled members are zero
}

TEST(Uniforms, EarlierLayersWin) {
  BlockMember m{.name = "_LightColor0", .type = "float4", .offset = 0, .size = 16};
  UniformBlock block{.name = "$Globals", .size = 16, .members = {m}};
  UniformValues light, frame;
  light.set_vector("_LightColor0", 1, 2, 3, 4);
  frame.set_vector("_LightColor0", 9, 9, 9, 9);
  std::vector<std::byte> bytes(16);
  fill_block(bytes, block, {&light, &frame});
  EXPECT_EQ(read_float(bytes, 0), 1.0f);
}

ir::StateValue literal(const char* text) { return {text, "", {}}; }
ir::StateValue property(const char* name) { return {"", name, {}}; }

TEST(RenderState, DefaultsAreUnitysDefaults) {
  Diagnostics diags;
  auto s = resolve_state({}, Material{}, diags);
  ASSERT_TRUE(s);
  EXPECT_EQ(s->cull, VkCullModeFlags(VK_CULL_MODE_BACK_BIT));
  EXPECT_EQ(s->ztest, VK_COMPARE_OP_LESS_OR_EQUAL);
  EXPECT_TRUE(s->zwrite);
  EXPECT_FALSE(s->blend);
}

TEST(RenderState, LiteralsAndPropertiesResolve) {
  ir::RenderState state;
  state.cull = property("_Cull");
  state.zwrite = literal("Off");
  state.blend.push_back({.src = literal("SrcAlpha"), .dst = property("_DstBlend")});
  state.color_mask.push_back({.mask = literal("RGB")});
  Material m;
  m.numbers["_Cull"] = {0, 0, 0, 0};       // CullMode.Off
  m.numbers["_DstBlend"] = {10, 0, 0, 0};  // BlendMode.OneMinusSrcAlpha
  Diagnostics diags;
  auto s = resolve_state(state, m, diags);
  ASSERT_TRUE(s) << render_text(diags, {});
  EXPECT_EQ(s->cull, VkCullModeFlags(VK_CULL_MODE_NONE));
  EXPECT_FALSE(s->zwrite);
  EXPECT_TRUE(s->blend);
  EXPECT_EQ(s->src, VK_BLEND_FACTOR_SRC_ALPHA);
  EXPECT_EQ(s->dst, VK_BLEND_FACTOR_ONE_MINUS_SRC_ALPHA);
  EXPECT_EQ(s->color_mask, VkColorComponentFlags(VK_COLOR_COMPONENT_R_BIT | VK_COLOR_COMPONENT_G_BIT | VK_COLOR_COMPONENT_B_BIT));
}

TEST(RenderState, MissingPropertyIsAnErrorNamingIt) {
  ir::RenderState state;
  state.ztest = property("_ZTest");
  Diagnostics diags;
  auto s = resolve_state(state, Material{}, diags);
  ASSERT_FALSE(s);
  ASSERT_EQ(diags.size(), 1u);
  EXPECT_EQ(diags.all()[0].id, DiagId::render_state_property);
  EXPECT_EQ(diags.all()[0].message, "ZTest: the material has no number property '_ZTest'");
}

// 2^31 wrapped to INT_MIN (then overflowed subtracting the first index),
// and 1e30 converted to 0, i.e. ZTest Disabled, without a word.
TEST(RenderState, ANumberPastIntIsOutOfRangeNotWrapped) {
  for (float value : {2147483648.0f, -2147483649.0f, 1e30f, -1e30f, 3.4e38f}) {
    for (bool ztest : {true, false}) {
      ir::RenderState state;
      if (ztest) {
        state.ztest = property("_Value");
      } else {
        state.cull = property("_Value");
      }
      Material m;
      m.numbers["_Value"] = {value, 0, 0, 0};
      Diagnostics diags;
      auto s = resolve_state(state, m, diags);
      ASSERT_FALSE(s) << value;
      ASSERT_EQ(diags.size(), 1u);
      EXPECT_EQ(diags.all()[0].id, DiagId::render_state_property);
      EXPECT_EQ(diags.all()[0].message,
                fmt::format("{}: property '_Value' = {} is out of range", ztest ? "ZTest" : "Cull", value));
    }
  }
}

TEST(Meshes, BuiltinsFaceOutwardWithUnitNormalsAndOrthogonalTangents) {
  for (const std::string& name : builtin_mesh_names()) {
    std::optional<MeshData> mesh = builtin_mesh(name);
    ASSERT_TRUE(mesh) << name;
    ASSERT_FALSE(mesh->indices.empty()) << name;
    for (size_t t = 0; t + 2 < mesh->indices.size(); t += 3) {
      const Vertex& a = mesh->vertices[mesh->indices[t]];
      const Vertex& b = mesh->vertices[mesh->indices[t + 1]];
      const Vertex& c = mesh->vertices[mesh->indices[t + 2]];
      glm::vec3 pa(a.position[0], a.position[1], a.position[2]), pb(b.position[0], b.position[1], b.position[2]),
          pc(c.position[0], c.position[1], c.position[2]);
      glm::vec3 n(a.normal[0], a.normal[1], a.normal[2]);
      ASSERT_GT(glm::dot(glm::cross(pb - pa, pc - pa), n), 0) << name << " triangle " << t / 3;
    }
    for (const Vertex& v : mesh->vertices) {
      glm::vec3 n(v.normal[0], v.normal[1], v.normal[2]), tg(v.tangent[0], v.tangent[1], v.tangent[2]);
      ASSERT_NEAR(glm::length(n), 1, 1e-4) << name;
      ASSERT_NEAR(glm::dot(n, tg), 0, 1e-4) << name;
      ASSERT_TRUE(v.tangent[3] == 1 || v.tangent[3] == -1) << name;
    }
  }
  EXPECT_FALSE(builtin_mesh("teapot"));
}

TEST(Meshes, UnitySizes) {
  EXPECT_NEAR(mesh_bounds(*builtin_mesh("sphere")).radius, 0.5, 1e-4);
  EXPECT_NEAR(mesh_bounds(*builtin_mesh("plane")).radius, std::sqrt(50.0), 1e-3);
  EXPECT_NEAR(mesh_bounds(*builtin_mesh("cube")).radius, std::sqrt(0.75), 1e-4);
}

TEST(Colour, SrgbRoundTrip) {
  EXPECT_NEAR(srgb_to_linear(0.5), 0.214041, 1e-6);
  EXPECT_NEAR(linear_to_srgb(srgb_to_linear(0.3)), 0.3, 1e-12);
}

}  // namespace
}  // namespace facet::runtime
