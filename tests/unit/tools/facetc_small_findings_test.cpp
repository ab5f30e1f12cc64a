// Findings of a fuzzing probe of facetc, each from the input that found it:
// -o in every mode, property numbers past the float range, diagnostic
// floods, merges of incomplete shard sets.
#include "facetc_test_util.h"

namespace facet::tools::testing {
namespace {

using ::testing::HasSubstr;
using ::testing::Not;
using ::testing::StartsWith;

std::string shader_with(const std::string& properties, const std::string& pragmas) {
  return "Shader \"T/Finding\" {\n  Properties {\n" + properties +
         "\n  }\n  SubShader {\n    Pass {\n      CGPROGRAM\n      #pragma vertex vert\n      #pragma fragment frag\n" +
         pragmas +
         "\n      float4 vert(float4 v : POSITION) : SV_POSITION { return v; }\n"
         "      float4 frag() : SV_Target { return 1; }\n      ENDCG\n    }\n  }\n}\n";
}

class FacetcFindingsTest : public FacetcTest {
 protected:
  // `args` + "-o out.txt": exit 0, nothing on standard output, the output in the file.
  void expect_written_to_file(std::vector<std::string> args) {
    args.insert(args.end(), {"-o", "out.txt"});
    FacetcRun run = facetc(args);
    std::string what = ::testing::PrintToString(args);
    EXPECT_EQ(run.exit_code, 0) << what << run.err;
    EXPECT_EQ(run.out, "") << what << ": -o was not honoured";
    EXPECT_FALSE(read_all(dir_ / "out.txt").empty()) << what;
    fs::remove(dir_ / "out.txt");
  }
};

TEST_F(FacetcFindingsTest, DumpOfAPackageWritesTheFileThatOutputNames) {
  ASSERT_EQ(facetc({example("Unlit.shader"), "-o", "u.facetpkg"}).exit_code, 0);
  FacetcRun run = facetc({"--dump", "u.facetpkg", "-o", "dump.json"});
  EXPECT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(run.out, "");
  EXPECT_THAT(read_all(dir_ / "dump.json"), StartsWith("{\n  \"format_version\": 6"));
  FacetcRun onto_input = facetc({"--dump", "u.facetpkg", "-o", "u.facetpkg"});
  EXPECT_EQ(onto_input.exit_code, 1);
  EXPECT_THAT(onto_input.err, HasSubstr("output 'u.facetpkg' is also an input of this build (the shader)"));
}

TEST_F(FacetcFindingsTest, EveryTextModeWritesTheFileThatOutputNames) {
  std::string shader = example("Unlit.shader");
  for (std::string dump : {"--dump", "--dump=package", "--dump=ast", "--dump=ir", "--dump=variants"}) {
    expect_written_to_file({shader, dump});
  }
  expect_written_to_file({shader, "--list-variants"});
  expect_written_to_file({shader, "--reflect"});
  expect_written_to_file({shader, "-S"});
  expect_written_to_file({shader, "--emit=glsl"});
  expect_written_to_file({shader, "-E"});
  expect_written_to_file({shader, "--report"});
  expect_written_to_file({shader, "--estimate"});
}

TEST_F(FacetcFindingsTest, DepfileOnlyWritesItsRuleToTheFileThatOutputNames) {
  FacetcRun run = facetc({example("Diffuse.shader"), "-M", "-o", "rule.d"});
  EXPECT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(run.out, "");
  std::string rule = read_all(dir_ / "rule.d");
  EXPECT_THAT(rule, StartsWith("Diffuse.facetpkg: \\\n  " + example("Diffuse.shader")));
  EXPECT_THAT(rule, HasSubstr("UnityCG.cginc"));
  EXPECT_EQ(files(), std::vector<std::string>{"rule.d"}) << "-M builds nothing";
  FacetcRun both = facetc({example("Diffuse.shader"), "-M", "-o", "a.d", "-MF", "b.d"});
  EXPECT_EQ(both.exit_code, 2);
  EXPECT_THAT(both.err, HasSubstr("-M writes its rule to the file -o or -MF names; give one of them"));
}

TEST_F(FacetcFindingsTest, PropertyNumbersPastTheFloatRangeAreLocatedErrors) {
  write_all(dir_ / "big.shader", shader_with("    _A (\"A\", Float) = 3.5e38", ""));
  FacetcRun run = facetc({"big.shader", "-o", "big.facetpkg"});
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_THAT(run.err, HasSubstr("big.shader:3:23: error: number '3.5e38' does not fit a 32-bit float"));
  write_all(dir_ / "range.shader", shader_with("    _R (\"R\", Range(-1e39, 1e39)) = 0", ""));
  run = facetc({"range.shader", "-o", "range.facetpkg"});
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_THAT(run.err, HasSubstr("range.shader:3:20: error: number '-1e39' does not fit a 32-bit float"));
  EXPECT_EQ(files(), (std::vector<std::string>{"big.shader", "range.shader"}));
}

TEST_F(FacetcFindingsTest, AHugeNumberIsNotEchoedBackWhole) {
  write_all(dir_ / "huge.shader", shader_with("    _A (\"A\", Float) = " + std::string(100000, '1'), ""));
  FacetcRun run = facetc({"huge.shader", "-o", "huge.facetpkg"});
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_LT(run.err.size(), 2000u) << run.err.substr(0, 500);
  EXPECT_THAT(run.err, HasSubstr("number '" + std::string(64, '1') + "...' is out of range"));
  FacetcRun json = facetc({"huge.shader", "-o", "huge.facetpkg", "--diagnostics-format=json"});
  EXPECT_LT(json.err.size(), 4000u);
}

TEST_F(FacetcFindingsTest, AFloodOfSkipVariantsWarningsIsCapped) {
  std::string names;
  for (int i = 0; i < 5000; ++i) names += " UNDECLARED_KEYWORD_" + std::to_string(i);
  std::string repeated;
  for (int i = 0; i < 2000; ++i) repeated += "      #pragma skip_variants NOPE\n";
  write_all(dir_ / "flood.shader", shader_with("", "      #pragma skip_variants" + names + "\n" + repeated));
  FacetcRun run = facetc({"flood.shader", "-o", "flood.facetpkg"});
  EXPECT_EQ(run.exit_code, 0) << run.err.substr(0, 2000);
  EXPECT_LT(run.err.size(), 100000u) << "6.7 MB before the cap";
  EXPECT_THAT(run.err, HasSubstr("UNDECLARED_KEYWORD_0'"));
  EXPECT_THAT(run.err, HasSubstr("facet: note: and "));
  EXPECT_THAT(run.err, HasSubstr(" more diagnostics (0 errors, "));
  FacetcRun json = facetc({"flood.shader", "-o", "flood.facetpkg", "--diagnostics-format=json"});
  EXPECT_LT(json.err.size(), 100000u);
  EXPECT_THAT(json.err, HasSubstr("\"id\": \"diagnostics_hidden\""));
  FacetcRun werror = facetc({"flood.shader", "-o", "flood2.facetpkg", "-Werror"});
  EXPECT_EQ(werror.exit_code, 1) << "hidden errors still fail the run";
  EXPECT_FALSE(fs::exists(dir_ / "flood2.facetpkg"));
}

class FacetcMergeFindingsTest : public FacetcTest {
 protected:
  void SetUp() override {
    FacetcTest::SetUp();
    for (int i = 0; i < 2; ++i) {
      FacetcRun shard = facetc({example("Keywords.shader"), "--shard", std::to_string(i) + "/2", "-o",
                                "s" + std::to_string(i) + ".facetpkg"});
      ASSERT_EQ(shard.exit_code, 0) << shard.err;
    }
  }
  void expect_merge_refused(const std::vector<std::string>& shards, const std::string& error) {
    std::vector<std::string> args{"--merge"};
    args.insert(args.end(), shards.begin(), shards.end());
    args.insert(args.end(), {"-o", "merged.facetpkg"});
    FacetcRun run = facetc(args);
    EXPECT_EQ(run.exit_code, 1) << ::testing::PrintToString(shards);
    EXPECT_THAT(run.err, HasSubstr(error));
    EXPECT_FALSE(fs::exists(dir_ / "merged.facetpkg"));
  }
};

TEST_F(FacetcMergeFindingsTest, OneShardOfTwoIsRefusedNamingTheMissingShard) {
  expect_merge_refused({"s0.facetpkg"}, "error: the build has 2 shards, but shard 1/2 is not given");
  expect_merge_refused({"s1.facetpkg"}, "shard 0/2 is not given");
}

TEST_F(FacetcMergeFindingsTest, TheSameShardTwiceIsRefused) {
  expect_merge_refused({"s0.facetpkg", "s0.facetpkg"}, "shard 0/2 is given twice: 's0.facetpkg' and 's0.facetpkg'");
  fs::copy_file(dir_ / "s1.facetpkg", dir_ / "copy.facetpkg");
  expect_merge_refused({"s0.facetpkg", "s1.facetpkg", "copy.facetpkg"},
                       "shard 1/2 is given twice: 's1.facetpkg' and 'copy.facetpkg'");
}

TEST_F(FacetcMergeFindingsTest, ShardsBuiltWithOtherOptionsAreRefused) {
  ASSERT_EQ(facetc({example("Keywords.shader"), "--shard", "1/2", "-O0", "-o", "o1.facetpkg"}).exit_code, 0);
  expect_merge_refused({"s0.facetpkg", "o1.facetpkg"}, "'o1.facetpkg' is not of the same build as 's0.facetpkg'");
  ASSERT_EQ(facetc({example("Keywords.shader"), "--shard", "1/3", "-o", "t1.facetpkg"}).exit_code, 0);
  expect_merge_refused({"s0.facetpkg", "t1.facetpkg"}, "shard 1/3 of build");
}

TEST_F(FacetcMergeFindingsTest, TheWholeSetStillMergesIntoTheUnshardedPackage) {
  ASSERT_EQ(facetc({example("Keywords.shader"), "-o", "full.facetpkg"}).exit_code, 0);
  FacetcRun run = facetc({"--merge", "s1.facetpkg", "s0.facetpkg", "-o", "merged.facetpkg"});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_TRUE(read_all(dir_ / "merged.facetpkg") == read_all(dir_ / "full.facetpkg")) << "byte-identical";
  FacetcRun dump = facetc({"--dump", "s1.facetpkg"});
  EXPECT_THAT(dump.out, HasSubstr("\"shard\": 1,\n      \"shards\": 2,"));
}

}  // namespace
}  // namespace facet::tools::testing
