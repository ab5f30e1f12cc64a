// Unity's forward semantics as a draw list: which passes of which objects
// are drawn with which light and keywords, in which order, and why.
#pragma once

#include <array>

#include <glm/glm.hpp>

#include <deque>
#include <map>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "facet/runtime/material.h"
#include "facet/runtime/mesh.h"
#include "facet/runtime/render_state.h"
#include "facet/runtime/renderer.h"
#include "facet/runtime/buffer.h"
#include "facet/runtime/image.h"
#include "facet/support/text.h"
#include "render/frame_values.h"
#include "render/shaders.h"
#include "render/failure.h"

namespace facet::runtime {

struct GpuMesh {
  Buffer vertices, indices;
  uint32_t index_count = 0;
  Bounds bounds;
};

// The mesh in host-visible vertex and index buffers.
Result<GpuMesh, Diagnostics> upload_mesh(const Context& context, const MeshData& data);

struct ObjectState {
  size_t index = 0;
  const SceneObject* scene = nullptr;
  ShaderAsset* shader = nullptr;
  Material material;
  glm::mat4 model{1};
  // The object's per-draw values. With `model_values` (a scene object) its
  // matrices (draw_uniforms of `model`) are computed when its sets are
  // written, not kept, and `draw` holds only what adds to them (the
  // reflection probes'); the sky, image effects and full-screen passes keep
  // their whole layer here.
  UniformValues draw;
  bool model_values = false;
  // The reflection probes' cubes unity_SpecCube0/1 bind (null: the environment).
  std::array<const Image*, 2> probes{};
  GpuMesh* mesh = nullptr;
  glm::vec3 center{0};
  float radius = 0;
  float distance = 0;  // from the camera to the bounds' centre
  bool mirrored = false;
  int queue = 2000;
  bool background = false;  // the camera's sky (background.h): no shadow or depth caster
};

struct Draw {
  size_t object = 0;
  size_t pass = 0;  // into ShaderAsset::passes
  const LightValues* light = nullptr;
  LoadedVariant* variant = nullptr;
  PipelineState state;
  DrawRecord record;
  // GrabPass textures to copy the screen into before this draw: the shader's
  // GrabPasses between its previous drawn pass and this one ("_GrabTexture"
  // for `GrabPass { }`, grabbed every time; a named one only the first time
  // in the frame, as Unity grabs it once).
  std::vector<std::string> grab_before;
  // An instanced draw (render/instancing.h): the objects it draws, this
  // draw's first, and the records of the draws merged into it. Empty: the
  // draw's object alone.
  std::vector<size_t> instances;
  std::vector<DrawRecord> instance_records;
};

using ir::kGrabTexture;  // the texture `GrabPass { }` fills

// "lights[1] (point)"
std::string light_description(const Scene& scene, size_t light);
// A record of pass `pass` of `object` with the object, shader, pass, LightMode and queue filled.
DrawRecord pass_record(const ObjectState& object, size_t pass);

struct LightSetup {
  std::vector<LightValues> lights;  // one per scene light
  int main = -1;                    // the brightest directional light, or -1
  LightValues none = no_light();
  glm::mat4 view{1};                // the camera's: vertex-lit lights are in view space
  UnitySh ambient;                  // the scene's SH (environment_lighting)
};

LightSetup setup_lights(const Scene& scene, const glm::mat4& view, const UnitySh& ambient);

// Unity's forward light scheduling for one object, among the lights that
// reach it other than the main light (directional first, then by
// importance): important lights and then auto ones up to pixel_light_count
// (the main light counts) are pixel lights, drawn additively; of the rest,
// the first four point lights light the ForwardBase pass per vertex
// (VERTEXLIGHT_ON) and every other light is added to its SH.
struct ObjectLights {
  std::vector<size_t> pixel;   // ForwardAdd, one draw each
  std::vector<size_t> vertex;  // at most 4, point lights
  std::vector<size_t> sh;
};
ObjectLights schedule_lights(const Scene& scene, const LightSetup& setup, const ObjectState& object);
// The lights of a vertex-lit pass of `object`: at most 8, the main light
// included, directional lights first, then by importance.
std::vector<size_t> vertex_lights(const Scene& scene, const LightSetup& setup, const ObjectState& object);

struct DrawListResult {
  std::vector<Draw> draws;            // sorted for submission
  // With the deferred path (SceneCamera::deferred): the LightMode Deferred
  // passes of the opaque objects, front to back, drawn into the G-buffer
  // before `draws`; those objects' forward passes are skipped.
  std::vector<Draw> gbuffer;
  std::vector<DrawRecord> skipped;    // passes not drawn
  uint64_t variants_compiled = 0;
  std::vector<std::string> compiled;  // descriptions, compile order
  // The lights made for one draw: a vertex-lit pass's, a ForwardBase pass's
  // with vertex or SH lights (a deque: Draw::light points into it, and
  // adding does not move what is there).
  std::deque<LightValues> draw_lights;
};

// Appends the draw of pass `pass_index` of `object` to out.draws: the
// variant Unity would pick for the material's and the `global` keywords
// (compiled on first use) and the render state resolved against the material.
Result<void, Diagnostics> add_draw(const Context& context, const Scene& scene, ShaderLibrary& library,
                                   ObjectState& object, size_t pass_index, const LightValues* light,
                                   const std::vector<std::string>& global, DrawRecord record, DrawListResult& out);

Result<DrawListResult, Diagnostics> build_draws(const Context& context, const Scene& scene,
                                                std::vector<ObjectState>& objects, const LightSetup& lights,
                                                ShaderLibrary& library);

}  // namespace facet::runtime
