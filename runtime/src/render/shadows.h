// Shadow maps, as Unity's forward path without screen-space shadows: a
// shadowed directional light (ForwardBase, SHADOWS_SCREEN) or spot light
// (ForwardAdd, SHADOWS_DEPTH) gets a depth map rendered from the light by
// the ShadowCaster passes of the objects around it; receivers sample it
// through unity_WorldToShadow[0] (stdlib/FacetShadow.hlsl). A point light
// (ForwardAdd, SHADOWS_CUBE) gets a cube of distances: the casters'
// SHADOWS_CUBE variants seen from the light through each of six 90-degree
// faces. A map is made only for a light whose receivers' variants actually
// sample it.
#pragma once

#include <glm/glm.hpp>

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "facet/runtime/scene.h"
#include "render/draw_list.h"
#include "render/frame_values.h"
#include "render/failure.h"

namespace facet::runtime {

// One cascade of a directional light: a slice of the camera's view
// (distances near..far along its forward) and the orthographic camera whose
// map covers it, drawn into `area` of the light's atlas.
struct ShadowCascade {
  CameraMatrices camera;
  SceneCamera lens;
  glm::mat4 world_to_shadow{1};  // world -> (u, v, depth, w) of the atlas, inside `area`
  glm::vec4 caster_bias{0};      // unity_LightShadowBias of this cascade's casters
  float near = 0, far = 0;       // _LightSplitsNear / _LightSplitsFar
  uint32_t x = 0, y = 0, size = 0;  // the cascade's square in the atlas, texels
};

// The light's shadow camera and what receivers and casters read of it.
struct ShadowView {
  size_t light = 0;             // into scene.lights
  CameraMatrices camera;        // the light as a camera (facet's conventions)
  SceneCamera lens;             // its projection, for the casters' frame uniforms
  glm::mat4 world_to_shadow{1}; // world -> (u, v, depth, w)
  float texel_world = 0;        // world size of one texel (at half the range for a spot)
  glm::vec4 caster_bias{0};     // unity_LightShadowBias
  // The casters' slope-scaled depth bias (the rasteriser's, in multiples of
  // the depth change over one texel): soft shadows compare neighbours up to
  // a texel diagonal away, which a constant bias cannot cover on a slope.
  float slope_bias = 0;
  // A point light's six cameras, one a cube face in Vulkan's order (+X, -X,
  // +Y, -Y, +Z, -Z) and orientation; empty for a depth map.
  std::vector<CameraMatrices> faces;
  // A directional light's 2 or 4 cascades (scene.shadow_cascades); empty
  // for a single map. The map is then an atlas of `width` x `height` texels.
  std::vector<ShadowCascade> cascades;
  uint32_t width = 0, height = 0;  // the map's texels
};

// Where `light` (shadows on) looks from, fitted for a directional light to
// the bounds of the objects within the shadow distance; a point light looks
// through the six faces of a cube.
std::optional<ShadowView> shadow_view(const Scene& scene, size_t light, const std::vector<ObjectState>& objects,
                                      const CameraMatrices& camera, float aspect);

// Unity's default cascade splits as fractions of the shadow distance: the
// far end of every cascade but the last (which ends at the distance).
std::vector<float> cascade_splits(int cascades);

// Adds the receivers' values (unity_WorldToShadow[0], _LightShadowData,
// _ShadowMapTexture_TexelSize) and the casters' unity_LightShadowBias.
void add_shadow_values(LightValues& light, const SceneLight& scene_light, const ShadowView& view, int resolution);

// Whether a variant with these keywords samples the light's shadow map.
bool samples_shadow_map(const std::vector<std::string>& keywords);

// The shadow keywords a pass with this light asks for ({} without shadows).
std::vector<std::string> shadow_keywords(const SceneLight& light);

// The ShadowCaster draws (`keyword`: SHADOWS_DEPTH, or SHADOWS_CUBE for a
// point light's cube; with `light`) of the objects that `include` takes;
// those without such a pass are listed in out.skipped as not in `target`
// ("the camera depth texture").
Result<DrawListResult, Diagnostics> caster_draws(const Context& context, const Scene& scene,
                                                 std::vector<ObjectState>& objects, const LightValues& light,
                                                 const std::function<bool(const ObjectState&)>& include,
                                                 const std::string& light_text, const std::string& target,
                                                 const std::string& keyword, ShaderLibrary& library);

// The ShadowCaster draws of `objects` into the map of `view`: every object
// whose shader has a ShadowCaster pass and whose bounds reach the light's
// view; skipped casters (no such pass) are listed in out.skipped.
Result<DrawListResult, Diagnostics> build_caster_draws(const Context& context, const Scene& scene,
                                                       std::vector<ObjectState>& objects, const LightValues& light,
                                                       const ShadowView& view, ShaderLibrary& library);

}  // namespace facet::runtime
