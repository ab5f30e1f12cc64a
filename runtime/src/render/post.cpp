#include "render/post.h"

#include <fmt/format.h>

#include <algorithm>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <fmt/ranges.h>

#include "render/frame_values.h"

namespace facet::runtime {

// The built-in quad (-0.5..0.5, uv 0..1) moved to 0..1 and a view-projection
// taking that square to the whole of Vulkan's clip space. uv.y = 0 lands on
// image row 0, the top, which is also texel row 0 of every source: the chain
// samples each image where it was drawn (the UNITY_UV_STARTS_AT_TOP layout).
UniformValues blit_uniforms() {
  UniformValues v = draw_uniforms(glm::translate(glm::mat4(1), glm::vec3(0.5f, 0.5f, 0)));
  glm::mat4 to_clip = glm::translate(glm::mat4(1), glm::vec3(-1, -1, 0)) * glm::scale(glm::mat4(1), glm::vec3(2, 2, 1));
  glm::mat4 identity(1);
  v.set_matrix("unity_MatrixVP", glm::value_ptr(to_clip));
  v.set_matrix("unity_MatrixP", glm::value_ptr(to_clip));
  v.set_matrix("unity_MatrixV", glm::value_ptr(identity));
  v.set_matrix("unity_MatrixInvV", glm::value_ptr(identity));
  return v;
}

namespace {

Result<void, Diagnostics> texel_sizes(Material& material, Resources& resources, const Scene& scene,
                                      const ScenePostEffect& effect) {
  for (const auto& [name, ref] : material.textures) {
    Result<const LoadedTexture*, std::string> t = resources.texture(ref);
    if (!t) {
      return unexpected(
          render_error(fmt::format("{}: {}.properties.{}: {}", scene.path, effect.json_path, name, t.error()),
                       DiagId::texture_invalid));
    }
    float w = float((*t)->width), h = float((*t)->height);
    material.uniforms.set_vector(name + "_TexelSize", 1 / w, 1 / h, w, h);
  }
  return {};
}

DrawRecord step_record(const PostChain& chain, size_t i, size_t pass_index) {
  const ObjectState& s = chain.steps[i];
  DrawRecord r = pass_record(s, pass_index);
  r.object = fmt::format("{} (image effect)", s.scene->json_path);
  r.object_index = i;
  r.why = fmt::format("image effect step {}: the {} image bound as _MainTex", i + 1,
                      i == 0 ? "camera's" : "previous step's");
  return r;
}

}  // namespace

bool samples(const Draw& draw, std::string_view name) {
  const std::vector<ResourceBinding>& r = draw.variant->program->resources;
  return std::any_of(r.begin(), r.end(), [&](const ResourceBinding& b) { return b.name == name; });
}

Result<std::unique_ptr<PostChain>, Diagnostics> build_post_chain(const Context& context, const Scene& scene,
                                                                 ShaderLibrary& library, Resources& resources,
                                                                 GpuMesh* quad, const LightValues* none, int width,
                                                                 int height) {
  auto chain = std::make_unique<PostChain>();
  chain->sources.reserve(scene.post.size());
  std::vector<size_t> positions;  // of each step's pass in its shader's passes
  for (size_t i = 0; i < scene.post.size(); ++i) {
    const ScenePostEffect& effect = scene.post[i];
    SceneObject& source = chain->sources.emplace_back();
    source.name = "image effect";
    source.json_path = effect.json_path;
    source.mesh = "quad";
    source.material = effect.material;
    Result<ShaderAsset*, Diagnostics> shader = library.load(effect.material.shader);
    if (!shader) {
      return unexpected(scene_error(library.report_sources(), scene, effect.json_path + ".shader",
                                    DiagId::shader_unavailable, "the shader does not compile", shader.error()));
    }
    // By the pass's index in its SubShader: a package may hold only some passes.
    const std::vector<SelectedPass>& passes = (*shader)->passes;
    auto at = std::find_if(passes.begin(), passes.end(), [&](const SelectedPass& p) { return p.pass == size_t(effect.pass); });
    if (at == passes.end()) {
      std::vector<std::string> indices;
      for (const SelectedPass& p : passes) indices.push_back(std::to_string(p.pass));
      return unexpected(
          render_error(fmt::format("{}: {}.pass: the shader '{}' has no pass {} (its passes: {})", scene.path,
                                   effect.json_path, (*shader)->shader.name, effect.pass,
                                   indices.empty() ? "none" : fmt::format("{}", fmt::join(indices, ", ")))));
    }
    positions.push_back(size_t(at - passes.begin()));
    ObjectState s;
    s.index = i;
    s.scene = &source;
    s.shader = *shader;
    Diagnostics material_diags;
    Result<Material> material =
        make_material(s.shader->shader, effect.material, scene.path, library.report_sources(), material_diags);
    if (!material) return unexpected(material_diags);
    s.material = std::move(*material);
    FACET_TRY(texel_sizes(s.material, resources, scene, effect));
    s.material.uniforms.set_vector("_MainTex_TexelSize", 1.0f / float(width), 1.0f / float(height), float(width),
                                   float(height));
    s.mesh = quad;
    s.draw = blit_uniforms();
    chain->steps.push_back(std::move(s));
  }
  for (size_t i = 0; i < chain->steps.size(); ++i) {
    FACET_TRY(add_draw(context, scene, library, chain->steps[i], positions[i], none, {},
                       step_record(*chain, i, positions[i]), chain->list));
  }
  return chain;
}

}  // namespace facet::runtime
