// reachable_text and without_unreachable_functions: what an entry point
// reaches of a preprocessed program.
#include <gtest/gtest.h>

#include <algorithm>

#include "facet/reachability.h"

namespace facet {
namespace {

const std::string kProgram =
    "#line \"<prelude>\"\n"
    "struct v2f { float4 pos : SV_POSITION; };\n"
    "cbuffer C : register(b0) { float4 _A; }\n"
    "float4 _Color;\n"
    "float helper() { return 1; }\n"
    "float only_frag() { return 2; }\n"
    "static float init = helper();\n"
    "v2f vert(float4 v : POSITION) { v2f o; o.pos = v * helper(); return o; }\n"
    "[earlydepthstencil] float4 frag(v2f i) : SV_Target { return _Color * only_frag(); }\n";

TEST(ReachableTest, KeepsDeclarationsAndReachedFunctionsOnly) {
  std::string vert = reachable_text(kProgram, "vert");
  EXPECT_NE(vert.find("struct v2f"), std::string::npos);
  EXPECT_NE(vert.find("cbuffer C"), std::string::npos);
  EXPECT_NE(vert.find("float4 _Color;"), std::string::npos);
  EXPECT_NE(vert.find("float helper()"), std::string::npos);
  EXPECT_NE(vert.find("v2f vert("), std::string::npos);
  EXPECT_EQ(vert.find("only_frag"), std::string::npos);
  EXPECT_EQ(vert.find("SV_Target"), std::string::npos);

  std::string frag = reachable_text(kProgram, "frag");
  EXPECT_NE(frag.find("float only_frag()"), std::string::npos);
  EXPECT_NE(frag.find("[earlydepthstencil] float4 frag("), std::string::npos);
  EXPECT_NE(frag.find("float helper()"), std::string::npos) << "a static initialiser calls it";
  EXPECT_EQ(frag.find("v2f vert("), std::string::npos);
}

TEST(ReachableTest, ChangesOutsideTheReachedPartDoNotMatter) {
  std::string other = kProgram;
  other.replace(other.find("return 2;"), 9, "return 3 + _Color.x;");
  EXPECT_EQ(reachable_text(kProgram, "vert"), reachable_text(other, "vert"));
  EXPECT_NE(reachable_text(kProgram, "frag"), reachable_text(other, "frag"));
}

TEST(ReachableTest, StringLiteralsReferenceFunctions) {
  std::string hull = "float4 constants() { return 0; }\n"
                     "[patchconstantfunc(\"constants\")] float4 hs(uint id : SV_OutputControlPointID) { return 1; }\n";
  EXPECT_NE(reachable_text(hull, "hs").find("constants() {"), std::string::npos);
}

TEST(ReachableTest, UnbalancedOrUnknownEntryKeepsEverything) {
  EXPECT_EQ(reachable_text("float f() { return 1; ", "f"), "float f() { return 1; ");
  EXPECT_EQ(reachable_text(kProgram, "nope"), kProgram);
}

TEST(ReachableTest, UnreachableFunctionsBecomeEmptyLinesSoLinesStayInPlace) {
  const std::string text =
      "#line 1 \"a.shader\"\n"
      "float4 _Color;\n"
      "float used() { return 1; }\n"
      "float unused(float x)\n{\n  return missing(x);\n}\n"
      "float4 frag() : SV_Target { return _Color * used(); }\n";
  std::string out = without_unreachable_functions(text, "frag");
  EXPECT_EQ(out.find("unused"), std::string::npos);
  EXPECT_EQ(out.find("missing"), std::string::npos);
  EXPECT_EQ(std::count(out.begin(), out.end(), '\n'), std::count(text.begin(), text.end(), '\n'));
  auto line_of = [](const std::string& t, const std::string& needle) {
    return std::count(t.begin(), t.begin() + long(t.find(needle)), '\n');
  };
  EXPECT_EQ(line_of(out, "float4 frag()"), line_of(text, "float4 frag()"));
  EXPECT_NE(out.find("float used() { return 1; }"), std::string::npos);
  EXPECT_EQ(without_unreachable_functions(text, "nope"), text);
}

TEST(ReachableTest, StaticInitialisersThatCallFunctionsRunFirstInTheEntryPoint) {
  const std::string text =
      "float f(float x) { return x; }\n"
      "static const float A = f(1);\n"
      "static float B = A +\n  f(2);\n"
      "static const float C = 3;\n"
      "float4 frag() : SV_Target {\n  return A + B + C;\n}\n";
  std::string out = with_static_initializers_in_entry(text, "frag");
  EXPECT_NE(out.find("static       float A ;"), std::string::npos) << out;
  EXPECT_NE(out.find("static float B ;"), std::string::npos) << out;
  EXPECT_NE(out.find("static const float C = 3;"), std::string::npos) << "no call: stays";
  EXPECT_NE(out.find("float4 frag() : SV_Target { A = f(1); B = A +   f(2);\n"), std::string::npos) << out;
  EXPECT_EQ(std::count(out.begin(), out.end(), '\n'), std::count(text.begin(), text.end(), '\n'));
  EXPECT_EQ(with_static_initializers_in_entry(text, "vert"), text);
}

TEST(FrontFacingTest, AVfaceParameterBecomesTheBoolBuiltInAndItsSign) {
  std::string text = "float4 frag(float4 p : SV_POSITION, float facing : VFACE) : SV_Target {\n"
                     "  return facing > 0 ? 1 : 0; }\n";
  std::string out = with_front_facing_as_bool(text, "frag");
  EXPECT_NE(out.find("bool facing_facet_front : SV_IsFrontFace)"), std::string::npos) << out;
  EXPECT_NE(out.find("{ float facing = facing_facet_front ? 1 : -1;"), std::string::npos) << out;
  EXPECT_EQ(out.find("VFACE"), std::string::npos) << out;
  EXPECT_EQ(std::count(out.begin(), out.end(), '\n'), std::count(text.begin(), text.end(), '\n'));
}

TEST(FrontFacingTest, ANonBoolFrontFaceParameterGetsOneOrZero) {
  std::string text = "float4 frag(in uint face\n : SV_ISFRONTFACE, float4 p : SV_POSITION) : SV_Target { return face; }\n";
  std::string out = with_front_facing_as_bool(text, "frag");
  EXPECT_NE(out.find("bool face_facet_front : SV_IsFrontFace\n, float4 p"), std::string::npos) << out;
  EXPECT_NE(out.find("{ uint face = face_facet_front ? 1 : 0;"), std::string::npos) << out;
  EXPECT_EQ(std::count(out.begin(), out.end(), '\n'), std::count(text.begin(), text.end(), '\n'));
}

TEST(FrontFacingTest, ABoolParameterOtherFunctionsAndOtherSemanticsStayAsTheyAre) {
  for (const char* text : {"float4 frag(bool f : SV_IsFrontFace) : SV_Target { return f; }\n",
                           "float4 other(float f : VFACE) { return f; }\nfloat4 frag() : SV_Target { return 1; }\n",
                           "float4 frag(float f : TEXCOORD0) : SV_Target { return f; }\n",
                           "float4 frag(float f : VFACE : SV_Target { return f; }\n"}) {
    EXPECT_EQ(with_front_facing_as_bool(text, "frag"), text);
  }
}

}  // namespace
}  // namespace facet
