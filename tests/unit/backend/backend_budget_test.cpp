// Hostile programs end in located errors before glslang's recursion
// overflows the stack or its preprocessor and spirv-opt's unroller eat
// gigabytes: the recursion pre-check, the macro budget, the include
// budgets, the [unroll] limit and the #line range (docs/cli.md, "Input
// limits"). Each input is built here, just past its limit.
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <pthread.h>

#include <filesystem>
#include <fstream>

#include "info_log.h"
#include "source_assembly.h"
#include "worker.h"
#include "backend_test_util.h"

namespace facet::backend {
namespace {

using testing::TestShader;

std::string repeat(const std::string& s, size_t n) {
  std::string out;
  out.reserve(s.size() * n);
  for (size_t i = 0; i < n; ++i) out += s;
  return out;
}

// A CGPROGRAM whose line 5 is `code`; vert and frag follow on lines 6 and 7.
TestShader inline_shader(const std::string& code) {
  return testing::make_shader(std::string(FACET_TESTDATA_DIR) + "/backend/inline.shader",
                              "Shader \"Inline\" { SubShader { Pass {\nCGPROGRAM\n"
                              "#pragma vertex vert\n#pragma fragment frag\n" +
                                  code +
                                  "\nfloat4 vert(float4 p : POSITION) : SV_POSITION { return p; }\n"
                                  "fixed4 frag(float4 p : SV_POSITION) : SV_Target { return f(p.x); }\nENDCG\n} } }\n");
}

class BackendBudgetTest : public ::testing::Test {
 protected:
  // Compiles the fragment stage expecting a failure; the first error.
  Diagnostic fail(TestShader& t, const BackendOptions& options = {}) {
    auto compiled = backend_.compile(t.shader, t.program, Stage::fragment, {}, options, t.sources, diags_);
    EXPECT_FALSE(compiled);
    text_ = render_text(diags_, t.sources);
    for (const Diagnostic& d : diags_.all()) {
      if (d.severity == Severity::error) return d;
    }
    ADD_FAILURE() << "no error";
    return {};
  }

  // "line:col" of a span in the shader.
  static std::string where(const TestShader& t, const Diagnostic& d) {
    if (!d.span.has_location()) return "nowhere";
    LineColumn lc = t.sources.line_column(d.span.file, d.span.begin);
    return std::to_string(lc.line) + ":" + std::to_string(lc.column);
  }

  Backend backend_;
  Diagnostics diags_;
  std::string text_;
};

TEST_F(BackendBudgetTest, LongRunOfNotIsRefusedWhereItStarts) {
  TestShader t = inline_shader("float f(float a) { return " + std::string(60000, '!') + "a; }");
  Diagnostic d = fail(t);
  EXPECT_EQ(d.id, DiagId::backend_nesting_too_deep) << text_;
  EXPECT_EQ(d.message, "more than 256 unary operators in a row");
  EXPECT_EQ(where(t, d), "5:27") << text_;
}

// Found by fuzz_hlsl: glslang's HLSL front end dereferences a null pointer
// on an initializer list inside an array size; the pre-check refuses it.
TEST_F(BackendBudgetTest, ABraceInsideAnArraySizeIsRefusedBeforeGlslang) {
  TestShader t = inline_shader("static const float w[X = { 0.1 };\nfloat f(float a) { return a; }");
  Diagnostic d = fail(t);
  EXPECT_EQ(d.id, DiagId::backend_nesting_too_deep) << text_;
  EXPECT_EQ(d.message, "'{' inside '[ ]': a ']' is missing before it");
  EXPECT_EQ(where(t, d), "5:26") << text_;
}

// Both found by fuzz_hlsl: glslang's HLSL front end dereferences a null
// pointer on them (growGlobalUniformBlock, convertInitializerList).
TEST_F(BackendBudgetTest, AGlobalDeclaredAgainWithAnotherTypeIsRefusedBeforeGlslang) {
  TestShader t = inline_shader("float4 unity_Tint; float f(float a) { return a; } float unity_Tint[2];");
  Diagnostic d = fail(t);
  EXPECT_EQ(d.message,
            "'unity_Tint': redefinition with another type (float[2] here, float4 at " + std::string(FACET_TESTDATA_DIR) +
                "/backend/inline.shader:5); a global has one type")
      << text_;
  EXPECT_EQ(where(t, d), "5:8") << text_;
}

TEST_F(BackendBudgetTest, ADeclarationMissingItsSemicolonBeforeAFunctionIsRead) {
  TestShader t = inline_shader("float4 _Tint;\nfloat _Tint\nfloat f(float a) { return a; }");
  Diagnostic d = fail(t);
  EXPECT_NE(d.message.find("redefinition with another type (float here, float4"), std::string::npos) << text_;
}

TEST_F(BackendBudgetTest, TwoOperandsInARowInAnArraySizeAreRefusedBeforeGlslang) {
  TestShader t = inline_shader("float w[t w];\nfloat f(float a) { return a; }");
  Diagnostic d = fail(t);
  EXPECT_EQ(d.message, "'[': an array size has two operands in a row, the second 'w'") << text_;
}

// Found by fuzz_hlsl: glslang reads a name after a function's declaration
// as a declarator of its type, and crashes when the name is a struct's or
// another global's (after the semantic too).
TEST_F(BackendBudgetTest, ANameAfterAFunctionsDeclarationIsRefusedBeforeGlslang) {
  const std::pair<const char*, const char*> cases[] = {
      {"float4x4 unity_VP;\nfloat4 g(float4 i) unity_VP;\nfloat f(float a) { return a; }", "unity_VP"},
      {"struct appdata { float4 v; };\nfloat4 g(float4 i) appdata { return i; }\nfloat f(float a) { return g(a).x; }",
       "appdata"},
      {"SamplerState sampler_T;\nfloat4 g(float4 i) : SV_Targe sampler_T;\nfloat f(float a) { return a; }",
       "sampler_T"},
  };
  for (const auto& [text, name] : cases) {
    diags_ = {};
    TestShader t = inline_shader(text);
    Diagnostic d = fail(t);
    EXPECT_EQ(d.message, std::string("'") + name + "': unexpected '" + name +
                             "' after the declaration of function 'g'; a function's parameters are followed by "
                             "its body or ';'")
        << text_;
    EXPECT_EQ(where(t, d).substr(0, 2), "6:") << text_;
  }
}

// Found by fuzz_frontend: glslang's HLSL front end dereferences a null
// pointer (growGlobalUniformBlock) on a global uniform named like a struct,
// which fxc refuses as a redefinition.
TEST_F(BackendBudgetTest, AGlobalNamedLikeAStructIsRefusedBeforeGlslang) {
  for (const char* global : {"half S;", "half _G S;", "float4 _G, S;"}) {
    diags_ = {};
    TestShader t = inline_shader(std::string("struct S { float a; };\n") + global + "\nfloat f(float a) { return a; }");
    Diagnostic d = fail(t);
    EXPECT_EQ(d.message, "'S': redefinition of the struct declared at " + std::string(FACET_TESTDATA_DIR) +
                             "/backend/inline.shader:5; a global cannot take a struct's name")
        << text_;
    EXPECT_EQ(where(t, d).substr(0, 2), "6:") << text_;
  }
}

TEST_F(BackendBudgetTest, AStaticNamedLikeAStructIsLeftToGlslang) {
  TestShader t = inline_shader("struct S { float a; };\nstatic half S;\nfloat f(float a) { return a; }");
  diags_ = {};
  (void)backend_.compile(t.shader, t.program, Stage::fragment, {}, {}, t.sources, diags_);
  for (const Diagnostic& d : diags_.all()) EXPECT_EQ(d.message.find("a global cannot take"), std::string::npos);
}

TEST_F(BackendBudgetTest, ABracketClosedByTheWrongOneIsRefusedBeforeGlslang) {
  TestShader t = inline_shader("static const float w[N * k) * w[k];\nfloat f(float a) { return a; }");
  Diagnostic d = fail(t);
  EXPECT_EQ(d.message, "')': ')' does not close the '[' at line 5") << text_;
}

TEST_F(BackendBudgetTest, ARedeclarationWithTheSameTypeIsNoProblem) {
  TestShader t = inline_shader("float4 _Tint; half4 _Tint; cbuffer C { float _Cut; }\nfloat _Cut;\n"
                               "float f(float a) { return a * _Tint.x * _Cut; }");
  auto compiled = backend_.compile(t.shader, t.program, Stage::fragment, {}, {}, t.sources, diags_);
  EXPECT_TRUE(compiled) << render_text(diags_, t.sources);
}

TEST_F(BackendBudgetTest, LongRunOfMinusIsRefused) {
  TestShader t = inline_shader("float f(float a) { return " + repeat("- ", 100000) + "a; }");
  Diagnostic d = fail(t);
  EXPECT_EQ(d.id, DiagId::backend_nesting_too_deep) << text_;
  EXPECT_EQ(where(t, d), "5:27") << text_;
}

TEST_F(BackendBudgetTest, AssignmentChainIsRefusedAtItsStatement) {
  TestShader t = inline_shader("float f(float a) { a = " + repeat("a = ", 50000) + "a; return a; }");
  Diagnostic d = fail(t);
  EXPECT_EQ(d.id, DiagId::backend_nesting_too_deep) << text_;
  EXPECT_EQ(d.message, "more than 256 assignments chained in one expression");
  EXPECT_EQ(where(t, d), "5:20") << text_;
}

TEST_F(BackendBudgetTest, ElseIfChainIsRefusedAtItsFirstIf) {
  TestShader t = inline_shader("float f(float a) { if (a > 0) a = 1;" + repeat(" else if (a > 1) a = 2;", 20000) +
                               " return a; }");
  Diagnostic d = fail(t);
  EXPECT_EQ(d.id, DiagId::backend_nesting_too_deep) << text_;
  EXPECT_NE(d.message.find("more than 1024 if statements"), std::string::npos) << text_;
  EXPECT_EQ(where(t, d), "5:20") << text_;
}

TEST_F(BackendBudgetTest, SeparateElseIfChainsAreCountedApart) {
  // Chains that follow one another are counted apart.
  std::string chain = "if (a > 0) a = 1;" + repeat(" else if (a > 1) { a = 2; }", 600) + "\n";
  EXPECT_FALSE(find_recursion_hazard("float f(float a) {\n" + chain + chain + "return a; }"));
  EXPECT_TRUE(find_recursion_hazard("float f(float a) {\n" + chain + repeat(" else if (a) a = 2;", 600) + "}"));
}

TEST_F(BackendBudgetTest, NotsInAnIfDirectiveAreRefused) {
  TestShader t = inline_shader("#if " + std::string(50000, '!') + "0\n#endif\nfloat f(float a) { return a; }");
  Diagnostic d = fail(t);
  EXPECT_EQ(d.id, DiagId::backend_nesting_too_deep) << text_;
  EXPECT_EQ(where(t, d), "5:5") << text_;
}

TEST_F(BackendBudgetTest, DeepParenthesesAreRefused) {
  TestShader t = inline_shader("float f(float a) { return " + std::string(100000, '(') + "a" +
                               std::string(100000, ')') + "; }");
  Diagnostic d = fail(t);
  EXPECT_EQ(d.id, DiagId::backend_nesting_too_deep) << text_;
  EXPECT_EQ(where(t, d), "5:282") << text_;  // the 257th '(' (col 27 + 256 - 1 + 1)
}

TEST_F(BackendBudgetTest, ObjectMacroBombIsRefusedAtTheDefineThatExceeds) {
  std::string defines = "#define M0 x\n";
  for (int i = 1; i <= 30; ++i) defines += "#define M" + std::to_string(i) + " M" + std::to_string(i - 1) + "+M" +
                                           std::to_string(i - 1) + "\n";
  TestShader t = inline_shader(defines + "float f(float x) { return M30; }");
  Diagnostic d = fail(t);
  EXPECT_EQ(d.id, DiagId::backend_input_limit) << text_;
  // M24 doubles past 64 MiB: 2^24 copies of "x +", 5 bytes each.
  EXPECT_NE(d.message.find("macro 'M24'"), std::string::npos) << text_;
  EXPECT_EQ(where(t, d), "29:9") << text_;
}

TEST_F(BackendBudgetTest, FunctionMacroBombIsRefused) {
  std::string defines = "#define F0(x) x x\n";
  for (int i = 1; i <= 30; ++i) defines += "#define F" + std::to_string(i) + "(x) F" + std::to_string(i - 1) + "(F" +
                                           std::to_string(i - 1) + "(x))\n";
  TestShader t = inline_shader(defines + "float f(float x) { return F30(x); }");
  Diagnostic d = fail(t);
  EXPECT_EQ(d.id, DiagId::backend_input_limit) << text_;
  EXPECT_NE(d.message.find("--max-preprocessed-bytes"), std::string::npos) << text_;
}

TEST_F(BackendBudgetTest, NestedCallsOfAMacroAtAUseSiteAreRefused) {
  // Each call of F quadruples its argument: 16 nested calls ask for 4^16 tokens.
  TestShader t = inline_shader("#define F(x) x x x x\nfloat f(float a) { return " + repeat("F(", 16) + "a" +
                               std::string(16, ')') + "; }");
  Diagnostic d = fail(t);
  EXPECT_EQ(d.id, DiagId::backend_input_limit) << text_;
  EXPECT_EQ(where(t, d), "6:27") << text_;
}

TEST_F(BackendBudgetTest, RaisedPreprocessedBudgetLetsABigMacroThrough) {
  std::string defines = "#define M0 x\n";
  for (int i = 1; i <= 6; ++i) defines += "#define M" + std::to_string(i) + " M" + std::to_string(i - 1) + "+M" +
                                          std::to_string(i - 1) + "\n";
  TestShader t = inline_shader(defines + "float f(float x) { return M6; }");
  BackendOptions options;
  options.limits.max_preprocessed_bytes = 100;  // M6 is 64 copies of "x+"
  Diagnostic d = fail(t, options);
  EXPECT_EQ(d.id, DiagId::backend_input_limit) << text_;
  diags_ = {};
  options.limits.max_preprocessed_bytes = 0;
  EXPECT_TRUE(backend_.compile(t.shader, t.program, Stage::fragment, {}, options, t.sources, diags_))
      << render_text(diags_, t.sources);
}

// An in-memory tree of 30 files, each including the next twice.
BackendOptions fan_out_options() {
  BackendOptions options;
  options.resolver = [](const std::string& requested, const std::string&) -> std::optional<IncludedFile> {
    if (!requested.starts_with("f")) return std::nullopt;
    int n = std::stoi(requested.substr(1));
    std::string next = "f" + std::to_string(n + 1) + ".h";
    std::string text = n < 29 ? "#include \"" + next + "\"\n#include \"" + next + "\"\n" : "// leaf\n";
    return IncludedFile{"/mem/" + requested, text};
  };
  return options;
}

TEST_F(BackendBudgetTest, IncludeFanOutStopsAtTheIncludeCount) {
  TestShader t = inline_shader("#include \"f0.h\"\nfloat f(float a) { return a; }");
  Diagnostic d = fail(t, fan_out_options());
  EXPECT_EQ(d.id, DiagId::backend_include_not_found) << text_;
  EXPECT_EQ(d.message, "more than 4096 #includes in one program (--max-includes)");
  EXPECT_FALSE(d.include_stack.empty()) << text_;
  // Reported once, not for every include refused after it.
  EXPECT_EQ(text_.find("more than 4096", text_.find("more than 4096") + 1), std::string::npos) << text_;
}

TEST_F(BackendBudgetTest, IncludedBytesAreSummedPerProgram) {
  BackendOptions options;
  options.limits.max_include_bytes = 3000;
  options.resolver = [](const std::string& requested, const std::string&) -> std::optional<IncludedFile> {
    if (requested.size() != 3) return std::nullopt;  // the stdlib's, from disk
    return IncludedFile{"/mem/" + requested, "// " + std::string(1000, 'x') + "\n"};
  };
  // HLSLPROGRAM: no implicit includes of the stdlib.
  TestShader t = testing::make_shader(std::string(FACET_TESTDATA_DIR) + "/backend/inline.shader",
                                      "Shader \"X\" { SubShader { Pass {\nHLSLPROGRAM\n#pragma vertex vert\n"
                                      "#pragma fragment frag\n#include \"a.h\"\n#include \"b.h\"\n#include \"c.h\"\n"
                                      "float4 vert(float4 p : POSITION) : SV_POSITION { return p; }\n"
                                      "float4 frag() : SV_Target { return 1; }\nENDHLSL\n} } }\n");
  Diagnostic d = fail(t, options);
  EXPECT_NE(d.message.find("exceed 3000 bytes together (--max-include-bytes)"), std::string::npos) << text_;
  EXPECT_EQ(where(t, d), "7:10") << text_;  // the third #include
}

TEST_F(BackendBudgetTest, IncludeOverTheFileCapIsRefusedUnread) {
  namespace fs = std::filesystem;
  fs::path dir = fs::temp_directory_path() / ("facet_budget_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  std::ofstream(dir / "huge.h").close();
  fs::resize_file(dir / "huge.h", 100u << 20);  // sparse: 100 MB that cost nothing
  TestShader t = testing::make_shader((dir / "x.shader").string(),
                                      "Shader \"X\" { SubShader { Pass {\nCGPROGRAM\n#pragma vertex vert\n"
                                      "#pragma fragment frag\n#include \"huge.h\"\n"
                                      "float4 vert(float4 p : POSITION) : SV_POSITION { return p; }\n"
                                      "fixed4 frag() : SV_Target { return 1; }\nENDCG\n} } }\n");
  Diagnostic d = fail(t);
  fs::remove_all(dir);
  EXPECT_EQ(d.message, "'huge.h' is larger than 64 MiB (104857600 bytes)") << text_;
  EXPECT_EQ(where(t, d), "5:10") << text_;
}

TEST_F(BackendBudgetTest, HazardInAnIncludedFileIsLocatedThere) {
  BackendOptions options;
  options.resolver = [](const std::string& requested, const std::string&) -> std::optional<IncludedFile> {
    if (requested != "deep.h") return std::nullopt;
    return IncludedFile{"/mem/" + requested, "float g(float a)\n{ return " + std::string(300, '~') + "a; }\n"};
  };
  TestShader t = inline_shader("#include \"deep.h\"\nfloat f(float a) { return g(a); }");
  Diagnostic d = fail(t, options);
  EXPECT_EQ(d.id, DiagId::backend_nesting_too_deep) << text_;
  ASSERT_TRUE(d.span.has_location()) << text_;
  EXPECT_EQ(t.sources.path(d.span.file), "/mem/deep.h");
  EXPECT_EQ(where(t, d), "2:10") << text_;
  ASSERT_EQ(d.include_stack.size(), 1u) << text_;
}

TEST_F(BackendBudgetTest, UnrollPastTheLimitIsRefusedAtTheAttribute) {
  TestShader t = inline_shader("float f(float a) { [unroll] for (int i = 0; i < 10000000; i++) a += sin(a); "
                               "return a; }");
  Diagnostic d = fail(t);
  EXPECT_EQ(d.id, DiagId::backend_input_limit) << text_;
  EXPECT_EQ(d.message, "a loop marked [unroll] runs 10000001 times, more than the limit of 4096 (--max-unroll)");
  EXPECT_EQ(where(t, d), "5:21") << text_;
}

TEST_F(BackendBudgetTest, ShortUnrolledLoopsCompile) {
  TestShader t = inline_shader("float f(float a) { [unroll] for (int i = 0; i < 16; i++) a += sin(a); return a; }");
  EXPECT_TRUE(backend_.compile(t.shader, t.program, Stage::fragment, {}, {}, t.sources, diags_))
      << render_text(diags_, t.sources);
}

TEST_F(BackendBudgetTest, LineDirectiveOutOfRangeIsRefused) {
  TestShader t = inline_shader("#line 4294967295\nfloat f(float a) { return b; }");
  Diagnostic d = fail(t);
  EXPECT_EQ(d.id, DiagId::backend_nesting_too_deep) << text_;
  EXPECT_EQ(d.message, "#line number out of range (at most 1000000000)");
  EXPECT_EQ(where(t, d), "5:7") << text_;
  EXPECT_EQ(text_.find(":-"), std::string::npos) << text_;
}

TEST(InfoLogLines, WrappedLineNumberIsNoPosition) {
  std::vector<LogMessage> messages = parse_info_log("ERROR: x.shader:-2: 'b' : undeclared identifier\n");
  ASSERT_EQ(messages.size(), 1u);
  EXPECT_EQ(messages[0].line, 0u);
  EXPECT_EQ(messages[0].file, "");
  EXPECT_EQ(messages[0].token, "b");
  EXPECT_EQ(messages[0].text, "undeclared identifier");
}

TEST(Worker, RunsWorkOnALargeStack) {
  size_t stack = 0;
  run_on_worker(
      [&] {
        pthread_attr_t attr;
        ASSERT_EQ(pthread_getattr_np(pthread_self(), &attr), 0);
        pthread_attr_getstacksize(&attr, &stack);
        pthread_attr_destroy(&attr);
      },
      10, [] { return std::string("timeout\n"); });
  EXPECT_GE(stack, kWorkerStackBytes);
}

TEST(Worker, ExceptionsReachTheCaller) {
  EXPECT_THROW(run_on_worker([] { throw std::bad_alloc(); }, 0, [] { return std::string(); }), std::bad_alloc);
}

}  // namespace
}  // namespace facet::backend
