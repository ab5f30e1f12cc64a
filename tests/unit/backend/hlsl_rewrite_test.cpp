// Matrix swizzles, which glslang lacks, become element reads before glslang.
#include <gtest/gtest.h>

#include "backend/hlsl_rewrite.h"

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

}  // namespace
}  // namespace facet::backend
