#include "lexer.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace facet::shaderlab {
namespace {

struct Lexed {
  std::vector<Token> tokens;
  std::vector<std::string> texts;
  Diagnostics diags;
};

Lexed lex(std::string_view text) {
  Lexed out;
  Reporter reporter(0, out.diags, 100);
  Lexer lexer(text, reporter);
  for (;;) {
    Token t = lexer.next();
    if (t.kind == TokenKind::eof) break;
    out.tokens.push_back(t);
    out.texts.emplace_back(t.kind == TokenKind::string ? lexer.string_value(t) : std::string(lexer.inner(t)));
  }
  return out;
}

std::vector<TokenKind> kinds(const Lexed& l) {
  std::vector<TokenKind> k;
  for (const Token& t : l.tokens) k.push_back(t.kind);
  return k;
}

TEST(ShaderlabLexerTest, PunctuationWordsNumbersStrings) {
  Lexed l = lex("Shader \"A/B\" { _X (\"d\", Range(-1, .5)) = 2e1 }");
  using K = TokenKind;
  EXPECT_EQ(kinds(l), (std::vector<K>{K::word, K::string, K::lbrace, K::word, K::lparen, K::string, K::comma,
                                      K::word, K::lparen, K::number, K::comma, K::number, K::rparen, K::rparen,
                                      K::equals, K::number, K::rbrace}));
  EXPECT_EQ(l.tokens[9].number, -1);
  EXPECT_EQ(l.tokens[11].number, 0.5);
  EXPECT_EQ(l.tokens[15].number, 20);
  EXPECT_EQ(l.texts[1], "A/B");
  EXPECT_TRUE(l.diags.all().empty());
}

TEST(ShaderlabLexerTest, TextureTypeNamesStartingWithDigitsAreWords) {
  Lexed l = lex("2D 3D 2DArray 2 -3D");
  ASSERT_EQ(l.tokens.size(), 6u);
  EXPECT_EQ(l.tokens[0].kind, TokenKind::word);
  EXPECT_EQ(l.texts[2], "2DArray");
  EXPECT_EQ(l.tokens[3].kind, TokenKind::number);
  // A sign makes a number; "-3D" is the number -3 and the word D.
  EXPECT_EQ(l.tokens[4].kind, TokenKind::number);
  EXPECT_EQ(l.texts[5], "D");
}

TEST(ShaderlabLexerTest, StringEscapes) {
  Lexed l = lex(R"("a\"b\\c\td")");
  ASSERT_EQ(l.tokens.size(), 1u);
  EXPECT_EQ(l.texts[0], "a\"b\\c\td");
}

TEST(ShaderlabLexerTest, CommentsAndLineStarts) {
  Lexed l = lex("a // x }\n/* {\n } */ b /* c */ d\ne");
  ASSERT_EQ(l.texts, (std::vector<std::string>{"a", "b", "d", "e"}));
  EXPECT_TRUE(l.tokens[0].line_start);
  EXPECT_TRUE(l.tokens[1].line_start);  // a block comment spanning a newline
  EXPECT_FALSE(l.tokens[2].line_start);
  EXPECT_TRUE(l.tokens[3].line_start);
}

TEST(ShaderlabLexerTest, BracketIsRawText) {
  Lexed l = lex("[Enum(Metallic Alpha,0)] [ _Prop ]");
  ASSERT_EQ(l.tokens.size(), 2u);
  EXPECT_EQ(l.tokens[0].kind, TokenKind::bracket);
  EXPECT_EQ(l.texts[0], "Enum(Metallic Alpha,0)");
  EXPECT_EQ(l.texts[1], " _Prop ");
}

TEST(ShaderlabLexerTest, ProgramTokenKeepsExactText) {
  std::string src = "Pass { CGPROGRAM\n#pragma vertex v // ENDCGX endcgy\nENDCG }";
  Lexed l = lex(src);
  ASSERT_EQ(l.tokens.size(), 4u);
  const Token& p = l.tokens[2];
  EXPECT_EQ(p.kind, TokenKind::program);
  EXPECT_EQ(p.language, ast::ProgramLanguage::cg);
  EXPECT_FALSE(p.is_include);
  EXPECT_EQ(l.texts[2], "\n#pragma vertex v // ENDCGX endcgy\n");
  EXPECT_EQ(src.substr(p.end - 5, 5), "ENDCG");
  EXPECT_EQ(l.tokens[3].kind, TokenKind::rbrace);
}

TEST(ShaderlabLexerTest, ProgramKeywordsAreCaseInsensitive) {
  Lexed l = lex("hlslinclude x EndHlsl GLSLPROGRAM y ENDGLSL cginclude z endcg");
  ASSERT_EQ(l.tokens.size(), 3u);
  EXPECT_EQ(l.tokens[0].language, ast::ProgramLanguage::hlsl);
  EXPECT_TRUE(l.tokens[0].is_include);
  EXPECT_EQ(l.tokens[1].language, ast::ProgramLanguage::glsl);
  EXPECT_EQ(l.texts[1], " y ");
  EXPECT_EQ(l.tokens[2].language, ast::ProgramLanguage::cg);
}

TEST(ShaderlabLexerTest, SkipsByteOrderMark) {
  Lexed l = lex("\xEF\xBB\xBFShader");
  ASSERT_EQ(l.tokens.size(), 1u);
  EXPECT_EQ(l.tokens[0].begin, 3u);
}

TEST(ShaderlabLexerTest, OtherCharactersAreTokensNotErrors) {
  // Legacy blocks hold text such as "combine texture * primary"; the parser
  // decides whether such a character is an error.
  Lexed l = lex("a * \xC3\xA9 : b");
  using K = TokenKind;
  EXPECT_EQ(kinds(l), (std::vector<K>{K::word, K::other, K::other, K::other, K::word}));
  EXPECT_EQ(l.texts[2], "\xC3\xA9");
  EXPECT_TRUE(l.diags.all().empty());
}

TEST(ShaderlabLexerTest, LoneSignAtEndIsOther) {
  Lexed l = lex("-");
  ASSERT_EQ(l.tokens.size(), 1u);
  EXPECT_EQ(l.tokens[0].kind, TokenKind::other);
}

TEST(ShaderlabLexerTest, UnterminatedTokensReportTheirStart) {
  Lexed s = lex("x \"abc\ny");
  ASSERT_EQ(s.diags.size(), 1u);
  EXPECT_EQ(s.diags.all()[0].id, DiagId::parse_unterminated_string);
  EXPECT_EQ(s.diags.all()[0].span.begin, 2u);
  EXPECT_EQ(s.texts.back(), "y");  // the string stops at the end of its line
  Lexed c = lex("x /* abc");
  ASSERT_EQ(c.diags.size(), 1u);
  EXPECT_EQ(c.diags.all()[0].id, DiagId::parse_unterminated_comment);
  EXPECT_EQ(c.diags.all()[0].span.begin, 2u);
  Lexed p = lex("x\n  CGPROGRAM\n  float4 f;\n");
  ASSERT_EQ(p.diags.size(), 1u);
  EXPECT_EQ(p.diags.all()[0].id, DiagId::parse_unterminated_program);
  EXPECT_EQ(p.diags.all()[0].span.begin, 4u);
  EXPECT_EQ(p.diags.all()[0].notes.at(0).message, "expected 'ENDCG' before the end of the file");
}

struct BadByteCase {
  const char* name;
  std::string text;
  std::optional<uint32_t> offset;
  DiagId id;
};

class ShaderlabBadByteTest : public testing::TestWithParam<BadByteCase> {};

TEST_P(ShaderlabBadByteTest, FindsFirstBadByte) {
  const BadByteCase& c = GetParam();
  auto bad = find_bad_byte(c.text);
  ASSERT_EQ(bad.has_value(), c.offset.has_value());
  if (!bad) return;
  EXPECT_EQ(bad->offset, *c.offset);
  EXPECT_EQ(bad->id, c.id);
}

INSTANTIATE_TEST_SUITE_P(
    Cases, ShaderlabBadByteTest,
    testing::Values(BadByteCase{"ascii", "Shader \"x\" {}", std::nullopt, DiagId::parse_nul_byte},
                    BadByteCase{"utf8", "// caf\xC3\xA9 \xE2\x82\xAC \xF0\x9F\x98\x80", std::nullopt, DiagId::parse_nul_byte},
                    BadByteCase{"nul", std::string("ab\0cd", 5), 2u, DiagId::parse_nul_byte},
                    BadByteCase{"latin1", "caf\xE9!", 3u, DiagId::parse_invalid_utf8},
                    BadByteCase{"overlong", "a\xC0\xAF", 1u, DiagId::parse_invalid_utf8},
                    BadByteCase{"surrogate", "\xED\xA0\x80", 0u, DiagId::parse_invalid_utf8},
                    BadByteCase{"truncated", "ab\xE2\x82", 2u, DiagId::parse_invalid_utf8},
                    BadByteCase{"too_big", "\xF4\x90\x80\x80", 0u, DiagId::parse_invalid_utf8}),
    [](const testing::TestParamInfo<BadByteCase>& info) { return std::string(info.param.name); });

}  // namespace
}  // namespace facet::shaderlab
