// facetc --report end to end: formats, folders, material manifests and their
// bad inputs.
#include <fmt/format.h>

#include <algorithm>

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
  // Columns that hold no data are left out: no materials were given, and the
  // compiled rungs of a pass not enumerated are unknown.
  EXPECT_THAT(text.out, ::testing::ContainsRegex(
                            "\n +full +after skip +reachable\n +pass +36893488147419103232 +36893488147419103232 "
                            "+36893488147419103232\n"));
  EXPECT_THAT(text.out, ::testing::ContainsRegex(
                            "vertex +18446744073709551616 +18446744073709551616 +18446744073709551616\n"));
  EXPECT_THAT(text.out, HasSubstr("not enumerated: 36893488147419103232 variants are more than --max-variants allows"));
  EXPECT_THAT(text.out, HasSubstr("x2    multi_compile _ K62  [vertex fragment]"));
  EXPECT_THAT(text.out, HasSubstr("x2    multi_compile_fragment _ FRAG_ON  [fragment]"));
  // Removing K0 halves both stages: (2^64 + 2^65) / 2 programs fewer.
  EXPECT_THAT(text.out, HasSubstr("what if: remove 'multi_compile _ K0' -> 27670116110564327424 programs fewer"));
  EXPECT_THAT(text.out,
              HasSubstr("what if: make 'multi_compile _ K0' fragment-only (_fragment) -> 9223372036854775808 programs fewer"));
  EXPECT_THAT(text.out, HasSubstr("what if: remove 'multi_compile_fragment _ FRAG_ON' -> 18446744073709551616 programs fewer"));
  // The small pass is built in full: its compiled rungs are there.
  EXPECT_THAT(text.out, ::testing::ContainsRegex("pass #0 'Small'[^\n]*\n[^\n]*\n +pass +2 +2 +2 +2 +4 +3 +"));
  EXPECT_THAT(text.out, HasSubstr("(1 pass too large to enumerate is not in these figures; see its what-ifs)"));

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

// Two materials of the uber shader: a plain one and a normal-mapped,
// emissive one. Its ShadowCaster and ForwardAdd passes keep the test small.
constexpr const char* kUberMaterials = R"({"materials": [
  {"name": "Plain", "shader": "Standard"},
  {"name": "Glowing", "shader": "Standard", "keywords": ["_NORMALMAP", "_EMISSION"]}
]})";

std::string uber() { return std::string(FACET_SOURCE_DIR) + "/stdlib/Shaders/Standard.shader"; }

uint64_t programs_of(const nlohmann::json& shader) {
  uint64_t n = 0;
  for (const auto& p : shader["passes"]) n += p["ladder"][0]["programs"].get<uint64_t>();
  return n;
}

TEST_F(FacetcTest, ReportWithManifestsCompilesOnlyTheManifestsVariants) {
  write_all(dir_ / "materials.json", kUberMaterials);
  FacetcRun run = facetc({"--report=json", "--materials", "materials.json", "--pass", "FORWARD_DELTA", uber()});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const auto doc = nlohmann::json::parse(run.out);
  const auto& pass = doc["shaders"][0]["passes"][0];
  const auto& ladder = pass["ladder"][0];
  ASSERT_TRUE(ladder["after_materials"].is_number()) << ladder;
  EXPECT_LT(ladder["after_materials"].get<uint64_t>(), ladder["after_skip_variants"].get<uint64_t>());
  // The stripped ladder: what is built is what the materials use.
  EXPECT_EQ(ladder["after_keyword_rules_and_strip"], ladder["reachable"]);
  EXPECT_EQ(pass["variants"].size(), ladder["reachable"].get<uint64_t>());
  // The pass declares no _EMISSION: its material combinations are {} and
  // {_NORMALMAP}. Every other shader_feature keyword (all start with '_') is
  // left out; the multi_compile sets stay whole.
  size_t normal_mapped = 0;
  for (const auto& v : pass["variants"]) {
    for (const std::string& k : v["keywords"].get<std::vector<std::string>>()) {
      EXPECT_TRUE(k[0] != '_' || k == "_NORMALMAP") << "a combination no material uses was built: " << v["keywords"];
      normal_mapped += k == "_NORMALMAP";
    }
  }
  EXPECT_EQ(normal_mapped * 2, pass["variants"].size());
  FacetcRun text = facetc({"--report", "--materials", "materials.json", "--pass", "FORWARD_DELTA", uber()});
  ASSERT_EQ(text.exit_code, 0) << text.err;
  EXPECT_THAT(text.out, ::testing::ContainsRegex("\n +full +after skip +materials +reachable +after strip +programs"));
  // The text form leads with the summary of the JSON form.
  const auto& summary = doc["shaders"][0]["summary"];
  ASSERT_FALSE(summary["steps"].empty()) << summary;
  EXPECT_THAT(text.out, HasSubstr(fmt::format("summary: {} programs now, {} after the ",
                                              summary["programs_now"].get<uint64_t>(),
                                              summary["programs_after"].get<uint64_t>())));
  EXPECT_THAT(text.out, HasSubstr(fmt::format("  1. pass #{} '{}': {} -> {} fewer",
                                              summary["steps"][0]["pass"].get<uint32_t>(),
                                              summary["steps"][0]["pass_name"].get<std::string>(),
                                              summary["steps"][0]["change"].get<std::string>(),
                                              summary["steps"][0]["programs_saved"].get<uint64_t>())));

  // --estimate predicts the same stripped build.
  FacetcRun estimate = facetc({"--estimate", "--materials", "materials.json", "--pass", "FORWARD_DELTA", uber()});
  ASSERT_EQ(estimate.exit_code, 0) << estimate.err;
  EXPECT_THAT(estimate.out, HasSubstr(fmt::format("{} variants, {} programs", pass["variants"].size(),
                                                  ladder["programs"].get<uint64_t>())));
}

TEST_F(FacetcTest, EmittedStripFedBackBuildsThePredictedPrograms) {
  write_all(dir_ / "materials.json", kUberMaterials);
  std::vector<std::string> common = {"--materials", "materials.json", "--pass", "ShadowCaster", "--pass",
                                     "FORWARD_DELTA", uber()};
  auto with = [&](std::vector<std::string> args) {
    args.insert(args.end(), common.begin(), common.end());
    return args;
  };
  FacetcRun first = facetc(with({"--report=json", "--emit-strip", "strip.json", "-o", "before.json"}));
  ASSERT_EQ(first.exit_code, 0) << first.err;
  auto before = nlohmann::json::parse(read_all(dir_ / "before.json"))["shaders"][0];
  const auto& summary = before["summary"];
  EXPECT_EQ(summary["programs_now"], programs_of(before));
  ASSERT_GE(summary["steps"].size(), 2u) << summary;
  EXPECT_LT(summary["programs_after"].get<uint64_t>(), summary["programs_now"].get<uint64_t>());
  uint64_t saved = 0;
  for (const auto& step : summary["steps"]) saved += step["programs_saved"].get<uint64_t>();
  EXPECT_EQ(summary["programs_now"].get<uint64_t>() - saved, summary["programs_after"]);

  auto strip = nlohmann::json::parse(read_all(dir_ / "strip.json"));
  ASSERT_EQ(strip["strip"].size(), summary["steps"].size());
  EXPECT_EQ(strip["strip"][0]["always_off"], summary["steps"][0]["always_off"]);
  EXPECT_EQ(strip["strip"][0]["pass"], summary["steps"][0]["pass"]);

  FacetcRun second = facetc(with({"--report=json", "--strip", "strip.json", "-o", "after.json"}));
  ASSERT_EQ(second.exit_code, 0) << second.err;
  auto after = nlohmann::json::parse(read_all(dir_ / "after.json"))["shaders"][0];
  EXPECT_EQ(programs_of(after), summary["programs_after"].get<uint64_t>());

}

TEST_F(FacetcTest, WhatIfsAreSortedBySavingWithoutRowsThatSaveNothing) {
  FacetcRun run = facetc({"--report=json", example("Keywords.shader")});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const auto doc = nlohmann::json::parse(run.out);
  for (const auto& pass : doc["shaders"][0]["passes"]) {
    ASSERT_FALSE(pass["what_if"].empty());
    for (size_t i = 0; i < pass["what_if"].size(); ++i) {
      EXPECT_GT(pass["what_if"][i]["programs_saved"].get<uint64_t>(), 0u) << pass["what_if"][i];
      if (i > 0) {
        EXPECT_LE(pass["what_if"][i]["programs_saved"], pass["what_if"][i - 1]["programs_saved"]);
      }
    }
  }
}

TEST_F(FacetcTest, EmitStripNeedsOneShaderAndNeverReplacesAnInput) {
  fs::create_directories(dir_ / "two");
  fs::copy_file(example("Unlit.shader"), dir_ / "two" / "Unlit.shader");
  fs::copy_file(example("VertexColor.shader"), dir_ / "two" / "VertexColor.shader");
  FacetcRun two = facetc({"--report", "--emit-strip", "strip.json", "two"});
  EXPECT_EQ(two.exit_code, 1);
  EXPECT_THAT(two.err, HasSubstr("facetc: error: --emit-strip writes the strip filter of one shader; the inputs name "
                                 "2 shaders"));
  EXPECT_FALSE(fs::exists(dir_ / "strip.json"));

  fs::copy_file(example("Keywords.shader"), dir_ / "Keywords.shader");
  std::string source = read_all(dir_ / "Keywords.shader");
  FacetcRun onto_input = facetc({"--report", "--emit-strip", "Keywords.shader", "Keywords.shader"});
  EXPECT_EQ(onto_input.exit_code, 1);
  EXPECT_THAT(onto_input.err, HasSubstr("Keywords.shader"));
  EXPECT_EQ(read_all(dir_ / "Keywords.shader"), source);

  FacetcRun no_report = facetc({"--emit-strip", "strip.json", "Keywords.shader"});
  EXPECT_EQ(no_report.exit_code, 2) << "a usage error";
  EXPECT_THAT(no_report.err, HasSubstr("--emit-strip goes with --report"));
  EXPECT_FALSE(fs::exists(dir_ / "strip.json"));
}

TEST_F(FacetcTest, ReportShowsAProgressBarOnlyOnATerminal) {
  FacetcRun piped = facetc({"--report", example("Keywords.shader"), "-o", "piped.txt"});
  ASSERT_EQ(piped.exit_code, 0);
  EXPECT_EQ(piped.err, "") << "no progress bar when stderr is not a terminal";
  // script(1) gives facetc a pseudo-terminal.
  std::string command = "cd " + shell_quote(dir_.string()) + " && script -qec " +
                        shell_quote(shell_quote(FACETC_PATH) + " --report " + shell_quote(example("Keywords.shader")) +
                                    " -o tty-report.txt") +
                        " /dev/null > tty.txt";
  ASSERT_EQ(std::system(command.c_str()), 0);
  std::string tty = read_all(dir_ / "tty.txt");
  EXPECT_THAT(tty, HasSubstr("] 50/50 programs"));
  EXPECT_THAT(tty, HasSubstr("\r"));
  EXPECT_THAT(read_all(dir_ / "tty-report.txt"), HasSubstr("summary: 64 programs now"));
}

TEST_F(FacetcTest, HtmlReportListsTheSlowestVariantsAndTheSummary) {
  FacetcRun html = facetc({"--report=html", "-o", "report.html", example("Keywords.shader")});
  ASSERT_EQ(html.exit_code, 0) << html.err;
  std::string page = read_all(dir_ / "report.html");
  EXPECT_THAT(page, HasSubstr("<table class=\"slowest\"><tr><th>variant keywords</th><th>compile seconds</th>"));
  EXPECT_THAT(page, ::testing::ContainsRegex("<p class=\"caption\">The 10 slowest of 48 variants \\([0-9]+ compiled\\)"));
  EXPECT_THAT(page, HasSubstr("<p class=\"summary\"><b>64 programs</b> now, <b>"));
  EXPECT_THAT(page, ::testing::Not(HasSubstr("after scene needs"))) << "a column that never holds data";
  EXPECT_THAT(page, ::testing::Not(HasSubstr("after materials"))) << "no manifest was given";
}

}  // namespace
}  // namespace facet::tools::testing
