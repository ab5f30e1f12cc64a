// Malformed input: every case gives a located error and no crash; nesting,
// error counts and time stay bounded on hostile files.
#include <gtest/gtest.h>

#include <chrono>
#include <fstream>
#include <memory>
#include <sstream>

#include "facet/shaderlab.h"

namespace facet::shaderlab {
namespace {

struct Parsed {
  SourceMap sources;
  Diagnostics diags;
  FileId file = kNoFile;
  bool ok = false;
  std::optional<ast::Shader> shader;
};

std::unique_ptr<Parsed> parse_text(std::string text, ParseOptions options = {}) {
  auto p = std::make_unique<Parsed>();
  p->file = p->sources.add_file("bad.shader", std::move(text));
  auto result = parse(p->file, p->sources, options, p->diags);
  p->ok = result.has_value();
  if (result) p->shader = std::move(*result);
  return p;
}

// Every diagnostic points into the file.
void expect_spans_in_file(const Parsed& p) {
  uint32_t size = uint32_t(p.sources.text(p.file).size());
  for (const Diagnostic& d : p.diags.all()) {
    EXPECT_EQ(d.span.file, p.file) << d.message;
    EXPECT_LE(d.span.begin, d.span.end) << d.message;
    EXPECT_LE(d.span.end, size) << d.message;
  }
}

std::string repeat(std::string_view s, size_t n) {
  std::string out;
  out.reserve(s.size() * n);
  for (size_t i = 0; i < n; ++i) out += s;
  return out;
}

struct ErrorCase {
  std::string name;
  std::string source;
  DiagId id;
  uint32_t line, column;  // of the first error
};

std::ostream& operator<<(std::ostream& os, const ErrorCase& c) { return os << c.name; }

class ShaderlabParseErrorTest : public testing::TestWithParam<ErrorCase> {};

TEST_P(ShaderlabParseErrorTest, ReportsLocatedError) {
  const ErrorCase& c = GetParam();
  auto p = parse_text(c.source);
  EXPECT_FALSE(p->ok);
  const Diagnostic* first = nullptr;
  for (const Diagnostic& d : p->diags.all()) {
    if (d.severity == Severity::error) {
      first = &d;
      break;
    }
  }
  ASSERT_NE(first, nullptr);
  EXPECT_EQ(first->id, c.id) << first->message;
  LineColumn at = p->sources.line_column(p->file, first->span.begin);
  EXPECT_EQ(at.line, c.line) << first->message;
  EXPECT_EQ(at.column, c.column) << first->message;
  expect_spans_in_file(*p);
}

std::vector<ErrorCase> error_cases() {
  const std::string pass = "Shader \"X\" { SubShader { Pass {\n";
  const std::string end = "\n} } }";
  return {
      {"empty_file", "", DiagId::parse_unexpected_token, 1, 1},
      {"no_shader_keyword", "\n  Properties { }", DiagId::parse_unexpected_token, 2, 3},
      {"no_shader_name", "Shader {", DiagId::parse_unexpected_token, 1, 8},
      {"truncated", "Shader \"X\" {\n  SubShader {\n    Pass {\n", DiagId::parse_unterminated_block, 3, 10},
      {"extra_close_brace", "Shader \"X\" { }\n}", DiagId::parse_extra_shader, 2, 1},
      {"unterminated_string", "Shader \"X {\n}", DiagId::parse_unterminated_string, 1, 8},
      {"unterminated_comment", "Shader \"X\" { /* no end\n", DiagId::parse_unterminated_comment, 1, 14},
      {"unterminated_program", pass + "  CGPROGRAM\n  float4 f;\n", DiagId::parse_unterminated_program, 2, 3},
      {"unterminated_hlsl", pass + "  HLSLPROGRAM\n ENDCG\n} } }", DiagId::parse_unterminated_program, 2, 3},
      {"unterminated_bracket", "Shader \"X\" { Properties {\n [Toggle(A) _A (\"a\", Float) = 0\n } }",
       DiagId::parse_unterminated_bracket, 2, 2},
      {"nul_byte", std::string("Shader \"X\" {\0}", 14), DiagId::parse_nul_byte, 1, 13},
      {"invalid_utf8", "Shader \"X\" {\n// caf\xE9\n}", DiagId::parse_invalid_utf8, 2, 7},
      {"unknown_command", pass + "  Foo Bar" + end, DiagId::parse_unknown_command, 2, 3},
      {"unexpected_character", pass + "  Cull Off ;" + end, DiagId::parse_unexpected_character, 2, 12},
      {"missing_value", pass + "  Cull\n  ZWrite Off" + end, DiagId::parse_unexpected_token, 3, 3},
      {"bad_property_reference", pass + "  Cull [1x]" + end, DiagId::parse_bad_property_reference, 2, 8},
      {"number_out_of_range", "Shader \"X\" { Properties { _F (\"F\", Float) = 1e999 } }", DiagId::parse_bad_number,
       1, 45},
      {"negative_lod", "Shader \"X\" { SubShader { LOD -1 } }", DiagId::parse_bad_number, 1, 30},
      {"include_in_pass", pass + "  CGINCLUDE ENDCG" + end, DiagId::parse_misplaced_block, 2, 3},
      {"program_at_shader_scope", "Shader \"X\" {\n CGPROGRAM ENDCG }", DiagId::parse_misplaced_block, 2, 2},
      {"second_program", pass + "CGPROGRAM ENDCG\n HLSLPROGRAM ENDHLSL" + end, DiagId::parse_duplicate_program, 3,
       2},
      {"unknown_stencil_field", pass + "Stencil { Ref 1\n  Colour 2 }" + end, DiagId::parse_unexpected_token, 3, 3},
      {"tag_without_equals", "Shader \"X\" { SubShader { Tags { \"A\" \"B\" } } }", DiagId::parse_unexpected_token,
       1, 37},
      {"unquoted_tag", "Shader \"X\" { SubShader { Tags { Queue=\"B\" } } }", DiagId::parse_unexpected_token, 1, 33},
      {"property_missing_paren", "Shader \"X\" { Properties {\n  _A \"a\", Float) = 0\n} }",
       DiagId::parse_unexpected_token, 2, 6},
      {"bad_attribute", "Shader \"X\" { Properties {\n  [(x)] _A (\"a\", Float) = 0\n} }",
       DiagId::parse_unexpected_token, 2, 3},
      {"blend_missing_factor", pass + "  Blend One" + end, DiagId::parse_unexpected_token, 3, 1},
      {"nesting_too_deep", "Shader \"X\" {\n" + repeat("Category {", 300) + repeat("}", 300) + "}",
       DiagId::parse_nesting_too_deep, 2, 2560},
      {"legacy_nesting_too_deep", pass + "Fog " + repeat("{", 300) + repeat("}", 300) + end,
       DiagId::parse_nesting_too_deep, 2, 258},
  };
}

INSTANTIATE_TEST_SUITE_P(Malformed, ShaderlabParseErrorTest, testing::ValuesIn(error_cases()),
                         [](const testing::TestParamInfo<ErrorCase>& info) { return info.param.name; });

TEST(ShaderlabParseErrorTest, UnterminatedProgramPointsAtItsKeywordWithNote) {
  auto p = parse_text("Shader \"X\" { SubShader { Pass {\n  CGPROGRAM\n  float4 f;\n");
  const Diagnostic& d = p->diags.all().at(0);
  ASSERT_EQ(d.id, DiagId::parse_unterminated_program);
  EXPECT_EQ(d.message, "unterminated 'CGPROGRAM' block");
  EXPECT_EQ(d.span.end - d.span.begin, 9u);
  ASSERT_EQ(d.notes.size(), 1u);
  EXPECT_EQ(d.notes[0].span.begin, p->sources.text(p->file).size());
  // The Pass, SubShader and Shader are unclosed as a consequence: no more errors.
  EXPECT_EQ(p->diags.error_count(), 1u) << render_text(p->diags, p->sources);
}

TEST(ShaderlabParseErrorTest, TruncatedFileReportsTheInnermostBlockOnly) {
  auto p = parse_text("Shader \"X\" {\n  SubShader {\n    Pass {\n      Cull Off\n");
  ASSERT_EQ(p->diags.error_count(), 1u) << render_text(p->diags, p->sources);
  const Diagnostic& d = p->diags.all().at(0);
  EXPECT_EQ(d.message, "missing '}' for this Pass block");
  EXPECT_EQ(d.notes.at(0).message, "the file ends here");
}

TEST(ShaderlabParseErrorTest, RecoversAndReportsSeveralErrors) {
  auto p = parse_text(R"(Shader "X" {
  Properties {
    _A ("a" Float) = 0
    _B ("b", Float) = 1
  }
  SubShader {
    Pass { Cull Sideways Foo
      ZWrite Off }
    Pass { Blend One }
    Pass { Name "ok" }
  }
})");
  EXPECT_FALSE(p->ok);
  EXPECT_EQ(p->diags.error_count(), 3u) << render_text(p->diags, p->sources);
  expect_spans_in_file(*p);
}

TEST(ShaderlabParseErrorTest, StopsAfterTooManyErrors) {
  auto p = parse_text("Shader \"X\" {\n" + repeat("Foo\n", 10000) + "}", {.max_errors = 20});
  EXPECT_FALSE(p->ok);
  EXPECT_EQ(p->diags.error_count(), 21u);
  EXPECT_EQ(p->diags.all().back().id, DiagId::parse_too_many_errors);
}

TEST(ShaderlabParseErrorTest, VeryDeepNestingIsBoundedAndFast) {
  auto p = parse_text("Shader \"X\" {\n" + repeat("Category {", 200000) + repeat("}", 200000) + "}");
  EXPECT_FALSE(p->ok);
  EXPECT_EQ(p->diags.error_count(), 1u);
  auto q = parse_text("Shader \"X\" { SubShader { Pass { Fog " + repeat("{", 200000) + " } } }");
  EXPECT_FALSE(q->ok);
  expect_spans_in_file(*q);
}

std::string read_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// Cutting a valid file anywhere must give errors, never a crash or a hang.
TEST(ShaderlabParseErrorTest, EveryTruncationOfAValidFile) {
  std::string text = read_file(FACET_TESTDATA_DIR "/shaderlab/book_constructs.shader");
  ASSERT_FALSE(text.empty());
  size_t last_brace = text.rfind('}');
  for (size_t n = 0; n < text.size(); n += 1) {
    auto p = parse_text(text.substr(0, n));
    if (n <= last_brace) {
      EXPECT_FALSE(p->ok) << "prefix " << n;
    }
    expect_spans_in_file(*p);
  }
}

// Deterministic byte mutations: replace bytes by syntax characters.
TEST(ShaderlabParseErrorTest, MutatedFilesNeverCrash) {
  std::string text = read_file(FACET_TESTDATA_DIR "/shaderlab/all_state.shader");
  ASSERT_FALSE(text.empty());
  const std::string alphabet = "{}()[]\",=;/*\n\\-.0aE";
  uint32_t seed = 12345;
  auto next = [&] { return seed = seed * 1664525u + 1013904223u; };
  for (int round = 0; round < 1500; ++round) {
    std::string mutated = text;
    for (int k = 0; k < 1 + round % 4; ++k) mutated[next() % mutated.size()] = alphabet[next() % alphabet.size()];
    auto p = parse_text(mutated);
    expect_spans_in_file(*p);
    if (p->ok) ast_to_json(*p->shader, p->sources);
  }
}

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// 10 MB inputs stay linear: a quadratic step would take minutes here.
TEST(ShaderlabParseErrorTest, TenMegabyteFilesParse) {
  std::string line = "            float4 value_with_a_long_name = float4(1.0, 2.0, 3.0, 4.0); // ENDCGX\n";
  std::string program = "Shader \"Big\" { SubShader { Pass {\nCGPROGRAM\n" +
                        repeat(line, 10'000'000 / line.size()) + "ENDCG\n} } }";
  auto start = std::chrono::steady_clock::now();
  auto p = parse_text(program);
  ASSERT_TRUE(p->ok);
  EXPECT_GT(p->shader->subshaders[0].passes[0].program->text.size(), 9'000'000u);

  std::string property = "  [HideInInspector] _Prop (\"A property\", Range(0, 1)) = 0.5 // c\n";
  std::string properties = "Shader \"Big\" { Properties {\n";
  for (size_t i = 0; properties.size() < 10'000'000; ++i) {
    properties += "  _P" + std::to_string(i) + property.substr(20);
  }
  properties += "} }";
  auto q = parse_text(properties);
  ASSERT_TRUE(q->ok);
  EXPECT_GT(q->shader->properties.size(), 100'000u);
  EXPECT_LT(seconds_since(start), 60.0);
}

TEST(ShaderlabParseErrorTest, LargeGarbageFileFailsQuickly) {
  std::string garbage;
  uint32_t seed = 7;
  for (size_t i = 0; i < 2'000'000; ++i) {
    seed = seed * 1664525u + 1013904223u;
    garbage += char(0x20 + (seed >> 24) % 0x5f);
  }
  auto start = std::chrono::steady_clock::now();
  auto p = parse_text("Shader \"G\" { " + garbage);
  EXPECT_FALSE(p->ok);
  EXPECT_LE(p->diags.error_count(), 101u);
  EXPECT_LT(seconds_since(start), 30.0);
}

}  // namespace
}  // namespace facet::shaderlab
