#include "facet/runtime/material.h"

#include "facet/reference/color.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "facet/support/suggest.h"
#include "facet/variants.h"
#include "scene/json_locate.h"

namespace facet::runtime {
namespace {

bool is_color(const ir::Property& p) { return p.type == ir::PropertyType::color; }

bool is_scalar(const ir::Property& p) {
  return p.type == ir::PropertyType::float_ || p.type == ir::PropertyType::int_ ||
         p.type == ir::PropertyType::integer || p.type == ir::PropertyType::range;
}

std::string unknown_property(const ir::Shader& shader, const SceneProperty& value) {
  std::vector<std::string_view> names;
  for (const ir::Property& p : shader.properties) names.push_back(p.name);
  std::string hint;
  if (auto near = closest_name(value.name, names)) hint = fmt::format(" (did you mean '{}'?)", *near);
  else if (names.empty()) hint = " (it declares no properties)";
  return fmt::format("the shader '{}' has no property '{}'{}", shader.name, value.name, hint);
}

// The property's value from the scene, or an error text.
Result<std::array<float, 4>, std::string> number_value(const ir::Property& p, const SceneProperty& value) {
  if (value.texture) return unexpected(std::string(is_scalar(p) ? "expected a number" : "expected 3 or 4 numbers"));
  const std::vector<float>& n = value.numbers;
  if (is_scalar(p)) {
    if (n.size() != 1) return unexpected(fmt::format("expected a number, got {} numbers", n.size()));
    return std::array<float, 4>{n[0], 0, 0, 0};
  }
  if (is_color(p)) {
    if (n.size() != 3 && n.size() != 4) return unexpected(std::string("expected 4 numbers (r, g, b[, a])"));
    return std::array<float, 4>{n[0], n[1], n[2], n.size() == 4 ? n[3] : 1.0f};
  }
  if (n.size() < 2) return unexpected(std::string("expected 2 to 4 numbers"));
  std::array<float, 4> v{0, 0, 0, 0};
  for (size_t i = 0; i < n.size(); ++i) v[i] = n[i];
  return v;
}

std::array<float, 4> linearised(const ir::Property& p, std::array<float, 4> v) {
  if (!is_color(p)) return v;
  for (int i = 0; i < 3; ++i) v[i] = float(srgb_to_linear(v[i]));
  return v;
}

SceneTexture default_texture(const ir::Property& p) {
  SceneTexture t;
  t.builtin = true;
  t.name = p.default_texture.empty() ? "gray" : p.default_texture;
  // Unity's built-in textures beyond these five do not exist here: treat them as gray.
  static const char* known[] = {"white", "black", "gray", "grey", "bump", "red"};
  if (std::find(std::begin(known), std::end(known), t.name) == std::end(known)) t.name = "gray";
  t.srgb = t.name != "bump";
  return t;
}

}  // namespace

double srgb_to_linear(double c) { return reference::FacetSRGBToLinear(c); }
double linear_to_srgb(double c) { return reference::FacetLinearToSRGB(c); }

Result<Material> make_material(const ir::Shader& shader, const SceneMaterial& scene, const std::string& scene_path,
                               SourceMap& sources, Diagnostics& diags) {
  Material m;
  m.shader_name = shader.name;
  m.queue = scene.queue;
  for (const ir::Property& p : shader.properties) {
    if (p.is_texture()) m.textures[p.name] = default_texture(p);
    else m.numbers[p.name] = linearised(p, p.default_value);
  }
  std::vector<variants::PropertyValue> floats;
  for (const SceneProperty& value : scene.properties) {
    const ir::Property* p = shader.find_property(value.name);
    auto fail = [&](const std::string& what) {
      SourceSpan span = scene_value_span(sources, scene_path, value.json_path);
      const std::string where = span.has_location() || scene_path.empty() ? "" : scene_path + ": ";
      diags.add(DiagId::scene_material_property, span, fmt::format("{}{}: {}", where, value.json_path, what));
      return failure();
    };
    if (!p && value.if_declared) continue;  // a glTF material's value for a property this shader lacks
    if (!p) return fail(unknown_property(shader, value));
    if (p->is_texture()) {
      if (!value.texture) return fail("expected a texture (a built-in name, a file, or {\"texture\": ...})");
      m.textures[p->name] = *value.texture;
      continue;
    }
    Result<std::array<float, 4>, std::string> v = number_value(*p, value);
    if (!v) return fail(v.error());
    m.numbers[p->name] = linearised(*p, *v);
    if (is_scalar(*p)) floats.push_back({p->name, (*v)[0]});
  }
  m.keywords = scene.keywords;
  if (scene.instancing && std::find(m.keywords.begin(), m.keywords.end(), "INSTANCING_ON") == m.keywords.end()) {
    m.keywords.push_back("INSTANCING_ON");
  }
  for (const std::string& k : variants::keywords_from_properties(shader.properties, floats)) {
    if (std::find(m.keywords.begin(), m.keywords.end(), k) == m.keywords.end()) m.keywords.push_back(k);
  }
  for (const auto& [name, v] : m.numbers) m.uniforms.set_vector(name, v);
  for (const auto& [name, floats] : scene.uniforms) m.uniforms.set_elements(name, floats);
  for (const auto& [name, t] : m.textures) {
    m.uniforms.set_vector(name + "_ST", t.scale[0], t.scale[1], t.offset[0], t.offset[1]);
    m.uniforms.set_vector(name + "_HDR", 1, 1, 0, 0);  // DecodeHDR: linear data, no RGBM
  }
  return m;
}

std::optional<float> state_property(const Material& material, const std::string& name) {
  auto it = material.numbers.find(name);
  if (it == material.numbers.end()) return std::nullopt;
  return it->second[0];
}

}  // namespace facet::runtime
