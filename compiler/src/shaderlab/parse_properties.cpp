// Properties { [Attr]* _Name ("Display", Type) = default ... }
//
// The parser accepts any word as the type and any default form; whether they
// fit together ("Flaot", a texture with a number default) is sema's question,
// so that one misspelt type does not hide the rest of the block.
#include <cmath>

#include "parser.h"
#include "facet/support/text.h"

namespace facet::shaderlab {
namespace {

bool is_attribute_name(std::string_view s) {
  if (s.empty() || !is_ident_start(s[0])) return false;
  for (char c : s) {
    if (!is_ident_char(c) && c != '.') return false;
  }
  return true;
}

// Splits "A, B C, D" on the commas outside parentheses and quotes.
std::vector<std::string> split_arguments(std::string_view inside) {
  std::vector<std::string> args;
  if (trim(inside).empty()) return args;
  int depth = 0;
  bool quoted = false;
  size_t start = 0;
  for (size_t i = 0; i <= inside.size(); ++i) {
    char c = i < inside.size() ? inside[i] : ',';
    if (c == '"') quoted = !quoted;
    if (quoted && i < inside.size()) continue;
    if (c == '(') ++depth;
    if (c == ')' && depth > 0) --depth;
    if (c == ',' && (depth == 0 || i == inside.size())) {
      args.emplace_back(trim(inside.substr(start, i - start)));
      start = i + 1;
    }
  }
  return args;
}

}  // namespace

void Parser::parse_properties(ast::Shader& shader) {
  auto open = expect(TokenKind::lbrace, "'{'", "after 'Properties'");
  if (!open) return skip_rest_of_command();
  parse_block(*open, "Properties", "a property such as '_Name (\"Display\", Float) = 0'",
              [&] { return parse_property(shader); });
}

bool Parser::parse_property(ast::Shader& shader) {
  if (!at(TokenKind::bracket) && !at(TokenKind::word)) return false;
  ast::Property p;
  uint32_t begin = current_.begin;
  auto fail = [&] {
    skip_rest_of_command();
    return true;
  };
  while (at(TokenKind::bracket)) {
    if (auto a = parse_attribute(take())) p.attributes.push_back(std::move(*a));
  }
  auto name = expect(TokenKind::word, "a property name", "after its attributes");
  if (!name) return fail();
  p.name = std::string(lexer_.text(*name));
  p.name_span = span(*name);
  std::string context = "in property '" + p.name + "'";
  if (!expect(TokenKind::lparen, "'('", "after the property name")) return fail();
  auto display = parse_string("a display name string", context);
  if (!display) return fail();
  p.display_name = *display;
  if (!expect(TokenKind::comma, "','", context) || !parse_property_type(p)) return fail();
  if (!expect(TokenKind::rparen, "')'", context) || !expect(TokenKind::equals, "'='", context)) return fail();
  if (!parse_property_default(p)) return fail();
  p.span = span(begin, last_end_);
  shader.properties.push_back(std::move(p));
  return true;
}

std::optional<ast::Attribute> Parser::parse_attribute(const Token& bracket) {
  std::string_view raw = lexer_.inner(bracket);
  ast::Attribute a;
  a.span = span(bracket);
  size_t paren = raw.find('(');
  a.name = std::string(trim(raw.substr(0, paren)));
  if (!is_attribute_name(a.name)) {
    reporter_.error(DiagId::parse_unexpected_token, span(bracket),
                    "expected an attribute name inside '[...]', as in '[HideInInspector]'");
    return std::nullopt;
  }
  if (paren == std::string_view::npos) return a;
  size_t close = raw.rfind(')');
  if (close == std::string_view::npos || close < paren || !trim(raw.substr(close + 1)).empty()) {
    reporter_.error(DiagId::parse_unexpected_token, span(bracket),
                    "expected ')' at the end of attribute '" + a.name + "'");
    return std::nullopt;
  }
  a.has_parens = true;
  a.args = split_arguments(raw.substr(paren + 1, close - paren - 1));
  return a;
}

bool Parser::parse_property_type(ast::Property& p) {
  auto type = expect(TokenKind::word, "a property type (Float, Range(min, max), Color, 2D, ...)",
                     "in property '" + p.name + "'");
  if (!type) return false;
  p.type = std::string(lexer_.text(*type));
  p.type_span = span(*type);
  if (!at(TokenKind::lparen)) return true;
  take();
  p.type_has_parens = true;
  std::string context = "in '" + p.type + "(...)'";
  if (!parse_number_list(p.type_args, context)) return false;
  if (!expect(TokenKind::rparen, "')'", context)) return false;
  p.type_span = span(type->begin, last_end_);
  return true;
}

bool Parser::parse_property_default(ast::Property& p) {
  ast::PropertyDefault& d = p.default_value;
  uint32_t begin = current_.begin;
  if (at(TokenKind::number) || at_non_finite_word()) {
    d.kind = ast::PropertyDefault::Kind::number;
    auto n = parse_float("in the default of '" + p.name + "'");
    if (!n) return false;
    d.numbers.push_back(*n);
  } else if (at(TokenKind::lparen)) {
    take();
    d.kind = ast::PropertyDefault::Kind::vector;
    if (!parse_number_list(d.numbers, "in the default of '" + p.name + "'")) return false;
    if (!expect(TokenKind::rparen, "')'", "in the default of '" + p.name + "'")) return false;
  } else if (at(TokenKind::string)) {
    d.kind = ast::PropertyDefault::Kind::texture;
    d.texture = lexer_.string_value(take());
    // "white" {} - the braces may hold legacy options (TexGen CubeReflect).
    if (at(TokenKind::lbrace)) {
      Token open = take();
      d.has_braces = true;
      if (!skip_balanced(open, true)) return false;
      std::string_view inside = lexer_.source().substr(open.end, last_end_ - 1 - open.end);
      d.texture_options = std::string(trim(inside));
    }
  } else {
    unexpected(current_, "a default value (a number, '(r, g, b, a)' or \"texture\" {})",
               "for property '" + p.name + "'");
    return false;
  }
  d.span = span(begin, last_end_);
  return true;
}

// Property values are 32-bit floats (docs/package-format.md): a number that
// does not fit one would become an infinity that no one wrote, so it is an
// error at the number, like a number too large for a double. Infinities and
// NaN cannot be written at all (the words 'inf' and 'nan').
std::optional<double> Parser::parse_float(std::string_view context) {
  if (at_non_finite_word()) {
    reporter_.error(DiagId::parse_bad_number, span(current_),
                    "'" + std::string(lexer_.text(current_)) + "' is not a number a property can hold " +
                        std::string(context) + "; write a finite number");
    return std::nullopt;
  }
  auto n = expect(TokenKind::number, "a number", context);
  if (!n) return std::nullopt;
  // Doubles from here up round to infinity as floats (half an ulp past FLT_MAX).
  constexpr double kFloatOverflow = 0x1.ffffffp+127;
  if (!(std::abs(n->number) < kFloatOverflow)) {
    reporter_.error(DiagId::parse_bad_number, span(*n),
                    "number '" + shorten_echo(lexer_.text(*n)) + "' does not fit a 32-bit float " +
                        std::string(context) + " (the largest is about 3.4e38)");
    return std::nullopt;
  }
  return n->number;
}

bool Parser::at_non_finite_word() const {
  if (current_.kind != TokenKind::word) return false;
  std::string_view w = lexer_.text(current_);
  if (!w.empty() && (w[0] == '-' || w[0] == '+')) w.remove_prefix(1);
  return iequals(w, "nan") || iequals(w, "inf") || iequals(w, "infinity");
}

bool Parser::parse_number_list(std::vector<double>& out, std::string_view context) {
  if (at(TokenKind::rparen)) return true;
  for (;;) {
    auto n = parse_float(context);
    if (!n) return false;
    out.push_back(*n);
    if (!at(TokenKind::comma)) return true;
    take();
  }
}

}  // namespace facet::shaderlab
