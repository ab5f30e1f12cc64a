// HLSL programs see fxc's predefined macros, not glslang's GLSL ones: the
// names of GLSL extensions, VULKAN and GL_SPIRV are undefined in CGPROGRAM
// and HLSLPROGRAM (FXAA 3.11 picks its gather path by GL_ARB_gpu_shader5).
#include <gtest/gtest.h>

#include "stdlib_compile.h"

namespace facet {
namespace {

std::string program(std::string_view keyword, std::string_view end_keyword) {
  return std::string(R"(Shader "Test/Predefines" { SubShader { Pass {
)") + std::string(keyword) + R"(
#pragma vertex vert
#pragma fragment frag
#if defined(GL_ARB_gpu_shader5) || defined(GL_NV_gpu_shader5) || defined(GL_KHR_shader_subgroup_basic)
#error a GLSL extension macro is defined
#endif
#if defined(VULKAN) || defined(GL_SPIRV) || defined(GL_GOOGLE_include_directive) || defined(GL_core_profile)
#error a glslang macro is defined
#endif
#if !defined(SHADER_API_VULKAN)
#error SHADER_API_VULKAN is missing
#endif
float4 vert(float4 v : POSITION) : SV_Position { return v; }
float4 frag() : SV_Target { return 1; }
)" + std::string(end_keyword) + R"(
} } }
)";
}

TEST(HlslPredefinesTest, CgProgramsSeeNoGlslangGlslMacros) {
  auto out = stdlib_test::compile_text("predefines.shader", program("CGPROGRAM", "ENDCG"));
  EXPECT_TRUE(out.ok) << out.log;
}

TEST(HlslPredefinesTest, HlslProgramsSeeNoGlslangGlslMacros) {
  auto out = stdlib_test::compile_text("predefines.shader", program("HLSLPROGRAM", "ENDHLSL"));
  EXPECT_TRUE(out.ok) << out.log;
}

TEST(HlslPredefinesTest, GlslProgramsKeepTheirExtensionMacros) {
  auto out = stdlib_test::compile_text("predefines.shader", R"(Shader "Test/GlslPredefines" { SubShader { Pass {
GLSLPROGRAM
#if !defined(GL_ARB_gpu_shader5) || !defined(VULKAN)
#error glslang's GLSL macros are missing
#endif
#ifdef VERTEX
layout(location = 0) in vec4 position;
void main() { gl_Position = position; }
#endif
#ifdef FRAGMENT
layout(location = 0) out vec4 color;
void main() { color = vec4(1.0); }
#endif
ENDGLSL
} } }
)");
  EXPECT_TRUE(out.ok) << out.log;
}

}  // namespace
}  // namespace facet
