// The built-in uniform values of docs/stdlib.md, computed from the scene:
// per frame (camera, time, fog, ambient SH), per light and per draw.
#pragma once

#include <glm/glm.hpp>

#include <optional>
#include <string>
#include <vector>

#include "facet/runtime/scene.h"
#include "facet/runtime/sky_sh.h"
#include "facet/runtime/uniforms.h"

namespace facet::runtime {

// Unity's Transform: T * Ry * Rx * Rz * S (Euler angles in degrees), or a
// rotation that looks at `look_at` with +Y up.
glm::mat4 rotation_matrix(const Transform& t);
glm::mat4 transform_matrix(const Transform& t);

struct CameraMatrices {
  glm::mat4 camera_to_world{1}, world_to_camera{1};  // left-handed, +Z forward
  glm::mat4 view{1};        // right-handed, looks down -Z (UNITY_MATRIX_V)
  glm::mat4 projection{1};  // Vulkan clip space: y down, depth 0..1
  glm::vec3 position{0};
};

CameraMatrices camera_matrices(const SceneCamera& camera, int width, int height);
// The same for a camera placed by a matrix (the lens fields of `lens` used),
// as a light's shadow camera is.
CameraMatrices camera_matrices_at(const glm::mat4& camera_to_world, const SceneCamera& lens, int width, int height);

glm::vec3 linear_color(const Vec3& srgb);

// `ambient` is the scene's SH (environment_lighting).
UniformValues frame_uniforms(const Scene& scene, const CameraMatrices& camera, int width, int height,
                             const UnitySh& ambient);
// The part of them that moves with the camera and time (matrices, projection
// and screen parameters, _Time): what a renderer recomputes every frame.
UniformValues per_frame_uniforms(const Scene& scene, const CameraMatrices& camera, int width, int height);

struct LightValues {
  UniformValues values;
  std::string keyword;       // DIRECTIONAL, POINT or SPOT
  float brightness = 0;      // intensity x luminance of the linear colour
  glm::vec3 position{0};     // point and spot
  glm::vec3 direction{0, 0, 1};  // the way a directional or spot light shines
  std::optional<SceneTexture> cookie;  // bound as _LightTexture0 (white when absent)
  std::string json_path;               // "lights[1]", for messages
  bool shadowed = false;               // has a shadow view (shadows.h): receivers ask for shadow keywords
  // A draw's own copy (forward_base_values) points at the scene light's
  // values it was made from, whose shadow map it samples.
  const LightValues* source = nullptr;
  const LightValues* scene_light() const { return source ? source : this; }
};

LightValues light_values(const SceneLight& light);
// The light of a ForwardBase pass when the scene has no directional light,
// and of passes without LightMode: black, pointing up.
LightValues no_light();

// The lights of a vertex-lit pass (LightMode Vertex): Unity's
// unity_LightColor, unity_LightPosition, unity_LightAtten and
// unity_SpotDirection[8] for up to 8 of the scene's lights (`lights`, most
// important first), in the view space of `view`; the other slots black.
// The pixel-light values are those of no_light().
LightValues vertex_light_values(const Scene& scene, const std::vector<size_t>& lights, const glm::mat4& view);

// The scene's ambient as L2 SH in Unity's packing (unity_SHAr...): a flat
// colour's L0 term, or the projected sky (with its sun's delta).
UnitySh ambient_sh(const Scene& scene);

// The sky's sun resolved against its light, or nullopt without one.
std::optional<SkySun> sky_sun(const Scene& scene);

// A ForwardBase draw's light when lights beyond the pixel lights reach the
// object: `main`'s values plus the four per-vertex point lights `vertex`
// (unity_4LightPosX0/Y0/Z0 in world space, unity_4LightAtten0 = 25 /
// range^2, unity_LightColor[0..3]; the other slots black) and `ambient`
// (ambient_sh of the scene) with the lights `sh_lights` added as seen from
// `object_center`.
LightValues forward_base_values(const LightValues& main, const Scene& scene, const UnitySh& ambient,
                                const std::vector<size_t>& vertex, const std::vector<size_t>& sh_lights,
                                const glm::vec3& object_center);

UniformValues draw_uniforms(const glm::mat4& object_to_world);

}  // namespace facet::runtime
