// glslang's messages mapped back to .shader (and included file) positions.
#include <gtest/gtest.h>

#include "backend_test_util.h"

namespace facet::backend {
namespace {

using testing::load_shader;
using testing::TestShader;

class BackendDiagnosticsTest : public ::testing::Test {
 protected:
  // Compiles `stage` expecting failure; returns the diagnostics as text.
  std::string fail(TestShader& t, Stage stage = Stage::fragment) {
    auto compiled = backend_.compile(t.shader, t.program, stage, {}, {}, t.sources, diags_);
    EXPECT_FALSE(compiled);
    EXPECT_TRUE(diags_.has_errors());
    return render_text(diags_, t.sources);
  }

  // "path:line:col" of the first occurrence of `needle` in file `file`.
  static std::string position_of(const SourceMap& sources, FileId file, const std::string& needle) {
    size_t at = sources.text(file).find(needle);
    EXPECT_NE(at, std::string::npos) << needle;
    LineColumn lc = sources.line_column(file, uint32_t(at));
    return sources.path(file) + ":" + std::to_string(lc.line) + ":" + std::to_string(lc.column);
  }

  const Diagnostic& first_error() const {
    for (const Diagnostic& d : diags_.all()) {
      if (d.severity == Severity::error) return d;
    }
    static const Diagnostic none;
    ADD_FAILURE() << "no error";
    return none;
  }

  Backend backend_;
  Diagnostics diags_;
};

TEST_F(BackendDiagnosticsTest, ErrorInBodyPointsAtShaderLineAndColumn) {
  TestShader t = load_shader("error.shader");
  std::string text = fail(t);
  std::string where = position_of(t.sources, t.shader.file, "undefinedThing");
  EXPECT_NE(text.find(where + ": error: use of undeclared identifier 'undefinedThing'"), std::string::npos) << text;
  // Exactly line 28, column 50 of the file, counted by hand.
  EXPECT_NE(where.find("error.shader:28:50"), std::string::npos) << where;
  const Diagnostic& d = first_error();
  EXPECT_EQ(d.id, DiagId::hlsl_error);
  EXPECT_EQ(d.span.end - d.span.begin, std::string("undefinedThing").size());
  EXPECT_TRUE(d.include_stack.empty());
  // Follow-on errors of the same line are not repeated.
  EXPECT_EQ(diags_.error_count(), 1u) << text;
  // The caret excerpt shows the .shader line itself.
  EXPECT_NE(text.find("   28 |                 float3 n = normalize(i.normal) * undefinedThing;"), std::string::npos)
      << text;
}

TEST_F(BackendDiagnosticsTest, NoiseLinesAreDropped) {
  TestShader t = load_shader("error.shader");
  std::string text = fail(t);
  EXPECT_EQ(text.find("compilation errors"), std::string::npos) << text;
  EXPECT_EQ(text.find("No code generated"), std::string::npos) << text;
  EXPECT_EQ(text.find("compilation terminated"), std::string::npos) << text;
}

TEST_F(BackendDiagnosticsTest, MissingIncludeIsLocatedAtTheDirective) {
  TestShader t = load_shader("missing_include.shader");
  std::string text = fail(t);
  const Diagnostic& d = first_error();
  EXPECT_EQ(d.id, DiagId::backend_include_not_found);
  EXPECT_EQ(d.message, "include file 'DoesNotExist.cginc' not found");
  std::string where = position_of(t.sources, t.shader.file, "\"DoesNotExist.cginc\"");
  EXPECT_NE(text.find(where + ": error: include file 'DoesNotExist.cginc' not found"), std::string::npos) << text;
  ASSERT_FALSE(d.notes.empty());
  EXPECT_NE(d.notes[0].message.find("stdlib"), std::string::npos) << d.notes[0].message;
}

// After `#line 5 "other.cginc"` glslang names a file the SourceMap does not
// have: the error was printed with no place at all.
TEST_F(BackendDiagnosticsTest, MissingIncludeAfterALineDirectiveIsLocatedAtTheDirective) {
  TestShader t = load_shader("missing_include_after_line.shader");
  std::string text = fail(t);
  const Diagnostic& d = first_error();
  EXPECT_EQ(d.id, DiagId::backend_include_not_found);
  ASSERT_TRUE(d.span.has_location()) << text;
  std::string where = position_of(t.sources, t.shader.file, "\"DoesNotExist.cginc\"");
  EXPECT_NE(text.find(where + ": error: include file 'DoesNotExist.cginc' not found"), std::string::npos) << text;
}

TEST_F(BackendDiagnosticsTest, ErrorInIncludedFileHasIncludeStack) {
  TestShader t = load_shader("include_error.shader");
  std::string text = fail(t);
  const Diagnostic& d = first_error();
  ASSERT_TRUE(d.span.has_location()) << text;
  EXPECT_TRUE(t.sources.path(d.span.file).ends_with("include/broken.cginc")) << t.sources.path(d.span.file);
  EXPECT_NE(text.find(position_of(t.sources, d.span.file, "xyz") + ": error:"), std::string::npos) << text;
  // broken.cginc <- outer.cginc line 5 <- include_error.shader line 10.
  ASSERT_EQ(d.include_stack.size(), 2u) << text;
  FileId outer = d.include_stack[0].file;
  EXPECT_TRUE(t.sources.path(outer).ends_with("include/outer.cginc"));
  EXPECT_EQ(t.sources.line_column(outer, d.include_stack[0].begin).line, 5u);
  EXPECT_EQ(d.include_stack[1].file, t.shader.file);
  EXPECT_EQ(t.sources.line_column(t.shader.file, d.include_stack[1].begin).line, 10u);
  EXPECT_NE(text.find("In file included from"), std::string::npos) << text;
  // What glslang says after its HLSL parser gave up is not repeated.
  EXPECT_EQ(diags_.error_count(), 1u) << text;
}

TEST_F(BackendDiagnosticsTest, ErrorInCgIncludeChunkMapsToItsLine) {
  TestShader t = load_shader("cginclude_error.shader");
  std::string text = fail(t);
  std::string where = position_of(t.sources, t.shader.file, "missingScale");
  EXPECT_NE(where.find("cginclude_error.shader:7:"), std::string::npos);
  EXPECT_NE(text.find(where + ": error: use of undeclared identifier 'missingScale'"), std::string::npos) << text;
}

TEST_F(BackendDiagnosticsTest, MissingSemicolonPointsAfterThePreviousToken) {
  TestShader t = load_shader("syntax_error.shader");
  std::string text = fail(t);
  const Diagnostic& d = first_error();
  EXPECT_EQ(d.message, "expected ';'") << text;
  // glslang notices the missing ';' at "return" on line 14; it belongs right
  // after "fixed4(1, 0, 0, 1)" on line 13, as Clang points it.
  EXPECT_EQ(d.span.file, t.shader.file);
  LineColumn lc = t.sources.line_column(d.span.file, d.span.begin);
  EXPECT_EQ(lc.line, 13u) << text;
  EXPECT_EQ(lc.column, 46u) << text;
}

TEST_F(BackendDiagnosticsTest, MissingEntryFunctionPointsAtThePragma) {
  TestShader t = load_shader("missing_entry.shader");
  std::string text = fail(t, Stage::vertex);
  EXPECT_NE(text.find("vertex entry point 'vertex_main' is not defined"), std::string::npos) << text;
  const Diagnostic& d = first_error();
  EXPECT_EQ(t.sources.line_column(d.span.file, d.span.begin).line, 8u) << text;
  // Only one diagnostic for it, although glslang complains twice.
  size_t count = 0;
  for (const Diagnostic& x : diags_.all()) count += x.message.find("entry point") != std::string::npos;
  EXPECT_EQ(count, 1u) << text;
}

TEST_F(BackendDiagnosticsTest, BadDefineIsLocatedInThePrelude) {
  TestShader t = load_shader("unlit.shader");
  BackendOptions options;
  options.defines = {{"BROKEN(", "1"}};
  auto compiled = backend_.compile(t.shader, t.program, Stage::vertex, {}, options, t.sources, diags_);
  EXPECT_FALSE(compiled);
  ASSERT_TRUE(diags_.has_errors());
  const Diagnostic& d = first_error();
  ASSERT_TRUE(d.span.has_location());
  EXPECT_EQ(t.sources.path(d.span.file), "<prelude>");
  EXPECT_NE(t.sources.line_text(d.span.file, t.sources.line_column(d.span.file, d.span.begin).line).find("BROKEN("),
            std::string::npos);
}

TestShader inline_shader(const std::string& body) {
  return testing::make_shader(std::string(FACET_TESTDATA_DIR) + "/backend/inline.shader",
                              "Shader \"Inline\" { SubShader { Pass {\nCGPROGRAM\n"
                              "#pragma vertex vert\n#pragma fragment frag\n" +
                                  body + "\nENDCG\n} } }\n");
}

TEST_F(BackendDiagnosticsTest, DeepNestingIsRefusedBeforeGlslang) {
  TestShader t = inline_shader("float4 vert(float4 p : POSITION) : SV_POSITION { return " + std::string(5000, '(') +
                               "p" + std::string(5000, ')') + "; }\nfixed4 frag() : SV_Target { return 1; }");
  std::string text = fail(t, Stage::vertex);
  EXPECT_EQ(first_error().id, DiagId::backend_nesting_too_deep) << text;
  EXPECT_EQ(t.sources.line_column(t.shader.file, first_error().span.begin).line, 5u);
}

TEST_F(BackendDiagnosticsTest, RecursiveIncludeStopsWithAnError) {
  TestShader t = inline_shader("#include \"include/self.cginc\"\n"
                               "float4 vert(float4 p : POSITION) : SV_POSITION { return p; }\n"
                               "fixed4 frag() : SV_Target { return 1; }");
  std::string text = fail(t);
  EXPECT_EQ(first_error().id, DiagId::backend_include_not_found) << text;
  EXPECT_NE(first_error().message.find("nested more than"), std::string::npos) << text;
}

TEST_F(BackendDiagnosticsTest, ErrorDirectiveIsReportedWhereItIs) {
  TestShader t = inline_shader("#if SHADER_TARGET < 30\n#error this shader needs target 3.0\n#endif\n"
                               "float4 vert(float4 p : POSITION) : SV_POSITION { return p; }\n"
                               "fixed4 frag() : SV_Target { return 1; }");
  std::string text = fail(t);
  EXPECT_NE(text.find("inline.shader:6:1: error: '#error': this shader needs target 3.0"), std::string::npos) << text;
}

}  // namespace
}  // namespace facet::backend
