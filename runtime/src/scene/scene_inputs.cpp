#include "facet/runtime/scene_inputs.h"

#include <fmt/format.h>

#include <filesystem>
#include <set>

#include "facet/runtime/gltf.h"
#include "facet/support/output_paths.h"

namespace facet::runtime {
namespace {

void add_texture(std::vector<SceneInput>& inputs, const std::optional<SceneTexture>& texture) {
  if (texture && !texture->builtin) inputs.push_back({texture->name, "a texture of the scene"});
}

void add_material(std::vector<SceneInput>& inputs, const SceneMaterial& material) {
  inputs.push_back({material.shader, "a shader of the scene"});
  for (const SceneProperty& p : material.properties) add_texture(inputs, p.texture);
}

// The .bin files of a glTF mesh (read once more here: the scene names only
// the .gltf); none when it does not load, which the render then reports.
void add_gltf_buffers(std::vector<SceneInput>& inputs, const std::string& mesh) {
  Diagnostics ignored;
  if (std::optional<GltfModel> model = load_gltf(mesh, ignored)) {
    for (const std::string& file : model->buffer_files) inputs.push_back({file, "a buffer of a glTF mesh of the scene"});
  }
}

}  // namespace

std::vector<SceneInput> scene_inputs(const std::string& scene_path, const Scene& scene) {
  std::vector<SceneInput> inputs{{scene_path, "the scene"}};
  std::set<std::string> gltf_meshes;
  for (const SceneObject& o : scene.objects) {
    if (!o.builtin_mesh) inputs.push_back({o.mesh, "a mesh of the scene"});
    if (!o.builtin_mesh && is_gltf_path(o.mesh) && gltf_meshes.insert(o.mesh).second) {
      add_gltf_buffers(inputs, o.mesh);
    }
    add_material(inputs, o.material);
  }
  for (const ScenePostEffect& p : scene.post) add_material(inputs, p.material);
  for (const SceneLight& l : scene.lights) add_texture(inputs, l.cookie);
  if (scene.environment && !scene.environment->file.empty()) {
    inputs.push_back({scene.environment->file, "the environment image of the scene"});
  }
  return inputs;
}

std::optional<std::string> output_clash(const std::string& program, const std::vector<std::string>& outputs,
                                        const std::vector<SceneInput>& inputs) {
  if (auto twice = support::repeated_output(outputs)) {
    return fmt::format("{}: error: outputs '{}' and '{}' are the same file; nothing was written", program, twice->first,
                       twice->second);
  }
  for (const std::string& output : outputs) {
    std::error_code ec;
    if (output.empty() || !std::filesystem::exists(output, ec)) continue;
    for (const SceneInput& input : inputs) {
      if (std::filesystem::equivalent(output, input.path, ec)) {
        return fmt::format("{}: error: output '{}' is also an input of this render ({}); nothing was written",
                           program, output, input.what);
      }
    }
  }
  return std::nullopt;
}

}  // namespace facet::runtime
