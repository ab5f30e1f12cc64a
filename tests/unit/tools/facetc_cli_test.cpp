// facetc end to end: options, outputs, exit codes, depfiles and determinism.
#include <nlohmann/json.hpp>

#include "facetc_test_util.h"

namespace facet::tools::testing {
namespace {

using ::testing::HasSubstr;

TEST_F(FacetcTest, VersionAndHelpExitZero) {
  FacetcRun version = facetc({"--version"});
  EXPECT_EQ(version.exit_code, 0);
  EXPECT_THAT(version.out, HasSubstr("facet "));
  FacetcRun help = facetc({"--help"});
  EXPECT_EQ(help.exit_code, 0);
  EXPECT_THAT(help.out, HasSubstr("--emit"));
}

TEST_F(FacetcTest, UsageErrorsExitTwoAndWriteNothing) {
  const std::vector<std::vector<std::string>> bad = {
      {},
      {"--bogus", example("Unlit.shader")},
      {"-E", "-S", example("Unlit.shader")},
      {"--emit=pdf", example("Unlit.shader")},
      {"--emit=spirv", example("Unlit.shader")},
      {"--stage", "tessellation", example("Unlit.shader")},
      {"--keywords", "A", "--all-variants", example("Unlit.shader")},
      {"-o", "x.facetpkg", example("Unlit.shader"), example("Diffuse.shader")},
      {"-MF", "x.d", example("Unlit.shader")},
      {"--target-env", "vulkan9", example("Unlit.shader")},
      {"-D", "=1", example("Unlit.shader")},
  };
  for (const auto& args : bad) {
    FacetcRun run = facetc(args);
    EXPECT_EQ(run.exit_code, 2) << ::testing::PrintToString(args) << run.err;
    EXPECT_THAT(run.err, HasSubstr("facetc: error:")) << ::testing::PrintToString(args);
    EXPECT_TRUE(files().empty()) << ::testing::PrintToString(args);
  }
}

TEST_F(FacetcTest, PackageDefaultsToTheInputStemAndDumpsAsJson) {
  FacetcRun run = facetc({example("PhongMultiLight.shader")});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  ASSERT_EQ(files(), std::vector<std::string>{"PhongMultiLight.facetpkg"});
  FacetcRun dump = facetc({"--dump", "PhongMultiLight.facetpkg"});
  ASSERT_EQ(dump.exit_code, 0) << dump.err;
  auto json = nlohmann::json::parse(dump.out);
  ASSERT_EQ(json["passes"].size(), 2u);
  EXPECT_EQ(json["shader"]["name"], "Examples/PhongMultiLight");
  // ForwardBase: fwdbase shortcut = 8 variants (its lightmap and shadowmask
  // keywords left out); ForwardAdd: 5 light kinds.
  EXPECT_EQ(json["passes"][0]["variants"].size(), 8u);
  EXPECT_EQ(json["passes"][1]["variants"].size(), 5u);
}

TEST_F(FacetcTest, OutputIsByteIdenticalAcrossRuns) {
  ASSERT_EQ(facetc({example("Keywords.shader"), "-j1", "-o", "a.facetpkg"}).exit_code, 0);
  ASSERT_EQ(facetc({"-o", "b.facetpkg", "-j", "2", "--all-variants", example("Keywords.shader")}).exit_code, 0);
  std::string a = read_all(dir_ / "a.facetpkg");
  EXPECT_GT(a.size(), 1000u);
  EXPECT_TRUE(a == read_all(dir_ / "b.facetpkg")) << "packages differ";
  FacetcRun glsl1 = facetc({example("Keywords.shader"), "-S", "--emit=glsl", "--all-variants"});
  FacetcRun glsl2 = facetc({example("Keywords.shader"), "-S", "--emit=glsl", "--all-variants"});
  ASSERT_EQ(glsl1.exit_code, 0) << glsl1.err;
  EXPECT_EQ(glsl1.out, glsl2.out);
}

TEST_F(FacetcTest, SeveralInputsGoToOutDir) {
  FacetcRun run = facetc({"--out-dir", "pkgs", "--stats", example("Unlit.shader"), example("VertexColor.shader")});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_TRUE(fs::exists(dir_ / "pkgs" / "Unlit.facetpkg"));
  EXPECT_TRUE(fs::exists(dir_ / "pkgs" / "VertexColor.facetpkg"));
  EXPECT_THAT(run.err, HasSubstr("1 pass, 1 variant (0 stripped); programs 2, unique after preprocessing 2 (compiled once each)"));
}

TEST_F(FacetcTest, WnoLegacySilencesTheLegacyCommandNote) {
  write_all(dir_ / "lo.shader", R"(Shader "X/LO" {
  SubShader { Pass {
    Lighting Off
    CGPROGRAM
    #pragma vertex vert
    #pragma fragment frag
    float4 vert(float4 v : POSITION) : SV_POSITION { return v; }
    float4 frag() : SV_Target { return 1; }
    ENDCG
  } }
}
)");
  FacetcRun noted = facetc({"lo.shader", "-o", "a.facetpkg"});
  ASSERT_EQ(noted.exit_code, 0) << noted.err;
  EXPECT_THAT(noted.err, HasSubstr("lo.shader:3:5: note: 'Lighting' is a legacy fixed-function command"));
  FacetcRun quiet = facetc({"lo.shader", "-o", "b.facetpkg", "-Wno-legacy"});
  ASSERT_EQ(quiet.exit_code, 0) << quiet.err;
  EXPECT_EQ(quiet.err, "");
}

TEST_F(FacetcTest, KeywordsSelectOneVariantByUnitysRule) {
  ASSERT_EQ(facetc({example("Keywords.shader"), "--keywords", "FOG_EXP2 _OVERLAY_ADD", "-o", "k.facetpkg"})
                .exit_code, 0);
  auto json = nlohmann::json::parse(facetc({"--dump", "k.facetpkg"}).out);
  ASSERT_EQ(json["passes"][0]["variants"].size(), 1u);
  EXPECT_EQ(json["passes"][0]["variants"][0]["keywords"], nlohmann::json({"FOG_EXP2", "_OVERLAY_ADD"}));
  // _OVERLAY_ADD alone exists; asking for an undeclared one is closest match,
  // or an error in strict mode.
  FacetcRun strict = facetc({example("Keywords.shader"), "--keywords", "FOG_EXP2 NOT_DECLARED", "--strict-variants",
                       "-o", "s.facetpkg"});
  EXPECT_EQ(strict.exit_code, 0) << strict.err;  // unknown keywords are ignored, as in Unity
}

TEST_F(FacetcTest, PreprocessShowsDefinesAndKeywords) {
  FacetcRun run = facetc({example("Keywords.shader"), "-E", "--stage", "fragment", "--keywords", "FOG_LINEAR",
                    "-DFACET_TEST_VALUE=42"});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_THAT(run.out, HasSubstr("frag"));
  EXPECT_EQ(run.out.find("#include"), std::string::npos) << "includes are expanded";
  EXPECT_EQ(run.out.find("FOG_LINEAR"), std::string::npos) << "macros are expanded";
}

TEST_F(FacetcTest, EmitKindsProduceTheirLanguages) {
  const std::vector<std::pair<std::string, std::string>> kinds = {
      {"spirv-asm", "OpEntryPoint Fragment"}, {"glsl", "#version 450"}, {"essl", "#version 300 es"},
      {"msl", "#include <metal_stdlib>"}};
  for (const auto& [kind, marker] : kinds) {
    FacetcRun run = facetc({example("Diffuse.shader"), "--emit=" + kind, "--stage", "fragment"});
    ASSERT_EQ(run.exit_code, 0) << kind << run.err;
    EXPECT_THAT(run.out, HasSubstr(marker)) << kind;
  }
  FacetcRun asm_all = facetc({example("Diffuse.shader"), "-S"});
  EXPECT_THAT(asm_all.out, HasSubstr("; facetc: pass #0"));
  EXPECT_THAT(asm_all.out, HasSubstr("OpEntryPoint Vertex"));
}

TEST_F(FacetcTest, BinarySpirvPassesSpirvVal) {
  FacetcRun run = facetc({example("Keywords.shader"), "--emit=spirv", "--stage", "fragment", "--keywords",
                    "FOG_EXP _EMISSION", "-o", "frag.spv"});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  std::string spv = read_all(dir_ / "frag.spv");
  ASSERT_GE(spv.size(), 20u);
  EXPECT_EQ(uint8_t(spv[0]), 0x03);  // magic 0x07230203, little-endian
  EXPECT_EQ(uint8_t(spv[3]), 0x07);
  std::string check = "spirv-val --target-env vulkan1.1 " + shell_quote((dir_ / "frag.spv").string());
  EXPECT_EQ(std::system(check.c_str()), 0);
  FacetcRun several = facetc({example("Keywords.shader"), "--emit=spirv", "-o", "all.spv"});
  EXPECT_EQ(several.exit_code, 2);
  EXPECT_THAT(several.err, HasSubstr("--emit=spirv writes one module"));
  EXPECT_FALSE(fs::exists(dir_ / "all.spv"));
}

TEST_F(FacetcTest, ReflectIsJsonPerStage) {
  FacetcRun run = facetc({example("TexturedAmbient.shader"), "--reflect"});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  auto json = nlohmann::json::parse(run.out);
  ASSERT_EQ(json.size(), 2u);
  EXPECT_EQ(json[0]["stage"], "vertex");
  EXPECT_EQ(json[1]["stage"], "fragment");
  bool main_tex = false;
  for (const auto& r : json[1]["reflection"]["resources"]) main_tex |= r["name"] == "_MainTex";
  EXPECT_TRUE(main_tex);
}

TEST_F(FacetcTest, ListVariantsGivesExactCounts) {
  FacetcRun run = facetc({example("Keywords.shader"), "--list-variants"});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_THAT(run.out, HasSubstr("variants: 48"));
  EXPECT_THAT(run.out, HasSubstr("FOG_EXP2 FACET_DEBUG_NORMALS _EMISSION _OVERLAY_MULTIPLY"));
}

TEST_F(FacetcTest, DepfilesListEveryIncludedFile) {
  FacetcRun run = facetc({example("Diffuse.shader"), "-MD", "-o", "d.facetpkg"});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  std::string rule = read_all(dir_ / "d.facetpkg.d");
  EXPECT_EQ(rule.rfind("d.facetpkg: \\\n  " + example("Diffuse.shader"), 0), 0u) << rule;
  EXPECT_THAT(rule, HasSubstr("UnityCG.cginc"));
  EXPECT_THAT(rule, HasSubstr("UnityLightingCommon.cginc"));
  FacetcRun only = facetc({example("Diffuse.shader"), "-M", "-MT", "custom target"});
  ASSERT_EQ(only.exit_code, 0) << only.err;
  EXPECT_EQ(only.out.rfind("custom\\ target:", 0), 0u) << only.out;
  EXPECT_EQ(files(), std::vector<std::string>({"d.facetpkg", "d.facetpkg.d"})) << "-M builds nothing";
}

TEST_F(FacetcTest, WerrorTurnsWarningsIntoFailures) {
  // A SubShader-level LightMode is a warning with a fix (docs/language.md).
  write_all(dir_ / "warn.shader", R"(Shader "T/Warn" {
  SubShader {
    Tags { "LightMode"="ForwardBase" }
    Pass {
      CGPROGRAM
      #pragma vertex vert
      #pragma fragment frag
      float4 vert(float4 v : POSITION) : SV_POSITION { return v; }
      float4 frag() : SV_Target { return 1; }
      ENDCG
    }
  }
})");
  FacetcRun plain = facetc({"warn.shader", "-o", "w.facetpkg"});
  EXPECT_EQ(plain.exit_code, 0);
  EXPECT_THAT(plain.err, HasSubstr("warn.shader:3:"));
  EXPECT_THAT(plain.err, HasSubstr("warning:"));
  fs::remove(dir_ / "w.facetpkg");
  FacetcRun werror = facetc({"warn.shader", "-Werror", "-o", "w.facetpkg"});
  EXPECT_EQ(werror.exit_code, 1);
  EXPECT_THAT(werror.err, HasSubstr("error:"));
  EXPECT_FALSE(fs::exists(dir_ / "w.facetpkg"));
  FacetcRun quiet = facetc({"warn.shader", "-w", "-o", "w.facetpkg"});
  EXPECT_EQ(quiet.exit_code, 0);
  EXPECT_EQ(quiet.err, "");
}

TEST_F(FacetcTest, HlslErrorIsReportedAtItsShaderLineAndColumn) {
  write_all(dir_ / "bad.shader", R"(Shader "T/Bad" {
  SubShader {
    Pass {
      CGPROGRAM
      #pragma vertex vert
      #pragma fragment frag
      #pragma multi_compile _ A B
      float4 vert(float4 v : POSITION) : SV_POSITION { return v; }
      float4 frag() : SV_Target {
        return undeclared_thing;
      }
      ENDCG
    }
  }
})");
  FacetcRun run = facetc({"bad.shader"});
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_THAT(run.err, HasSubstr("bad.shader:10:16: error:"));
  EXPECT_THAT(run.err, HasSubstr("'undeclared_thing'"));
  EXPECT_THAT(run.err, HasSubstr("[in 3 of 3 variants]"));
  EXPECT_TRUE(files() == std::vector<std::string>{"bad.shader"});
  FacetcRun json = facetc({"bad.shader", "--diagnostics-format=json"});
  EXPECT_EQ(json.exit_code, 1);
  auto diags = nlohmann::json::parse(json.err);
  ASSERT_FALSE(diags.empty());
  EXPECT_EQ(diags[0]["line"], 10);
  EXPECT_EQ(diags[0]["column"], 16);
  EXPECT_EQ(diags[0]["severity"], "error");
}

TEST_F(FacetcTest, CorruptPackageIsAnErrorNotACrash) {
  ASSERT_EQ(facetc({example("Unlit.shader"), "-o", "u.facetpkg"}).exit_code, 0);
  std::string bytes = read_all(dir_ / "u.facetpkg");
  write_all(dir_ / "cut.facetpkg", bytes.substr(0, bytes.size() / 2));
  FacetcRun run = facetc({"--dump", "cut.facetpkg"});
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_THAT(run.err, HasSubstr("cut.facetpkg: corrupt package"));
  EXPECT_EQ(run.out, "");
}

}  // namespace
}  // namespace facet::tools::testing

namespace facet::tools::testing {
namespace {

TEST_F(FacetcTest, ShardsMergeIntoTheUnshardedPackage) {
  ASSERT_EQ(facetc({example("PhongMultiLight.shader"), "-o", "full.facetpkg"}).exit_code, 0);
  for (int i = 0; i < 3; ++i) {
    FacetcRun shard = facetc({example("PhongMultiLight.shader"), "--shard", std::to_string(i) + "/3", "-o",
                              "s" + std::to_string(i) + ".facetpkg"});
    ASSERT_EQ(shard.exit_code, 0) << shard.err;
  }
  EXPECT_FALSE(read_all(dir_ / "s0.facetpkg") == read_all(dir_ / "full.facetpkg"));
  FacetcRun merge = facetc({"--merge", "s2.facetpkg", "s0.facetpkg", "s1.facetpkg", "-o", "merged.facetpkg"});
  ASSERT_EQ(merge.exit_code, 0) << merge.err;
  EXPECT_TRUE(read_all(dir_ / "merged.facetpkg") == read_all(dir_ / "full.facetpkg")) << "byte-identical";

  ASSERT_EQ(facetc({example("Unlit.shader"), "-o", "other.facetpkg"}).exit_code, 0);
  FacetcRun mismatch = facetc({"--merge", "s0.facetpkg", "other.facetpkg", "-o", "bad.facetpkg"});
  EXPECT_EQ(mismatch.exit_code, 1);
  EXPECT_THAT(mismatch.err, ::testing::HasSubstr("is not of the same build"));
  EXPECT_FALSE(fs::exists(dir_ / "bad.facetpkg"));
  for (std::string bad : {"3/3", "1/0", "x/2", "1-2"}) {
    EXPECT_EQ(facetc({example("Unlit.shader"), "--shard", bad}).exit_code, 2) << bad;
  }
}

}  // namespace
}  // namespace facet::tools::testing

namespace facet::tools::testing {
namespace {

TEST_F(FacetcTest, ProgressBarOnlyOnATerminal) {
  FacetcRun piped = facetc({example("Keywords.shader"), "-o", "a.facetpkg"});
  ASSERT_EQ(piped.exit_code, 0);
  EXPECT_EQ(piped.err, "") << "no progress bar when stderr is not a terminal";
  // script(1) gives facetc a pseudo-terminal.
  std::string command = "cd " + shell_quote(dir_.string()) + " && script -qec " +
                        shell_quote(shell_quote(FACETC_PATH) + " " + shell_quote(example("Keywords.shader")) +
                                    " -o b.facetpkg") +
                        " /dev/null > tty.txt";
  ASSERT_EQ(std::system(command.c_str()), 0);
  std::string tty = read_all(dir_ / "tty.txt");
  EXPECT_THAT(tty, ::testing::HasSubstr("] 50/50 programs"));
  EXPECT_THAT(tty, ::testing::HasSubstr("\r"));
  EXPECT_TRUE(read_all(dir_ / "a.facetpkg") == read_all(dir_ / "b.facetpkg"));
}

}  // namespace
}  // namespace facet::tools::testing

namespace facet::tools::testing {
namespace {

TEST_F(FacetcTest, EmittedNinjaJobsBuildTheSamePackage) {
  ASSERT_EQ(facetc({example("PhongMultiLight.shader"), "--no-cache", "-o", "ref.facetpkg"}).exit_code, 0);
  FacetcRun emit = facetc({example("PhongMultiLight.shader"), "--emit-jobs=ninja", "--cache-dir", "cache", "-o",
                           "build.ninja"});
  ASSERT_EQ(emit.exit_code, 0) << emit.err;
  EXPECT_THAT(read_all(dir_ / "build.ninja"), ::testing::HasSubstr("(10 jobs)")) << "one per distinct program";
  std::string ninja = "cd " + shell_quote(dir_.string()) + " && ninja > ninja.log 2>&1";
  ASSERT_EQ(std::system(ninja.c_str()), 0) << read_all(dir_ / "ninja.log");
  EXPECT_TRUE(read_all(dir_ / "PhongMultiLight.facetpkg") == read_all(dir_ / "ref.facetpkg"));
  ASSERT_EQ(std::system((ninja + " && ninja -t deps > deps.txt").c_str()), 0);
  EXPECT_THAT(read_all(dir_ / "ninja.log"), ::testing::HasSubstr("no work to do"));
  EXPECT_THAT(read_all(dir_ / "deps.txt"), ::testing::HasSubstr("UnityCG.cginc")) << "exact depfiles per job";

  FacetcRun json = facetc({example("PhongMultiLight.shader"), "--emit-jobs=json", "--cache-dir", "cache"});
  ASSERT_EQ(json.exit_code, 0);
  auto doc = nlohmann::json::parse(json.out);
  EXPECT_EQ(doc["jobs"].size(), 10u);
  EXPECT_EQ(doc["jobs"][0]["command"][2], "--program");

  EXPECT_EQ(facetc({example("PhongMultiLight.shader"), "--emit-jobs=ninja"}).exit_code, 2) << "needs a cache";
  EXPECT_EQ(facetc({example("PhongMultiLight.shader"), "--program", "zero:vertex:", "--cache-dir", "c"}).exit_code, 2);
  FacetcRun missing = facetc({example("PhongMultiLight.shader"), "--program", "7:vertex:", "--cache-dir", "c"});
  EXPECT_EQ(missing.exit_code, 1);
  EXPECT_THAT(missing.err, ::testing::HasSubstr("which this shader does not have"));
}

}  // namespace
}  // namespace facet::tools::testing
