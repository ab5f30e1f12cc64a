// Hostile and broken inputs through the whole facetc binary: each gives a
// located error, exit code 1, no output file and no crash (the suite runs
// under ASan + UBSan).
#include "facetc_test_util.h"

namespace facet::tools::testing {
namespace {

std::string pass_with(const std::string& program) {
  return "Shader \"T/Bad\" {\n  SubShader {\n    Pass {\n      CGPROGRAM\n      #pragma vertex vert\n"
         "      #pragma fragment frag\n" + program +
         "\n      ENDCG\n    }\n  }\n}\n";
}

const std::string kStages =
    "      float4 vert(float4 v : POSITION) : SV_POSITION { return v; }\n"
    "      float4 frag() : SV_Target { return 1; }";

struct BadInput {
  std::string name;
  std::string text;
  std::string expect;  // a fragment of the first error line, after "bad.shader:L:C: error: "
};

std::ostream& operator<<(std::ostream& os, const BadInput& b) { return os << b.name; }

std::string binary_garbage() {
  std::string s;
  uint32_t x = 12345;
  for (int i = 0; i < 4096; ++i) {
    x = x * 1103515245u + 12345u;
    s += char(x >> 24);
  }
  return s;
}

std::vector<BadInput> bad_inputs() {
  std::string good = pass_with(kStages);
  return {
      {"Truncated", good.substr(0, good.size() / 2), ""},
      {"Empty", "", "expected 'Shader'"},
      {"UnbalancedBraces", "Shader \"T\" { SubShader { Pass { } }", "missing '}'"},
      {"ExtraClosingBrace", "Shader \"T\" { SubShader { Pass { } } } }", ""},
      {"BadPropertyType", "Shader \"T\" { Properties { _A (\"A\", Flaot) = 1 } SubShader { Pass { } } }",
       "'Flaot'"},
      {"UnknownRenderStateValue", "Shader \"T\" { SubShader { Pass { ZTest Sometimes } } }", "'Sometimes'"},
      {"UnterminatedProgram", "Shader \"T\" { SubShader { Pass { CGPROGRAM\n float4 x;\n", "CGPROGRAM"},
      {"BadPragma", pass_with("      #pragma multi_compile\n" + kStages), "multi_compile"},
      {"BadTarget", pass_with("      #pragma target 9.7\n" + kStages), "9.7"},
      {"HlslError", pass_with("      float4 vert(float4 v : POSITION) : SV_POSITION { return v }\n"
                              "      float4 frag() : SV_Target { return 1; }"), ""},
      {"MissingInclude", pass_with("      #include \"NoSuchFile.cginc\"\n" + kStages), "NoSuchFile.cginc"},
      {"BinaryGarbage", binary_garbage(), ""},
      {"NulBytes", std::string("Shader \"T\" {\0\0\0 SubShader { } }", 30), ""},
      {"TenMegabytes", "Shader \"T\" { SubShader { Pass { " + std::string(10u << 20, 'x') + " } } }", ""},
      {"DeeplyNestedBraces", "Shader \"T\" { " + std::string(100000, '{') + std::string(100000, '}') + " }", ""},
      {"DeeplyNestedHlsl", pass_with("      float f() { return " + std::string(5000, '(') + "1" +
                                     std::string(5000, ')') + "; }\n" + kStages), ""},
  };
}

class FacetcMalformedTest : public FacetcTest, public ::testing::WithParamInterface<BadInput> {};

TEST_P(FacetcMalformedTest, LocatedErrorExitOneNoOutput) {
  const BadInput& bad = GetParam();
  write_all(dir_ / "bad.shader", bad.text);
  FacetcRun run = facetc({"bad.shader", "-o", "out.facetpkg"});
  EXPECT_EQ(run.exit_code, 1) << run.err;
  std::string first_line = run.err.substr(0, run.err.find('\n'));
  unsigned line = 0, column = 0;
  int message_at = 0;
  ASSERT_EQ(std::sscanf(first_line.c_str(), "bad.shader:%u:%u: error: %n", &line, &column, &message_at), 2)
      << run.err.substr(0, 2000);
  ASSERT_GT(message_at, 0) << first_line;
  EXPECT_GE(line, 1u);
  EXPECT_GE(column, 1u);
  EXPECT_THAT(first_line.substr(size_t(message_at)), ::testing::HasSubstr(bad.expect));
  EXPECT_LT(run.err.size(), 64u * 1024) << "diagnostics stay short";
  EXPECT_EQ(files(), std::vector<std::string>{"bad.shader"}) << "no output, no temporary left behind";
}

INSTANTIATE_TEST_SUITE_P(Inputs, FacetcMalformedTest, ::testing::ValuesIn(bad_inputs()),
                         [](const auto& info) { return info.param.name; });

TEST_F(FacetcTest, MissingInputFileIsAnError) {
  FacetcRun run = facetc({"nope.shader"});
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_THAT(run.err, ::testing::HasSubstr("cannot open 'nope.shader'"));
  EXPECT_TRUE(files().empty());
}

TEST_F(FacetcTest, UnwritableOutputIsAnError) {
  FacetcRun run = facetc({example("Unlit.shader"), "-o", "no/such/dir/x.facetpkg"});
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_THAT(run.err, ::testing::HasSubstr("cannot write"));
}

}  // namespace
}  // namespace facet::tools::testing
