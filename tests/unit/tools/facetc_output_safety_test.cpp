// An output path that is an input of the run is refused: exit 1, a clear
// error, the input's bytes untouched and nothing written. Paths are compared
// by identity, so another spelling or a hard link of an input counts.
#include "facetc_test_util.h"

namespace facet::tools::testing {
namespace {

using ::testing::HasSubstr;

// A shader with an include of its own next to it.
constexpr const char* kShader = R"(Shader "Tests/Included" {
    SubShader {
        Pass {
            CGPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            #include "Local.cginc"
            float4 vert(float4 v : POSITION) : SV_POSITION { return v; }
            fixed4 frag() : SV_Target { return LocalColor(); }
            ENDCG
        }
    }
}
)";
constexpr const char* kInclude = "fixed4 LocalColor() { return fixed4(1, 0, 0, 1); }\n";

class FacetcOutputSafetyTest : public FacetcTest {
 protected:
  void SetUp() override {
    FacetcTest::SetUp();
    fs::create_directories(dir_ / "src");
    write_all(dir_ / "src" / "Included.shader", kShader);
    write_all(dir_ / "src" / "Local.cginc", kInclude);
  }

  // The run fails, says `output` is `what`, and the two inputs are intact.
  void expect_refused(const std::vector<std::string>& args, const std::string& output, const std::string& what) {
    FacetcRun run = facetc(args);
    EXPECT_EQ(run.exit_code, 1) << run.err;
    EXPECT_THAT(run.err, HasSubstr("error: output '" + output + "' is also an input of this build (" + what +
                                   "); nothing was written"));
    EXPECT_EQ(read_all(dir_ / "src" / "Included.shader"), kShader) << "the shader was replaced";
    EXPECT_EQ(read_all(dir_ / "src" / "Local.cginc"), kInclude) << "the include file was replaced";
  }
};

TEST_F(FacetcOutputSafetyTest, OutputNamingTheShaderIsRefused) {
  expect_refused({"src/Included.shader", "-o", "src/Included.shader"}, "src/Included.shader", "the shader");
}

TEST_F(FacetcOutputSafetyTest, AnotherSpellingOrAHardLinkOfTheShaderIsRefused) {
  expect_refused({"src/Included.shader", "-o", "./src/../src/Included.shader"}, "./src/../src/Included.shader",
                 "the shader");
  fs::create_hard_link(dir_ / "src" / "Included.shader", dir_ / "link.shader");
  expect_refused({"src/Included.shader", "-o", "link.shader"}, "link.shader", "the shader");
}

TEST_F(FacetcOutputSafetyTest, OutputNamingAnIncludeFileIsRefused) {
  expect_refused({"src/Included.shader", "-o", "src/Local.cginc"}, "src/Local.cginc", "an include file");
}

// On a warm build the preprocessor does not run: the include is known from
// the cache entry, and is refused all the same.
TEST_F(FacetcOutputSafetyTest, AnIncludeKnownOnlyFromTheCacheIsRefused) {
  ASSERT_EQ(facetc({"src/Included.shader", "--cache-dir", "cache", "-o", "cold.facetpkg"}).exit_code, 0);
  expect_refused({"src/Included.shader", "--cache-dir", "cache", "-o", "src/Local.cginc"}, "src/Local.cginc",
                 "an include file");
}

TEST_F(FacetcOutputSafetyTest, PreprocessedOutputNamingTheShaderIsRefused) {
  expect_refused({"src/Included.shader", "-E", "-o", "src/Included.shader"}, "src/Included.shader", "the shader");
}

TEST_F(FacetcOutputSafetyTest, DepfileNamingAnInputIsRefusedAndNothingIsWritten) {
  expect_refused({"src/Included.shader", "-MD", "-MF", "src/Local.cginc", "-o", "out.facetpkg"}, "src/Local.cginc",
                 "an include file");
  EXPECT_FALSE(fs::exists(dir_ / "out.facetpkg")) << "the package must not be written either";
  expect_refused({"src/Included.shader", "-M", "-MF", "src/Included.shader"}, "src/Included.shader", "the shader");
}

TEST_F(FacetcOutputSafetyTest, OutDirGivingTheNameOfAnInputIsRefused) {
  // src/Included.shader built into --out-dir src is src/Included.facetpkg,
  // which is the run's second input.
  write_all(dir_ / "src" / "Included.facetpkg", "not a package");
  std::string before = read_all(dir_ / "src" / "Included.facetpkg");
  FacetcRun run = facetc({"src/Included.shader", "src/Included.facetpkg", "--out-dir", "src"});
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_THAT(run.err, HasSubstr("error: output 'src/Included.facetpkg' is also an input of this build (a shader "
                                 "of this run); nothing was written"));
  EXPECT_EQ(read_all(dir_ / "src" / "Included.facetpkg"), before);
}

// The second input's package is named like a file the first input included.
TEST_F(FacetcOutputSafetyTest, AnOutputNamingAnIncludeOfAnEarlierInputIsRefused) {
  std::string first = kShader;
  first.replace(first.find("Local.cginc"), 11, "Second.facetpkg");
  write_all(dir_ / "src" / "First.shader", first);
  write_all(dir_ / "src" / "Second.facetpkg", kInclude);
  write_all(dir_ / "src" / "Second.shader", kShader);
  FacetcRun run = facetc({"src/First.shader", "src/Second.shader", "--out-dir", "src"});
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_THAT(run.err, HasSubstr("error: output 'src/Second.facetpkg' is also an input of this build (a file an "
                                 "earlier input read); nothing was written"));
  EXPECT_EQ(read_all(dir_ / "src" / "Second.facetpkg"), kInclude);
  EXPECT_TRUE(fs::exists(dir_ / "src" / "First.facetpkg")) << "the first input's package is fine";
}

TEST_F(FacetcOutputSafetyTest, ReportOutputNamingTheShaderIsRefused) {
  FacetcRun run = facetc({"src/Included.shader", "--report", "-o", "src/Local.cginc"});
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_THAT(run.err, HasSubstr("error: output 'src/Local.cginc' is also an input of this build"));
  EXPECT_EQ(read_all(dir_ / "src" / "Local.cginc"), kInclude);
}

TEST_F(FacetcOutputSafetyTest, MergeOutputNamingAShardIsRefused) {
  ASSERT_EQ(facetc({"src/Included.shader", "-o", "a.facetpkg"}).exit_code, 0);
  std::string before = read_all(dir_ / "a.facetpkg");
  FacetcRun run = facetc({"--merge", "a.facetpkg", "-o", "a.facetpkg"});
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_THAT(run.err, HasSubstr("error: output 'a.facetpkg' is also an input of this build (a package being "
                                 "merged); nothing was written"));
  EXPECT_TRUE(read_all(dir_ / "a.facetpkg") == before);
}

TEST_F(FacetcOutputSafetyTest, OutputNamingTheMaterialsFileIsRefused) {
  write_all(dir_ / "materials.json", R"({"materials": []})");
  std::string before = read_all(dir_ / "materials.json");
  FacetcRun run = facetc({"src/Included.shader", "--materials", "materials.json", "-o", "materials.json"});
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_THAT(run.err, HasSubstr("(a materials file); nothing was written"));
  EXPECT_EQ(read_all(dir_ / "materials.json"), before);
}

TEST_F(FacetcOutputSafetyTest, CheckReportNamingAShaderIsRefusedBeforeCompiling) {
  FacetcRun run = facetc({"--check", "src", "--junit", "src/Included.shader"});
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_THAT(run.err, HasSubstr("facetc: error: output 'src/Included.shader' is also an input of this build (a "
                                 "shader); nothing was written"));
  EXPECT_EQ(read_all(dir_ / "src" / "Included.shader"), kShader);
}

// The includes and the shaders a Fallback names are known only after the
// checks: a report naming one is refused then, before it is written.
TEST_F(FacetcOutputSafetyTest, CheckReportNamingAnIncludeOrAFallbackShaderIsRefused) {
  fs::create_directories(dir_ / "lint");
  write_all(dir_ / "lint" / "Falls.shader", R"(Shader "Tests/Falls" {
    SubShader { Pass { } }
    Fallback "Tests/Included"
}
)");
  fs::copy_file(dir_ / "src" / "Included.shader", dir_ / "lint" / "Included.shader");
  fs::copy_file(dir_ / "src" / "Local.cginc", dir_ / "lint" / "Local.cginc");
  for (const char* report : {"--junit", "--sarif"}) {
    FacetcRun run = facetc({"--check", "lint/Falls.shader", report, "lint/Included.shader"});
    EXPECT_EQ(run.exit_code, 1) << report << run.err;
    EXPECT_THAT(run.err, HasSubstr("output 'lint/Included.shader' is also an input of this build (a file a checked "
                                   "shader read); nothing was written"));
    EXPECT_EQ(read_all(dir_ / "lint" / "Included.shader"), kShader);
  }
  FacetcRun run = facetc({"--check", "src/Included.shader", "--junit", "src/Local.cginc"});
  EXPECT_EQ(run.exit_code, 1) << run.err;
  EXPECT_THAT(run.err, HasSubstr("output 'src/Local.cginc' is also an input of this build"));
  EXPECT_EQ(read_all(dir_ / "src" / "Local.cginc"), kInclude);
}

TEST_F(FacetcOutputSafetyTest, ThePackageAndTheDepfileNamingOneFileAreRefused) {
  FacetcRun run = facetc({"src/Included.shader", "-MD", "-MF", "o.facetpkg", "-o", "o.facetpkg"});
  EXPECT_EQ(run.exit_code, 1) << run.err;
  EXPECT_THAT(run.err,
              HasSubstr("error: outputs 'o.facetpkg' and 'o.facetpkg' are the same file; nothing was written"));
  EXPECT_FALSE(fs::exists(dir_ / "o.facetpkg"));
}

TEST_F(FacetcOutputSafetyTest, AnOutputThatIsNoInputIsWritten) {
  FacetcRun run = facetc({"src/Included.shader", "-MD", "-o", "src/Included.facetpkg"});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_TRUE(fs::exists(dir_ / "src" / "Included.facetpkg"));
  EXPECT_THAT(read_all(dir_ / "src" / "Included.facetpkg.d"), HasSubstr("Local.cginc"));
}

}  // namespace
}  // namespace facet::tools::testing
