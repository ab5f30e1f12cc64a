// The Backend's glslang work in a child process (crash_isolation.h) against
// the same work in this process (FACET_GLSLANG_IN_PROCESS=1).
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstdlib>
#include <memory>

#include "backend_test_util.h"

namespace facet::backend {
namespace {

using ::testing::HasSubstr;
using testing::load_shader;
using testing::make_shader;
using testing::TestShader;

// Debian 12's glslang dereferences a null pointer in
// HlslParseContext::handleAssign (from transformEntryPoint) on an entry
// point whose parameter is a struct holding a buffer; fxc rejects it.
constexpr const char* kGlslangCrash =
    "Shader \"Test/Crash\" {\n"
    "  SubShader {\n"
    "    Pass {\n"
    "      HLSLPROGRAM\n"
    "      #pragma vertex vert\n"
    "      #pragma fragment frag\n"
    "      struct O { RWStructuredBuffer<float4> b; };\n"
    "      float4 vert(O o) : SV_Position { return 0; }\n"
    "      float4 frag() : SV_Target { return 1; }\n"
    "      ENDHLSL\n"
    "    }\n"
    "  }\n"
    "}\n";

// A Backend made while FACET_GLSLANG_IN_PROCESS is `value` (unset when null).
std::unique_ptr<Backend> backend_with(const char* value) {
  const char* before = std::getenv("FACET_GLSLANG_IN_PROCESS");
  std::string saved = before ? before : "";
  if (value) {
    setenv("FACET_GLSLANG_IN_PROCESS", value, 1);
  } else {
    unsetenv("FACET_GLSLANG_IN_PROCESS");
  }
  auto backend = std::make_unique<Backend>();
  if (before) {
    setenv("FACET_GLSLANG_IN_PROCESS", saved.c_str(), 1);
  } else {
    unsetenv("FACET_GLSLANG_IN_PROCESS");
  }
  return backend;
}

TEST(BackendIsolationTest, AChildCompilesWhatThisProcessCompilesByteForByte) {
  std::unique_ptr<Backend> isolated = backend_with(nullptr);
  std::unique_ptr<Backend> in_process = backend_with("1");
  for (const char* file : {"unlit.shader", "forward_lit.shader", "geometry.shader", "dx9.shader"}) {
    TestShader t = load_shader(file);
    for (Stage stage : {Stage::vertex, Stage::geometry, Stage::fragment}) {
      if (!t.program.has_stage(stage)) continue;
      Diagnostics a_diags, b_diags;
      auto a = isolated->compile(t.shader, t.program, stage, {}, {}, t.sources, a_diags);
      auto b = in_process->compile(t.shader, t.program, stage, {}, {}, t.sources, b_diags);
      ASSERT_TRUE(a && b) << file << "\n" << render_text(a_diags, t.sources) << render_text(b_diags, t.sources);
      EXPECT_EQ(a->spirv, b->spirv) << file << " " << stage_name(stage);
      EXPECT_EQ(a->included_files, b->included_files) << file;
      EXPECT_EQ(render_text(a_diags, t.sources), render_text(b_diags, t.sources)) << file;
    }
  }
}

TEST(BackendIsolationTest, ErrorsFromAChildAreLocatedAsInThisProcess) {
  std::unique_ptr<Backend> isolated = backend_with(nullptr);
  std::unique_ptr<Backend> in_process = backend_with("1");
  for (const char* file : {"error.shader", "syntax_error.shader", "include_error.shader"}) {
    TestShader t = load_shader(file);
    Diagnostics a_diags, b_diags;
    auto a = isolated->compile(t.shader, t.program, Stage::fragment, {}, {}, t.sources, a_diags);
    auto b = in_process->compile(t.shader, t.program, Stage::fragment, {}, {}, t.sources, b_diags);
    EXPECT_FALSE(a || b) << file;
    EXPECT_TRUE(a_diags.has_errors()) << file;
    EXPECT_EQ(render_text(a_diags, t.sources), render_text(b_diags, t.sources)) << file;
  }
}

TEST(BackendIsolationTest, AProgramGlslangCrashesOnIsAnErrorAtItsEntryFunctionAndTheBackendGoesOn) {
  std::unique_ptr<Backend> backend = backend_with(nullptr);
  TestShader t = make_shader("Crash.shader", kGlslangCrash);
  Diagnostics diags;
  EXPECT_FALSE(backend->compile(t.shader, t.program, Stage::vertex, {}, {}, t.sources, diags));
  std::string text = render_text(diags, t.sources);
  EXPECT_THAT(text, HasSubstr("Crash.shader:8:14: error: 'vert': glslang crashed on this program")) << text;
  // The fragment stage of the same program, and the next program, compile.
  Diagnostics fragment_diags;
  EXPECT_TRUE(backend->compile(t.shader, t.program, Stage::fragment, {}, {}, t.sources, fragment_diags))
      << render_text(fragment_diags, t.sources);
  TestShader next = load_shader("unlit.shader");
  Diagnostics next_diags;
  EXPECT_TRUE(backend->compile(next.shader, next.program, Stage::vertex, {}, {}, next.sources, next_diags))
      << render_text(next_diags, next.sources);
}

}  // namespace
}  // namespace facet::backend
