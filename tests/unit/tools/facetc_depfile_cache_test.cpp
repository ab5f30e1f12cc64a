// A depfile written by a warm build (programs served by the compile cache,
// preprocessing skipped) names the same files as the cold build's: a build
// system must still see the includes to rebuild when one changes.
#include "facetc_test_util.h"

namespace facet::tools::testing {
namespace {

using ::testing::HasSubstr;

constexpr const char* kShader = R"(Shader "T" { SubShader { Pass {
CGPROGRAM
#pragma vertex vert
#pragma fragment frag
#include "tint.hlsl"
float4 vert(float4 v : POSITION) : SV_Position { return UnityObjectToClipPos(v); }
float4 frag() : SV_Target { return Tint(); }
ENDCG
} } }
)";

// The rule's prerequisites, without its target line.
std::string prerequisites(const std::string& rule) { return rule.substr(rule.find('\n') + 1); }

TEST_F(FacetcTest, AWarmCacheBuildWritesTheSameDepfileAsTheColdOne) {
  write_all(dir_ / "s.shader", kShader);
  write_all(dir_ / "tint.hlsl", "float4 Tint() { return float4(1, 0, 0, 1); }\n");
  FacetcRun cold = facetc({"s.shader", "-o", "a.facetpkg", "-MD", "-MF", "a.d", "--cache-dir", "cache"});
  ASSERT_EQ(cold.exit_code, 0) << cold.err;
  FacetcRun warm = facetc({"s.shader", "-o", "b.facetpkg", "-MD", "-MF", "b.d", "--cache-dir", "cache", "--stats"});
  ASSERT_EQ(warm.exit_code, 0) << warm.err;
  std::string cold_rule = read_all(dir_ / "a.d"), warm_rule = read_all(dir_ / "b.d");
  EXPECT_THAT(cold_rule, HasSubstr("tint.hlsl"));
  EXPECT_EQ(prerequisites(warm_rule), prerequisites(cold_rule));
  // -M on the warm cache lists the include too.
  FacetcRun rule = facetc({"s.shader", "-M", "--cache-dir", "cache"});
  ASSERT_EQ(rule.exit_code, 0) << rule.err;
  EXPECT_THAT(rule.out, HasSubstr("tint.hlsl"));
}

}  // namespace
}  // namespace facet::tools::testing
