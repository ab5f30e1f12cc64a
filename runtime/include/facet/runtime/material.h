// Materials: a value for every property of the shader (the shader's
// defaults, overridden by the scene), the keywords the material enables
// (explicit plus those its Toggle/KeywordEnum properties imply), the render
// queue, and the uniform table that fills `$Globals` by member name.
//
// Colour properties are authored in sRGB, as in Unity's colour picker, and
// converted to linear here (alpha unchanged); Float, Range and Vector
// properties are used as written.
#pragma once

#include <array>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "facet/diagnostics.h"
#include "facet/ir.h"
#include "facet/result.h"
#include "facet/runtime/scene.h"
#include "facet/runtime/uniforms.h"

namespace facet::runtime {

struct Material {
  std::string shader_name;
  std::map<std::string, std::array<float, 4>> numbers;  // every non-texture property, linear
  std::map<std::string, SceneTexture> textures;         // every texture property
  std::vector<std::string> keywords;                    // explicit, then property-derived
  std::optional<int> queue;                             // the scene's override
  UniformValues uniforms;  // numbers and each texture's _ST; _TexelSize once textures are loaded
};

double srgb_to_linear(double c);
double linear_to_srgb(double c);

// Checks each scene property against the shader (name, and numbers vs
// texture, count), and builds the material. An error
// (scene_material_property) is located at the property's value in the scene
// file `scene_path` (read into `sources` if it is not there yet); a scene
// with no file names the property's JSON path only.
Result<Material> make_material(const ir::Shader& shader, const SceneMaterial& scene, const std::string& scene_path,
                               SourceMap& sources, Diagnostics& diags);
// A property used as render state ([_Cull] etc.): its value, if the material has it.
std::optional<float> state_property(const Material& material, const std::string& name);

}  // namespace facet::runtime
