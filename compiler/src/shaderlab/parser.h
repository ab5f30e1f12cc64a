// The recursive-descent parser behind shaderlab::parse. One token of
// lookahead; every block body goes through parse_block so that nesting is
// bounded by ParseOptions::max_depth and every unexpected token is reported
// once, followed by recovery to the next line.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "facet/shaderlab.h"
#include "lexer.h"
#include "reporter.h"

namespace facet::shaderlab {

// The parts of a Category, SubShader or Pass that commands may fill.
struct ScopeRefs {
  std::vector<ast::Tag>* tags;
  SourceSpan* tags_brace;
  std::vector<ast::Command>* state;
  std::vector<ast::IgnoredCommand>* ignored;
};

class Parser {
 public:
  Parser(FileId file, const SourceMap& sources, const ParseOptions& options, Diagnostics& diags);

  ast::Shader parse_file();
  uint32_t error_count() const { return reporter_.error_count(); }

 private:
  // Tokens (parser.cpp).
  const Token& peek() const { return current_; }
  Token take();
  bool at(TokenKind kind) const { return current_.kind == kind; }
  bool at_word(std::string_view word) const;
  std::optional<Token> expect(TokenKind kind, std::string_view what, std::string_view context);
  std::string describe(const Token& t) const;
  SourceSpan span(const Token& t) const { return reporter_.span(t.begin, t.end); }
  SourceSpan span(uint32_t begin, uint32_t end) const { return reporter_.span(begin, end); }
  void unexpected(const Token& t, std::string_view expected, std::string_view context);

  // Blocks and recovery (parser.cpp).
  // Parses `item* }` after the opening brace was taken; `item` returns false
  // when the current token starts nothing it knows, which is then reported
  // ("expected <expected> or '}'" when given, else "unknown command").
  void parse_block(const Token& open, std::string_view context, std::string_view expected,
                   const std::function<bool()>& item);
  void report_unclosed(const Token& open, std::string_view context);
  // Skips to the '}' matching `open` (already taken) without recursion.
  // Returns false at the end of the file.
  bool skip_balanced(const Token& open, bool report_depth);
  // Skips the rest of the current line (commands are line-shaped), never
  // past a '}'.
  void skip_rest_of_command();
  void recover(std::string_view context, std::string_view expected);

  // Structure (parser.cpp).
  void parse_shader(ast::Shader& shader);
  bool parse_shader_item(ast::Shader& shader);
  void parse_ignored_strings(ast::Shader& shader);
  void parse_category(ast::Shader& shader, int parent, const Token& keyword);
  void parse_subshader(ast::Shader& shader, int category, const Token& keyword);
  bool parse_subshader_item(ast::SubShader& sub);
  void parse_lod(std::optional<int>& lod, SourceSpan& lod_span, const Token& keyword);
  void parse_pass(ast::SubShader& sub, const Token& keyword);
  void add_pass_program(ast::Pass& pass, const Token& program);
  void parse_use_pass(ast::SubShader& sub, const Token& keyword);
  void parse_grab_pass(ast::SubShader& sub, const Token& keyword);
  void parse_fallback(ast::Shader& shader, const Token& keyword);
  ast::ProgramBlock make_program(const Token& t) const;
  std::optional<std::string> parse_string(std::string_view what, std::string_view context,
                                          SourceSpan* where = nullptr);

  // Commands shared by every scope (parse_state.cpp).
  bool parse_scope_item(const ScopeRefs& scope);
  void parse_tags(const ScopeRefs& scope);
  std::optional<ast::Command> parse_state_command(ast::CommandKind kind, const Token& keyword);
  bool parse_blend_values(ast::Command& c, const std::string& context);
  bool parse_stencil(ast::Command& c);
  std::optional<ast::Value> parse_value(std::string_view context);
  bool at_value() const;
  bool parse_legacy_command(const ScopeRefs& scope, const Token& keyword);
  bool collect_legacy_body(const Token& open, ast::LegacyCommand& c);
  void parse_ignored_block(std::vector<ast::IgnoredCommand>& out, const Token& keyword);
  void note_ignored(std::vector<ast::IgnoredCommand>& out, const Token& keyword, uint32_t end, bool legacy);

  // Properties (parse_properties.cpp).
  void parse_properties(ast::Shader& shader);
  bool parse_property(ast::Shader& shader);
  std::optional<ast::Attribute> parse_attribute(const Token& bracket);
  bool parse_property_type(ast::Property& p);
  bool parse_property_default(ast::Property& p);
  bool parse_number_list(std::vector<double>& out, std::string_view context);
  std::optional<double> parse_float(std::string_view context);
  bool at_non_finite_word() const;

  FileId file_;
  const SourceMap& sources_;
  ParseOptions options_;
  Reporter reporter_;
  Lexer lexer_;
  Token current_;
  uint32_t depth_ = 0;
  uint32_t last_end_ = 0;  // end of the last token taken
};

}  // namespace facet::shaderlab
