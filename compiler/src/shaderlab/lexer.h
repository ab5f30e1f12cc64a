// The ShaderLab lexer. It produces tokens on demand (so memory stays flat on
// large files) and switches to raw mode by itself: a CGPROGRAM-like keyword
// becomes one `program` token whose inner range is the exact program text up
// to the END marker, and `[...]` becomes one `bracket` token whose inner
// range is the raw text, because attribute arguments ("Metallic Alpha",
// "UnityEngine.Rendering.BlendMode") are not ShaderLab tokens.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "facet/shaderlab.h"
#include "facet/support/text.h"
#include "reporter.h"

namespace facet::shaderlab {

enum class TokenKind : uint8_t {
  eof, word, number, string, bracket, program, lbrace, rbrace, lparen, rparen, comma, equals,
  // Any other character (one UTF-8 sequence): the parser reports it where it
  // is unexpected, and legacy blocks ("combine texture * primary") skip it.
  other
};

struct Token {
  TokenKind kind = TokenKind::eof;
  uint32_t begin = 0, end = 0;              // the whole token
  uint32_t inner_begin = 0, inner_end = 0;  // string/bracket contents; program text
  bool line_start = false;                  // first token on its line
  double number = 0;                        // number tokens
  // program tokens
  ast::ProgramLanguage language = ast::ProgramLanguage::cg;
  bool is_include = false;
  uint32_t keyword_end = 0;  // end of "CGPROGRAM"
};

// Checks that `text` is text: no NUL byte and valid UTF-8. Returns the
// offset of the first offending byte with the error id, nullopt when fine.
struct BadByte {
  uint32_t offset;
  DiagId id;
};
std::optional<BadByte> find_bad_byte(std::string_view text);

class Lexer {
 public:
  // `text` must outlive the lexer. A UTF-8 byte-order mark is skipped.
  Lexer(std::string_view text, Reporter& reporter);

  // The next token; eof forever at the end.
  Token next();

  std::string_view text(const Token& t) const { return text_.substr(t.begin, t.end - t.begin); }
  std::string_view inner(const Token& t) const {
    return text_.substr(t.inner_begin, t.inner_end - t.inner_begin);
  }
  // A string token's value with escapes applied.
  std::string string_value(const Token& t) const;
  std::string_view source() const { return text_; }

 private:
  void skip_trivia();
  bool skip_block_comment();
  Token lex_string(uint32_t start);
  Token lex_bracket(uint32_t start);
  Token lex_number(uint32_t start);
  Token lex_word(uint32_t start);
  void lex_program(Token& t, std::string_view end_marker);
  Token make(TokenKind kind, uint32_t begin, uint32_t end);
  Token lex_other(uint32_t start);
  bool number_starts_at(uint32_t i) const;

  std::string_view text_;
  Reporter& reporter_;
  uint32_t pos_ = 0;
  bool line_start_ = true;
};

bool is_ident_start(char c);
bool is_ident_char(char c);

}  // namespace facet::shaderlab
