// Editing a scene object's material the way Unity's Material is edited
// from a script: a property's number, colour, vector or texture by name,
// a matrix or other value of a uniform no property declares, keywords on
// and off, the render queue. The edits go into the SceneMaterial (plain
// data); the next Renderer::render draws them, re-resolving the
// `[_Prop]` render state and the variant the keywords pick.
//
//   runtime::MaterialInstance(scene.objects[3].material)
//       .set_color("_Color", {1, 0.5f, 0.2f, 1})
//       .enable_keyword("_EMISSION");
//
// A name the shader does not declare is the render's error, naming the
// property's path as a scene file's would ("objects[3].material.properties._Colr").
#pragma once

#include <array>
#include <optional>
#include <string>

#include "facet/runtime/scene.h"

namespace facet::runtime {

class MaterialInstance {
 public:
  explicit MaterialInstance(SceneMaterial& material) : material_(material) {}

  MaterialInstance& set_float(const std::string& name, float value);
  MaterialInstance& set_vector(const std::string& name, const Vec4& value);
  // An sRGB-authored colour, as a Color property takes it (linearised when drawn).
  MaterialInstance& set_color(const std::string& name, const Vec4& srgb);
  MaterialInstance& set_texture(const std::string& name, const SceneTexture& texture);
  // A uniform no property declares (SceneMaterial::uniforms), column-major.
  MaterialInstance& set_matrix(const std::string& name, const std::array<float, 16>& column_major);
  MaterialInstance& enable_keyword(const std::string& keyword);
  MaterialInstance& disable_keyword(const std::string& keyword);
  bool keyword_enabled(const std::string& keyword) const;
  // nullopt: the shader's queue.
  MaterialInstance& set_queue(std::optional<int> queue);

  SceneMaterial& material() { return material_; }

 private:
  SceneProperty& property(const std::string& name);

  SceneMaterial& material_;
};

}  // namespace facet::runtime
