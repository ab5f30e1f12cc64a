#include "render/shadows.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <glm/gtc/matrix_transform.hpp>

#include "facet/runtime/sky_sh.h"

namespace facet::runtime {
namespace {

bool has_shadow_keyword(const std::vector<std::string>& keywords, const char* name) {
  return std::find(keywords.begin(), keywords.end(), name) != keywords.end();
}

// Whether the object is inside what a directional light's map covers.
bool within_shadow_distance(const Scene& scene, const ObjectState& o, const glm::vec3& camera_position) {
  return glm::length(o.center - camera_position) - o.radius < scene.shadow_distance;
}

bool reaches(const Scene& scene, const SceneLight& light, const ObjectState& o, const glm::vec3& camera_position) {
  if (light.type == LightType::directional) return within_shadow_distance(scene, o, camera_position);
  glm::vec3 position(light.transform.position[0], light.transform.position[1], light.transform.position[2]);
  return glm::length(o.center - position) < light.range + o.radius;
}

// An orthographic box around the bounding spheres of what the map covers,
// seen along the light's direction, square in x and y.
std::optional<ShadowView> directional_view(const Scene& scene, size_t index, const std::vector<ObjectState>& objects,
                                           const glm::vec3& camera_position) {
  const SceneLight& light = scene.lights[index];
  glm::mat4 rotation = rotation_matrix(light.transform);
  glm::mat3 to_light = glm::transpose(glm::mat3(rotation));
  glm::vec3 lo(1e30f), hi(-1e30f);
  for (const ObjectState& o : objects) {
    if (!within_shadow_distance(scene, o, camera_position)) continue;
    glm::vec3 c = to_light * o.center;
    lo = glm::min(lo, c - o.radius);
    hi = glm::max(hi, c + o.radius);
  }
  if (lo.x > hi.x) return std::nullopt;
  glm::vec3 mid = (lo + hi) * 0.5f;
  float half = std::max({hi.x - lo.x, hi.y - lo.y, 1e-3f}) * 0.5f * 1.02f;
  const float back = 1.0f;  // the camera stands this far behind the first caster
  ShadowView v;
  v.light = index;
  v.lens.projection = Projection::orthographic;
  v.lens.size = half;
  v.lens.near = back * 0.5f;
  v.lens.far = hi.z - lo.z + back * 1.5f;
  glm::vec3 origin = glm::vec3(rotation * glm::vec4(mid.x, mid.y, lo.z - back, 1));
  v.camera = camera_matrices_at(glm::translate(glm::mat4(1), origin) * rotation, v.lens, 1, 1);
  int resolution = scene.shadow_resolution;
  v.texel_world = 2 * half / float(resolution);
  float depth_range = v.lens.far - v.lens.near;
  // y = 1: casters in front of the near plane are flattened onto it.
  v.caster_bias = {light.shadow_bias * v.texel_world / depth_range, 1, light.shadow_normal_bias * v.texel_world, 0};
  return v;
}

ShadowView spot_view(const Scene& scene, size_t index) {
  const SceneLight& light = scene.lights[index];
  ShadowView v;
  v.light = index;
  v.lens.projection = Projection::perspective;
  v.lens.fov = light.spot_angle;
  v.lens.near = std::max(0.01f, light.range * 0.02f);
  v.lens.far = light.range;
  glm::vec3 position(light.transform.position[0], light.transform.position[1], light.transform.position[2]);
  v.camera = camera_matrices_at(glm::translate(glm::mat4(1), position) * rotation_matrix(light.transform), v.lens, 1, 1);
  float middle = light.range * 0.5f;
  v.texel_world = 2 * middle * std::tan(glm::radians(light.spot_angle) * 0.5f) / float(scene.shadow_resolution);
  // Perspective depth is not linear: the bias is the world bias times
  // d(depth)/d(distance) at half the range.
  float n = v.lens.near, f = v.lens.far;
  float slope = f * n / ((f - n) * middle * middle);
  v.caster_bias = {light.shadow_bias * v.texel_world * slope, 0, light.shadow_normal_bias * v.texel_world, 0};
  return v;
}

// Six 90-degree cameras at the light, each looking through one face of a
// cube so that the image of face f, row t and column s, is what the cube
// holds at cube_direction(f, s, t): the camera's +X along growing s, its +Y
// against growing t (rows go down), its +Z through the face's centre.
ShadowView point_view(const Scene& scene, size_t index) {
  const SceneLight& light = scene.lights[index];
  ShadowView v;
  v.light = index;
  v.lens.projection = Projection::perspective;
  v.lens.fov = 90;
  v.lens.near = std::max(0.01f, light.range * 0.01f);
  v.lens.far = light.range;
  glm::vec3 position(light.transform.position[0], light.transform.position[1], light.transform.position[2]);
  for (int face = 0; face < 6; ++face) {
    glm::vec3 x = glm::normalize(cube_direction(face, 1, 0.5f) - cube_direction(face, 0, 0.5f));
    glm::vec3 y = -glm::normalize(cube_direction(face, 0.5f, 1) - cube_direction(face, 0.5f, 0));
    glm::vec3 z = cube_direction(face, 0.5f, 0.5f);
    glm::mat4 rotation(glm::vec4(x, 0), glm::vec4(y, 0), glm::vec4(z, 0), glm::vec4(0, 0, 0, 1));
    v.faces.push_back(camera_matrices_at(glm::translate(glm::mat4(1), position) * rotation, v.lens, 1, 1));
  }
  v.camera = v.faces.front();
  // A texel's width at half the range; the caster adds its bias to the
  // distance it stores (world units, then over the range: UnityCG.cginc).
  v.texel_world = light.range / float(scene.shadow_resolution);
  v.caster_bias = {light.shadow_bias * v.texel_world, 0, light.shadow_normal_bias * v.texel_world, 0};
  return v;
}

}  // namespace

std::optional<ShadowView> shadow_view(const Scene& scene, size_t light, const std::vector<ObjectState>& objects,
                                      const glm::vec3& camera_position) {
  const SceneLight& l = scene.lights[light];
  if (l.shadows == ShadowMode::none) return std::nullopt;
  if (l.type == LightType::point) return point_view(scene, light);
  std::optional<ShadowView> v =
      l.type == LightType::directional ? directional_view(scene, light, objects, camera_position) : spot_view(scene, light);
  if (!v) return v;
  // The 3x3 filter's taps lie up to sqrt(2) texels away, and the receiver up
  // to half a texel off the texel centre the caster's depth was taken at.
  if (l.shadows == ShadowMode::soft) v->slope_bias = 2;
  // Clip xy (-1..1, y down like the image rows) to texture uv (0..1); depth stays.
  glm::mat4 to_uv = glm::translate(glm::mat4(1), {0.5f, 0.5f, 0}) * glm::scale(glm::mat4(1), {0.5f, 0.5f, 1});
  v->world_to_shadow = to_uv * v->camera.projection * v->camera.view;
  return v;
}

void add_shadow_values(LightValues& light, const SceneLight& scene_light, const ShadowView& view, int resolution) {
  std::vector<float> matrices(64, 0.0f);
  const float* m = &view.world_to_shadow[0][0];
  std::copy(m, m + 16, matrices.begin());
  light.values.set_elements("unity_WorldToShadow", std::move(matrices));
  float soft = scene_light.shadows == ShadowMode::soft ? 1.0f : 0.0f;
  light.values.set_vector("_LightShadowData", 1 - scene_light.shadow_strength, soft, 0, 0);
  float r = float(resolution);
  light.values.set_vector("_ShadowMapTexture_TexelSize", 1 / r, 1 / r, r, r);
  light.values.set_vector("unity_LightShadowBias", view.caster_bias.x, view.caster_bias.y, view.caster_bias.z, 0);
  light.shadowed = true;
}

bool samples_shadow_map(const std::vector<std::string>& keywords) {
  return has_shadow_keyword(keywords, "SHADOWS_SCREEN") || has_shadow_keyword(keywords, "SHADOWS_DEPTH") ||
         has_shadow_keyword(keywords, "SHADOWS_CUBE");
}

std::vector<std::string> shadow_keywords(const SceneLight& light) {
  if (light.shadows == ShadowMode::none) return {};
  // Directional lights use SHADOWS_SCREEN in ForwardBase and ForwardAdd alike, as in Unity.
  // Soft filtering is a uniform (_LightShadowData.y), so no SHADOWS_SOFT variant is asked for.
  if (light.type == LightType::point) return {"SHADOWS_CUBE"};
  return {light.type == LightType::directional ? "SHADOWS_SCREEN" : "SHADOWS_DEPTH"};
}

Result<DrawListResult, RenderError> caster_draws(const Context& context, const Scene& scene,
                                                std::vector<ObjectState>& objects, const LightValues& light,
                                                const std::function<bool(const ObjectState&)>& include,
                                                const std::string& light_text, const std::string& target,
                                                const std::string& keyword, ShaderLibrary& library) {
  DrawListResult out;
  for (ObjectState& object : objects) {
    if (object.background || !include(object)) continue;
    bool cast = false;
    for (size_t p = 0; p < object.shader->passes.size(); ++p) {
      if (!iequals(object.shader->passes[p].ir.tag("LightMode"), "ShadowCaster")) continue;
      DrawRecord record = pass_record(object, p);
      record.light = light_text;
      record.why = (keyword == "SHADOWS_CUBE" ? "ShadowCaster: distance into " : "ShadowCaster: depth into ") + target;
      FACET_TRY(add_draw(context, scene, library, object, p, &light, {keyword}, std::move(record), out));
      cast = true;
      break;  // one caster pass per object, as Unity takes the first
    }
    if (!cast) {
      DrawRecord record = pass_record(object, 0);
      record.pass = "-";
      record.light_mode = "ShadowCaster";
      record.light = light_text;
      record.drawn = false;
      record.why = fmt::format("not in {}: its shader has no ShadowCaster pass", target);
      out.skipped.push_back(std::move(record));
    }
  }
  return out;
}

Result<DrawListResult, RenderError> build_caster_draws(const Context& context, const Scene& scene,
                                                      std::vector<ObjectState>& objects, const LightValues& light,
                                                      const ShadowView& view, ShaderLibrary& library) {
  const SceneLight& scene_light = scene.lights[view.light];
  glm::vec3 camera_position = camera_matrices(scene.camera, 1, 1).position;
  std::string light_text = light_description(scene, view.light);
  const bool cube = scene_light.type == LightType::point;
  return caster_draws(
      context, scene, objects, light,
      [&](const ObjectState& o) { return reaches(scene, scene_light, o, camera_position); }, light_text,
      fmt::format("the {}x{} shadow {} of {}", scene.shadow_resolution, scene.shadow_resolution, cube ? "cube" : "map",
                  light_text),
      cube ? "SHADOWS_CUBE" : "SHADOWS_DEPTH", library);
}

}  // namespace facet::runtime
