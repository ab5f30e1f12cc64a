#include "render/background.h"

#include <fmt/format.h>

#include "render/frame_values.h"
#include "render/post.h"

namespace facet::runtime {
namespace {

SceneProperty colour(const std::string& name, const std::string& key, const Vec3& c) {
  return {name, "ambient.sky." + key, {c[0], c[1], c[2], 1}, std::nullopt};
}

}  // namespace

Result<void, Diagnostics> add_sky_background(const Context& context, const Scene& scene, ShaderLibrary& library,
                                             GpuMesh* quad, const LightValues* none, SceneObject& source,
                                             std::vector<ObjectState>& objects, DrawListResult& list) {
  source.name = scene.environment ? "environment" : "procedural sky";
  source.json_path = "camera.clear";
  source.mesh = "quad";
  source.material.json_path = "camera.clear";
  if (scene.environment) {
    // Mip 0 of unity_SpecCube0: the environment cube is bound to every Cube slot nothing else fills.
    source.material.shader = "EnvironmentSky.shader";
  } else {
    const SceneSky& sky = *scene.sky;
    source.material.shader = "ProceduralSky.shader";
    source.material.properties = {colour("_Zenith", "zenith", sky.zenith), colour("_Horizon", "horizon", sky.horizon),
                                  colour("_Ground", "ground", sky.ground),
                                  {"_Intensity", "ambient.sky.intensity", {sky.intensity}, std::nullopt}};
    if (std::optional<SkySun> sun = sky_sun(scene)) {
      source.material.properties.push_back(
          {"_SunDirection", "ambient.sky.sun", {sun->to_sun.x, sun->to_sun.y, sun->to_sun.z, 0}, std::nullopt});
      source.material.properties.push_back(
          {"_SunRadiance", "ambient.sky.sun", {sun->radiance.r, sun->radiance.g, sun->radiance.b, 0}, std::nullopt});
      source.material.properties.push_back({"_SunCos", "ambient.sky.sun", {sun->cos_radius}, std::nullopt});
    }
  }
  Result<ShaderAsset*, Diagnostics> shader = library.load_built_in(source.material.shader);
  if (!shader) {
    return unexpected(scene_error(library.report_sources(), scene, "camera.clear", DiagId::shader_unavailable,
                                  fmt::format("the sky shader, the stdlib's {}, does not load", source.material.shader),
                                  shader.error()));
  }
  source.material.shader = (*shader)->path;
  ObjectState s;
  s.index = objects.size();
  s.scene = &source;
  s.shader = *shader;
  Diagnostics material_diags;
  Result<Material> material =
      make_material(s.shader->shader, source.material, scene.path, library.report_sources(), material_diags);
  if (!material) return unexpected(material_diags);
  s.material = std::move(*material);
  s.mesh = quad;
  s.draw = blit_uniforms();
  s.queue = 1000;  // Background
  s.background = true;
  objects.push_back(std::move(s));
  DrawListResult sky_list;
  DrawRecord record = pass_record(objects.back(), 0);
  record.why = scene.environment ? "camera.clear is \"sky\": the environment behind everything"
                                  : "camera.clear is \"sky\": the procedural sky of ambient.sky behind everything";
  FACET_TRY(add_draw(context, scene, library, objects.back(), 0, none, {}, std::move(record), sky_list));
  list.draws.insert(list.draws.begin(), std::move(sky_list.draws.front()));
  list.compiled.insert(list.compiled.end(), sky_list.compiled.begin(), sky_list.compiled.end());
  list.variants_compiled += sky_list.variants_compiled;
  return {};
}

}  // namespace facet::runtime
