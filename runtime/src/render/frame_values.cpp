#include "render/frame_values.h"

#include <algorithm>
#include <cmath>
#include <glm/gtc/matrix_access.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "facet/runtime/material.h"
#include "facet/runtime/sky_sh.h"

namespace facet::runtime {
namespace {

glm::vec3 v3(const Vec3& a) { return {a[0], a[1], a[2]}; }

void set(UniformValues& u, const std::string& name, const glm::mat4& m) { u.set_matrix(name, glm::value_ptr(m)); }
void set(UniformValues& u, const std::string& name, const glm::vec4& v) { u.set_vector(name, v.x, v.y, v.z, v.w); }

void set_sh(UniformValues& u, const UnitySh& sh) {
  const char* a[3] = {"unity_SHAr", "unity_SHAg", "unity_SHAb"};
  const char* b[3] = {"unity_SHBr", "unity_SHBg", "unity_SHBb"};
  for (int ch = 0; ch < 3; ++ch) {
    set(u, a[ch], sh.a[ch]);
    set(u, b[ch], sh.b[ch]);
  }
  set(u, "unity_SHC", sh.c);
}

// unity_Ambient* are a sky's three colours, or the flat ambient thrice.
void set_ambient(UniformValues& u, const Scene& scene, const UnitySh& sh) {
  glm::vec3 ambient = linear_color(scene.ambient);
  glm::vec3 sky = ambient, equator = ambient, ground = ambient;
  if (scene.sky) {
    SkyRadiance r = linear_sky(*scene.sky);
    sky = r.zenith, equator = r.horizon, ground = r.ground;
    ambient = sky;  // UNITY_LIGHTMODEL_AMBIENT is the sky colour of a gradient
  }
  set(u, "unity_AmbientSky", glm::vec4(sky, 1));
  set(u, "unity_AmbientEquator", glm::vec4(equator, 1));
  set(u, "unity_AmbientGround", glm::vec4(ground, 1));
  set(u, "glstate_lightmodel_ambient", glm::vec4(ambient, 1));
  set_sh(u, sh);
}

// Directional cookies repeat every `size` world units over the light's XY
// plane; uv (0.5, 0.5) is on the light's axis through its position.
glm::mat4 directional_cookie_matrix(const glm::mat4& light_to_world, float size) {
  glm::mat4 to_uv = glm::translate(glm::mat4(1), {0.5f, 0.5f, 0}) * glm::scale(glm::mat4(1), {1 / size, 1 / size, 1});
  return to_uv * glm::inverse(light_to_world);
}

}  // namespace

glm::mat4 rotation_matrix(const Transform& t) {
  if (t.look_at) {
    glm::vec3 forward = v3(*t.look_at) - v3(t.position);
    if (glm::dot(forward, forward) < 1e-12f) return glm::mat4(1);
    forward = glm::normalize(forward);
    glm::vec3 up = std::abs(forward.y) > 0.999f ? glm::vec3(0, 0, 1) : glm::vec3(0, 1, 0);
    glm::vec3 right = glm::normalize(glm::cross(up, forward));
    glm::vec3 true_up = glm::cross(forward, right);
    glm::mat4 r(1);
    r[0] = glm::vec4(right, 0);
    r[1] = glm::vec4(true_up, 0);
    r[2] = glm::vec4(forward, 0);
    return r;
  }
  glm::vec3 a = glm::radians(v3(t.rotation));
  glm::mat4 ry = glm::rotate(glm::mat4(1), a.y, {0, 1, 0});
  glm::mat4 rx = glm::rotate(glm::mat4(1), a.x, {1, 0, 0});
  glm::mat4 rz = glm::rotate(glm::mat4(1), a.z, {0, 0, 1});
  return ry * rx * rz;
}

glm::mat4 transform_matrix(const Transform& t) {
  return glm::translate(glm::mat4(1), v3(t.position)) * rotation_matrix(t) * glm::scale(glm::mat4(1), v3(t.scale));
}

CameraMatrices camera_matrices(const SceneCamera& camera, int width, int height) {
  glm::mat4 to_world = glm::translate(glm::mat4(1), v3(camera.transform.position)) * rotation_matrix(camera.transform);
  return camera_matrices_at(to_world, camera, width, height);
}

CameraMatrices camera_matrices_at(const glm::mat4& camera_to_world, const SceneCamera& camera, int width, int height) {
  CameraMatrices m;
  m.position = glm::vec3(camera_to_world[3]);
  m.camera_to_world = camera_to_world;
  m.world_to_camera = glm::inverse(m.camera_to_world);
  m.view = glm::scale(glm::mat4(1), {1, 1, -1}) * m.world_to_camera;
  float aspect = float(width) / float(height);
  if (camera.projection == Projection::perspective) {
    m.projection = glm::perspectiveRH_ZO(glm::radians(camera.fov), aspect, camera.near, camera.far);
  } else {
    m.projection = glm::orthoRH_ZO(-camera.size * aspect, camera.size * aspect, -camera.size, camera.size, camera.near,
                                   camera.far);
  }
  m.projection[1][1] = -m.projection[1][1];  // Vulkan's y points down: row 0 is the top of the image
  return m;
}

glm::vec3 linear_color(const Vec3& c) {
  return {float(srgb_to_linear(c[0])), float(srgb_to_linear(c[1])), float(srgb_to_linear(c[2]))};
}

UniformValues per_frame_uniforms(const Scene& scene, const CameraMatrices& cam, int width, int height) {
  UniformValues u;
  const SceneCamera& c = scene.camera;
  set(u, "unity_MatrixV", cam.view);
  set(u, "unity_MatrixInvV", glm::inverse(cam.view));
  set(u, "unity_MatrixP", cam.projection);
  set(u, "unity_MatrixVP", cam.projection * cam.view);
  set(u, "unity_CameraProjection", cam.projection);
  set(u, "unity_CameraInvProjection", glm::inverse(cam.projection));
  set(u, "unity_WorldToCamera", cam.world_to_camera);
  set(u, "unity_CameraToWorld", cam.camera_to_world);
  set(u, "_WorldSpaceCameraPos", glm::vec4(cam.position, 0));
  set(u, "_ProjectionParams", {1, c.near, c.far, 1 / c.far});
  float w = float(width), h = float(height);
  set(u, "_ScreenParams", {w, h, 1 + 1 / w, 1 + 1 / h});
  float x = 1 - c.far / c.near, y = c.far / c.near;
  set(u, "_ZBufferParams", {x, y, x / c.far, y / c.far});
  bool ortho = c.projection == Projection::orthographic;
  float aspect = w / h;
  set(u, "unity_OrthoParams", {c.size * aspect, c.size, 0, ortho ? 1.0f : 0.0f});
  float t = scene.time, dt = 1.0f / 60.0f;
  set(u, "_Time", {t / 20, t, 2 * t, 3 * t});
  set(u, "_SinTime", {std::sin(t / 8), std::sin(t / 4), std::sin(t / 2), std::sin(t)});
  set(u, "_CosTime", {std::cos(t / 8), std::cos(t / 4), std::cos(t / 2), std::cos(t)});
  set(u, "unity_DeltaTime", {dt, 1 / dt, dt, 1 / dt});
  return u;
}

UniformValues frame_uniforms(const Scene& scene, const CameraMatrices& cam, int width, int height,
                             const UnitySh& ambient) {
  UniformValues u = per_frame_uniforms(scene, cam, width, height);
  const SceneFog& fog = scene.fog;
  glm::vec3 fog_color = linear_color({fog.color[0], fog.color[1], fog.color[2]});
  set(u, "unity_FogColor", glm::vec4(fog_color, fog.color[3]));
  float range = fog.end - fog.start;
  set(u, "unity_FogParams", {fog.density / std::sqrt(std::log(2.0f)), fog.density / std::log(2.0f), -1 / range,
                             fog.end / range});
  set_ambient(u, scene, ambient);
  // One probe, the environment, for every object: BoxMin.w is Unity's blend
  // weight of probe 0 (1: probe 1 unused), ProbePosition.w = 0 turns box
  // projection off. unity_SpecCube1 (bound to the same cube) decodes the
  // same way, for shaders that sample it whatever the weight.
  set(u, "unity_SpecCube0_HDR", {1, 1, 0, 0});
  set(u, "unity_SpecCube0_BoxMax", {0, 0, 0, 0});
  set(u, "unity_SpecCube0_BoxMin", {0, 0, 0, 1});
  set(u, "unity_SpecCube0_ProbePosition", {0, 0, 0, 0});
  set(u, "unity_SpecCube1_HDR", {1, 1, 0, 0});
  set(u, "unity_SpecCube1_BoxMax", {0, 0, 0, 0});
  set(u, "unity_SpecCube1_BoxMin", {0, 0, 0, 1});
  set(u, "unity_SpecCube1_ProbePosition", {0, 0, 0, 0});
  set(u, "unity_ColorSpaceDielectricSpec", {0.04f, 0.04f, 0.04f, 0.96f});
  return u;
}

LightValues light_values(const SceneLight& light) {
  LightValues l;
  glm::vec3 color = linear_color(light.color) * light.intensity;
  l.brightness = light.intensity * glm::dot(linear_color(light.color), glm::vec3(0.2126f, 0.7152f, 0.0722f));
  glm::mat4 rotation = rotation_matrix(light.transform);
  l.direction = glm::normalize(glm::vec3(rotation * glm::vec4(0, 0, 1, 0)));
  l.position = v3(light.transform.position);
  glm::mat4 light_to_world = glm::translate(glm::mat4(1), l.position) * rotation;
  UniformValues& u = l.values;
  set(u, "_FacetLightColor0", glm::vec4(color, 1));
  set(u, "_LightColor0", glm::vec4(color, 1));
  set(u, "_LightShadowData", {1, 0, 0, 0});
  // The deferred light pass's names for the same light (UnityDeferredLibrary.cginc).
  set(u, "_LightColor", glm::vec4(color, 1));
  set(u, "_LightDir", glm::vec4(l.direction, 0));
  set(u, "_LightPos", glm::vec4(l.position, light.type == LightType::directional ? 0 : 1 / (light.range * light.range)));
  u.set_elements("unity_WorldToShadow", std::vector<float>(64, 0.0f));
  l.cookie = light.cookie;
  l.json_path = light.json_path;
  if (light.type == LightType::directional) {
    l.keyword = light.cookie ? "DIRECTIONAL_COOKIE" : "DIRECTIONAL";
    set(u, "_WorldSpaceLightPos0", glm::vec4(-l.direction, 0));
    set(u, "unity_WorldToLight", light.cookie ? directional_cookie_matrix(light_to_world, light.cookie_size)
                                              : glm::inverse(rotation));
    set(u, "_LightPositionRange", {0, 0, 0, 0});
    return l;
  }
  l.keyword = light.type == LightType::point ? "POINT" : "SPOT";
  set(u, "_WorldSpaceLightPos0", glm::vec4(l.position, 1));
  glm::mat4 to_light = light.type == LightType::point ? glm::translate(glm::mat4(1), -l.position)
                                                      : glm::inverse(light_to_world);
  glm::mat4 world_to_light = glm::scale(glm::mat4(1), glm::vec3(1 / light.range)) * to_light;
  float outer = std::cos(glm::radians(light.spot_angle / 2)), inner = std::cos(glm::radians(light.inner_spot_angle / 2));
  float cone = 2 * std::tan(glm::radians(light.spot_angle / 2));
  if (light.type == LightType::spot) {
    // Unity's projective spot matrix: w = z * 2 tan(angle / 2), so that
    // xy / w + 0.5 is the cookie's uv, 0..1 across the cone; xyz stay as
    // they are for the distance and cone falloffs.
    world_to_light = glm::row(world_to_light, 3, glm::row(world_to_light, 2) * cone);
  }
  set(u, "unity_WorldToLight", world_to_light);
  set(u, "_LightPositionRange", glm::vec4(l.position, 1 / light.range));
  set(u, "_FacetSpotParams", {outer, 1 / std::max(inner - outer, 1e-4f), cone, 0});
  return l;
}

std::optional<SkySun> sky_sun(const Scene& scene) {
  if (!scene.sky || !scene.sky->sun) return std::nullopt;
  const SceneSkySun& sun = *scene.sky->sun;
  // The JSON reader checks the index; a Scene built in code may not have.
  if (sun.light < 0 || size_t(sun.light) >= scene.lights.size()) return std::nullopt;
  const SceneLight& light = scene.lights[size_t(sun.light)];
  if (light.type != LightType::directional) return std::nullopt;
  SkySun out;
  out.to_sun = -light_values(light).direction;
  out.radiance = linear_color(light.color) * light.intensity * sun.intensity;
  out.cos_radius = std::cos(glm::radians(sun.size * 0.5f));
  return out;
}

UnitySh ambient_sh(const Scene& scene) {
  if (!scene.sky) return flat_unity_sh(linear_color(scene.ambient));
  SkyRadiance r = linear_sky(*scene.sky);
  ShCoefficients sky = project_sh([&](const glm::vec3& d) { return sky_radiance(r, d); });
  if (std::optional<SkySun> sun = sky_sun(scene)) {
    ShCoefficients disc = sun_sh(*sun);
    for (size_t i = 0; i < sky.size(); ++i) sky[i] += disc[i];
  }
  return pack_unity_sh(sky);
}

LightValues forward_base_values(const LightValues& main, const Scene& scene, const UnitySh& ambient,
                                const std::vector<size_t>& vertex, const std::vector<size_t>& sh_lights,
                                const glm::vec3& object_center) {
  LightValues l = main;
  l.source = main.scene_light();
  constexpr size_t kSlots = 4;
  glm::vec4 x(0), y(0), z(0), atten(1);
  std::vector<float> colors(4 * 8, 0.0f);  // unity_LightColor[8]: ForwardBase uses the first four
  for (size_t slot = 0; slot < std::min(kSlots, vertex.size()); ++slot) {
    const SceneLight& light = scene.lights[vertex[slot]];
    glm::vec3 c = linear_color(light.color) * light.intensity;
    x[int(slot)] = light.transform.position[0];
    y[int(slot)] = light.transform.position[1];
    z[int(slot)] = light.transform.position[2];
    atten[int(slot)] = 25 / (light.range * light.range);
    for (int k = 0; k < 3; ++k) colors[4 * slot + k] = c[k];
    colors[4 * slot + 3] = 1;
  }
  set(l.values, "unity_4LightPosX0", x);
  set(l.values, "unity_4LightPosY0", y);
  set(l.values, "unity_4LightPosZ0", z);
  set(l.values, "unity_4LightAtten0", atten);
  l.values.set_elements("unity_LightColor", std::move(colors));
  // SH lights as Unity adds them to an object's probe: each light's colour
  // at the object's centre, from its direction there (a spot as a point
  // light: its cone is not taken into account).
  UnitySh sh = ambient;
  for (size_t index : sh_lights) {
    const SceneLight& light = scene.lights[index];
    LightValues values = light_values(light);
    glm::vec3 c = linear_color(light.color) * light.intensity;
    glm::vec3 to_light = -values.direction;
    if (light.type != LightType::directional) {
      glm::vec3 d = values.position - object_center;
      float distance = glm::length(d);
      if (distance < 1e-6f) continue;
      to_light = d / distance;
      float r = distance / light.range;
      c /= 1 + 25 * r * r;
    }
    sh = sh + pack_unity_sh(light_sh(to_light, c));
  }
  set_sh(l.values, sh);
  return l;
}

LightValues no_light() {
  LightValues l;
  l.keyword = "DIRECTIONAL";
  set(l.values, "_WorldSpaceLightPos0", {0, 1, 0, 0});
  set(l.values, "_FacetLightColor0", glm::vec4(0));
  set(l.values, "_LightColor0", glm::vec4(0));
  set(l.values, "unity_WorldToLight", glm::mat4(1));
  set(l.values, "_LightShadowData", {1, 0, 0, 0});
  return l;
}

LightValues vertex_light_values(const Scene& scene, const std::vector<size_t>& lights, const glm::mat4& view) {
  constexpr size_t kSlots = 8;
  LightValues l = no_light();
  // An empty slot: black, and a position and cone that keep the shader's
  // arithmetic finite.
  std::vector<float> color(4 * kSlots, 0.0f), position(4 * kSlots, 0.0f), atten(4 * kSlots, 0.0f),
      spot(4 * kSlots, 0.0f);
  for (size_t slot = 0; slot < kSlots; ++slot) {
    position[4 * slot + 2] = 1;
    atten[4 * slot + 0] = -1;
    atten[4 * slot + 1] = 1;
    spot[4 * slot + 2] = 1;
  }
  for (size_t slot = 0; slot < std::min(kSlots, lights.size()); ++slot) {
    const SceneLight& light = scene.lights[lights[slot]];
    LightValues world = light_values(light);
    glm::vec3 c = linear_color(light.color) * light.intensity;
    glm::vec4 pos = light.type == LightType::directional ? view * glm::vec4(-world.direction, 0)
                                                         : view * glm::vec4(world.position, 1);
    // Unity's vertex-light falloff: 1 / (1 + 25 d^2 / range^2), cut at the
    // range; a spot's cone fades from cos(angle / 2) to cos(angle / 4).
    glm::vec4 a = {-1, 1, 0, 1};
    glm::vec4 s = {0, 0, 1, 0};
    if (light.type != LightType::directional) a = {-1, 1, 25 / (light.range * light.range), light.range * light.range};
    if (light.type == LightType::spot) {
      float outer = std::cos(glm::radians(light.spot_angle / 2)), mid = std::cos(glm::radians(light.spot_angle / 4));
      a.x = outer;
      a.y = 1 / std::max(mid - outer, 0.001f);
      s = view * glm::vec4(-world.direction, 0);
    }
    for (int k = 0; k < 4; ++k) {
      color[4 * slot + k] = k < 3 ? c[k] : 1.0f;
      position[4 * slot + k] = pos[k];
      atten[4 * slot + k] = a[k];
      spot[4 * slot + k] = s[k];
    }
  }
  l.values.set_elements("unity_LightColor", std::move(color));
  l.values.set_elements("unity_LightPosition", std::move(position));
  l.values.set_elements("unity_LightAtten", std::move(atten));
  l.values.set_elements("unity_SpotDirection", std::move(spot));
  return l;
}

UniformValues draw_uniforms(const glm::mat4& m) {
  UniformValues u;
  set(u, "unity_ObjectToWorld", m);
  set(u, "unity_WorldToObject", glm::inverse(m));
  set(u, "unity_LODFade", {1, 1, 0, 0});
  set(u, "unity_WorldTransformParams", {0, 0, 0, glm::determinant(glm::mat3(m)) < 0 ? -1.0f : 1.0f});
  return u;
}

}  // namespace facet::runtime
