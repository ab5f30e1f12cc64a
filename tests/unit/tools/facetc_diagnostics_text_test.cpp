// The diagnostics a Clang user expects, each on its exact text and column:
// undeclared names with a did-you-mean, a missing ';' after the previous
// token, a misspelt property reference, the stage in the note, the search
// folders of a missing include, -Werror's group, notes printed once.
#include "facetc_test_util.h"

namespace facet::tools::testing {
namespace {

using ::testing::HasSubstr;
using ::testing::Not;

// A one-pass shader around `globals` and a fragment function body.
std::string shader_with(const std::string& name, const std::string& globals, const std::string& frag_body,
                        const std::string& pragmas = "") {
  return "Shader \"Test/" + name + "\" {\n"                        // 1
         "  Properties { _Tint (\"Tint\", Color) = (1,1,1,1) }\n"   // 2
         "  SubShader {\n"                                         // 3
         "    Pass {\n"                                            // 4
         "      CGPROGRAM\n"                                       // 5
         "      #pragma vertex vert\n"                             // 6
         "      #pragma fragment frag\n" +                         // 7
         pragmas +
         "      float4 _Tint;\n" + globals +
         "      float4 vert(float4 v : POSITION) : SV_POSITION { return v; }\n"
         "      float4 frag() : SV_Target {\n" +
         frag_body +
         "      }\n"
         "      ENDCG\n"
         "    }\n"
         "  }\n"
         "}\n";
}

size_t occurrences(const std::string& text, const std::string& what) {
  size_t n = 0;
  for (size_t pos = text.find(what); pos != std::string::npos; pos = text.find(what, pos + 1)) ++n;
  return n;
}

TEST_F(FacetcTest, CallToAnUndeclaredFunctionSaysSoWithTheClosestName) {
  write_all(dir_ / "U.shader", shader_with("U", "      float4 shade(float4 c) { return c * 2; }\n",
                                           "        return shadee(_Tint);\n"));
  FacetcRun run = facetc({"U.shader", "-o", "u.facetpkg"});
  EXPECT_EQ(run.exit_code, 1);
  // Line 12 is the return; 'shadee' starts at column 16.
  EXPECT_THAT(run.err, HasSubstr("U.shader:12:16: error: use of undeclared identifier 'shadee'; did you mean 'shade'?"))
      << run.err;
  EXPECT_THAT(run.err, Not(HasSubstr("no matching overloaded function")));
}

TEST_F(FacetcTest, UndeclaredIntrinsicSpellingSuggestsTheIntrinsic) {
  write_all(dir_ / "I.shader", shader_with("I", "", "        return saturat(_Tint);\n"));
  FacetcRun run = facetc({"I.shader", "-o", "i.facetpkg"});
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_THAT(run.err,
              HasSubstr("I.shader:11:16: error: use of undeclared identifier 'saturat'; did you mean 'saturate'?"))
      << run.err;
}

TEST_F(FacetcTest, UndeclaredVariableSaysSoWithTheClosestName) {
  write_all(dir_ / "V.shader", shader_with("V", "", "        return _Tnt;\n"));
  FacetcRun run = facetc({"V.shader", "-o", "v.facetpkg"});
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_THAT(run.err, HasSubstr("V.shader:11:16: error: use of undeclared identifier '_Tnt'; did you mean '_Tint'?"))
      << run.err;
}

TEST_F(FacetcTest, WrongArgumentsToADeclaredFunctionStayAnOverloadError) {
  write_all(dir_ / "W.shader", shader_with("W", "      struct S { float a; };\n      float4 shade(S s) { return s.a; }\n",
                                           "        return shade(_Tint) + lerp(_Tint);\n"));
  FacetcRun run = facetc({"W.shader", "-o", "w.facetpkg"});
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_THAT(run.err, HasSubstr("'shade': no matching overloaded function found")) << run.err;
  EXPECT_THAT(run.err, Not(HasSubstr("undeclared identifier")));
}

TEST_F(FacetcTest, MissingSemicolonPointsAfterThePreviousToken) {
  // "        float4 c = 1 // one" on line 11: the ';' belongs at column 21, after '1'.
  write_all(dir_ / "S.shader", shader_with("S", "", "        float4 c = 1 // one\n\n        return c;\n"));
  FacetcRun run = facetc({"S.shader", "-o", "s.facetpkg"});
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_THAT(run.err, HasSubstr("S.shader:11:21: error: expected ';'")) << run.err;
  EXPECT_THAT(run.err, HasSubstr("   11 |         float4 c = 1 // one\n      | " + std::string(20, ' ') + "^\n"))
      << run.err;
}

TEST_F(FacetcTest, MisspeltPropertyReferenceSuggestsTheDeclaredOne) {
  write_all(dir_ / "P.shader", R"(Shader "Test/P" {
  Properties { _Tint ("Tint", Color) = (1,1,1,1) _SrcBlend ("Src", Float) = 1 }
  SubShader {
    Pass {
      Blend [_SrcBlnd] Zero
      ZTest [unity_GUIZTestMode]
      Color [_Tnt]
    }
  }
}
)");
  FacetcRun run = facetc({"P.shader", "-o", "p.facetpkg"});
  EXPECT_EQ(run.exit_code, 0) << run.err;
  EXPECT_THAT(run.err, HasSubstr("P.shader:5:14: warning: '_SrcBlnd' is not a declared property; did you mean "
                                 "'_SrcBlend'? [-Wproperty]"))
      << run.err;
  EXPECT_THAT(run.err, HasSubstr("P.shader:7:14: warning: '_Tnt' is not a declared property; did you mean '_Tint'? "
                                 "[-Wproperty]"))
      << run.err;
  EXPECT_THAT(run.err, HasSubstr("    5 |       Blend [_SrcBlnd] Zero\n      |              ^~~~~~~~\n      | fix: replace with "
                                 "'_SrcBlend'\n"));
  // A global property (Shader.SetGlobal*) near no declared name is fine.
  EXPECT_THAT(run.err, Not(HasSubstr("unity_GUIZTestMode")));
}

TEST_F(FacetcTest, TheNoteNamesTheStageTheErrorIsIn) {
  write_all(dir_ / "N.shader", shader_with("N", "", "        return missing_value;\n"));
  FacetcRun run = facetc({"N.shader", "-o", "n.facetpkg"});
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_THAT(run.err, HasSubstr("note: while compiling pass #0, fragment stage, keywords {none}")) << run.err;
  EXPECT_THAT(run.err, Not(HasSubstr("vertex stage")));
}

TEST_F(FacetcTest, IncludeNotFoundNeverListsAnEmptyFolder) {
  write_all(dir_ / "M.shader", shader_with("M", "      #include \"Missing.cginc\"\n", "        return 1;\n"));
  FacetcRun run = facetc({"M.shader", "-o", "m.facetpkg"});
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_THAT(run.err, HasSubstr("M.shader:9:16: error: include file 'Missing.cginc' not found")) << run.err;
  EXPECT_THAT(run.err, HasSubstr("note: searched '.', ")) << run.err;
  EXPECT_THAT(run.err, Not(HasSubstr("''")));
}

TEST_F(FacetcTest, WerrorKeepsTheWarningsGroup) {
  write_all(dir_ / "E.shader", shader_with("E", "", "        return 1;\n", "      #pragma fragmnet frag\n"));
  FacetcRun plain = facetc({"E.shader", "-o", "e.facetpkg"});
  EXPECT_EQ(plain.exit_code, 0) << plain.err;
  EXPECT_THAT(plain.err, HasSubstr("E.shader:8:7: warning: unknown pragma 'fragmnet' is ignored [-Wunknown-pragma]"));
  FacetcRun strict = facetc({"E.shader", "-o", "e2.facetpkg", "-Werror"});
  EXPECT_EQ(strict.exit_code, 1);
  EXPECT_THAT(strict.err,
              HasSubstr("E.shader:8:7: error: unknown pragma 'fragmnet' is ignored [-Werror,-Wunknown-pragma]"));
  EXPECT_FALSE(fs::exists(dir_ / "e2.facetpkg"));
}

TEST_F(FacetcTest, ANoteIsPrintedOnceNotOncePerVariant) {
  write_all(dir_ / "O.shader",
            shader_with("O", "", "      #ifdef A\n        return undefined_thing;\n      #endif\n        return 1;\n",
                        "      #pragma fragmnet frag\n      #pragma multi_compile _ A B C\n      #pragma multi_compile _ D\n"));
  FacetcRun run = facetc({"O.shader", "-o", "o.facetpkg"});
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_EQ(occurrences(run.err, "did you mean 'fragment'?"), 1u) << run.err;
  EXPECT_EQ(occurrences(run.err, "use of undeclared identifier 'undefined_thing'"), 1u) << run.err;
  EXPECT_THAT(run.err, HasSubstr("[in 2 of 8 variants]"));
  EXPECT_EQ(occurrences(run.err, "note: while compiling pass #0, fragment stage, keywords {A}"), 1u) << run.err;
  // The return of a name that does not resolve is no second error (Clang's way).
  EXPECT_THAT(run.err, Not(HasSubstr("'return': type does not match")));
}

}  // namespace
}  // namespace facet::tools::testing
