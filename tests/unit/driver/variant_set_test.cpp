// Compiler::select_variants hands the variant stage's VariantSet on: the
// pass's keyword space, the surviving keys in ascending order, and how many
// the strip rules and the filter callback removed.
#include <gtest/gtest.h>

#include <algorithm>

#include "facet/compiler.h"

namespace facet {
namespace {

constexpr const char* kShader = R"(Shader "Test/VariantSet" { SubShader { Pass {
CGPROGRAM
#pragma vertex vert
#pragma fragment frag
#pragma multi_compile _ FOG_A FOG_B
#pragma shader_feature _ DETAIL
float4 vert(float4 v : POSITION) : SV_Position { return v; }
float4 frag() : SV_Target { return 1; }
ENDCG
} } }
)";

struct Loaded {
  Compiler compiler;
  SourceMap sources;
  Diagnostics diags;
  std::vector<SelectedPass> passes;
  ir::Shader shader;
};

void load(Loaded& l) {
  auto shader = l.compiler.load_source("variant_set.shader", kShader, l.sources, l.diags);
  ASSERT_TRUE(shader) << render_text(l.diags, l.sources);
  l.shader = std::move(*shader);
  auto passes = l.compiler.select_passes(l.shader, {}, l.diags);
  ASSERT_TRUE(passes);
  l.passes = std::move(*passes);
  ASSERT_EQ(l.passes.size(), 1u);
}

TEST(VariantSetTest, EveryVariantInAscendingOrderWithTheSpaceAndNothingStripped) {
  Loaded l;
  load(l);
  auto set = l.compiler.select_variants(l.passes[0], {}, l.diags);
  ASSERT_TRUE(set) << render_text(l.diags, l.sources);
  EXPECT_EQ(set->keys.size(), 6u);  // 3 x 2
  EXPECT_TRUE(std::is_sorted(set->keys.begin(), set->keys.end()));
  EXPECT_EQ(set->space.sets.size(), 2u);
  EXPECT_EQ(set->stripped, 0u);
  EXPECT_EQ(set->keywords(set->keys.back()), (std::vector<std::string>{"FOG_B", "DETAIL"}));
}

TEST(VariantSetTest, StrippedCountsWhatTheRulesAndTheCallbackRemoved) {
  Loaded l;
  load(l);
  CompileOptions options;
  options.strip.rules.push_back({.kind = variants::StripKind::deny, .keywords = {"FOG_A"}});
  options.variant_filter = [](const VariantInfo& v) {
    return std::find(v.keywords.begin(), v.keywords.end(), "DETAIL") == v.keywords.end() ||
           std::find(v.keywords.begin(), v.keywords.end(), "FOG_B") == v.keywords.end();
  };
  auto set = l.compiler.select_variants(l.passes[0], options, l.diags);
  ASSERT_TRUE(set) << render_text(l.diags, l.sources);
  EXPECT_EQ(set->keys.size(), 3u);  // {}, {DETAIL}, {FOG_B}
  EXPECT_EQ(set->stripped, 3u);     // FOG_A twice, FOG_B + DETAIL once
  for (const variants::VariantKey& key : set->keys) {
    std::vector<std::string> keywords = set->keywords(key);
    EXPECT_EQ(std::count(keywords.begin(), keywords.end(), "FOG_A"), 0);
  }
}

TEST(VariantSetTest, ADrawTimePickIsOneKeyAndStripsNothing) {
  Loaded l;
  load(l);
  CompileOptions options;
  options.keywords = std::vector<std::string>{"FOG_B"};
  options.strip.rules.push_back({.kind = variants::StripKind::deny, .keywords = {"FOG_A"}});
  auto set = l.compiler.select_variants(l.passes[0], options, l.diags);
  ASSERT_TRUE(set) << render_text(l.diags, l.sources);
  ASSERT_EQ(set->keys.size(), 1u);
  EXPECT_EQ(set->keywords(set->keys[0]), (std::vector<std::string>{"FOG_B"}));
  EXPECT_EQ(set->stripped, 0u);
}

}  // namespace
}  // namespace facet
