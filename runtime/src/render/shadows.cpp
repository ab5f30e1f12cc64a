#include "render/shadows.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
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

// An orthographic camera along the light's direction over the square of
// half width `half` around light-space (x, y), from depth lo_z to hi_z, for
// a map of `resolution` texels a side: its lens, camera, texel size and the
// casters' bias.
struct OrthoBox {
  SceneCamera lens;
  CameraMatrices camera;
  float texel_world = 0;
  glm::vec4 caster_bias{0};
};

OrthoBox ortho_box(const SceneLight& light, const glm::mat4& rotation, glm::vec2 centre, float half, float lo_z,
                   float hi_z, uint32_t resolution) {
  const float back = 1.0f;  // the camera stands this far behind the first caster
  OrthoBox box;
  box.lens.projection = Projection::orthographic;
  box.lens.size = half;
  box.lens.near = back * 0.5f;
  box.lens.far = hi_z - lo_z + back * 1.5f;
  glm::vec3 origin = glm::vec3(rotation * glm::vec4(centre.x, centre.y, lo_z - back, 1));
  box.camera = camera_matrices_at(glm::translate(glm::mat4(1), origin) * rotation, box.lens, 1, 1);
  box.texel_world = 2 * half / float(resolution);
  float depth_range = box.lens.far - box.lens.near;
  // y = 1: casters in front of the near plane are flattened onto it.
  box.caster_bias = {light.shadow_bias * box.texel_world / depth_range, 1, light.shadow_normal_bias * box.texel_world, 0};
  return box;
}

// Light-space bounds of the bounding spheres of what the map covers.
std::pair<glm::vec3, glm::vec3> caster_bounds(const Scene& scene, const glm::mat3& to_light,
                                              const std::vector<ObjectState>& objects, const glm::vec3& camera_position) {
  glm::vec3 lo(1e30f), hi(-1e30f);
  for (const ObjectState& o : objects) {
    if (!within_shadow_distance(scene, o, camera_position)) continue;
    glm::vec3 c = to_light * o.center;
    lo = glm::min(lo, c - o.radius);
    hi = glm::max(hi, c + o.radius);
  }
  return {lo, hi};
}

// An orthographic box around the bounding spheres of what the map covers,
// seen along the light's direction, square in x and y.
std::optional<ShadowView> directional_view(const Scene& scene, size_t index, const std::vector<ObjectState>& objects,
                                           const glm::vec3& camera_position) {
  const SceneLight& light = scene.lights[index];
  glm::mat4 rotation = rotation_matrix(light.transform);
  auto [lo, hi] = caster_bounds(scene, glm::transpose(glm::mat3(rotation)), objects, camera_position);
  if (lo.x > hi.x) return std::nullopt;
  glm::vec3 mid = (lo + hi) * 0.5f;
  float half = std::max({hi.x - lo.x, hi.y - lo.y, 1e-3f}) * 0.5f * 1.02f;
  OrthoBox box = ortho_box(light, rotation, {mid.x, mid.y}, half, lo.z, hi.z, uint32_t(scene.shadow_resolution));
  ShadowView v;
  v.light = index;
  v.lens = box.lens;
  v.camera = box.camera;
  v.texel_world = box.texel_world;
  v.caster_bias = box.caster_bias;
  return v;
}

// The eight corners of the camera's view between distances `near` and `far`
// along its forward.
std::array<glm::vec3, 8> slice_corners(const SceneCamera& lens, const CameraMatrices& camera, float aspect, float near,
                                       float far) {
  const glm::mat4 to_world = glm::inverse(camera.view);  // right-handed: forward is -Z
  const glm::vec3 right(to_world[0]), up(to_world[1]), forward(-glm::vec3(to_world[2]));
  std::array<glm::vec3, 8> corners;
  size_t i = 0;
  for (float d : {near, far}) {
    const bool ortho = lens.projection == Projection::orthographic;
    const float h = ortho ? lens.size : d * std::tan(glm::radians(lens.fov) * 0.5f), w = h * aspect;
    for (float sx : {-1.0f, 1.0f})
      for (float sy : {-1.0f, 1.0f}) corners[i++] = camera.position + forward * d + right * (sx * w) + up * (sy * h);
  }
  return corners;
}

// Unity's cascaded shadow maps with its "stable fit": each cascade a slice
// of the view, covered by a square around the slice's bounding sphere (its
// size does not change as the camera turns) whose centre moves in whole
// texels (so the map does not shimmer as the camera moves); every caster
// within the shadow distance is in depth range. The atlas: cascades side by
// side (2), or 2 x 2 (4), each half the resolution a side.
std::optional<ShadowView> cascaded_view(const Scene& scene, size_t index, const std::vector<ObjectState>& objects,
                                        const CameraMatrices& camera, float aspect) {
  std::optional<ShadowView> v = directional_view(scene, index, objects, camera.position);
  if (!v) return v;
  const SceneLight& light = scene.lights[index];
  const glm::mat4 rotation = rotation_matrix(light.transform);
  const glm::mat3 to_light = glm::transpose(glm::mat3(rotation));
  auto [lo, hi] = caster_bounds(scene, to_light, objects, camera.position);
  const int count = scene.shadow_cascades;
  const uint32_t size = uint32_t(scene.shadow_resolution) / 2;
  v->width = uint32_t(scene.shadow_resolution);
  v->height = count == 2 ? size : uint32_t(scene.shadow_resolution);
  std::vector<float> ends = cascade_splits(count);
  ends.push_back(1);
  float start = scene.camera.near;
  for (int c = 0; c < count; ++c) {
    const float end = std::max(ends[size_t(c)] * scene.shadow_distance, start + 1e-3f);
    std::array<glm::vec3, 8> corners = slice_corners(scene.camera, camera, aspect, start, end);
    glm::vec3 centre(0);
    for (const glm::vec3& p : corners) centre += p / 8.0f;
    float radius = 0;
    for (const glm::vec3& p : corners) radius = std::max(radius, glm::distance(p, centre));
    radius = std::ceil(radius * 16.0f) / 16.0f;  // a size that does not flicker with rounding
    glm::vec3 light_centre = to_light * centre;
    const float texel = 2 * radius / float(size);
    glm::vec2 snapped = glm::floor(glm::vec2(light_centre) / texel) * texel;
    OrthoBox box = ortho_box(light, rotation, snapped, radius, std::min(lo.z, light_centre.z - radius),
                             std::max(hi.z, light_centre.z + radius), size);
    ShadowCascade cascade;
    cascade.lens = box.lens;
    cascade.camera = box.camera;
    cascade.caster_bias = box.caster_bias;
    cascade.near = start;
    cascade.far = end;
    cascade.size = size;
    cascade.x = uint32_t(c % 2) * size;
    cascade.y = uint32_t(c / 2) * size;
    // Clip xy (-1..1) to the cascade's square of the atlas; depth stays.
    const glm::vec2 scale = glm::vec2(float(size)) / glm::vec2(float(v->width), float(v->height));
    const glm::vec2 offset = glm::vec2(float(cascade.x), float(cascade.y)) / glm::vec2(float(v->width), float(v->height));
    glm::mat4 to_uv = glm::translate(glm::mat4(1), {offset.x + 0.5f * scale.x, offset.y + 0.5f * scale.y, 0}) *
                      glm::scale(glm::mat4(1), {0.5f * scale.x, 0.5f * scale.y, 1});
    cascade.world_to_shadow = to_uv * box.camera.projection * box.camera.view;
    v->cascades.push_back(cascade);
    start = end;
  }
  v->camera = v->cascades.front().camera;
  v->lens = v->cascades.front().lens;
  v->caster_bias = v->cascades.front().caster_bias;
  v->texel_world = 2 * v->cascades.front().lens.size / float(size);
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

std::vector<float> cascade_splits(int cascades) {
  if (cascades == 2) return {1.0f / 3.0f};
  if (cascades == 4) return {0.067f, 0.2f, 0.467f};
  return {};
}

std::optional<ShadowView> shadow_view(const Scene& scene, size_t light, const std::vector<ObjectState>& objects,
                                      const CameraMatrices& camera, float aspect) {
  const SceneLight& l = scene.lights[light];
  if (l.shadows == ShadowMode::none) return std::nullopt;
  std::optional<ShadowView> v;
  if (l.type == LightType::point) {
    v = point_view(scene, light);
  } else if (l.type == LightType::spot) {
    v = spot_view(scene, light);
  } else if (scene.shadow_cascades > 1) {
    v = cascaded_view(scene, light, objects, camera, aspect);
  } else {
    v = directional_view(scene, light, objects, camera.position);
  }
  if (!v) return v;
  if (v->width == 0) v->width = v->height = uint32_t(scene.shadow_resolution);
  if (l.type == LightType::point) return v;
  // The 3x3 filter's taps lie up to sqrt(2) texels away, and the receiver up
  // to half a texel off the texel centre the caster's depth was taken at.
  if (l.shadows == ShadowMode::soft) v->slope_bias = 2;
  if (!v->cascades.empty()) return v;
  // Clip xy (-1..1, y down like the image rows) to texture uv (0..1); depth stays.
  glm::mat4 to_uv = glm::translate(glm::mat4(1), {0.5f, 0.5f, 0}) * glm::scale(glm::mat4(1), {0.5f, 0.5f, 1});
  v->world_to_shadow = to_uv * v->camera.projection * v->camera.view;
  return v;
}

void add_shadow_values(LightValues& light, const SceneLight& scene_light, const ShadowView& view, int resolution) {
  std::vector<float> matrices(64, 0.0f);
  // Cascades beyond the count never match: _LightSplitsNear > any distance.
  glm::vec4 splits_near(1e30f), splits_far(1e30f);
  if (view.cascades.empty()) {
    const float* m = &view.world_to_shadow[0][0];
    std::copy(m, m + 16, matrices.begin());
    splits_near.x = -1e30f;
  } else {
    for (size_t c = 0; c < view.cascades.size(); ++c) {
      const float* m = &view.cascades[c].world_to_shadow[0][0];
      std::copy(m, m + 16, matrices.begin() + std::ptrdiff_t(16 * c));
      splits_near[int(c)] = view.cascades[c].near;
      splits_far[int(c)] = view.cascades[c].far;
    }
  }
  light.values.set_elements("unity_WorldToShadow", std::move(matrices));
  light.values.set_vector("_LightSplitsNear", splits_near.x, splits_near.y, splits_near.z, splits_near.w);
  light.values.set_vector("_LightSplitsFar", splits_far.x, splits_far.y, splits_far.z, splits_far.w);
  // The cascades' layout in the atlas: count, columns, rows.
  const float count = float(std::max<size_t>(view.cascades.size(), 1));
  light.values.set_vector("_FacetShadowCascades", count, count > 1 ? 2.0f : 1.0f, count > 2 ? 2.0f : 1.0f, 0);
  float soft = scene_light.shadows == ShadowMode::soft ? 1.0f : 0.0f;
  light.values.set_vector("_LightShadowData", 1 - scene_light.shadow_strength, soft, 0, 0);
  const float w = float(view.width ? view.width : uint32_t(resolution)), h = float(view.height ? view.height : uint32_t(resolution));
  light.values.set_vector("_ShadowMapTexture_TexelSize", 1 / w, 1 / h, w, h);
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

Result<DrawListResult, Diagnostics> caster_draws(const Context& context, const Scene& scene,
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

Result<DrawListResult, Diagnostics> build_caster_draws(const Context& context, const Scene& scene,
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
