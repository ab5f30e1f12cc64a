// facetc --strip and --materials on package builds.
#include <nlohmann/json.hpp>

#include "facetc_test_util.h"

namespace facet::tools::testing {
namespace {

using ::testing::HasSubstr;

size_t variants_in(const std::string& package_json) {
  return nlohmann::json::parse(package_json)["passes"][0]["variants"].size();
}

TEST_F(FacetcTest, StripFilterAndMaterialsShrinkThePackage) {
  // Keywords.shader: 48 variants = fog 4 x debug 2 x _EMISSION 2 x overlay 3.
  write_all(dir_ / "strip.json", R"({"strip": [
    {"always_off": ["FACET_DEBUG_NORMALS"]},
    {"deny": ["FOG_EXP", "_EMISSION"]},
    {"allow": ["FOG_EXP", "_EMISSION", "_OVERLAY_ADD"]}
  ]})");
  FacetcRun run = facetc({example("Keywords.shader"), "--strip", "strip.json", "--stats", "-o", "s.facetpkg"});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  // 24 without debug normals, minus FOG_EXP+_EMISSION (3 overlays) but one allowed back.
  EXPECT_EQ(variants_in(facetc({"--dump", "s.facetpkg"}).out), 22u);
  EXPECT_THAT(run.err, HasSubstr("22 variants (26 stripped)"));

  write_all(dir_ / "materials.json", R"({"materials": [
    {"shader": "Examples/Keywords", "keywords": ["_EMISSION"]},
    {"shader": "Examples/Keywords", "properties": {"_Overlay": 1}}
  ]})");
  FacetcRun m = facetc({example("Keywords.shader"), "--materials", "materials.json", "-o", "m.facetpkg"});
  ASSERT_EQ(m.exit_code, 0) << m.err;
  // shader_feature combinations used: {_EMISSION, NONE} and {off, ADD}: 2 x fog 4 x debug 2.
  EXPECT_EQ(variants_in(facetc({"--dump", "m.facetpkg"}).out), 16u);
}

TEST_F(FacetcTest, BadStripFiltersAreLocatedErrors) {
  const std::vector<std::pair<std::string, std::string>> bad = {
      {"{\"strip\": [}", "strip.json:1:12: error: invalid JSON"},
      {"{\"rules\": []}", "$: expected an object with a 'strip' array"},
      {"{\"strip\": [{\"deny\": \"A\"}]}", "strip[0].deny: expected a non-empty array"},
      {"{\"strip\": [{\"deny\": [\"A\"], \"allow\": [\"B\"]}]}", "a rule has one kind"},
      {"{\"strip\": [{\"drop\": [\"A\"]}]}", "strip[0].drop: unknown key"},
      {"{\"strip\": [{\"pass\": \"X\"}]}", "a rule needs one of"},
      {"{\"strip\": [{\"deny\": [\"A\"], \"pass\": true}]}", "expected a pass name or index"},
  };
  for (const auto& [text, message] : bad) {
    write_all(dir_ / "strip.json", text);
    FacetcRun run = facetc({example("Unlit.shader"), "--strip", "strip.json", "-o", "x.facetpkg"});
    EXPECT_EQ(run.exit_code, 1) << text;
    EXPECT_THAT(run.err, HasSubstr(message)) << text;
    EXPECT_FALSE(fs::exists(dir_ / "x.facetpkg")) << text;
  }
  FacetcRun misuse = facetc({example("Unlit.shader"), "-E", "--strip", "strip.json"});
  EXPECT_EQ(misuse.exit_code, 2);
}

}  // namespace
}  // namespace facet::tools::testing
