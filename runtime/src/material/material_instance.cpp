#include "facet/runtime/material_instance.h"

#include <algorithm>

namespace facet::runtime {

SceneProperty& MaterialInstance::property(const std::string& name) {
  auto it = std::find_if(material_.properties.begin(), material_.properties.end(),
                         [&](const SceneProperty& p) { return p.name == name; });
  if (it != material_.properties.end()) return *it;
  SceneProperty added;
  added.name = name;
  added.json_path = material_.json_path + ".properties." + name;
  return material_.properties.emplace_back(std::move(added));
}

MaterialInstance& MaterialInstance::set_float(const std::string& name, float value) {
  SceneProperty& p = property(name);
  p.numbers = {value};
  p.texture.reset();
  return *this;
}

MaterialInstance& MaterialInstance::set_vector(const std::string& name, const Vec4& value) {
  SceneProperty& p = property(name);
  p.numbers.assign(value.begin(), value.end());
  p.texture.reset();
  return *this;
}

MaterialInstance& MaterialInstance::set_color(const std::string& name, const Vec4& srgb) { return set_vector(name, srgb); }

MaterialInstance& MaterialInstance::set_texture(const std::string& name, const SceneTexture& texture) {
  SceneProperty& p = property(name);
  p.numbers.clear();
  p.texture = texture;
  return *this;
}

MaterialInstance& MaterialInstance::set_matrix(const std::string& name, const std::array<float, 16>& column_major) {
  material_.uniforms[name].assign(column_major.begin(), column_major.end());
  return *this;
}

MaterialInstance& MaterialInstance::enable_keyword(const std::string& keyword) {
  if (!keyword_enabled(keyword)) material_.keywords.push_back(keyword);
  return *this;
}

MaterialInstance& MaterialInstance::disable_keyword(const std::string& keyword) {
  std::erase(material_.keywords, keyword);
  return *this;
}

bool MaterialInstance::keyword_enabled(const std::string& keyword) const {
  return std::find(material_.keywords.begin(), material_.keywords.end(), keyword) != material_.keywords.end();
}

MaterialInstance& MaterialInstance::set_queue(std::optional<int> queue) {
  material_.queue = queue;
  return *this;
}

}  // namespace facet::runtime
