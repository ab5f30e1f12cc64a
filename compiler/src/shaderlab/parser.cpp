// Structure of a .shader file: Shader, Properties, Category, SubShader, Pass,
// UsePass, GrabPass, Fallback, CustomEditor, program blocks. Commands shared
// by every scope are in parse_state.cpp, properties in parse_properties.cpp.
#include "parser.h"

#include <algorithm>
#include <cmath>

namespace facet::shaderlab {
namespace {

std::string shorten(std::string_view s) {
  constexpr size_t kMax = 32;
  return s.size() <= kMax ? std::string(s) : std::string(s.substr(0, kMax)) + "...";
}

std::string hex_byte(unsigned char c) {
  const char* digits = "0123456789abcdef";
  return std::string("0x") + digits[c >> 4] + digits[c & 15];
}

}  // namespace

Parser::Parser(FileId file, const SourceMap& sources, const ParseOptions& options, Diagnostics& diags)
    : file_(file),
      sources_(sources),
      options_(options),
      reporter_(file, diags, std::max<uint32_t>(1, options.max_errors)),
      lexer_(sources.text(file), reporter_) {
  current_ = lexer_.next();
}

Token Parser::take() {
  Token t = current_;
  last_end_ = t.end;
  current_ = lexer_.next();
  return t;
}

bool Parser::at_word(std::string_view word) const {
  return current_.kind == TokenKind::word && iequals(lexer_.text(current_), word);
}

std::string Parser::describe(const Token& t) const {
  switch (t.kind) {
    case TokenKind::eof: return "end of file";
    case TokenKind::string: return "string \"" + shorten(lexer_.inner(t)) + "\"";
    case TokenKind::program:
      return "'" + std::string(lexer_.source().substr(t.begin, t.keyword_end - t.begin)) + "' block";
    case TokenKind::other: {
      unsigned char c = uint8_t(lexer_.source()[t.begin]);
      bool printable = c >= 0x20 && c != 0x7f;
      return "character '" + (printable ? std::string(lexer_.text(t)) : "\\x" + hex_byte(c).substr(2)) + "'";
    }
    default: return "'" + shorten(lexer_.text(t)) + "'";
  }
}

void Parser::unexpected(const Token& t, std::string_view expected, std::string_view context) {
  std::string message = "expected " + std::string(expected);
  if (!context.empty()) message += " " + std::string(context);
  reporter_.error(DiagId::parse_unexpected_token, span(t), message + ", found " + describe(t));
}

std::optional<Token> Parser::expect(TokenKind kind, std::string_view what, std::string_view context) {
  if (at(kind)) return take();
  unexpected(current_, what, context);
  return std::nullopt;
}

std::optional<std::string> Parser::parse_string(std::string_view what, std::string_view context,
                                                SourceSpan* where) {
  auto t = expect(TokenKind::string, what, context);
  if (!t) return std::nullopt;
  if (where) *where = span(*t);
  return lexer_.string_value(*t);
}

// --- blocks and recovery ----------------------------------------------------

void Parser::parse_block(const Token& open, std::string_view context, std::string_view expected,
                         const std::function<bool()>& item) {
  if (depth_ >= options_.max_depth) {
    reporter_.error(DiagId::parse_nesting_too_deep, span(open),
                    "blocks are nested too deeply (the limit is " + std::to_string(options_.max_depth) + ")");
    skip_balanced(open, false);
    return;
  }
  ++depth_;
  while (!reporter_.stopped()) {
    if (at(TokenKind::rbrace)) {
      take();
      break;
    }
    if (at(TokenKind::eof)) {
      report_unclosed(open, context);
      break;
    }
    uint32_t before = current_.begin;
    if (!item()) recover(context, expected);
    // An item that took nothing would loop forever; never let it.
    if (current_.begin == before && !at(TokenKind::eof) && !at(TokenKind::rbrace)) take();
  }
  --depth_;
}

void Parser::report_unclosed(const Token& open, std::string_view context) {
  if (reporter_.early_eof()) return;
  reporter_.mark_early_eof();
  std::string what = context.empty() ? "this '{'" : "this " + std::string(context) + " block";
  if (Diagnostic* d = reporter_.error(DiagId::parse_unterminated_block, span(open), "missing '}' for " + what)) {
    d->note(span(current_.begin, current_.begin), "the file ends here");
  }
}

bool Parser::skip_balanced(const Token& open, bool report_depth) {
  uint32_t level = 1;
  bool reported = !report_depth;
  while (level > 0 && !reporter_.stopped()) {
    if (at(TokenKind::eof)) {
      report_unclosed(open, "");
      return false;
    }
    Token t = take();
    if (t.kind == TokenKind::lbrace) {
      ++level;
      if (!reported && depth_ + level > options_.max_depth) {
        reporter_.error(DiagId::parse_nesting_too_deep, span(t),
                        "blocks are nested too deeply (the limit is " + std::to_string(options_.max_depth) + ")");
        reported = true;
      }
    } else if (t.kind == TokenKind::rbrace) {
      --level;
    }
  }
  return level == 0;
}

void Parser::skip_rest_of_command() {
  while (!at(TokenKind::eof) && !at(TokenKind::rbrace) && !current_.line_start && !reporter_.stopped()) {
    Token t = take();
    if (t.kind == TokenKind::lbrace) skip_balanced(t, true);
  }
}

void Parser::recover(std::string_view context, std::string_view expected) {
  const Token& t = current_;
  if (!expected.empty()) {
    unexpected(t, std::string(expected) + " or '}'", "in " + std::string(context));
  } else if (t.kind == TokenKind::other) {
    reporter_.error(DiagId::parse_unexpected_character, span(t), "unexpected " + describe(t) + " in " + std::string(context));
  } else if (t.kind == TokenKind::word) {
    reporter_.error(DiagId::parse_unknown_command, span(t),
                    "unknown command '" + shorten(lexer_.text(t)) + "' in " + std::string(context));
  } else {
    reporter_.error(DiagId::parse_unexpected_token, span(t),
                    "unexpected " + describe(t) + " in " + std::string(context));
  }
  Token first = take();
  if (first.kind == TokenKind::lbrace) skip_balanced(first, true);
  skip_rest_of_command();
}

// --- structure ----------------------------------------------------------------

ast::Shader Parser::parse_file() {
  ast::Shader shader;
  shader.file = file_;
  if (!at_word("Shader")) {
    unexpected(current_, "'Shader'", "at the start of the file");
    return shader;
  }
  parse_shader(shader);
  if (!at(TokenKind::eof) && reporter_.error_count() == 0) {
    if (Diagnostic* d = reporter_.error(DiagId::parse_extra_shader, span(current_),
                                        "unexpected " + describe(current_) + " after the end of the Shader block")) {
      d->note(shader.span, "a file holds exactly one Shader block");
    }
  }
  return shader;
}

void Parser::parse_shader(ast::Shader& shader) {
  Token keyword = take();
  auto name = parse_string("a shader name string", "after 'Shader'", &shader.name_span);
  if (!name) return;
  shader.name = *name;
  auto open = expect(TokenKind::lbrace, "'{'", "after the shader name");
  if (!open) return;
  parse_block(*open, "Shader", "", [&] { return parse_shader_item(shader); });
  shader.span = span(keyword.begin, last_end_);
}

bool Parser::parse_shader_item(ast::Shader& shader) {
  if (at(TokenKind::program)) {
    Token p = take();
    if (p.is_include) {
      shader.includes.push_back(make_program(p));
    } else {
      reporter_.error(DiagId::parse_misplaced_block, span(p.begin, p.keyword_end),
                      describe(p) + " must be inside a SubShader or a Pass");
    }
    return true;
  }
  if (at_word("Properties")) {
    take();
    parse_properties(shader);
  } else if (at_word("SubShader")) {
    parse_subshader(shader, -1, take());
  } else if (at_word("Category")) {
    parse_category(shader, -1, take());
  } else if (at_word("Fallback")) {
    parse_fallback(shader, take());
  } else if (at_word("CustomEditor")) {
    take();
    if (auto s = parse_string("an editor class name string", "after 'CustomEditor'")) shader.custom_editor = *s;
    else skip_rest_of_command();
  } else if (at_word("CustomEditorForRenderPipeline") || at_word("Dependency")) {
    parse_ignored_strings(shader);
  } else {
    return false;
  }
  return true;
}

// "CustomEditorForRenderPipeline "Editor" "Pipeline"" and "Dependency "A" = "B"":
// metadata for Unity's editor, kept only as ignored commands.
void Parser::parse_ignored_strings(ast::Shader& shader) {
  Token keyword = take();
  bool dependency = iequals(lexer_.text(keyword), "Dependency");
  std::string context = "after '" + std::string(lexer_.text(keyword)) + "'";
  bool ok = parse_string("a string", context).has_value();
  if (ok && dependency) ok = expect(TokenKind::equals, "'='", context).has_value();
  if (ok) ok = parse_string("a string", context).has_value();
  if (!ok) skip_rest_of_command();
  note_ignored(shader.ignored, keyword, last_end_, false);
}

void Parser::parse_fallback(ast::Shader& shader, const Token& keyword) {
  if (at_word("Off")) {
    Token off = take();
    shader.fallback = "Off";
    shader.fallback_off = true;
    shader.fallback_span = span(keyword.begin, off.end);
    return;
  }
  if (auto name = parse_string("a shader name string or 'Off'", "after 'Fallback'")) {
    shader.fallback = *name;
    shader.fallback_span = span(keyword.begin, last_end_);
  } else {
    skip_rest_of_command();
  }
}

void Parser::parse_category(ast::Shader& shader, int parent, const Token& keyword) {
  int index = int(shader.categories.size());
  shader.categories.push_back({});
  shader.categories.back().parent = parent;
  auto open = expect(TokenKind::lbrace, "'{'", "after 'Category'");
  if (!open) return skip_rest_of_command();
  parse_block(*open, "Category", "", [&] {
    if (at_word("SubShader")) {
      parse_subshader(shader, index, take());
      return true;
    }
    if (at_word("Category")) {
      parse_category(shader, index, take());
      return true;
    }
    // Shader-level commands inside a Category apply to the shader, as in
    // Unity (old shaders put their CustomEditor or Fallback there).
    if (at_word("CustomEditor") || at_word("Fallback") || at_word("CustomEditorForRenderPipeline") ||
        at_word("Dependency")) {
      return parse_shader_item(shader);
    }
    // Refer to the category by index: nested categories grow the vector.
    ast::Category& cat = shader.categories[size_t(index)];
    if (at_word("LOD")) {
      parse_lod(cat.lod, cat.lod_span, take());
      return true;
    }
    if (at(TokenKind::program) && current_.is_include) {
      cat.includes.push_back(make_program(take()));
      return true;
    }
    SourceSpan unused_brace;
    return parse_scope_item({&cat.tags, &unused_brace, &cat.state, &cat.ignored});
  });
  shader.categories[size_t(index)].span = span(keyword.begin, last_end_);
}

void Parser::parse_subshader(ast::Shader& shader, int category, const Token& keyword) {
  ast::SubShader sub;
  sub.category = category;
  auto open = expect(TokenKind::lbrace, "'{'", "after 'SubShader'");
  if (!open) return skip_rest_of_command();
  parse_block(*open, "SubShader", "", [&] { return parse_subshader_item(sub); });
  sub.span = span(keyword.begin, last_end_);
  shader.subshaders.push_back(std::move(sub));
}

bool Parser::parse_subshader_item(ast::SubShader& sub) {
  if (at(TokenKind::program)) {
    Token p = take();
    (p.is_include ? sub.includes : sub.programs).push_back(make_program(p));
    return true;
  }
  if (at_word("Pass")) {
    parse_pass(sub, take());
  } else if (at_word("UsePass")) {
    parse_use_pass(sub, take());
  } else if (at_word("GrabPass")) {
    parse_grab_pass(sub, take());
  } else if (at_word("LOD")) {
    parse_lod(sub.lod, sub.lod_span, take());
  } else {
    return parse_scope_item({&sub.tags, &sub.tags_brace, &sub.state, &sub.ignored});
  }
  return true;
}

void Parser::parse_lod(std::optional<int>& lod, SourceSpan& lod_span, const Token& keyword) {
  auto n = expect(TokenKind::number, "a level of detail number", "after 'LOD'");
  if (!n) return skip_rest_of_command();
  lod_span = span(keyword.begin, n->end);
  if (!(n->number >= 0 && n->number <= 1e9 && n->number == std::floor(n->number))) {
    reporter_.error(DiagId::parse_bad_number, span(*n), "LOD must be a non-negative integer");
    return;
  }
  lod = int(n->number);
}

void Parser::parse_pass(ast::SubShader& sub, const Token& keyword) {
  ast::Pass pass;
  auto open = expect(TokenKind::lbrace, "'{'", "after 'Pass'");
  if (!open) return skip_rest_of_command();
  pass.body_brace = span(*open);
  parse_block(*open, "Pass", "", [&] {
    if (at(TokenKind::program)) {
      add_pass_program(pass, take());
      return true;
    }
    if (at_word("Name")) {
      take();
      if (auto name = parse_string("a pass name string", "after 'Name'", &pass.name_span)) pass.name = *name;
      else skip_rest_of_command();
      return true;
    }
    if (at_word("LOD")) {  // Unity accepts LOD in a Pass and ignores it
      std::optional<int> unused_lod;
      SourceSpan unused_span;
      Token keyword = take();
      parse_lod(unused_lod, unused_span, keyword);
      note_ignored(pass.ignored, keyword, last_end_, false);
      return true;
    }
    return parse_scope_item({&pass.tags, &pass.tags_brace, &pass.state, &pass.ignored});
  });
  pass.span = span(keyword.begin, last_end_);
  sub.passes.push_back(std::move(pass));
}

void Parser::add_pass_program(ast::Pass& pass, const Token& p) {
  if (p.is_include) {
    reporter_.error(DiagId::parse_misplaced_block, span(p.begin, p.keyword_end),
                    describe(p) + " must be at Shader or SubShader scope, not inside a Pass");
  } else if (pass.program) {
    if (Diagnostic* d = reporter_.error(DiagId::parse_duplicate_program, span(p.begin, p.keyword_end),
                                        "a Pass holds one program block; this is a second one")) {
      d->note(pass.program->keyword_span, "the first program block is here");
    }
  } else {
    pass.program = make_program(p);
  }
}

void Parser::parse_use_pass(ast::SubShader& sub, const Token& keyword) {
  ast::Pass pass;
  pass.kind = ast::PassKind::use_pass;
  auto name = parse_string("a \"Shader/PASSNAME\" string", "after 'UsePass'");
  if (!name) return skip_rest_of_command();
  pass.use_pass = *name;
  pass.span = span(keyword.begin, last_end_);
  sub.passes.push_back(std::move(pass));
}

void Parser::parse_grab_pass(ast::SubShader& sub, const Token& keyword) {
  ast::Pass pass;
  pass.kind = ast::PassKind::grab_pass;
  auto open = expect(TokenKind::lbrace, "'{'", "after 'GrabPass'");
  if (!open) return skip_rest_of_command();
  pass.body_brace = span(*open);
  parse_block(*open, "GrabPass", "", [&] {
    if (at(TokenKind::string)) {
      pass.grab_texture = lexer_.string_value(take());
      return true;
    }
    if (at_word("Name")) {
      take();
      if (auto name = parse_string("a pass name string", "after 'Name'", &pass.name_span)) pass.name = *name;
      return true;
    }
    if (at_word("Tags")) {
      take();
      parse_tags({&pass.tags, &pass.tags_brace, &pass.state, &pass.ignored});
      return true;
    }
    return false;
  });
  pass.span = span(keyword.begin, last_end_);
  sub.passes.push_back(std::move(pass));
}

ast::ProgramBlock Parser::make_program(const Token& t) const {
  ast::ProgramBlock p;
  p.language = t.language;
  p.is_include = t.is_include;
  p.text = std::string(lexer_.inner(t));
  p.text_span = span(t.inner_begin, t.inner_end);
  p.first_line = sources_.line_column(file_, t.inner_begin).line;
  p.keyword_span = span(t.begin, t.keyword_end);
  return p;
}

// --- entry --------------------------------------------------------------------

Result<ast::Shader> parse(FileId file, const SourceMap& sources, const ParseOptions& options,
                          Diagnostics& diags) {
  if (file >= sources.file_count()) {
    diags.add(DiagId::io_cannot_read, SourceSpan{}, "no source file with id " + std::to_string(file));
    return failure("no such file");
  }
  const std::string& text = sources.text(file);
  // Spans are 32-bit offsets, and the end of file must be representable.
  if (text.size() >= UINT32_MAX) {
    diags.add(DiagId::io_too_large, SourceSpan{file, 0, 0}, "file is too large (4 GiB or more)");
    return failure("file too large");
  }
  if (auto bad = find_bad_byte(text)) {
    SourceSpan where{file, bad->offset, bad->offset + 1};
    std::string message = bad->id == DiagId::parse_nul_byte
                              ? "file contains a NUL byte; it looks like a binary file, not ShaderLab text"
                              : "invalid UTF-8 byte " + hex_byte(uint8_t(text[bad->offset])) +
                                    "; ShaderLab files must be UTF-8 text";
    diags.add(bad->id, where, std::move(message));
    return failure("not a text file");
  }
  Parser parser(file, sources, options, diags);
  ast::Shader shader = parser.parse_file();
  if (parser.error_count() > 0) return failure("ShaderLab parse errors");
  return shader;
}

}  // namespace facet::shaderlab
