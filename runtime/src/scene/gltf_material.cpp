#include "scene/gltf_material.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace facet::runtime {
namespace {

// Colour properties are authored in sRGB (the material converts them to
// linear); glTF's factors are linear already, so they are encoded here and
// reach the shader unchanged. The inverse of srgb_to_linear in material.cpp.
float to_srgb(float c) { return c <= 0.0031308f ? c * 12.92f : float(1.055 * std::pow(double(c), 1.0 / 2.4) - 0.055); }

struct Mapping {
  const GltfMaterial& gltf;
  int index;
  SceneMaterial out;

  bool set_by_scene(const std::string& name) const {
    return std::any_of(out.properties.begin(), out.properties.end(),
                       [&](const SceneProperty& p) { return p.name == name; });
  }

  SceneProperty& add(const std::string& name) {
    SceneProperty p;
    p.name = name;
    p.json_path = index >= 0
                      ? fmt::format("{}.properties.{} (from the glTF file's materials[{}])", out.json_path, name, index)
                      : fmt::format("{}.properties.{} (from glTF's default material)", out.json_path, name);
    p.if_declared = true;
    added.push_back(std::move(p));
    return added.back();
  }
  void number(const std::string& name, std::vector<float> values) {
    if (!set_by_scene(name)) add(name).numbers = std::move(values);
  }
  void texture(const std::string& name, const GltfTexture& t, bool srgb,
               std::optional<std::array<float, 2>> metallic_roughness = std::nullopt) {
    if (set_by_scene(name)) return;
    SceneTexture texture;
    texture.name = t.path;
    texture.srgb = srgb;
    texture.gltf_metallic_roughness = metallic_roughness;
    add(name).texture = texture;
  }
  void keyword(const std::string& k) {
    if (std::find(out.keywords.begin(), out.keywords.end(), k) == out.keywords.end()) out.keywords.push_back(k);
  }

  std::vector<SceneProperty> added;
};

// Standard's main maps all read TEXCOORD_0 (_UVSec picks the UV set of the
// detail maps only).
std::optional<std::string> uv_problem(const std::optional<GltfTexture>& t, int index, const char* key) {
  if (!t || t->texcoord == 0) return std::nullopt;
  return fmt::format(
      "materials[{}].{}.texCoord: the texture reads TEXCOORD_{}, and the Standard shader's maps read "
      "TEXCOORD_0",
      index, key, t->texcoord);
}

}  // namespace

Result<SceneMaterial, std::string> with_gltf_material(const SceneMaterial& base, const GltfMaterial& m, int index) {
  for (auto problem : {uv_problem(m.base_color_texture, index, "pbrMetallicRoughness.baseColorTexture"),
                       uv_problem(m.metallic_roughness_texture, index, "pbrMetallicRoughness.metallicRoughnessTexture"),
                       uv_problem(m.normal_texture, index, "normalTexture"),
                       uv_problem(m.emissive_texture, index, "emissiveTexture")}) {
    if (problem) return unexpected(*problem);
  }
  Mapping map{m, index, base, {}};
  const auto& c = m.base_color;
  map.number("_Color", {to_srgb(c[0]), to_srgb(c[1]), to_srgb(c[2]), c[3]});
  if (m.base_color_texture) map.texture("_MainTex", *m.base_color_texture, true);
  map.number("_Metallic", {m.metallic});
  map.number("_Glossiness", {1 - m.roughness});
  if (m.metallic_roughness_texture) {
    // Standard reads metallic from R and smoothness from A (times
    // _GlossMapScale) and ignores _Metallic and _Glossiness: the factors go
    // into the converted texels.
    map.texture("_MetallicGlossMap", *m.metallic_roughness_texture, false,
                std::array<float, 2>{m.metallic, m.roughness});
    map.number("_GlossMapScale", {1});
    map.keyword("_METALLICGLOSSMAP");
  }
  if (m.normal_texture) {
    map.texture("_BumpMap", *m.normal_texture, false);
    map.number("_BumpScale", {m.normal_scale});
    map.keyword("_NORMALMAP");
  }
  const auto& e = m.emissive;
  bool emits = e[0] > 0 || e[1] > 0 || e[2] > 0;
  if (emits) {
    map.number("_EmissionColor", {to_srgb(e[0]), to_srgb(e[1]), to_srgb(e[2]), 1});
    if (m.emissive_texture) map.texture("_EmissionMap", *m.emissive_texture, true);
    map.keyword("_EMISSION");
  }
  // The glTF values first, then the scene's own, which are checked by name
  // against the shader as always.
  SceneMaterial out = std::move(map.out);
  out.properties.insert(out.properties.begin(), map.added.begin(), map.added.end());
  return out;
}

}  // namespace facet::runtime
