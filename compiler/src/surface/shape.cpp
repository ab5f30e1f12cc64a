#include "shape.h"

#include <fmt/format.h>

namespace facet::surface {
namespace {

InputField classify(const AnalyzedField& f) {
  InputField in{.name = f.name, .type = f.type};
  auto is = [&](std::string_view n) { return f.name == n; };
  // Unity's rule: "uv" + the texture's name, which starts with '_'
  // (uv_MainTex reads _MainTex through _MainTex_ST).
  if (f.name.starts_with("uv2_")) {
    in.kind = InputKind::uv2;
    in.texture = f.name.substr(3);
  } else if (f.name.starts_with("uv_")) {
    in.kind = InputKind::uv;
    in.texture = f.name.substr(2);
  } else if (is("viewDir")) {
    in.kind = InputKind::view_dir;
  } else if (is("worldPos")) {
    in.kind = InputKind::world_pos;
  } else if (is("worldNormal")) {
    in.kind = InputKind::world_normal;
  } else if (is("worldRefl")) {
    in.kind = InputKind::world_refl;
  } else if (is("screenPos")) {
    in.kind = InputKind::screen_pos;
  } else if (f.semantic == "COLOR" || f.semantic == "COLOR0") {
    in.kind = InputKind::color;
  } else if (f.semantic == "VFACE" || f.semantic == "SV_ISFRONTFACE") {
    in.kind = InputKind::face;
  } else if (f.name.starts_with("internalSurfaceTtoW")) {
    in.kind = InputKind::internal;
  }
  return in;
}

const AnalyzedFunction* require(const ProgramAnalysis& analysis, const std::string& name,
                                         const char* role, const Directive& d, Diagnostics& diags) {
  const AnalyzedFunction* f = analysis.find(name);
  if (!f) {
    diags.add(DiagId::surface_missing_function, d.span, fmt::format("{} '{}' is not defined", role, name));
  }
  return f;
}

bool signature_error(const Directive& d, Diagnostics& diags, std::string message, std::string expected) {
  diags.add(DiagId::surface_bad_signature, d.span, std::move(message)).note({}, std::move(expected));
  return false;
}

bool read_lighting(const ProgramAnalysis& analysis, const Directive& d, Shape& s, Diagnostics& diags) {
  const std::string name = "Lighting" + d.model;
  const AnalyzedFunction* f = require(analysis, name, "the lighting function", d, diags);
  if (!f) return false;
  const auto& p = f->params;
  const char* forms = "forms: (s, UnityGI gi), (s, half3 viewDir, UnityGI gi), (s, half3 lightDir, half atten), "
                      "(s, half3 lightDir, half3 viewDir, half atten)";
  if (p.size() < 2 || p.size() > 4 || !p[0].is_struct) {
    return signature_error(d, diags, fmt::format("'{}' has no lighting-function form", name), forms);
  }
  if (p[0].type != s.output_struct) {
    return signature_error(d, diags,
                           fmt::format("'{}' takes '{}' but '{}' writes '{}'", name, p[0].type, d.surface_function,
                                       s.output_struct),
                           "the lighting function's first parameter is the surface output struct");
  }
  if (p.size() == 2 && p[1].type == "UnityGI") s.lighting = LightingForm::gi;
  else if (p.size() == 3 && p[2].type == "UnityGI") s.lighting = LightingForm::view_gi;
  else if (p.size() == 3) s.lighting = LightingForm::light_atten;
  else if (p.size() == 4) s.lighting = LightingForm::light_view_atten;
  else return signature_error(d, diags, fmt::format("'{}' has no lighting-function form", name), forms);
  s.has_gi_function = analysis.find(name + "_GI") != nullptr;
  s.has_deferred_function = analysis.find(name + "_Deferred") != nullptr;
  bool gi_form = s.lighting == LightingForm::gi || s.lighting == LightingForm::view_gi;
  if (gi_form && !s.has_gi_function) {
    diags.add(DiagId::surface_missing_gi, d.span,
              fmt::format("lighting model '{}' takes UnityGI but '{}_GI' is not defined", d.model, name))
        .note({}, fmt::format("define 'inline void {}_GI({} s, UnityGIInput data, inout UnityGI gi)', e.g. "
                              "'gi = UnityGlobalIllumination(data, 1.0, s.Normal);'",
                              name, s.output_struct));
    return false;
  }
  return true;
}

bool read_vertex_modifier(const ProgramAnalysis& analysis, const Directive& d, Shape& s, Diagnostics& diags) {
  if (d.vertex_function.empty()) return true;
  const AnalyzedFunction* f = require(analysis, d.vertex_function, "the vertex modifier", d, diags);
  if (!f) return false;
  const auto& p = f->params;
  if (d.tessellated() && (p.size() != 1 || !p[0].is_struct || !p[0].is_out)) {
    // It runs in the domain stage, on each vertex that tessellation makes.
    return signature_error(d, diags,
                           fmt::format("with 'tessellate:', vertex modifier '{}' must take only 'inout appdata v'",
                                       d.vertex_function),
                           fmt::format("write 'void {}(inout appdata v)': with tessellation it runs in the domain "
                                       "stage and cannot fill '{}'",
                                       d.vertex_function, s.input_struct));
  }
  if (p.empty() || p.size() > 2 || !p[0].is_struct || (p.size() == 2 && p[1].type != s.input_struct)) {
    return signature_error(d, diags, fmt::format("vertex modifier '{}' has the wrong parameters", d.vertex_function),
                           fmt::format("write 'void {}(inout appdata_full v)' or 'void {}(inout appdata_full v, out {} o)'",
                                       d.vertex_function, d.vertex_function, s.input_struct));
  }
  s.vertex_input = p[0].type;
  s.vertex_fills_input = p.size() == 2;
  return true;
}

// appdata_full's members, for a tessellated shader whose code names the
// struct in no function (no vertex modifier, a tessellate function without
// parameters).
std::vector<AnalyzedField> appdata_full_fields() {
  return {{"vertex", "float4", "POSITION"},   {"tangent", "float4", "TANGENT"},
          {"normal", "float3", "NORMAL"},     {"texcoord", "float4", "TEXCOORD0"},
          {"texcoord1", "float4", "TEXCOORD1"}, {"texcoord2", "float4", "TEXCOORD2"},
          {"texcoord3", "float4", "TEXCOORD3"}, {"color", "float4", "COLOR"}};
}

bool has_field(const std::vector<AnalyzedField>& fields, std::string_view name) {
  for (const AnalyzedField& f : fields) {
    if (f.name == name) return true;
  }
  return false;
}

// tessellate:fn is `float4 fn()` (fixed factors) or `float4 fn(appdata v0,
// appdata v1, appdata v2)`, appdata being the vertex modifier's struct (or,
// without one, the vertex input); it may return a single float for all four.
bool read_tessellation(const ProgramAnalysis& analysis, const Directive& d, Shape& s, Diagnostics& diags) {
  if (!d.tessellated()) return true;
  const AnalyzedFunction* f = require(analysis, d.tessellate_function, "the tessellation function", d, diags);
  if (!f) return false;
  const auto& p = f->params;
  auto expected = [&] {
    return fmt::format("write 'float4 {}()' or 'float4 {}({} v0, {} v1, {} v2)': edge factors in xyz, the inside "
                       "factor in w",
                       d.tessellate_function, d.tessellate_function, s.vertex_input, s.vertex_input, s.vertex_input);
  };
  bool vertices = p.size() == 3 && p[0].is_struct && p[1].type == p[0].type && p[2].type == p[0].type;
  if (vertices && d.vertex_function.empty()) s.vertex_input = p[0].type;
  if (!p.empty() && !(vertices && p[0].type == s.vertex_input)) {
    return signature_error(d, diags,
                           fmt::format("tessellation function '{}' has the wrong parameters", d.tessellate_function),
                           expected());
  }
  std::string_view ret = f->return_type;
  if (ret != "float4" && ret != "float") {
    return signature_error(d, diags,
                           fmt::format("tessellation function '{}' returns '{}'", d.tessellate_function, f->return_type),
                           expected());
  }
  s.tessellate_takes_vertices = vertices;
  if (const auto* fields = analysis.find_struct(s.vertex_input)) s.vertex_fields = *fields;
  else if (s.vertex_input == "appdata_full") s.vertex_fields = appdata_full_fields();
  if (!has_field(s.vertex_fields, "vertex")) {
    diags.add(DiagId::surface_bad_signature, d.span,
              fmt::format("'{}' has no 'vertex' member for tessellation to interpolate", s.vertex_input))
        .note({}, "the vertex input needs 'float4 vertex : POSITION;'");
    return false;
  }
  if (!d.tess_phong.empty() && !has_field(s.vertex_fields, "normal")) {
    diags.add(DiagId::surface_bad_signature, d.span,
              fmt::format("'tessphong:' needs a 'normal' member in '{}'", s.vertex_input))
        .note({}, "Phong tessellation projects onto the vertices' tangent planes: add 'float3 normal : NORMAL;'");
    return false;
  }
  return true;
}

}  // namespace

Result<Shape> read_shape(const ProgramAnalysis& analysis, const Directive& d, Diagnostics& diags) {
  Shape s;
  const AnalyzedFunction* surf = require(analysis, d.surface_function, "the surface function", d, diags);
  if (!surf) return failure("no surface function");
  if (surf->params.size() != 2 || !surf->params[0].is_struct || !surf->params[1].is_struct || !surf->params[1].is_out) {
    signature_error(d, diags, fmt::format("surface function '{}' has the wrong parameters", d.surface_function),
                    fmt::format("write 'void {}(Input IN, inout SurfaceOutputStandard o)' (or another output struct)",
                                d.surface_function));
    return failure("bad surf");
  }
  s.input_struct = surf->params[0].type;
  s.output_struct = surf->params[1].type;
  const AnalyzedParam& in = surf->params[0];
  const AnalyzedParam& out = surf->params[1];
  s.writes_normal = out.writes("Normal");
  s.writes_emission = out.writes("Emission");
  s.writes_alpha = out.writes("Alpha");
  const AnalyzedFunction* final_color = nullptr;
  if (!d.final_color_function.empty()) {
    final_color = require(analysis, d.final_color_function, "the final colour function", d, diags);
    if (!final_color) return failure("no finalcolor");
  }
  if (const auto* fields = analysis.find_struct(s.input_struct)) {
    for (const AnalyzedField& f : *fields) {
      InputField field = classify(f);
      field.used = in.reads(f.name) ||
                   (final_color && !final_color->params.empty() && final_color->params[0].reads(f.name));
      s.has_internal_data = s.has_internal_data || field.kind == InputKind::internal;
      s.inputs.push_back(std::move(field));
    }
  }
  if (const auto* fields = analysis.find_struct(s.output_struct)) {
    for (const AnalyzedField& f : *fields) s.output_has_occlusion = s.output_has_occlusion || f.name == "Occlusion";
  }
  if (!read_lighting(analysis, d, s, diags) || !read_vertex_modifier(analysis, d, s, diags) ||
      !read_tessellation(analysis, d, s, diags)) {
    return failure("bad functions");
  }
  return s;
}

}  // namespace facet::surface
