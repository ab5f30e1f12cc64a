// facetc on hostile programs: a located error, exit code 1 and nothing
// written, quickly and in little memory (docs/cli.md, "Input limits").
#include <sys/resource.h>

#include "facetc_test_util.h"

namespace facet::tools::testing {
namespace {

std::string repeat(const std::string& s, size_t n) {
  std::string out;
  for (size_t i = 0; i < n; ++i) out += s;
  return out;
}

// A pass whose line 5 is `code` and whose fragment stage calls f().
std::string shader(const std::string& code) {
  return "Shader \"P\" { SubShader { Pass {\nCGPROGRAM\n#pragma vertex vert\n#pragma fragment frag\n" + code +
         "\nfloat4 vert(float4 p : POSITION) : SV_POSITION { return p; }\n"
         "fixed4 frag(float4 p : SV_POSITION) : SV_Target { return f(p.x); }\nENDCG\n} } }\n";
}

class FacetcBudgetTest : public FacetcTest {
 protected:
  // Compiles x.shader to x.facetpkg expecting exit 1, no package, and `error` in standard error.
  void expect_refused(const std::string& text, const std::string& error, std::vector<std::string> extra = {}) {
    write_all(dir_ / "x.shader", text);
    std::vector<std::string> args = {"--no-cache", "x.shader", "-o", "x.facetpkg"};
    args.insert(args.end(), extra.begin(), extra.end());
    FacetcRun run = facetc(args);
    EXPECT_EQ(run.exit_code, 1) << run.err;
    EXPECT_NE(run.err.find(error), std::string::npos) << run.err;
    EXPECT_FALSE(fs::exists(dir_ / "x.facetpkg"));
  }
};

TEST_F(FacetcBudgetTest, UnaryRunEndsInALocatedError) {
  // With the main thread's usual 8 MiB stack, as a user's shell gives it.
  rlimit stack{8u << 20, RLIM_INFINITY};
  setrlimit(RLIMIT_STACK, &stack);
  expect_refused(shader("float f(float a) { return " + std::string(100000, '-') + "a; }"),
                 "x.shader:5:27: error: more than 256 unary operators in a row");
}

TEST_F(FacetcBudgetTest, ChainedAssignmentsEndInALocatedError) {
  expect_refused(shader("float f(float a) { a = " + repeat("a = ", 50000) + "a; return a; }"),
                 "x.shader:5:20: error: more than 256 assignments chained");
}

TEST_F(FacetcBudgetTest, MacroBombEndsInALocatedError) {
  std::string defines = "#define M0 x\n";
  for (int i = 1; i <= 30; ++i) {
    defines += "#define M" + std::to_string(i) + " M" + std::to_string(i - 1) + "+M" + std::to_string(i - 1) + "\n";
  }
  expect_refused(shader(defines + "float f(float x) { return M30; }"),
                 "x.shader:29:9: error: macro 'M24' expands to about");
}

TEST_F(FacetcBudgetTest, IncludeFanOutEndsAtTheIncludeCount) {
  for (int i = 0; i < 30; ++i) {
    std::string next = "f" + std::to_string(i + 1) + ".h";
    write_all(dir_ / ("f" + std::to_string(i) + ".h"),
              i < 29 ? "#include \"" + next + "\"\n#include \"" + next + "\"\n" : "// leaf\n");
  }
  expect_refused(shader("#include \"f0.h\"\nfloat f(float a) { return a; }"),
                 "f28.h:1:10: error: more than 4096 #includes in one program (--max-includes)");
}

TEST_F(FacetcBudgetTest, UnrollPastTheLimitEndsInALocatedError) {
  expect_refused(shader("float f(float a) { [unroll] for (int i = 0; i < 10000000; i++) a += sin(a); return a; }"),
                 "x.shader:5:21: error: a loop marked [unroll] runs 10000001 times");
}

TEST_F(FacetcBudgetTest, MaxUnrollLowersTheLimit) {
  std::string text = shader("float f(float a) { [unroll] for (int i = 0; i < 32; i++) a += sin(a); return a; }");
  write_all(dir_ / "x.shader", text);
  FacetcRun run = facetc({"--no-cache", "x.shader", "-o", "x.facetpkg"});
  EXPECT_EQ(run.exit_code, 0) << run.err;
  fs::remove(dir_ / "x.facetpkg");
  expect_refused(text, "more than the limit of 16 (--max-unroll)", {"--max-unroll", "16"});
}

TEST_F(FacetcBudgetTest, TimeLimitEndsTheProcessWithALocatedError) {
  // Unrolling a million iterations takes far longer than a second.
  expect_refused(shader("float f(float a) { [unroll] for (int i = 0; i < 1000000; i++) a += sin(a); return a; }"),
                 "x.shader:2:10: error: compiling the fragment stage took longer than 1 s (--time-limit)",
                 {"--max-unroll", "0", "--time-limit", "1"});
}

TEST_F(FacetcBudgetTest, LimitOptionsTakeSizes) {
  write_all(dir_ / "x.shader", shader("float f(float a) { return a; }"));
  EXPECT_EQ(facetc({"--no-cache", "x.shader", "-o", "x.facetpkg", "--max-include-bytes", "128M",
                    "--max-preprocessed-bytes", "1G", "--max-includes", "0", "--time-limit", "0"})
                .exit_code,
            0);
  FacetcRun bad = facetc({"x.shader", "--max-include-bytes", "lots"});
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_NE(bad.err.find("--max-include-bytes takes a number such as 4096, 64K, 64M or 1G"), std::string::npos)
      << bad.err;
}

}  // namespace
}  // namespace facet::tools::testing
