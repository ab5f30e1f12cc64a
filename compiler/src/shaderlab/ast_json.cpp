// ast_to_json: a stable dump for `facetc --dump=ast` and golden tests. Keys
// keep insertion order (ordered_json) so that the text only changes when the
// AST does; optional parts are left out rather than written as null.
#include <algorithm>
#include <nlohmann/json.hpp>

#include "facet/support/json_print.h"
#include "facet/shaderlab.h"

namespace facet::shaderlab {
namespace {

using Json = nlohmann::ordered_json;

class AstJson {
 public:
  explicit AstJson(const SourceMap& sources) : sources_(sources) {}

  Json shader(const ast::Shader& s) const {
    Json j;
    j["name"] = s.name;
    j["span"] = span(s.span);
    j["properties"] = list(s.properties, [&](const ast::Property& p) { return property(p); });
    j["includes"] = programs(s.includes);
    j["categories"] = list(s.categories, [&](const ast::Category& c) { return category(c); });
    j["subshaders"] = list(s.subshaders, [&](const ast::SubShader& x) { return subshader(x); });
    if (s.fallback) {
      j["fallback"] = *s.fallback;
      j["fallback_off"] = s.fallback_off;
    }
    if (!s.custom_editor.empty()) j["custom_editor"] = s.custom_editor;
    j["ignored"] = ignored(s.ignored);
    return j;
  }

 private:
  template <typename T, typename F>
  static Json list(const std::vector<T>& items, F&& f) {
    Json a = Json::array();
    for (const T& item : items) a.push_back(f(item));
    return a;
  }

  // "line:col-line:col" is what a reviewer can check against the file.
  std::string span(SourceSpan s) const {
    if (!s.has_location()) return "";
    LineColumn b = sources_.line_column(s.file, s.begin);
    LineColumn e = sources_.line_column(s.file, s.end);
    return std::to_string(b.line) + ":" + std::to_string(b.column) + "-" + std::to_string(e.line) + ":" +
           std::to_string(e.column);
  }

  Json property(const ast::Property& p) const {
    Json j;
    j["name"] = p.name;
    j["display"] = p.display_name;
    j["type"] = p.type;
    if (p.type_has_parens) j["type_args"] = p.type_args;
    j["attributes"] = list(p.attributes, [&](const ast::Attribute& a) {
      Json x;
      x["name"] = a.name;
      if (a.has_parens) x["args"] = a.args;
      return x;
    });
    j["default"] = property_default(p.default_value);
    j["span"] = span(p.span);
    return j;
  }

  Json property_default(const ast::PropertyDefault& d) const {
    Json j;
    switch (d.kind) {
      case ast::PropertyDefault::Kind::none: j["kind"] = "none"; break;
      case ast::PropertyDefault::Kind::number: j["kind"] = "number"; break;
      case ast::PropertyDefault::Kind::vector: j["kind"] = "vector"; break;
      case ast::PropertyDefault::Kind::texture: j["kind"] = "texture"; break;
    }
    if (d.kind == ast::PropertyDefault::Kind::texture) {
      j["texture"] = d.texture;
      if (d.has_braces) j["options"] = d.texture_options;
    } else {
      j["numbers"] = d.numbers;
    }
    return j;
  }

  Json tags(const std::vector<ast::Tag>& tags) const {
    Json j = Json::array();
    for (const ast::Tag& t : tags) j.push_back(Json::array({t.key, t.value}));
    return j;
  }

  // Words and numbers as written; a property as "[_Prop]".
  static Json value(const ast::Value& v) {
    return v.kind == ast::Value::Kind::property ? "[" + v.text + "]" : v.text;
  }

  Json command(const ast::Command& c) const {
    Json j;
    j["command"] = command_name(c.kind);
    j["as_written"] = c.name;
    if (c.render_target) j["render_target"] = value(*c.render_target);
    if (c.kind == ast::CommandKind::stencil) {
      j["fields"] = list(c.stencil, [&](const ast::StencilField& f) { return Json::array({f.name, value(f.value)}); });
    } else {
      j["values"] = list(c.values, [&](const ast::Value& v) { return value(v); });
    }
    j["span"] = span(c.span);
    return j;
  }

  Json state(const std::vector<ast::Command>& commands) const {
    return list(commands, [&](const ast::Command& c) { return command(c); });
  }

  Json ignored(const std::vector<ast::IgnoredCommand>& items) const {
    return list(items, [&](const ast::IgnoredCommand& c) { return c.name; });
  }

  Json program(const ast::ProgramBlock& p) const {
    Json j;
    static const char* const kLanguages[] = {"cg", "hlsl", "glsl"};
    j["language"] = kLanguages[size_t(p.language)];
    j["include"] = p.is_include;
    j["first_line"] = p.first_line;
    j["span"] = span(p.text_span);
    j["text"] = p.text;
    return j;
  }

  Json programs(const std::vector<ast::ProgramBlock>& items) const {
    return list(items, [&](const ast::ProgramBlock& p) { return program(p); });
  }

  Json category(const ast::Category& c) const {
    Json j;
    j["parent"] = c.parent;
    if (c.lod) j["lod"] = *c.lod;
    j["tags"] = tags(c.tags);
    j["state"] = state(c.state);
    j["includes"] = programs(c.includes);
    j["ignored"] = ignored(c.ignored);
    j["span"] = span(c.span);
    return j;
  }

  Json subshader(const ast::SubShader& s) const {
    Json j;
    if (s.category >= 0) j["category"] = s.category;
    j["tags"] = tags(s.tags);
    if (s.lod) j["lod"] = *s.lod;
    j["state"] = state(s.state);
    j["includes"] = programs(s.includes);
    j["programs"] = programs(s.programs);
    j["passes"] = list(s.passes, [&](const ast::Pass& p) { return pass(p); });
    j["ignored"] = ignored(s.ignored);
    j["span"] = span(s.span);
    return j;
  }

  Json pass(const ast::Pass& p) const {
    Json j;
    static const char* const kKinds[] = {"pass", "use_pass", "grab_pass"};
    j["kind"] = kKinds[size_t(p.kind)];
    if (!p.name.empty()) j["name"] = p.name;
    if (p.kind == ast::PassKind::use_pass) j["use_pass"] = p.use_pass;
    if (p.kind == ast::PassKind::grab_pass) j["grab_texture"] = p.grab_texture;
    j["tags"] = tags(p.tags);
    j["state"] = state(p.state);
    if (p.program) j["program"] = program(*p.program);
    j["ignored"] = ignored(p.ignored);
    j["span"] = span(p.span);
    return j;
  }

  const SourceMap& sources_;
};

}  // namespace

std::string ast_to_json(const ast::Shader& shader, const SourceMap& sources) {
  return pretty_json(AstJson(sources).shader(shader));
}

}  // namespace facet::shaderlab
