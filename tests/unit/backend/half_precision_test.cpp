// 16-bit compute kernels: to_half_precision's rewrite, glslang's 16-bit HLSL
// types (BackendOptions::hlsl_16bit_types) and the stdlib compiled in half
// through half_precision_stdlib and FacetHalf.hlsl.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "facet/backend.h"

namespace facet::backend {
namespace {

TEST(HalfPrecisionRewriteTest, RenamesFloatTypesAndSuffixesFloatingLiterals) {
  EXPECT_EQ(to_half_precision("float a = 0.5 * b; float3 v = float3(1.0, 2.5f, .25);"),
            "half a = 0.5h * b; half3 v = half3(1.0h, 2.5h, .25h);");
  EXPECT_EQ(to_half_precision("float4x4 m; float2x3 n; float1 s;"), "half4x4 m; half2x3 n; half1 s;");
  EXPECT_EQ(to_half_precision("#define FACET_MIN_NOV 1e-4\n#define K 453.5"), "#define FACET_MIN_NOV 1e-4h\n#define K 453.5h");
  EXPECT_EQ(to_half_precision("x = 6.103515625e-5 + 2E+3f;"), "x = 6.103515625e-5h + 2E+3h;");
}

TEST(HalfPrecisionRewriteTest, LeavesIntegersIdentifiersCommentsAndStringsAlone) {
  EXPECT_EQ(to_half_precision("int i = 2; uint u = 3u; int h = 0x1F; x[16]; double d = 1.0L;"),
            "int i = 2; uint u = 3u; int h = 0x1F; x[16]; double d = 1.0L;");
  EXPECT_EQ(to_half_precision("floaty float5 asfloat(x) myfloat p0 f32tof16"), "floaty float5 asfloat(x) myfloat p0 f32tof16");
  EXPECT_EQ(to_half_precision("// float 0.5\n/* float3 1.0 */ \"float 2.0\" float"),
            "// float 0.5\n/* float3 1.0 */ \"float 2.0\" half");
  EXPECT_EQ(to_half_precision("0.5h 1.0H"), "0.5h 1.0h");
  const std::string lines = "a\nfloat b = 1.0;\n\n// c\n", rewritten = to_half_precision(lines);
  EXPECT_EQ(std::count(lines.begin(), lines.end(), '\n'), std::count(rewritten.begin(), rewritten.end(), '\n'));
}

constexpr const char* kKernel = R"(
StructuredBuffer<float> facet_in : register(t0);
RWStructuredBuffer<float> facet_out : register(u1);
[numthreads(64, 1, 1)] void main(uint3 id : SV_DispatchThreadID) {
  half a = (half)facet_in[id.x];
  half b = a * a + (half)0.5;
  facet_out[id.x] = (float)b;
}
)";

size_t occurrences(const std::string& text, const std::string& what) {
  size_t n = 0;
  for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

TEST(HalfPrecisionCompileTest, With16BitTypesHalfIsAFloat16AndTheKernelDeclaresFloat16) {
  Diagnostics diags;
  BackendOptions options;
  options.hlsl_16bit_types = true;
  auto spirv = compile_hlsl_compute(kKernel, "main", options, diags);
  ASSERT_TRUE(spirv) << (diags.size() ? diags.all()[0].message : "");
  std::string text = disassemble(*spirv);
  EXPECT_NE(text.find("OpCapability Float16"), std::string::npos) << text;
  EXPECT_NE(text.find("OpTypeFloat 16"), std::string::npos) << text;
  EXPECT_GE(occurrences(text, "OpFConvert"), 2u) << "float in, half arithmetic, float out";
  EXPECT_EQ(text.find("SPV_AMD_gpu_shader_half_float"), std::string::npos) << "no vendor extension: Vulkan 1.2's Float16";

  // Without the option (as every pass of a .shader is compiled), half is 32-bit.
  Diagnostics plain_diags;
  auto plain = compile_hlsl_compute(kKernel, "main", BackendOptions{}, plain_diags);
  ASSERT_TRUE(plain);
  EXPECT_EQ(disassemble(*plain).find("Float16"), std::string::npos);
}

TEST(HalfPrecisionCompileTest, FacetHalfDefinesTheIntrinsicsInHalfAndNothingWhereHalfIs32Bit) {
  const std::string kernel = std::string("#include \"FacetHalf.hlsl\"\n") + R"(
RWStructuredBuffer<float> facet_out : register(u1);
[numthreads(64, 1, 1)] void main(uint3 id : SV_DispatchThreadID) {
  half a = (half)facet_out[id.x];
  half3 v = normalize(half3(a, 0.5h, 1.0h));
  half r = sqrt(max(a, 0.25h)) + dot(v, cross(v, v)) + lerp(a, 1.0h, 0.5h) + saturate(a);
  facet_out[id.x] = (float)r;
}
)";
  Diagnostics diags;
  BackendOptions options;
  options.hlsl_16bit_types = true;
  auto spirv = compile_hlsl_compute(kernel, "main", options, diags);
  ASSERT_TRUE(spirv) << (diags.size() ? diags.all()[0].message : "");

  // Without 16-bit types (half is float) the file defines nothing, and the
  // same kernel compiles against the float intrinsics.
  Diagnostics plain_diags;
  auto plain = compile_hlsl_compute(kernel, "main", BackendOptions{}, plain_diags);
  ASSERT_TRUE(plain) << (plain_diags.size() ? plain_diags.all()[0].message : "");
  EXPECT_EQ(disassemble(*plain).find("Float16"), std::string::npos);
}

// The whole of FacetBRDF.hlsl compiles in half (every function of it is
// type-checked), and GGX D's arithmetic is 16-bit: its multiplies are on half.
TEST(HalfPrecisionCompileTest, TheStdlibBrdfCompilesInHalfThroughTheHalfResolver) {
  const std::string kernel = std::string("#include \"FacetHalf.hlsl\"\n#include \"FacetBRDF.hlsl\"\n") + R"(
StructuredBuffer<float> facet_in : register(t0);
RWStructuredBuffer<float> facet_out : register(u1);
[numthreads(64, 1, 1)] void main(uint3 id : SV_DispatchThreadID) {
  half NoH = (half)facet_in[2 * id.x], alpha = (half)facet_in[2 * id.x + 1];
  facet_out[id.x] = (float)FacetD_GGX(NoH, alpha);
}
)";
  Diagnostics diags;
  BackendOptions options;
  options.hlsl_16bit_types = true;
  options.stdlib_dir = default_stdlib_dir();
  options.resolver = half_precision_stdlib(options.stdlib_dir);
  auto spirv = compile_hlsl_compute(kernel, "main", options, diags);
  ASSERT_TRUE(spirv) << (diags.size() ? diags.all()[0].message : "");
  std::string text = disassemble(*spirv);
  EXPECT_NE(text.find("OpFMul %half"), std::string::npos) << text;
  EXPECT_NE(text.find("OpFDiv %half"), std::string::npos) << text;
  EXPECT_EQ(text.find("OpFMul %float"), std::string::npos) << "nothing of D is left in fp32:\n" << text;

  // Without the rewrite, glslang refuses the stdlib in 16-bit mode: its float
  // literals stay 32-bit and do not convert to half implicitly.
  Diagnostics refused;
  BackendOptions unrewritten;
  unrewritten.hlsl_16bit_types = true;
  std::string direct = kernel;
  direct.replace(direct.find("#include \"FacetBRDF"), 0, "#define float half\n#define float3 half3\n");
  EXPECT_FALSE(compile_hlsl_compute(direct, "main", unrewritten, refused));
}

}  // namespace
}  // namespace facet::backend
