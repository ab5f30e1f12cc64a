// find_declaration_problem on preprocessed text: what it refuses and where.
#include "global_declarations.h"

#include <gtest/gtest.h>

namespace facet::backend {
namespace {

TEST(GlobalDeclarationsTest, PositionsFollowLineDirectives) {
  auto p = find_declaration_problem("#line 7 \"a.shader\"\nfloat4 X;\n#line 40 \"b.cginc\"\n\nfloat X;\n");
  ASSERT_TRUE(p);
  EXPECT_EQ(p->file, "b.cginc");
  EXPECT_EQ(p->line, 41u);
  EXPECT_EQ(p->token, "X");
  EXPECT_EQ(p->message, "redefinition with another type (float here, float4 at a.shader:7); a global has one type");
}

TEST(GlobalDeclarationsTest, TheEndOfTheTextEndsADeclarationAndMustCloseItsBrackets) {
  // fuzz_hlsl's wrapper has nothing after the program: "float w[t w" at the end.
  auto last = find_declaration_problem("float f() { return 1; }\nfloat w[t w");
  ASSERT_TRUE(last);
  EXPECT_EQ(last->message, "an array size has two operands in a row, the second 'w'");
  EXPECT_EQ(last->line, 2u);
  auto open = find_declaration_problem("float f() { return (1; }");
  ASSERT_TRUE(open);
  EXPECT_EQ(open->message, "'}' does not close the '(' at line 1");
  auto never = find_declaration_problem("float f() { return 1;");
  ASSERT_TRUE(never);
  EXPECT_EQ(never->message, "'{' is never closed");
}

// Found by fuzz_hlsl: glslang crashes on a broken array size followed by an
// initializer list.
TEST(GlobalDeclarationsTest, AnArraySizeMustReadAsAnExpression) {
  const std::pair<const char*, const char*> bad[] = {
      {"static const float w[N\\] = {1, 2};", "an array size holds an unexpected '\\'"},
      {"static const float w[* 2] = {1, 2};", "an array size cannot start with '*'"},
      {"static const float w[,] = {1, 2};", "an array size cannot start with ','"},
      {"static const float w[2, 3] = {1, 2};", "an array size holds an unexpected ','"},
      {"static const float w[2 2] = {1, 2};", "an array size has two operands in a row, the second '2'"},
      {"static const float w[N|] = {1, 2};", "an array size cannot end with '|'"},
  };
  for (const auto& [text, message] : bad) {
    auto p = find_declaration_problem(text);
    ASSERT_TRUE(p) << text;
    EXPECT_EQ(p->message, message) << text;
    EXPECT_EQ(p->token, "[") << text;
  }
  for (const char* ok : {"float w[(N + 1) * 2];", "static const int N = 2; static const float w[-1 + N] = {1};", "float w[N][M];", "float w[];"}) {
    EXPECT_FALSE(find_declaration_problem(ok)) << ok;
  }
}

// Found by fuzz_hlsl (2026-12-06): glslang dereferences a null pointer in
// convertInitializerList on these sizes before an initializer list.
TEST(GlobalDeclarationsTest, AnInitializedArraysSizeNamesOnlyWhatIsDeclared) {
  const std::pair<const char*, const char*> bad[] = {
      {"static const float w[C + U] = {1, 2};", "undeclared identifier 'C' in the array size"},
      {"static const float w[C =T] {1, 2};", "an array size holds an unexpected '='"},
      {"static const float w[A.B] = {1, 2};", "an array size holds an unexpected '.'"},
  };
  for (const auto& [text, message] : bad) {
    auto p = find_declaration_problem(text);
    ASSERT_TRUE(p) << text;
    EXPECT_EQ(p->message, message) << text;
  }
  for (const char* ok : {"static const int C = 2; cbuffer B { int U; }; static const float w[C + U] = {1, 2};",
                         "float w[C + U];", "static const int N = 3; static const float w[(N)] = {1, 2, 3};"}) {
    EXPECT_FALSE(find_declaration_problem(ok)) << ok;
  }
}

// Found by fuzz_hlsl (2026-12-06): glslang crashes in handleReturnValue.
TEST(GlobalDeclarationsTest, AnUndeclaredNameInAReturnedConditionIsRefused) {
  auto p = find_declaration_problem("float4 f(bool b) {\n float4 c = 1;\n return b ? c : EXCOORD0c; }");
  ASSERT_TRUE(p);
  EXPECT_EQ(p->message, "undeclared identifier 'EXCOORD0c'");
  EXPECT_EQ(p->line, 3u);
  for (const char* ok : {"struct S { float4 v; }; float4 f(bool b, S s) { return b ? (half4)s.v : saturate(s.v); }",
                         "float4 f(bool b, float4 c) { return b ? c : float4(0, 0, 0, 1); }",
                         "bool f(bool b) { return b ? true : false; }"}) {
    EXPECT_FALSE(find_declaration_problem(ok)) << ok;
  }
}

// Found by fuzz_hlsl (2026-12-06): glslang crashes in wrapupSwitchSubsequence.
TEST(GlobalDeclarationsTest, ACaseLabelOutsideASwitchIsRefused) {
  auto p = find_declaration_problem("struct L { float3 c; float3 f(float3 n) { return c case 0: n; } };");
  ASSERT_TRUE(p);
  EXPECT_EQ(p->message, "'case' outside a switch statement");
  EXPECT_FALSE(find_declaration_problem(
      "int f(int x) { switch (x) { case 0: { if (x) { return 1; } } default: return 2; } return 0; }"));
}

// Found by fuzz_hlsl (2026-12-06): glslang crashes in handleAssign when the
// entry point returns a buffer.
TEST(GlobalDeclarationsTest, AnEntryPointReturningAResourceIsRefused) {
  const char* text = "RWStructuredBuffer<float4> _U vert(float4 p : POSITION) : SV_Position { return p; }";
  auto p = find_declaration_problem(text, "vert");
  ASSERT_TRUE(p);
  EXPECT_EQ(p->message, "the entry point 'vert' returns a 'RWStructuredBuffer<float4>'; an entry point returns "
                        "values or structs, not resource objects");
  EXPECT_FALSE(find_declaration_problem(text, "frag"));
}

// Found by fuzz_hlsl (2026-12-06, second run): glslang crashes in
// remapEntryPointIO on an unnamed parameter of the entry point, in
// growGlobalUniformBlock on ", name" after a function's semantic, and in
// convertInitializerList on a static const array sized by undeclared names.
TEST(GlobalDeclarationsTest, AnEntryPointsParametersAreNamed) {
  auto p = find_declaration_problem("float4 vert(uint : SV_VertexID) : SV_Position { return 0; }", "vert");
  ASSERT_TRUE(p);
  EXPECT_EQ(p->message, "a parameter of the entry point 'vert' has no name");
  for (const char* ok : {"float4 vert(void) : SV_Position { return 0; }", "float4 vert() : SV_Position { return 0; }",
                         "struct v2g { float4 p; }; struct g2f { float4 p; };\n"
                         "void vert(triangle v2g IN[3], inout TriangleStream<g2f> s, uint id : SV_PrimitiveID) {}",
                         "struct v2h { float4 p; }; float4 vert(InputPatch<v2h, 3> patch, uint i : SV_OutputControlPointID) "
                         ": SV_Position { return 0; }"}) {
    EXPECT_FALSE(find_declaration_problem(ok, "vert")) << ok;
  }
  EXPECT_FALSE(find_declaration_problem("float f(float) { return 0; }", "vert"));
}

TEST(GlobalDeclarationsTest, NothingFollowsAFunctionsSemanticButItsBody) {
  auto p = find_declaration_problem("half S;\nfloat4 vert(float4 p : POSITION) : S, V_Position\nhalf _G S;");
  ASSERT_TRUE(p);
  EXPECT_EQ(p->message, "unexpected ',' after the declaration of function 'vert'; a function's parameters are "
                        "followed by its body or ';'");
}

TEST(GlobalDeclarationsTest, AStaticConstArraysSizeNamesOnlyWhatIsDeclared) {
  auto p = find_declaration_problem("static const float w[C & OUNT];");
  ASSERT_TRUE(p);
  EXPECT_EQ(p->message, "undeclared identifier 'C' in the array size");
  EXPECT_FALSE(find_declaration_problem("float w[C & OUNT];"));
}

TEST(GlobalDeclarationsTest, WhatGlslangTakesIsNoProblem) {
  for (const char* ok : {"float4 X; float4 X;", "half4 X; float4 X;", "static float X; static float X;",
                         "struct S { float4 X; }; float X;", "Texture2D<float4> T; SamplerState s;",
                         "cbuffer C : register(b0) { float4 A; } float4 A;", "float a[2] = {1, 2};",
                         "float4 f(float4 p : POSITION) : SV_Position { float X = 1; return p * X; } float4 X;",
                         "[numthreads(8, 8, 1)] void cs(uint3 id : SV_DispatchThreadID) {}"}) {
    EXPECT_FALSE(find_declaration_problem(ok)) << ok;
  }
}

}  // namespace
}  // namespace facet::backend

namespace facet::backend {
namespace {

TEST(FunctionPositionTest, FindsATopLevelDeclarationByNameThroughLineDirectives) {
  std::string text = "#line 3 \"a.shader\"\nfloat4 helper(float x) { return vert(x); }\n#line 20 \"b.cginc\"\n\n"
                     "float4 vert(float x) : SV_Position { return 0; }\n";
  auto vert = function_position(text, "vert");
  ASSERT_TRUE(vert);
  EXPECT_EQ(vert->file, "b.cginc");  // not the call inside helper's body
  EXPECT_EQ(vert->line, 21u);
  EXPECT_EQ(vert->token, "vert");
  EXPECT_FALSE(function_position(text, "frag"));
  auto first = function_position(text, "");
  ASSERT_TRUE(first);
  EXPECT_EQ(first->file, "a.shader");
  EXPECT_EQ(first->line, 3u);
  EXPECT_EQ(first->token, "float4");
}

}  // namespace
}  // namespace facet::backend
