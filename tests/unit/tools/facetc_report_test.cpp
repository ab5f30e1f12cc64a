// facetc --report end to end: formats, folders, material manifests and their
// bad inputs.
#include <nlohmann/json.hpp>

#include "facetc_test_util.h"

namespace facet::tools::testing {
namespace {

using ::testing::HasSubstr;

TEST_F(FacetcTest, ReportFormatsAndFolders) {
  FacetcRun text = facetc({"--report", example("Keywords.shader")});
  ASSERT_EQ(text.exit_code, 0) << text.err;
  EXPECT_THAT(text.out, HasSubstr("shader 'Examples/Keywords'"));
  EXPECT_THAT(text.out, HasSubstr("what if: remove 'multi_compile_fog _ FOG_LINEAR FOG_EXP FOG_EXP2'"));
  EXPECT_THAT(text.out, HasSubstr("estimated before building: ~"));
  EXPECT_THAT(text.out, HasSubstr("(50 programs to compile at"));
  FacetcRun estimate = facetc({"--estimate", example("Keywords.shader")});
  ASSERT_EQ(estimate.exit_code, 0) << estimate.err;
  EXPECT_THAT(estimate.out, HasSubstr("48 variants, 64 programs, 50 to compile; ~"));

  // A folder of small shaders, one nested: the report compiles every
  // variant, so the whole examples folder would cost minutes under the
  // sanitizers.
  fs::create_directories(dir_ / "shaders" / "nested");
  fs::copy_file(example("VertexColor.shader"), dir_ / "shaders" / "VertexColor.shader");
  fs::copy_file(example("DepthFade.shader"), dir_ / "shaders" / "nested" / "DepthFade.shader");
  fs::copy_file(example("Unlit.shader"), dir_ / "shaders" / "Unlit.shader");
  write_all(dir_ / "shaders" / "notes.txt", "not a shader");
  FacetcRun json = facetc({"--report=json", "shaders"});
  ASSERT_EQ(json.exit_code, 0) << json.err;
  auto doc = nlohmann::json::parse(json.out);
  EXPECT_EQ(doc["format"], "facet-variant-report");
  ASSERT_EQ(doc["shaders"].size(), 3u) << "every .shader in the folder and below it, nothing else";
  EXPECT_EQ(doc["shaders"][0]["name"], "Examples/Unlit") << "sorted by path";
  EXPECT_EQ(doc["shaders"][1]["name"], "Examples/VertexColor");
  EXPECT_EQ(doc["shaders"][2]["name"], "Examples/DepthFade");

  FacetcRun html = facetc({"--report=html", "-o", "report.html", example("PhongMultiLight.shader")});
  ASSERT_EQ(html.exit_code, 0) << html.err;
  EXPECT_THAT(read_all(dir_ / "report.html"), HasSubstr("<svg class=\"chart-sets\""));
}

TEST_F(FacetcTest, ReportOfAMissingPathOrAnEmptyFolderIsAnError) {
  fs::create_directories(dir_ / "empty");
  FacetcRun missing = facetc({"--report", "absent.shader", "-o", "r.txt"});
  EXPECT_EQ(missing.exit_code, 1);
  EXPECT_THAT(missing.err, HasSubstr("facetc: error: 'absent.shader' does not exist"));
  FacetcRun empty = facetc({"--report", "empty", "-o", "r.txt"});
  EXPECT_EQ(empty.exit_code, 1);
  EXPECT_THAT(empty.err, HasSubstr("facetc: error: no .shader files under 'empty'"));
  EXPECT_FALSE(fs::exists(dir_ / "r.txt"));
}

TEST_F(FacetcTest, ReportWithMaterialManifest) {
  write_all(dir_ / "materials.json", R"({"materials": [
    {"name": "Glow", "shader": "Examples/Keywords", "keywords": ["_EMISSION"], "properties": {"_Overlay": 2}},
    {"name": "Other", "shader": "Examples/Unlit"}
  ]})");
  FacetcRun run = facetc({"--report=json", "--materials", "materials.json", example("Keywords.shader")});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  auto doc = nlohmann::json::parse(run.out);
  const auto& ladder = doc["shaders"][0]["passes"][0]["ladder"];
  // fog 4 x debug 2 x (_EMISSION) x (_OVERLAY_MULTIPLY, from the KeywordEnum value 2)
  EXPECT_EQ(ladder[0]["after_materials"], 8);
  EXPECT_EQ(ladder[0]["full"], 48);
}

TEST_F(FacetcTest, BadManifestsAreLocatedErrors) {
  const std::vector<std::pair<std::string, std::string>> bad = {
      {"{\"materials\": [", "materials.json:1:16: error: invalid JSON"},
      {"[1, 2]", "materials.json:1:1: error: $: expected an object with a 'materials' array"},
      {"{\"materials\": [{\"shader\": 3}]}", "materials[0].shader: expected a string"},
      {"{\"materials\": [{\"shader\": \"S\", \"keywords\": [1]}]}", "materials[0].keywords[0]: expected a string"},
      {"{\"materials\": [{\"shader\": \"S\", \"colour\": 1}]}", "materials[0].colour: unknown key"},
      {"{\"materials\": [{\"name\": \"x\"}]}", "a material needs 'shader'"},
      {std::string(100000, '['), "JSON nests more than 64 deep"},
  };
  for (const auto& [text, message] : bad) {
    write_all(dir_ / "materials.json", text);
    FacetcRun run = facetc({"--report", "--materials", "materials.json", example("Unlit.shader"), "-o", "r.txt"});
    EXPECT_EQ(run.exit_code, 1) << text;
    EXPECT_THAT(run.err, HasSubstr(message)) << text;
    EXPECT_FALSE(fs::exists(dir_ / "r.txt"));
  }
}

}  // namespace
}  // namespace facet::tools::testing
