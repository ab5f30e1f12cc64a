// Commands that may appear in a Category, SubShader or Pass: Tags, render
// state, legacy fixed-function commands and ignored metadata blocks.
//
// Commands have no terminator, and one line may hold several
// ("Cull Off ZWrite Off ZTest Always"), so each command's shape (its arity)
// decides where it ends.
#include <algorithm>
#include <array>

#include "parser.h"
#include "facet/support/text.h"

namespace facet::shaderlab {
namespace {

struct StateKeyword {
  std::string_view word;
  ast::CommandKind kind;
};

constexpr std::array<StateKeyword, 11> kStateKeywords = {{
    {"Cull", ast::CommandKind::cull},
    {"ZTest", ast::CommandKind::ztest},
    {"ZWrite", ast::CommandKind::zwrite},
    {"Blend", ast::CommandKind::blend},
    {"BlendOp", ast::CommandKind::blend_op},
    {"ColorMask", ast::CommandKind::color_mask},
    {"Offset", ast::CommandKind::offset},
    {"Stencil", ast::CommandKind::stencil},
    {"AlphaToMask", ast::CommandKind::alpha_to_mask},
    {"ZClip", ast::CommandKind::zclip},
    {"Conservative", ast::CommandKind::conservative},
}};

constexpr std::string_view kLegacyKeywords[] = {
    "Lighting", "SeparateSpecular", "ColorMaterial", "AlphaTest", "Fog",
    "Material", "BindChannels", "SetTexture", "Color",
};

// Other words that start a command somewhere; a value never starts a line
// with one of these, so "Cull" followed by a line "ZWrite Off" is a missing
// value rather than "Cull ZWrite".
constexpr std::string_view kStructureKeywords[] = {
    "Tags", "Pass", "UsePass", "GrabPass", "Name", "LOD", "SubShader", "Category",
    "Fallback", "CustomEditor", "Properties", "PackageRequirements",
};

constexpr std::string_view kStencilFields[] = {
    "Ref", "ReadMask", "WriteMask", "Comp", "Pass", "Fail", "ZFail",
    "CompBack", "PassBack", "FailBack", "ZFailBack",
    "CompFront", "PassFront", "FailFront", "ZFailFront",
};

template <typename List>
bool contains_word(const List& list, std::string_view word) {
  for (std::string_view w : list) {
    if (iequals(w, word)) return true;
  }
  return false;
}

bool is_command_keyword(std::string_view word) {
  for (const StateKeyword& k : kStateKeywords) {
    if (iequals(k.word, word)) return true;
  }
  return contains_word(kLegacyKeywords, word) || contains_word(kStructureKeywords, word);
}

bool is_identifier(std::string_view s) {
  if (s.empty() || !is_ident_start(s[0])) return false;
  for (char c : s) {
    if (!is_ident_char(c)) return false;
  }
  return true;
}

}  // namespace

std::string_view command_name(ast::CommandKind kind) {
  for (const StateKeyword& k : kStateKeywords) {
    if (k.kind == kind) return k.word;
  }
  return "?";
}

bool Parser::parse_scope_item(const ScopeRefs& scope) {
  if (!at(TokenKind::word)) return false;
  if (at_word("Tags")) {
    take();
    parse_tags(scope);
    return true;
  }
  for (const StateKeyword& k : kStateKeywords) {
    if (!at_word(k.word)) continue;
    Token keyword = take();
    if (auto command = parse_state_command(k.kind, keyword)) scope.state->push_back(std::move(*command));
    else skip_rest_of_command();
    return true;
  }
  if (contains_word(kLegacyKeywords, lexer_.text(current_))) {
    parse_legacy_command(scope, take());
    return true;
  }
  if (at_word("PackageRequirements")) {
    parse_ignored_block(*scope.ignored, take());
    return true;
  }
  return false;
}

void Parser::parse_tags(const ScopeRefs& scope) {
  auto open = expect(TokenKind::lbrace, "'{'", "after 'Tags'");
  if (!open) return skip_rest_of_command();
  if (!scope.tags_brace->has_location()) *scope.tags_brace = span(*open);
  parse_block(*open, "Tags", "a \"Key\"=\"Value\" pair", [&] {
    if (!at(TokenKind::string)) return false;
    Token key = take();
    if (!expect(TokenKind::equals, "'='", "after the tag name")) {
      skip_rest_of_command();
      return true;
    }
    auto value = expect(TokenKind::string, "a tag value string", "after '='");
    if (!value) {
      skip_rest_of_command();
      return true;
    }
    scope.tags->push_back({lexer_.string_value(key), lexer_.string_value(*value), span(key.begin, value->end),
                           span(key), span(*value)});
    return true;
  });
}

bool Parser::at_value() const {
  switch (current_.kind) {
    case TokenKind::number:
    case TokenKind::bracket: return true;
    case TokenKind::word: return !(current_.line_start && is_command_keyword(lexer_.text(current_)));
    default: return false;
  }
}

std::optional<ast::Value> Parser::parse_value(std::string_view context) {
  if (!at_value()) {
    unexpected(current_, "a value", context);
    return std::nullopt;
  }
  Token t = take();
  ast::Value v;
  v.span = span(t);
  if (t.kind == TokenKind::bracket) {
    v.kind = ast::Value::Kind::property;
    v.text = std::string(trim(lexer_.inner(t)));
    if (!is_identifier(v.text)) {
      reporter_.error(DiagId::parse_bad_property_reference, span(t),
                      "expected a property name inside '[...]', as in '[_SrcBlend]'");
      return std::nullopt;
    }
    return v;
  }
  v.kind = t.kind == TokenKind::number ? ast::Value::Kind::number : ast::Value::Kind::word;
  v.text = std::string(lexer_.text(t));
  return v;
}

std::optional<ast::Command> Parser::parse_state_command(ast::CommandKind kind, const Token& keyword) {
  ast::Command c;
  c.kind = kind;
  c.name = std::string(lexer_.text(keyword));
  std::string context = "after '" + std::string(command_name(kind)) + "'";
  // "Blend 1 ...", "BlendOp 1 ...": a leading number on the same line.
  auto take_render_target = [&] {
    if (at(TokenKind::number) && !current_.line_start) c.render_target = parse_value(context);
  };
  auto add_value = [&] {
    auto v = parse_value(context);
    if (v) c.values.push_back(std::move(*v));
    return v.has_value();
  };
  bool ok = true;
  switch (kind) {
    case ast::CommandKind::blend: ok = parse_blend_values(c, context); break;
    case ast::CommandKind::blend_op:
      take_render_target();
      ok = add_value();
      if (ok && at(TokenKind::comma)) {
        take();
        ok = add_value();
      }
      break;
    case ast::CommandKind::color_mask:
      ok = add_value();
      take_render_target();
      break;
    case ast::CommandKind::offset:
      ok = add_value();
      if (ok && at(TokenKind::comma)) take();
      ok = ok && add_value();
      break;
    case ast::CommandKind::stencil: ok = parse_stencil(c); break;
    default: ok = add_value(); break;
  }
  if (!ok) return std::nullopt;
  c.span = span(keyword.begin, last_end_);
  return c;
}

// Blend Off | Blend [rt] src dst [, src_alpha dst_alpha]
bool Parser::parse_blend_values(ast::Command& c, const std::string& context) {
  if (at(TokenKind::number) && !current_.line_start) c.render_target = parse_value(context);
  for (int i = 0; i < 2; ++i) {
    auto v = parse_value(context);
    if (!v) return false;
    bool off = i == 0 && v->kind == ast::Value::Kind::word && iequals(v->text, "Off");
    c.values.push_back(std::move(*v));
    if (off) return true;
  }
  if (!at(TokenKind::comma)) return true;
  take();
  for (int i = 0; i < 2; ++i) {
    auto v = parse_value("after ',' in 'Blend'");
    if (!v) return false;
    c.values.push_back(std::move(*v));
  }
  return true;
}

bool Parser::parse_stencil(ast::Command& c) {
  auto open = expect(TokenKind::lbrace, "'{'", "after 'Stencil'");
  if (!open) return false;
  parse_block(*open, "Stencil", "a Stencil field (Ref, Comp, Pass, ...)", [&] {
    if (!at(TokenKind::word) || !contains_word(kStencilFields, lexer_.text(current_))) return false;
    Token field = take();
    std::string name(lexer_.text(field));
    auto v = parse_value("after '" + name + "'");
    if (!v) {
      skip_rest_of_command();
      return true;
    }
    c.stencil.push_back({std::move(name), std::move(*v), span(field.begin, last_end_)});
    return true;
  });
  return true;
}

// Fixed-function commands keep their arguments (sema lowers them into a
// generated program for a Pass without one); block bodies are kept as tokens,
// since "combine texture * primary" is not ShaderLab's command grammar.
bool Parser::parse_legacy_command(const ScopeRefs& scope, const Token& keyword) {
  std::string_view word = lexer_.text(keyword);
  std::string context = "after '" + std::string(word) + "'";
  ast::LegacyCommand c;
  c.name = std::string(word);
  c.keyword_span = span(keyword);
  auto add_value = [&] {
    auto v = parse_value(context);
    if (v) c.values.push_back(std::move(*v));
    return v.has_value();
  };
  bool ok = true;
  if (iequals(word, "Fog") || iequals(word, "Material") || iequals(word, "BindChannels") ||
      iequals(word, "SetTexture")) {
    if (iequals(word, "SetTexture")) ok = add_value();
    std::optional<Token> open;
    if (ok) open = expect(TokenKind::lbrace, "'{'", context);
    ok = open && collect_legacy_body(*open, c);
  } else if (iequals(word, "Color") && at(TokenKind::lparen)) {
    Token paren = take();  // "Color (r, g, b, a)"
    ok = parse_number_list(c.color, context) && expect(TokenKind::rparen, "')'", context).has_value();
    c.color_span = span(paren.begin, last_end_);
  } else {
    ok = add_value();
    // "AlphaTest Greater [_Cutoff]": a comparison and a reference value.
    if (ok && iequals(word, "AlphaTest") && !iequals(c.values[0].text, "Off") && !current_.line_start &&
        (at(TokenKind::number) || at(TokenKind::bracket))) {
      ok = add_value();
    }
  }
  if (!ok) skip_rest_of_command();
  c.span = span(keyword.begin, std::max(last_end_, keyword.end));
  note_ignored(*scope.ignored, keyword, last_end_, true);
  if (ok) scope.ignored->back().legacy = std::move(c);
  return ok;
}

// The tokens up to the '}' matching `open` (already taken). Legacy blocks do
// not nest in Unity's grammar, but nested braces are kept balanced anyway.
bool Parser::collect_legacy_body(const Token& open, ast::LegacyCommand& c) {
  c.has_body = true;
  uint32_t level = 1;
  while (!reporter_.stopped()) {
    if (at(TokenKind::eof)) {
      report_unclosed(open, "");
      return false;
    }
    Token t = take();
    if (t.kind == TokenKind::rbrace && --level == 0) break;
    if (t.kind == TokenKind::lbrace && ++level + depth_ > options_.max_depth) {
      reporter_.error(DiagId::parse_nesting_too_deep, span(t),
                      "blocks are nested too deeply (the limit is " + std::to_string(options_.max_depth) + ")");
      return false;
    }
    ast::LegacyToken lt;
    lt.span = span(t);
    lt.line_start = t.line_start;
    switch (t.kind) {
      case TokenKind::word: lt.kind = ast::LegacyToken::Kind::word; break;
      case TokenKind::number:
        lt.kind = ast::LegacyToken::Kind::number;
        lt.number = t.number;
        break;
      case TokenKind::string: lt.kind = ast::LegacyToken::Kind::string; break;
      case TokenKind::bracket: lt.kind = ast::LegacyToken::Kind::property; break;
      default: lt.kind = ast::LegacyToken::Kind::symbol; break;
    }
    if (t.kind == TokenKind::string) lt.text = lexer_.string_value(t);
    else if (t.kind == TokenKind::bracket) lt.text = std::string(trim(lexer_.inner(t)));
    else lt.text = std::string(lexer_.text(t));
    c.body.push_back(std::move(lt));
  }
  c.body_span = span(open.begin, last_end_);
  return true;
}

void Parser::parse_ignored_block(std::vector<ast::IgnoredCommand>& out, const Token& keyword) {
  auto open = expect(TokenKind::lbrace, "'{'", "after '" + std::string(lexer_.text(keyword)) + "'");
  if (open) skip_balanced(*open, true);
  else skip_rest_of_command();
  note_ignored(out, keyword, last_end_, false);
}

void Parser::note_ignored(std::vector<ast::IgnoredCommand>& out, const Token& keyword, uint32_t end, bool legacy) {
  std::string name(lexer_.text(keyword));
  out.push_back({name, span(keyword.begin, std::max(end, keyword.end)), std::nullopt});
  if (legacy) {
    reporter_.report(DiagId::parse_legacy_command, span(keyword),
                     "'" + name + "' is a legacy fixed-function command; it only affects a Pass without a program block");
  } else {
    reporter_.report(DiagId::parse_ignored_command, span(keyword), "'" + name + "' is not used by facet; ignored");
  }
}

}  // namespace facet::shaderlab
