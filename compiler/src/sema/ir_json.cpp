// ir_to_json: a stable dump of the ShaderIr for `facetc --dump=ir` and
// golden tests. Optional parts are left out rather than written as null;
// floats are printed in their shortest round-trip form (0.1, not
// 0.10000000149011612).
#include <charconv>
#include <algorithm>
#include <nlohmann/json.hpp>

#include "facet/support/json_print.h"
#include "facet/support/state_json.h"
#include "facet/sema.h"

namespace facet::sema {
namespace {

using Json = nlohmann::ordered_json;

Json number(float f) {
  char buffer[32];
  auto [end, ec] = std::to_chars(buffer, buffer + sizeof buffer, f);
  double d = f;
  if (ec == std::errc()) std::from_chars(buffer, end, d);
  return d;
}

// "begin-end" byte offsets: one line per span keeps the dump readable.
Json span(SourceSpan s) {
  if (!s.has_location()) return "";
  return std::to_string(s.begin) + "-" + std::to_string(s.end);
}

Json property(const ir::Property& p) {
  Json j;
  j["name"] = p.name;
  j["display"] = p.display_name;
  j["type"] = std::string(ir::property_type_name(p.type));
  Json attributes = Json::array();
  for (const ir::PropertyAttribute& a : p.attributes) attributes.push_back({{"name", a.name}, {"args", a.args}});
  j["attributes"] = attributes;
  if (p.type == ir::PropertyType::range) j["range"] = {number(p.range_min), number(p.range_max)};
  if (p.is_texture()) {
    j["default_texture"] = p.default_texture;
  } else {
    Json d = Json::array();
    for (float f : p.default_value) d.push_back(number(f));
    j["default"] = d;
  }
  j["span"] = span(p.span);
  return j;
}

Json chunk(const ir::SourceChunk& c) {
  return {{"first_line", c.first_line}, {"span", span(c.span)}, {"text", c.text}};
}

Json program(const ir::Program& p) {
  static const char* const kLanguages[] = {"cg", "hlsl", "glsl"};
  Json j;
  j["language"] = kLanguages[size_t(p.language)];
  Json entries = Json::object();
  for (int s = 0; s < kStageCount; ++s) {
    if (!p.entry_points[size_t(s)].empty()) entries[std::string(stage_name(Stage(s)))] = p.entry_points[size_t(s)];
  }
  j["entry_points"] = entries;
  j["shader_target"] = p.shader_target;
  if (p.is_surface()) j["surface_function"] = p.surface_function;
  Json pragmas = Json::array();
  for (const ir::Pragma& pr : p.pragmas) pragmas.push_back({{"name", pr.name}, {"args", pr.args}, {"span", span(pr.span)}});
  j["pragmas"] = pragmas;
  Json includes = Json::array();
  for (const ir::SourceChunk& c : p.includes) includes.push_back(chunk(c));
  j["includes"] = includes;
  j["body"] = chunk(p.body);
  return j;
}

Json pass(const ir::Pass& p) {
  static const char* const kKinds[] = {"pass", "use_pass", "grab_pass"};
  Json j;
  j["kind"] = kKinds[size_t(p.kind)];
  j["name"] = p.name;
  if (p.kind == ir::PassKind::use_pass) j["use_pass"] = p.use_pass;
  if (p.kind == ir::PassKind::grab_pass) j["grab_texture"] = p.grab_texture;
  if (!p.origin.empty()) j["origin"] = p.origin;
  j["tags"] = tags_json(p.tags);
  j["state"] = render_state_json(p.state);
  if (p.program) j["program"] = program(*p.program);
  j["span"] = span(p.span);
  return j;
}

Json subshader(const ir::SubShader& s) {
  Json j;
  j["tags"] = tags_json(s.tags);
  j["lod"] = s.lod;
  j["queue"] = s.queue;
  j["state"] = render_state_json(s.state);
  if (!s.surface_programs.empty()) {
    Json surface = Json::array();
    for (const ir::SurfaceProgram& sp : s.surface_programs) {
      surface.push_back({{"program", program(sp.program)}, {"before_pass", sp.before_pass}});
    }
    j["surface_programs"] = surface;
  }
  Json passes = Json::array();
  for (const ir::Pass& p : s.passes) passes.push_back(pass(p));
  j["passes"] = passes;
  j["span"] = span(s.span);
  return j;
}

}  // namespace

std::string ir_to_json(const ir::Shader& shader) {
  Json j;
  j["name"] = shader.name;
  Json properties = Json::array();
  for (const ir::Property& p : shader.properties) properties.push_back(property(p));
  j["properties"] = properties;
  Json subshaders = Json::array();
  for (const ir::SubShader& s : shader.subshaders) subshaders.push_back(subshader(s));
  j["subshaders"] = subshaders;
  if (shader.fallback) j["fallback"] = *shader.fallback;
  if (!shader.custom_editor.empty()) j["custom_editor"] = shader.custom_editor;
  j["span"] = span(shader.span);
  return pretty_json(j);
}

}  // namespace facet::sema
