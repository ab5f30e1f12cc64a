// The ShaderLab front end: a hand-written lexer and recursive-descent parser
// that turn one .shader file into an AST with source spans. The AST keeps the
// text as written (keyword case, value spellings, unknown property types):
// checking and canonicalising is facet::sema's job.
//
//   SourceMap sources;
//   FileId file = sources.add_file("Unlit.shader", text);
//   Diagnostics diags;
//   Result<shaderlab::ast::Shader> shader = shaderlab::parse(file, sources, {}, diags);
//   if (!shader) { /* diags holds located errors */ }
//
// Invariants of every AST: lists are in file order; every span lies in the
// parsed file; strings are decoded (escapes applied); Category blocks are kept
// as nodes referenced by index (sema flattens them).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "facet/diagnostics.h"
#include "facet/result.h"
#include "facet/source.h"

namespace facet::shaderlab {

struct ParseOptions {
  // Deepest nesting of braces accepted; deeper input is a located error
  // rather than unbounded recursion.
  uint32_t max_depth = 256;
  // Parsing stops after this many errors (one more error says so).
  uint32_t max_errors = 100;
};

namespace ast {

// "[Toggle(_FOO)]" -> {name "Toggle", args {"_FOO"}}. Arguments are the raw
// comma-separated texts between the parentheses, trimmed, so that
// "[Enum(Metallic Alpha,0)]" keeps its spaces.
struct Attribute {
  std::string name;
  std::vector<std::string> args;
  bool has_parens = false;  // "[Space()]" vs "[Space]"
  SourceSpan span;          // from '[' to ']'
};

// The part after '=' of a property.
struct PropertyDefault {
  enum class Kind : uint8_t { none, number, vector, texture };
  Kind kind = Kind::none;
  std::vector<double> numbers;   // number: one; vector: as many as written
  std::string texture;           // texture: "white", "bump", "" ...
  bool has_braces = false;       // texture: followed by "{ ... }"
  std::string texture_options;   // the legacy text inside the braces, trimmed
  SourceSpan span;
};

// `[Attr]* _Name ("Display", Type) = default`.
struct Property {
  std::vector<Attribute> attributes;
  std::string name;
  SourceSpan name_span;
  std::string display_name;
  std::string type;               // as written: "Range", "2D", "color", "Flaot"
  SourceSpan type_span;
  std::vector<double> type_args;  // "Range(0, 1)" -> {0, 1}
  bool type_has_parens = false;
  PropertyDefault default_value;
  SourceSpan span;
};

struct Tag {
  std::string key;
  std::string value;
  SourceSpan span;  // the whole "Key"="Value"
  SourceSpan key_span;
  SourceSpan value_span;
};

// One argument of a render-state command.
struct Value {
  enum class Kind : uint8_t { word, number, property };
  Kind kind = Kind::word;
  std::string text;  // as written; for `[_Prop]` the trimmed name inside
  SourceSpan span;
};

enum class CommandKind : uint8_t {
  cull, ztest, zwrite, blend, blend_op, color_mask, offset, stencil,
  alpha_to_mask, zclip, conservative
};

// A field of a Stencil block: "Ref 2", "CompBack [_Comp]".
struct StencilField {
  std::string name;  // as written
  Value value;
  SourceSpan span;
};

// A render-state command. `values` by kind:
//   cull/ztest/zwrite/alpha_to_mask/zclip/conservative: one value;
//   blend: {Off} | {src, dst} | {src, dst, src_alpha, dst_alpha};
//   blend_op: {op} | {op, alpha_op};  color_mask: {mask};  offset: {factor, units};
//   stencil: none (see `stencil`).
// `render_target` is set for "Blend 1 ...", "BlendOp 1 ...", "ColorMask RGB 1".
struct Command {
  CommandKind kind = CommandKind::cull;
  std::string name;  // the keyword as written ("zwrite")
  std::optional<Value> render_target;
  std::vector<Value> values;
  std::vector<StencilField> stencil;
  SourceSpan span;
};

// One token inside the braces of a legacy block (Material, SetTexture, Fog,
// BindChannels), kept as the lexer saw it: sema reads "combine texture *
// primary DOUBLE, texture" itself, because those blocks have a grammar of
// their own.
struct LegacyToken {
  enum class Kind : uint8_t { word, number, string, property, symbol };
  Kind kind = Kind::word;
  std::string text;   // as written; property: the name inside '[...]'; string: decoded
  double number = 0;  // number tokens
  bool line_start = false;
  SourceSpan span;
};

// A legacy fixed-function command with its arguments. sema lowers these into
// a generated program for a Pass that has no program block.
//   Lighting/SeparateSpecular/ColorMaterial: values {word};
//   AlphaTest: {Off} | {comparison, reference};  Color: {[_Prop]} or `color`;
//   SetTexture: values {[_Tex]} and `body`;  Material/Fog/BindChannels: `body`.
struct LegacyCommand {
  std::string name;  // the keyword as written
  std::vector<Value> values;
  std::vector<double> color;      // "Color (r, g, b, a)"
  SourceSpan color_span;
  std::vector<LegacyToken> body;  // between the braces, in order
  bool has_body = false;
  SourceSpan body_span;           // from '{' to '}'
  SourceSpan keyword_span;
  SourceSpan span;
};

// A command that is parsed but not turned into render state: legacy
// fixed-function commands (Lighting, Fog {}, SetTexture, ...; `legacy` holds
// their arguments) and metadata facet does not use (Dependency,
// PackageRequirements, ...; `legacy` is empty).
struct IgnoredCommand {
  std::string name;  // as written
  SourceSpan span;
  std::optional<LegacyCommand> legacy;
};

enum class ProgramLanguage : uint8_t { cg, hlsl, glsl };

// CGPROGRAM/HLSLPROGRAM/GLSLPROGRAM or a *INCLUDE block; `text` is the exact
// source between the opening keyword and the END marker.
struct ProgramBlock {
  ProgramLanguage language = ProgramLanguage::cg;
  bool is_include = false;
  std::string text;
  SourceSpan text_span;      // the bytes of `text` in the file
  uint32_t first_line = 1;   // 1-based line of text[0]
  SourceSpan keyword_span;   // "CGPROGRAM"
};

enum class PassKind : uint8_t { normal, use_pass, grab_pass };

struct Pass {
  PassKind kind = PassKind::normal;
  std::string name;  // "Name \"X\"" as written; empty when absent
  SourceSpan name_span;
  std::vector<Tag> tags;           // every Tags block, concatenated
  SourceSpan tags_brace;           // '{' of the first Tags block, if any
  std::vector<Command> state;      // in order; later commands win
  std::optional<ProgramBlock> program;
  std::vector<IgnoredCommand> ignored;
  std::string use_pass;            // UsePass "Shader/PASS"
  std::string grab_texture;        // GrabPass { "_Name" }
  SourceSpan body_brace;           // the '{' after Pass/GrabPass
  SourceSpan span;
};

struct SubShader {
  std::vector<Tag> tags;
  SourceSpan tags_brace;
  std::optional<int> lod;
  SourceSpan lod_span;
  std::vector<Command> state;
  std::vector<ProgramBlock> includes;  // CGINCLUDE/HLSLINCLUDE at this scope
  std::vector<ProgramBlock> programs;  // program blocks outside a Pass (surface shaders)
  std::vector<Pass> passes;
  std::vector<IgnoredCommand> ignored;
  int category = -1;  // index into Shader::categories, -1: none
  SourceSpan span;
};

// `Category { state... SubShader... }`: state and tags inherited by the
// SubShaders inside (which point back with SubShader::category).
struct Category {
  int parent = -1;  // enclosing Category, -1: none
  std::vector<Tag> tags;
  std::optional<int> lod;  // inherited by SubShaders without their own LOD
  SourceSpan lod_span;
  std::vector<Command> state;
  std::vector<ProgramBlock> includes;
  std::vector<IgnoredCommand> ignored;
  SourceSpan span;
};

struct Shader {
  std::string name;
  SourceSpan name_span;
  std::vector<Property> properties;
  std::vector<ProgramBlock> includes;  // Shader-scope *INCLUDE blocks
  std::vector<SubShader> subshaders;   // Category members included, file order
  std::vector<Category> categories;
  std::optional<std::string> fallback;  // "Fallback Off" -> "Off" with fallback_off
  bool fallback_off = false;
  SourceSpan fallback_span;
  std::string custom_editor;
  std::vector<IgnoredCommand> ignored;
  FileId file = kNoFile;
  SourceSpan span;
};

}  // namespace ast

// Parses the file `file` of `sources`. Every problem becomes a diagnostic;
// the result is a failure when any error was reported, even if parsing
// recovered. Linear in the file size; never recurses deeper than
// options.max_depth.
Result<ast::Shader> parse(FileId file, const SourceMap& sources, const ParseOptions& options,
                          Diagnostics& diags);

// A stable, indented JSON dump of the AST (spans as "line:col-line:col"),
// used by `facetc --dump=ast` and golden tests.
std::string ast_to_json(const ast::Shader& shader, const SourceMap& sources);

// "Cull", "ZTest", ...: the canonical spelling of a command kind.
std::string_view command_name(ast::CommandKind kind);

}  // namespace facet::shaderlab
