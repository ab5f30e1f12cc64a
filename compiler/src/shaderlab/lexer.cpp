#include "lexer.h"

#include <charconv>
#include <cmath>

namespace facet::shaderlab {
namespace {

bool is_digit(char c) { return c >= '0' && c <= '9'; }

// The length of the UTF-8 sequence starting at text[i], 0 when invalid.
// Rejects overlong forms, surrogates and code points above U+10FFFF.
size_t utf8_length(std::string_view text, size_t i) {
  auto b = [&](size_t k) { return uint8_t(text[i + k]); };
  uint8_t c = b(0);
  size_t n = c < 0x80 ? 1 : (c >> 5) == 0x6 ? 2 : (c >> 4) == 0xe ? 3 : (c >> 3) == 0x1e ? 4 : 0;
  if (n == 0 || i + n > text.size()) return 0;
  for (size_t k = 1; k < n; ++k) {
    if ((b(k) & 0xc0) != 0x80) return 0;
  }
  if (n == 2 && c < 0xc2) return 0;
  if (n == 3 && c == 0xe0 && b(1) < 0xa0) return 0;
  if (n == 3 && c == 0xed && b(1) >= 0xa0) return 0;
  if (n == 4 && (c > 0xf4 || (c == 0xf0 && b(1) < 0x90) || (c == 0xf4 && b(1) >= 0x90))) return 0;
  return n;
}

struct ProgramKeyword {
  std::string_view keyword;
  std::string_view end_marker;
  ast::ProgramLanguage language;
  bool is_include;
};

constexpr ProgramKeyword kProgramKeywords[] = {
    {"CGPROGRAM", "ENDCG", ast::ProgramLanguage::cg, false},
    {"CGINCLUDE", "ENDCG", ast::ProgramLanguage::cg, true},
    {"HLSLPROGRAM", "ENDHLSL", ast::ProgramLanguage::hlsl, false},
    {"HLSLINCLUDE", "ENDHLSL", ast::ProgramLanguage::hlsl, true},
    {"GLSLPROGRAM", "ENDGLSL", ast::ProgramLanguage::glsl, false},
    {"GLSLINCLUDE", "ENDGLSL", ast::ProgramLanguage::glsl, true},
};

}  // namespace

bool is_ident_start(char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_'; }
bool is_ident_char(char c) { return is_ident_start(c) || is_digit(c); }

std::optional<BadByte> find_bad_byte(std::string_view text) {
  size_t i = 0;
  while (i < text.size()) {
    if (text[i] == '\0') return BadByte{uint32_t(i), DiagId::parse_nul_byte};
    if (uint8_t(text[i]) < 0x80) {  // fast path: ASCII
      ++i;
      continue;
    }
    size_t n = utf8_length(text, i);
    if (n == 0) return BadByte{uint32_t(i), DiagId::parse_invalid_utf8};
    i += n;
  }
  return std::nullopt;
}

Lexer::Lexer(std::string_view text, Reporter& reporter) : text_(text), reporter_(reporter) {
  // UTF-8 byte-order marks; editors that add one unconditionally leave two
  // in files that already had one.
  while (text_.substr(pos_, 3) == "\xEF\xBB\xBF") pos_ += 3;
}

Token Lexer::make(TokenKind kind, uint32_t begin, uint32_t end) {
  Token t;
  t.kind = kind;
  t.begin = begin;
  t.end = end;
  t.inner_begin = begin;
  t.inner_end = end;
  t.line_start = line_start_;
  line_start_ = false;
  return t;
}

void Lexer::skip_trivia() {
  while (pos_ < text_.size()) {
    char c = text_[pos_];
    if (c == '\n') {
      line_start_ = true;
      ++pos_;
    } else if (c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v') {
      ++pos_;
    } else if (c == '/' && pos_ + 1 < text_.size() && text_[pos_ + 1] == '/') {
      while (pos_ < text_.size() && text_[pos_] != '\n') ++pos_;
    } else if (c == '/' && pos_ + 1 < text_.size() && text_[pos_ + 1] == '*') {
      if (!skip_block_comment()) return;
    } else {
      return;
    }
  }
}

// Returns false when the comment runs to the end of the file.
bool Lexer::skip_block_comment() {
  uint32_t start = pos_;
  size_t close = text_.find("*/", pos_ + 2);
  size_t stop = close == std::string_view::npos ? text_.size() : close + 2;
  if (text_.substr(pos_, stop - pos_).find('\n') != std::string_view::npos) line_start_ = true;
  pos_ = uint32_t(stop);
  if (close != std::string_view::npos) return true;
  reporter_.mark_early_eof();
  if (Diagnostic* d = reporter_.error(DiagId::parse_unterminated_comment, reporter_.span(start, start + 2),
                                      "unterminated '/*' comment")) {
    d->note(reporter_.span(pos_, pos_), "the file ends here without '*/'");
  }
  return false;
}

bool Lexer::number_starts_at(uint32_t i) const {
  auto digit_at = [&](size_t k) { return k < text_.size() && is_digit(text_[k]); };
  char c = text_[i];
  if (c == '-' || c == '+') ++i;
  return digit_at(i) || (i < text_.size() && text_[i] == '.' && digit_at(i + 1));
}

Token Lexer::next() {
  skip_trivia();
  uint32_t start = pos_;
  if (pos_ >= text_.size() || reporter_.stopped()) return make(TokenKind::eof, uint32_t(text_.size()), uint32_t(text_.size()));
  switch (text_[pos_]) {
    case '{': ++pos_; return make(TokenKind::lbrace, start, pos_);
    case '}': ++pos_; return make(TokenKind::rbrace, start, pos_);
    case '(': ++pos_; return make(TokenKind::lparen, start, pos_);
    case ')': ++pos_; return make(TokenKind::rparen, start, pos_);
    case ',': ++pos_; return make(TokenKind::comma, start, pos_);
    case '=': ++pos_; return make(TokenKind::equals, start, pos_);
    case '"': return lex_string(start);
    case '[': return lex_bracket(start);
    default: break;
  }
  if (number_starts_at(pos_)) return lex_number(start);
  if (is_ident_start(text_[pos_])) return lex_word(start);
  return lex_other(start);
}

Token Lexer::lex_other(uint32_t start) {
  size_t n = utf8_length(text_, start);
  pos_ = uint32_t(start + (n == 0 ? 1 : n));
  return make(TokenKind::other, start, pos_);
}

// A string may span lines, as Unity allows (long display names and attribute
// texts are wrapped in real shaders). One with no closing quote before the
// end of the file is reported and ends at its own line, so that parsing goes
// on from the next line.
Token Lexer::lex_string(uint32_t start) {
  uint32_t i = start + 1;
  while (i < text_.size() && text_[i] != '"') {
    if (text_[i] == '\\' && i + 1 < text_.size()) ++i;
    ++i;
  }
  bool closed = i < text_.size();
  if (!closed) {
    size_t line_end = text_.find('\n', start);
    i = line_end == std::string_view::npos ? uint32_t(text_.size()) : uint32_t(line_end);
  }
  pos_ = closed ? i + 1 : i;
  Token t = make(TokenKind::string, start, pos_);
  t.inner_begin = start + 1;
  t.inner_end = i;
  if (!closed) {
    if (Diagnostic* d = reporter_.error(DiagId::parse_unterminated_string, reporter_.span(start, start + 1),
                                        "unterminated string")) {
      d->note(reporter_.span(uint32_t(text_.size()), uint32_t(text_.size())),
              "expected '\"' before the end of the file");
    }
  }
  return t;
}

std::string Lexer::string_value(const Token& t) const {
  std::string_view raw = inner(t);
  std::string out;
  out.reserve(raw.size());
  for (size_t i = 0; i < raw.size(); ++i) {
    if (raw[i] != '\\' || i + 1 >= raw.size()) {
      out += raw[i];
      continue;
    }
    char e = raw[++i];
    out += e == 'n' ? '\n' : e == 't' ? '\t' : e == 'r' ? '\r' : e;
  }
  return out;
}

// "[...]" ends at the first ']' outside quotes, on the same line unless a
// quoted argument spans lines.
Token Lexer::lex_bracket(uint32_t start) {
  uint32_t i = start + 1;
  bool quoted = false;
  while (i < text_.size() && (quoted || (text_[i] != ']' && text_[i] != '\n'))) {
    if (text_[i] == '"') quoted = !quoted;
    ++i;
  }
  bool closed = i < text_.size() && text_[i] == ']';
  if (!closed && quoted) {  // an open quote: stop at the bracket's own line
    size_t line_end = text_.find('\n', start);
    i = line_end == std::string_view::npos ? uint32_t(text_.size()) : uint32_t(line_end);
  }
  pos_ = closed ? i + 1 : i;
  Token t = make(TokenKind::bracket, start, pos_);
  t.inner_begin = start + 1;
  t.inner_end = i;
  if (!closed) {
    if (Diagnostic* d = reporter_.error(DiagId::parse_unterminated_bracket, reporter_.span(start, start + 1),
                                        "unterminated '['")) {
      d->note(reporter_.span(i, i), "expected ']' before the end of the line");
    }
  }
  return t;
}

Token Lexer::lex_number(uint32_t start) {
  uint32_t i = start;
  if (text_[i] == '-' || text_[i] == '+') ++i;
  uint32_t digits_begin = i;
  while (i < text_.size() && is_digit(text_[i])) ++i;
  auto exponent_at = [&](uint32_t k) {
    if (k >= text_.size() || (text_[k] != 'e' && text_[k] != 'E')) return false;
    ++k;
    if (k < text_.size() && (text_[k] == '+' || text_[k] == '-')) ++k;
    if (k >= text_.size() || !is_digit(text_[k])) return false;
    while (k < text_.size() && is_digit(text_[k])) ++k;
    return k >= text_.size() || !is_ident_char(text_[k]);
  };
  // "2D", "3D", "2DArray": a word that starts with digits.
  if (text_[start] != '-' && text_[start] != '+' && i < text_.size() && is_ident_start(text_[i]) &&
      !exponent_at(i)) {
    return lex_word(start);
  }
  if (i < text_.size() && text_[i] == '.') {
    ++i;
    while (i < text_.size() && is_digit(text_[i])) ++i;
  }
  if (i < text_.size() && (text_[i] == 'e' || text_[i] == 'E')) {
    uint32_t k = i + 1;
    if (k < text_.size() && (text_[k] == '+' || text_[k] == '-')) ++k;
    if (k < text_.size() && is_digit(text_[k])) {
      i = k;
      while (i < text_.size() && is_digit(text_[i])) ++i;
    }
  }
  pos_ = i;
  Token t = make(TokenKind::number, start, pos_);
  double value = 0;
  // from_chars takes neither '+' nor a bare ".5": parse the magnitude and
  // apply the sign ourselves.
  std::string magnitude(text_.substr(digits_begin, i - digits_begin));
  if (!magnitude.empty() && magnitude[0] == '.') magnitude.insert(magnitude.begin(), '0');
  auto [ptr, ec] = std::from_chars(magnitude.data(), magnitude.data() + magnitude.size(), value);
  if (ec != std::errc() || ptr != magnitude.data() + magnitude.size() || !std::isfinite(value)) {
    reporter_.error(DiagId::parse_bad_number, reporter_.span(start, pos_),
                    "number '" + shorten_echo(text(t)) + "' is out of range");
    value = 0;
  }
  t.number = text_[start] == '-' ? -value : value;
  return t;
}

Token Lexer::lex_word(uint32_t start) {
  uint32_t i = start;
  while (i < text_.size() && is_ident_char(text_[i])) ++i;
  pos_ = i;
  Token t = make(TokenKind::word, start, pos_);
  for (const ProgramKeyword& k : kProgramKeywords) {
    if (iequals(text(t), k.keyword)) {
      t.kind = TokenKind::program;
      t.language = k.language;
      t.is_include = k.is_include;
      t.keyword_end = pos_;
      lex_program(t, k.end_marker);
      break;
    }
  }
  return t;
}

// Finds the END marker as a whole token (case-insensitive), as Unity does:
// textually, so an "ENDCG" inside a program comment also ends the block.
void Lexer::lex_program(Token& t, std::string_view end_marker) {
  uint32_t i = t.keyword_end;
  const char first_lower = ascii_lower(end_marker[0]);
  for (; i + end_marker.size() <= text_.size(); ++i) {
    if (ascii_lower(text_[i]) != first_lower) continue;
    if (is_ident_char(text_[i - 1])) continue;
    if (!iequals(text_.substr(i, end_marker.size()), end_marker)) continue;
    size_t after = i + end_marker.size();
    if (after < text_.size() && is_ident_char(text_[after])) continue;
    t.inner_begin = t.keyword_end;
    t.inner_end = i;
    t.end = uint32_t(after);
    pos_ = t.end;
    return;
  }
  t.inner_begin = t.keyword_end;
  t.inner_end = uint32_t(text_.size());
  t.end = t.inner_end;
  pos_ = t.end;
  std::string keyword(text_.substr(t.begin, t.keyword_end - t.begin));
  reporter_.mark_early_eof();
  if (Diagnostic* d = reporter_.error(DiagId::parse_unterminated_program, reporter_.span(t.begin, t.keyword_end),
                                      "unterminated '" + keyword + "' block")) {
    d->note(reporter_.span(t.end, t.end), "expected '" + std::string(end_marker) + "' before the end of the file");
  }
}

}  // namespace facet::shaderlab
