// A scene's frame as the renderer keeps it between draws: what the scene
// loads (objects, materials, meshes, lights), its draw lists, the targets,
// render passes and pipelines they need, and their descriptor sets. Prepared
// once (prepare_frame), drawn any number of times (record_frame), and, for a
// forward scene whose objects, materials, lights or camera changed, brought
// up to date in place (update_frame) without creating the GPU objects again.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "facet/runtime/frame_capture.h"
#include "facet/runtime/renderer.h"
#include "render/capture.h"
#include "render/deferred.h"
#include "render/descriptor_binder.h"
#include "render/draw_list.h"
#include "render/environment_lighting.h"
#include "render/grab.h"
#include "render/post.h"
#include "render/resources.h"
#include "render/scene_targets.h"
#include "render/screen_shadows.h"
#include "render/shadow_pass.h"
#include "render/failure.h"

namespace facet::runtime {

// What a frame is prepared for, besides the scene.
struct FrameSetup {
  int width = 0, height = 0;
  FrameCapture* capture = nullptr;  // filled by the first record_frame
  bool keep_scene = true;           // copy the scene into the frame (see SceneFrame::scene)
  RenderOptions probe_options;      // for the reflection probes' own renders
};

struct SceneFrame {
  explicit SceneFrame(Context& context) : context(context), resources(context), binder(context, resources) {}
  SceneFrame(const SceneFrame&) = delete;
  SceneFrame& operator=(const SceneFrame&) = delete;

  Context& context;
  // The scene as prepared or last updated, which the objects point into: the
  // frame's own copy (kept_scene), which a Renderer compares the next scene
  // with, or, for a frame drawn by one render only (FrameSetup::keep_scene
  // false: render_scene), the caller's scene, valid during that render.
  std::optional<Scene> kept_scene;
  const Scene* scene = nullptr;
  int width = 0, height = 0;
  ShaderLibrary* library = nullptr;
  Resources resources;
  std::map<std::string, std::unique_ptr<GpuMesh>> meshes;  // by mesh name (and glTF material) or MeshData address
  std::vector<std::shared_ptr<const MeshData>> mesh_sources;  // the MeshData `meshes` hold: their addresses stay theirs
  CameraMatrices camera;
  std::optional<EnvironmentLighting> environment;
  UniformValues frame_values;  // in place: kept uniform blocks point at it
  std::vector<const Image*> probe_images;
  std::vector<ObjectState> objects;
  LightSetup lights;
  std::vector<ShadowView> shadow_views;
  DrawListResult list;
  uint64_t instanced_away = 0;
  std::unique_ptr<GpuMesh> quad;
  SceneObject sky_source;
  std::unique_ptr<PostChain> post;
  std::unique_ptr<DeferredLights> deferred;
  bool depth_sampled = false;
  SceneTargets targets;
  PostTargets post_targets;
  DeferredTargets gbuffer;
  VkPipelineCache pipeline_cache = VK_NULL_HANDLE;
  std::vector<VkPipeline> pipelines, gbuffer_pipelines, light_pipelines, post_pipelines;
  GrabPlan grabs;
  ShadowPasses shadows;
  ScreenShadows screen_shadows;
  DescriptorBinder binder;
  std::optional<CaptureBuilder> capture;
  FrameCapture* capture_out = nullptr;
  std::optional<Buffer> readback;
  uint64_t pipelines_created = 0;  // by the last prepare_frame or update_frame
  uint64_t meshes_loaded = 0;

  ~SceneFrame();
};

// Loads, builds and creates everything the frame draws. `library` must
// outlive the frame.
Result<std::unique_ptr<SceneFrame>, Diagnostics> prepare_frame(Context& context, const Scene& scene,
                                                               ShaderLibrary& library, const FrameSetup& setup);

// Why `scene` cannot be drawn by updating `frame` in place (empty: it can):
// update_frame covers forward scenes without shadows, image effects,
// GrabPasses, reflection probes or a sky background, drawn at the prepared
// size with the prepared environment.
std::string update_blocker(const SceneFrame& frame, const Scene& scene, int width, int height);

// Rebuilds the objects, lights, draw list and descriptor sets of `frame` for
// `scene` (update_blocker empty), creating only pipelines and meshes it has
// not seen. Returns why it could not after all (the new draws need a pass
// the frame was not prepared with; the frame must then be prepared anew),
// or "".
Result<std::string, Diagnostics> update_frame(SceneFrame& frame, const Scene& scene);

// The camera and time values of the frame, recomputed from `scene` (whose
// only difference from the frame's scene is its time).
void refresh_frame_values(SceneFrame& frame, const Scene& scene);

// Where a recorded frame goes: into an engine's image, to the host, or both.
struct FrameOutput {
  const ImageTarget* target = nullptr;
  bool read_back = true;
};

// Records one frame: shadow maps, the scene, image effects, the copies of
// `output`. `capturing`: fill the capture (the first frame after preparing).
Result<void, Diagnostics> record_frame(SceneFrame& frame, VkCommandBuffer commands, bool capturing,
                                       const FrameOutput& output, RenderStats& stats);

// Why `target` cannot receive frames on `context` ("" when it can).
std::string target_problem(const Context& context, const ImageTarget& target);

// The draw counts of the frame into out.stats; with `records` its draw
// records appended to out.draws, with `compiled` the variants its lists
// compiled (when they were built by this render) to out.compiled.
void collect_records(const SceneFrame& frame, RenderedFrame& out, bool records, bool compiled);

}  // namespace facet::runtime
