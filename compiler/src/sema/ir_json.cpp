// ir_to_json: a stable dump of the ShaderIr for `facetc --dump=ir` and
// golden tests. Optional parts are left out rather than written as null;
// floats are printed in their shortest round-trip form (0.1, not
// 0.10000000149011612).
#include <charconv>
#include <algorithm>
#include <nlohmann/json.hpp>

#include "facet/support/json_print.h"
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

Json value(const ir::StateValue& v) { return v.is_property() ? "[" + v.property + "]" : v.literal; }

Json optional_value(const std::optional<ir::StateValue>& v) { return v ? value(*v) : Json(); }

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

Json tags(const std::vector<ir::Tag>& tags) {
  Json j = Json::array();
  for (const ir::Tag& t : tags) j.push_back(Json::array({t.key, t.value}));
  return j;
}

void put(Json& j, const char* key, const std::optional<ir::StateValue>& v) {
  if (v) j[key] = value(*v);
}

Json stencil(const ir::StencilState& s) {
  Json j = Json::object();
  put(j, "Ref", s.ref);
  put(j, "ReadMask", s.read_mask);
  put(j, "WriteMask", s.write_mask);
  put(j, "Comp", s.comp);
  put(j, "Pass", s.pass);
  put(j, "Fail", s.fail);
  put(j, "ZFail", s.zfail);
  put(j, "CompBack", s.comp_back);
  put(j, "PassBack", s.pass_back);
  put(j, "FailBack", s.fail_back);
  put(j, "ZFailBack", s.zfail_back);
  put(j, "CompFront", s.comp_front);
  put(j, "PassFront", s.pass_front);
  put(j, "FailFront", s.fail_front);
  put(j, "ZFailFront", s.zfail_front);
  return j;
}

Json state(const ir::RenderState& s) {
  Json j = Json::object();
  put(j, "Cull", s.cull);
  put(j, "ZTest", s.ztest);
  put(j, "ZWrite", s.zwrite);
  put(j, "AlphaToMask", s.alpha_to_mask);
  put(j, "ZClip", s.zclip);
  put(j, "Conservative", s.conservative);
  if (s.offset_factor || s.offset_units) j["Offset"] = {optional_value(s.offset_factor), optional_value(s.offset_units)};
  if (!s.blend.empty()) {
    Json& list = j["Blend"] = Json::array();
    for (const ir::BlendState& b : s.blend) {
      Json e = {{"rt", b.render_target}};
      if (b.off) {
        e["off"] = true;
      } else {
        e["src"] = value(b.src);
        e["dst"] = value(b.dst);
        if (b.src_alpha) e["src_alpha"] = value(*b.src_alpha);
        if (b.dst_alpha) e["dst_alpha"] = value(*b.dst_alpha);
      }
      list.push_back(e);
    }
  }
  if (!s.blend_op.empty()) {
    Json& list = j["BlendOp"] = Json::array();
    for (const ir::BlendOpState& b : s.blend_op) {
      Json e = {{"rt", b.render_target}, {"op", value(b.color_op)}};
      if (b.alpha_op) e["alpha_op"] = value(*b.alpha_op);
      list.push_back(e);
    }
  }
  if (!s.color_mask.empty()) {
    Json& list = j["ColorMask"] = Json::array();
    for (const ir::ColorMaskState& m : s.color_mask) list.push_back({{"rt", m.render_target}, {"mask", value(m.mask)}});
  }
  if (s.stencil) j["Stencil"] = stencil(*s.stencil);
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
  j["tags"] = tags(p.tags);
  j["state"] = state(p.state);
  if (p.program) j["program"] = program(*p.program);
  j["span"] = span(p.span);
  return j;
}

Json subshader(const ir::SubShader& s) {
  Json j;
  j["tags"] = tags(s.tags);
  j["lod"] = s.lod;
  j["state"] = state(s.state);
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
