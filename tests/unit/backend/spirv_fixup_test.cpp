// The semantic -> location table and the material-set binding rule.
#include "spirv_fixup.h"

#include <gtest/gtest.h>

namespace facet::backend {
namespace {

TEST(SpirvFixupLocationTest, VertexInputsHaveUnityChannelSlots) {
  auto at = [](const char* s) { return semantic_location(s, Stage::vertex, true); };
  EXPECT_EQ(at("POSITION"), 0u);
  EXPECT_EQ(at("SV_Position"), 0u);
  EXPECT_EQ(at("NORMAL"), 1u);
  EXPECT_EQ(at("TANGENT"), 2u);
  EXPECT_EQ(at("COLOR"), 3u);
  EXPECT_EQ(at("COLOR0"), 3u);
  EXPECT_EQ(at("TEXCOORD"), 4u);
  EXPECT_EQ(at("TEXCOORD0"), 4u);
  EXPECT_EQ(at("texcoord7"), 11u);
  EXPECT_EQ(at("BLENDWEIGHTS"), 12u);
  EXPECT_EQ(at("BLENDINDICES"), 13u);
  EXPECT_EQ(at("COLOR1"), 14u);
  EXPECT_EQ(at("TEXCOORD8"), std::nullopt);
  EXPECT_EQ(at("MYDATA"), std::nullopt);
}

TEST(SpirvFixupLocationTest, VaryingsMatchBetweenStages) {
  for (const char* s : {"TEXCOORD0", "TEXCOORD9", "TEXCOORD15", "COLOR", "COLOR1", "NORMAL", "TANGENT", "FOG"}) {
    auto out = semantic_location(s, Stage::vertex, false);
    ASSERT_TRUE(out) << s;
    EXPECT_EQ(out, semantic_location(s, Stage::fragment, true)) << s;
  }
  EXPECT_EQ(semantic_location("TEXCOORD9", Stage::fragment, true), 9u);
  EXPECT_EQ(semantic_location("COLOR", Stage::fragment, true), 16u);
  EXPECT_EQ(semantic_location("TEXCOORD16", Stage::fragment, true), std::nullopt);
}

TEST(SpirvFixupLocationTest, FragmentOutputsAreRenderTargets) {
  EXPECT_EQ(semantic_location("SV_Target", Stage::fragment, false), 0u);
  EXPECT_EQ(semantic_location("SV_TARGET3", Stage::fragment, false), 3u);
  EXPECT_EQ(semantic_location("COLOR1", Stage::fragment, false), 1u);
}

DeclaredResource resource(std::string key, bool block = false) {
  DeclaredResource r;
  r.key = std::move(key);
  r.block = block;
  return r;
}

TEST(SpirvFixupBindingTest, GlobalsFirstThenDeclarationOrder) {
  DeclaredResource builtin = resource("FacetPerFrame", true);
  builtin.has_set = builtin.has_binding = true;
  auto table = material_bindings({resource("_MainTex"), builtin, resource("$Global", true), resource("_Bump")});
  EXPECT_EQ(table, (std::vector<std::pair<std::string, uint32_t>>{{"$Global", 0}, {"_MainTex", 1}, {"_Bump", 2}}));
}

TEST(SpirvFixupBindingTest, ExplicitBindingsAreKeptAndSkipped) {
  DeclaredResource fixed = resource("_Fixed");
  fixed.has_binding = true;
  fixed.binding = 1;
  DeclaredResource other_set = resource("_Other");
  other_set.has_set = other_set.has_binding = true;
  other_set.set = 0;
  other_set.binding = 5;
  auto table = material_bindings({resource("_A"), fixed, other_set, resource("$Global", true), resource("_B")});
  EXPECT_EQ(table,
            (std::vector<std::pair<std::string, uint32_t>>{{"$Global", 0}, {"_A", 2}, {"_Fixed", 1}, {"_B", 3}}));
}

TEST(SpirvFixupBindingTest, NoGlobalsStartsAtZero) {
  auto table = material_bindings({resource("_MainTex"), resource("MyBuffer", true)});
  EXPECT_EQ(table, (std::vector<std::pair<std::string, uint32_t>>{{"_MainTex", 0}, {"MyBuffer", 1}}));
}

}  // namespace
}  // namespace facet::backend
