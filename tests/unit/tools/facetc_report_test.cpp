// facetc --report end to end: formats, folders, material manifests and their
// bad inputs.
#include <fmt/format.h>

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
  EXPECT_THAT(text.out, HasSubstr("estimate (as --estimate gives it before a build): ~"));
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

// A pass of 2^65 variants (63 multi_compile sets, a fragment-only one and a
// shader_feature) cannot be enumerated; its report still gives the exact
// ladder, each set's factor and the what-ifs, counted from the sets, while
// the small pass beside it is reported from its full build.
std::string huge_space_shader() {
  std::string pragmas, uses;
  for (int i = 0; i < 63; ++i) {
    pragmas += fmt::format("        #pragma multi_compile _ K{}\n", i);
    uses += fmt::format("        #ifdef K{}\n        c.r += 0.01;\n        #endif\n", i);
  }
  return R"(Shader "Test/Huge" {
  SubShader {
    Pass {
      Name "Small"
      CGPROGRAM
      #pragma vertex vert
      #pragma fragment frag
      #pragma multi_compile _ SMALL_ON
      float4 vert(float4 v : POSITION) : SV_POSITION { return v; }
      float4 frag() : SV_Target {
      #ifdef SMALL_ON
        return 1;
      #else
        return 0;
      #endif
      }
      ENDCG
    }
    Pass {
      Name "Huge"
      CGPROGRAM
      #pragma vertex vert
      #pragma fragment frag
)" + pragmas + R"(        #pragma multi_compile_fragment _ FRAG_ON
        #pragma shader_feature _ SF_ON
        float4 vert(float4 v : POSITION) : SV_POSITION { return v; }
        float4 frag() : SV_Target {
        float4 c = 0;
)" + uses + R"(        #ifdef FRAG_ON
        c.g = 1;
        #endif
        #ifdef SF_ON
        c.b = 1;
        #endif
        return c;
        }
      ENDCG
    }
  }
}
)";
}

TEST_F(FacetcTest, ReportOfASpaceTooLargeToEnumerateCountsItExactly) {
  write_all(dir_ / "Huge.shader", huge_space_shader());
  FacetcRun text = facetc({"--report", "Huge.shader"});
  ASSERT_EQ(text.exit_code, 0) << text.err;
  EXPECT_THAT(text.out, HasSubstr("pass #1 'Huge'"));
  EXPECT_THAT(text.out, ::testing::ContainsRegex(
                            "pass +36893488147419103232 +36893488147419103232 +- +36893488147419103232 +- +- +- +-\n"));
  EXPECT_THAT(text.out, ::testing::ContainsRegex(
                            "vertex +18446744073709551616 +18446744073709551616 +- +18446744073709551616 +- +- +- +-\n"));
  EXPECT_THAT(text.out, HasSubstr("not enumerated: 36893488147419103232 variants are more than --max-variants allows"));
  EXPECT_THAT(text.out, HasSubstr("x2    multi_compile _ K62  [vertex fragment]"));
  EXPECT_THAT(text.out, HasSubstr("x2    multi_compile_fragment _ FRAG_ON  [fragment]"));
  // Removing K0 halves both stages: (2^64 + 2^65) / 2 programs fewer.
  EXPECT_THAT(text.out, HasSubstr("what if: remove 'multi_compile _ K0' -> 27670116110564327424 programs fewer"));
  EXPECT_THAT(text.out,
              HasSubstr("what if: make 'multi_compile _ K0' fragment-only (_fragment) -> 9223372036854775808 programs fewer"));
  EXPECT_THAT(text.out, HasSubstr("what if: remove 'multi_compile_fragment _ FRAG_ON' -> 18446744073709551616 programs fewer"));
  // The small pass is built in full: its compiled rungs are there.
  EXPECT_THAT(text.out, ::testing::ContainsRegex("pass #0 'Small'[^\n]*\n[^\n]*\n +pass +2 +2 +- +2 +2 +4 +3 +"));

  FacetcRun json = facetc({"--report=json", "Huge.shader"});
  ASSERT_EQ(json.exit_code, 0) << json.err;
  auto doc = nlohmann::json::parse(json.out);
  const auto& passes = doc["shaders"][0]["passes"];
  ASSERT_EQ(passes.size(), 2u);
  EXPECT_EQ(passes[0]["enumerated"], true);
  EXPECT_EQ(passes[1]["enumerated"], false);
  EXPECT_EQ(passes[1]["ladder"][0]["full"], "36893488147419103232");
  EXPECT_TRUE(passes[1]["ladder"][0]["programs"].is_null());
  EXPECT_EQ(passes[1]["keyword_sets"].size(), 65u);
  EXPECT_EQ(passes[1]["what_if"][0]["programs_saved"], "27670116110564327424");

  // Under the limit, the same pass is refused by a plain build as before.
  FacetcRun build = facetc({"Huge.shader", "-o", "huge.facetpkg"});
  EXPECT_EQ(build.exit_code, 1);
  EXPECT_FALSE(fs::exists(dir_ / "huge.facetpkg"));
}

}  // namespace
}  // namespace facet::tools::testing
