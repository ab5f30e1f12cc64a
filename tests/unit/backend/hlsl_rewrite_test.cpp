// Rewrites before glslang: matrix swizzles, which glslang lacks, become
// element reads; global uniforms a program assigns become static copies.
#include <gtest/gtest.h>

#include "hlsl_rewrite.h"

namespace facet::backend {
namespace {

struct RewriteCase {
  const char* name;
  const char* input;
  const char* output;
};

class MatrixSwizzleTest : public testing::TestWithParam<RewriteCase> {};

TEST_P(MatrixSwizzleTest, RewritesToElementReads) {
  EXPECT_EQ(rewrite_matrix_swizzles(GetParam().input), GetParam().output);
}

INSTANTIATE_TEST_SUITE_P(
    Forms, MatrixSwizzleTest,
    testing::Values(
        RewriteCase{"one_based_column", "float3 p = m._14_24_34;", "float3 p = float3(m[0][3], m[1][3], m[2][3]);"},
        RewriteCase{"zero_based", "x = m._m00_m11;", "x = float2(m[0][0], m[1][1]);"},
        RewriteCase{"single_element", "s = m._12 + 1;", "s = (m[0][1]) + 1;"},
        RewriteCase{"member_and_index_chain", "v = a.b[i]._11_22_33_44;",
                    "v = float4(a.b[i][0][0], a.b[i][1][1], a.b[i][2][2], a.b[i][3][3]);"},
        RewriteCase{"member_named_like_a_property_stays", "c = s._Color + s._15x;", "c = s._Color + s._15x;"},
        RewriteCase{"out_of_range_stays", "c = m._05 + m._m44;", "c = m._05 + m._m44;"},
        RewriteCase{"comment_and_string_stay", "// m._11\n/* m._22 */ \"m._33\" m._44",
                    "// m._11\n/* m._22 */ \"m._33\" (m[3][3])"},
        RewriteCase{"five_components_stay", "m._11_12_13_14_21", "m._11_12_13_14_21"},
        RewriteCase{"lines_kept", "a = m._11;\nb = m._22;\n", "a = (m[0][0]);\nb = (m[1][1]);\n"}),
    [](const testing::TestParamInfo<RewriteCase>& info) { return std::string(info.param.name); });

class AssignedUniformTest : public testing::TestWithParam<RewriteCase> {};

TEST_P(AssignedUniformTest, AssignedNamesBecomeStaticCopiesOnTheSameLine) {
  EXPECT_EQ(rewrite_assigned_uniforms(GetParam().input, {"T", "col"}), GetParam().output);
}

INSTANTIATE_TEST_SUITE_P(
    Forms, AssignedUniformTest,
    testing::Values(
        RewriteCase{"single", "float T;", "float T_facet_uniform; static float T = T_facet_uniform;"},
        RewriteCase{"uniform_keyword_and_comment", "uniform float T; // time",
                    "float T_facet_uniform; static float T = T_facet_uniform; // time"},
        RewriteCase{"list_splits", "float A,B, T ,N;",
                    "float A; float B; float T_facet_uniform; static float T = T_facet_uniform; float N;"},
        RewriteCase{"initializer_is_the_uniforms_default", "float3 col = float3(0, 0, 0);",
                    "float3 col_facet_uniform = float3(0, 0, 0); static float3 col = col_facet_uniform;"},
        RewriteCase{"list_with_initializers", "float N = max(1, 2), T = 0.5;",
                    "float N = max(1, 2); float T_facet_uniform = 0.5; static float T = T_facet_uniform;"},
        RewriteCase{"unassigned_list_stays", "float A, B;", "float A, B;"},
        RewriteCase{"static_stays", "static float T;", "static float T;"},
        RewriteCase{"static_beside_an_assigned_one_stays", "static float k = 2; float T;",
                    "static float k = 2; float T_facet_uniform; static float T = T_facet_uniform;"},
        RewriteCase{"semantic_stays", "float4 T : register(c0);", "float4 T : register(c0);"},
        RewriteCase{"array_stays", "float T[4];", "float T[4];"},
        RewriteCase{"prototype_stays", "float T(float x);", "float T(float x);"},
        RewriteCase{"inside_a_function_stays", "void f() {\nfloat T;\n}", "void f() {\nfloat T;\n}"},
        RewriteCase{"code_after_the_semicolon_stays", "float T; T = 1;", "float T; T = 1;"},
        RewriteCase{"several_declarations_on_a_line", "float A; float3 col;  // c",
                    "float A; float3 col_facet_uniform; static float3 col = col_facet_uniform;  // c"},
        RewriteCase{"a_rewritten_line_is_rewritten_again",
                    "float T_facet_uniform; static float T = T_facet_uniform; float col;",
                    "float T_facet_uniform; static float T = T_facet_uniform; float col_facet_uniform; "
                    "static float col = col_facet_uniform;"},
        RewriteCase{"braces_in_comments_and_strings_do_not_nest",
                    "// if (x) {\n/* { */ #pragma message \"{\"\nfloat T;",
                    "// if (x) {\n/* { */ #pragma message \"{\"\nfloat T_facet_uniform; static float T = T_facet_uniform;"},
        RewriteCase{"braces_of_a_block_comment_over_lines_do_not_nest", "/*\n{\n*/\nfloat T;",
                    "/*\n{\n*/\nfloat T_facet_uniform; static float T = T_facet_uniform;"},
        RewriteCase{"lines_kept", "int I;\nfloat T, col;\n",
                    "int I;\nfloat T_facet_uniform; static float T = T_facet_uniform; float col_facet_uniform; "
                    "static float col = col_facet_uniform;\n"}),
    [](const testing::TestParamInfo<RewriteCase>& info) { return std::string(info.param.name); });

}  // namespace
}  // namespace facet::backend

namespace facet::backend {
namespace {

class ScalarSwizzleTest : public testing::TestWithParam<RewriteCase> {};

TEST_P(ScalarSwizzleTest, SwizzlesOfOneComponentNamesAreBlankedOthersStay) {
  EXPECT_EQ(drop_scalar_swizzles(GetParam().input), GetParam().output);
}

INSTANTIATE_TEST_SUITE_P(
    Forms, ScalarSwizzleTest,
    testing::Values(
        // Unity's UNITY_FOG_COORDS and UNITY_TRANSFER_FOG, expanded.
        RewriteCase{"fog_member_written", "struct v2f { float1 fogCoord : TEXCOORD7; }; o.fogCoord.x = f;",
                    "struct v2f { float1 fogCoord : TEXCOORD7; }; o.fogCoord   = f;"},
        RewriteCase{"read_and_red", "half1 h; float y = h.r + i.h.x;", "half1 h; float y = h   + i.h  ;"},
        RewriteCase{"scalar_too", "float s = 1; s.x = 2;", "float s = 1; s   = 2;"},
        RewriteCase{"wider_swizzle_stays", "float1 a; float2 b = a.xx;", "float1 a; float2 b = a.xx;"},
        RewriteCase{"declared_wider_elsewhere_stays", "float1 c; float4 c2; struct S { float4 c; }; s.c.x = 1;",
                    "float1 c; float4 c2; struct S { float4 c; }; s.c.x = 1;"},
        RewriteCase{"struct_typed_stays", "float1 p; Light p2; struct T { Light p; }; t.p.x = 1;",
                    "float1 p; Light p2; struct T { Light p; }; t.p.x = 1;"},
        RewriteCase{"other_names_stay", "float4 v; v.x = 1;", "float4 v; v.x = 1;"},
        // Declared as a scalar in one function and as the second of a list in another.
        RewriteCase{"later_declarator_of_a_list_stays", "float w = 1; return w.x; float4 base, w; base * w.x;",
                    "float w = 1; return w.x; float4 base, w; base * w.x;"},
        RewriteCase{"template_typed_stays", "float v; vector<float, 4> v; v.x = 1;",
                    "float v; vector<float, 4> v; v.x = 1;"},
        RewriteCase{"comments_and_strings_skip", "float1 f; // f.x\n\"f.x\" f.x",
                    "float1 f; // f.x\n\"f.x\" f  "}),
    [](const testing::TestParamInfo<RewriteCase>& info) { return std::string(info.param.name); });

}  // namespace
}  // namespace facet::backend
