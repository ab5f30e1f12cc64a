// The forward renderer: Unity's forward-rendering semantics over a Scene
// (docs/rendering.md). A scene's shaders are packages (.facetpkg), drawn as
// built, or, with a ShaderCompiler (facet/runtime/shader_compiler.h),
// .shader files whose variants are compiled when a draw first needs them;
// nothing else is compiled.
//
// One frame, everything made for it and released after:
//
//   SourceMap sources;
//   Diagnostics diags;
//   auto scene = runtime::load_scene("examples/scenes/unlit.json", sources, diags);
//   auto frame = runtime::render_scene(*context, *scene, {.shader_compiler = runtime::make_shader_compiler()},
//                                      sources, diags);
//   if (!frame) { fputs(render_text(diags, sources).c_str(), stderr); return 1; }
//   runtime::write_png(*frame, "out.png", diags);
//
// Errors are facet's Diagnostics, as the compiler's are: each has an id
// (scene_material_property, shader_unavailable, vulkan_failed, ...) and,
// where it has a place, a span in `sources`: a shader's compile errors where
// they are in the .shader and its includes, a material value where it is in
// the scene file.
//
// An engine's loop: a Renderer keeps the frame it drew and draws the next
// one by updating it (docs/library.md):
//
//   auto renderer = runtime::Renderer::create(*context, {.strict_variants = true}, diags);
//   runtime::RenderedFrame frame;
//   for (...) { change(scene); (*renderer)->render(scene, frame, {.records = false}, sources, diags); }
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

#include "facet/diagnostics.h"
#include "facet/result.h"
#include "facet/runtime/scene.h"
#include "facet/runtime/shader_compiler.h"

namespace facet::runtime {

class Context;

struct FrameCapture;

// Shaders kept from one render_scene call to the next, for an engine's or an
// editor's loop: the .shader files and packages scenes named and the
// variants compiled and created on the GPU for their draws, so that a later
// render compiles and loads nothing it already has. Before each render, a
// shader whose .shader or package file, or any file its variants included,
// changed on disk (modification time or size) is forgotten: it is loaded
// again and its variants compiled again as draws need them
// (RenderStats::shaders_reloaded). A store holds GPU programs and pipelines
// of the Context it first rendered with and renders with no other: destroy
// it before that Context. One render at a time.
class ShaderStore;
std::shared_ptr<ShaderStore> make_shader_store();

struct RenderOptions {
  int width = 0, height = 0;  // 0: the scene's size
  // Loads and compiles the scene's .shader files; empty: the scene's shaders
  // must be packages, and a .shader is an error naming it.
  std::shared_ptr<const ShaderCompiler> shader_compiler;
  // Frames rendered after loading and compiling once, for timing: the first
  // writes every draw's descriptor sets and uniform data; each later one
  // recomputes the camera and time uniforms, rewrites the members that come
  // from the frame layer, records, submits and waits. The image is the last
  // frame's.
  int frames = 1;
  FrameCapture* capture = nullptr;  // filled from the first frame (facet/runtime/frame_capture.h)
  // Called after each frame's wait, outside its timing: a benchmark runs
  // its baseline here, so that the two alternate frame by frame.
  std::function<void(int frame)> after_frame;
  // A scene's shaders may be packages (.facetpkg from facetc): a draw whose
  // keywords have no exact variant in one is an error naming the keyword set
  // when strict (Unity's strictShaderVariantMatching), else drawn with
  // Unity's closest match and listed once in RenderedFrame::variant_misses.
  bool strict_variants = false;
  // Shaders kept between calls (make_shader_store); empty: loaded for this
  // call only.
  std::shared_ptr<ShaderStore> shaders;
};

// One draw (or one pass that was not drawn), for --explain and tests.
struct DrawRecord {
  std::string object;           // "objects[1] (ball)"
  size_t object_index = 0;
  std::string shader;           // the shader's name
  std::string shader_path;      // the .shader or .facetpkg it was loaded from
  std::string pass;             // "1 FORWARD_DELTA"
  size_t pass_index = 0;        // the pass's index in its SubShader (in its package, for a package)
  std::string pass_name;        // "FORWARD_DELTA" ("" when unnamed)
  std::string light_mode;       // the pass's LightMode tag ("" when none)
  std::string light;            // "lights[2] (point)" or "" when the pass has no light
  int queue = 2000;
  std::vector<std::string> keywords;  // of the variant drawn
  bool exact = true;            // false: Unity's closest-match rule picked the variant
  bool additive = false;        // a ForwardAdd draw
  bool drawn = true;            // false: the pass was skipped (the reason is in `why`)
  std::string state;            // fixed-function state
  std::string why;
};

// What a Renderer kept from its previous render (RenderStats::frame_path).
enum class FramePath {
  prepared,  // everything loaded, built and created for this scene
  updated,   // the draw list rebuilt for changed objects, materials, lights or camera; GPU objects kept
  repeated,  // drawn again as it was: only the scene's time changed
};
std::string_view frame_path_name(FramePath path);  // "prepared", "updated", "repeated"

struct RenderStats {
  uint64_t draws = 0;               // shadow-map and depth-texture draws included
  uint64_t additive_draws = 0;
  uint64_t instanced_draws = 0;    // draws of several objects at once (GPU instancing)
  uint64_t instanced_away = 0;     // the draws those replaced, less one each: `draws` counts draw calls
  uint64_t gbuffer_draws = 0;    // the deferred path's Deferred passes into the G-buffer
  uint64_t deferred_lights = 0;  // the deferred path's light draws (one a light)
  uint64_t shadow_maps = 0;         // lights whose shadow map was rendered
  uint64_t shadow_draws = 0;        // ShadowCaster draws into them
  uint64_t depth_texture_draws = 0; // ShadowCaster draws into the camera depth texture (objects sample it)
  uint64_t screen_shadow_masks = 0; // directional lights' screen-space shadow masks (one full-screen draw each)
  uint64_t triangles = 0;
  uint64_t grabs = 0;              // screen copies into GrabPass textures, in the last frame
  uint64_t pipelines = 0;          // graphics pipelines created
  uint64_t variants_compiled = 0;  // (pass, variant) pairs compiled
  uint64_t shaders_loaded = 0;     // .shader files and packages loaded by this render
  uint64_t shaders_reloaded = 0;   // of RenderOptions::shaders: forgotten before it, their files having changed
  uint64_t textures_loaded = 0;    // from files
  std::optional<double> gpu_ms;    // the frame's GPU time from timestamps (the median over frames)
  std::vector<double> frame_ms;     // per frame: host time from the first uniform to the fence
  std::vector<double> frame_cpu_ms; // per frame: the host's work, from the first uniform to the submission (no wait)
  std::vector<double> frame_gpu_ms; // per frame, from timestamps
  double compile_ms = 0;           // loading and compiling shaders
  double total_ms = 0;
  // What this render kept from the Renderer's previous one, and why it
  // prepared anew ("" for a first render and when it kept the frame).
  FramePath frame_path = FramePath::prepared;
  std::string prepared_because;
  // GPU objects this render created besides pipelines (which `pipelines`
  // counts): meshes uploaded, descriptor pools and uniform buffers. A
  // repeated or updated frame whose draws the renderer has seen before
  // creates none.
  uint64_t meshes_loaded = 0;
  uint64_t descriptor_pools_created = 0;
  uint64_t uniform_buffers_created = 0;
};

struct RenderedFrame {
  int width = 0, height = 0;
  std::vector<float> hdr;        // RGBA, linear, exposure applied, row 0 at the top
  std::vector<uint8_t> ldr;      // RGBA8: tone-mapped, sRGB-encoded, alpha 255
  std::vector<DrawRecord> draws; // in submission order; skipped passes after them
  std::vector<std::string> compiled;  // "Examples/PhongMultiLight FORWARD_DELTA: POINT", in compile order
  std::vector<std::string> shader_files;  // every .shader and include the shaders and variants drawn read, sorted
  std::vector<std::string> variant_misses;  // distinct draws a package had no exact variant for (closest match
                                            // used, or the variant compiled on demand; each says which)
  RenderStats stats;
};

// One render of `scene` by a Renderer made for it (RendererOptions::one_render):
// errors go to `diags`, located in `sources` (see Renderer::render).
Result<RenderedFrame> render_scene(Context& context, const Scene& scene, const RenderOptions& options,
                                   SourceMap& sources, Diagnostics& diags);

struct RendererOptions {
  // Loads and compiles .shader files; empty: packages only (RenderOptions).
  std::shared_ptr<const ShaderCompiler> shader_compiler;
  bool strict_variants = false;  // as RenderOptions::strict_variants
  // Shaders shared with other renders (make_shader_store); empty: the
  // renderer keeps its own.
  std::shared_ptr<ShaderStore> shaders;
  // A renderer for one render (render_scene's): it keeps no copy of the
  // scene (0.36 KB an object in facet_scaling_bench's grid), so each render
  // prepares anew.
  bool one_render = false;
};

// An engine's image a Renderer copies each frame into (FrameOptions::target):
// the scene's linear colour after the image effects, before exposure and
// tone mapping (RenderedFrame::hdr without the exposure), scaled with a
// linear filter when the sizes differ. The image needs
// VK_IMAGE_USAGE_TRANSFER_DST_BIT, optimal tiling, one layer and mip 0, and
// a float or normalized colour format the device can blit to (RGBA16F,
// RGBA8, ...; not an integer or depth one).
struct ImageTarget {
  VkImage image = VK_NULL_HANDLE;
  VkFormat format = VK_FORMAT_UNDEFINED;
  uint32_t width = 0, height = 0;
  // The layout before the frame (UNDEFINED: its contents may be dropped)
  // and the one it is left in, with the writes visible to every later stage.
  VkImageLayout layout = VK_IMAGE_LAYOUT_UNDEFINED;
  VkImageLayout final_layout = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
};

// What one Renderer::render draws and returns.
struct FrameOptions {
  int width = 0, height = 0;  // 0: the scene's size
  int frames = 1;             // as RenderOptions::frames
  FrameCapture* capture = nullptr;
  std::function<void(int frame)> after_frame;
  // Fill RenderedFrame::draws and compiled (--explain, tests); an engine's
  // loop leaves them out and keeps the counts in stats.
  bool records = true;
  std::optional<ImageTarget> target;
  // Copy the frame to the host and tone-map it into RenderedFrame::hdr and
  // ldr; off (an engine drawing into `target`): they are left empty.
  bool read_back = true;
};

// A renderer that keeps what it made from one render to the next, for an
// engine's or an editor's loop. Each render compares the scene with the one
// it drew last:
//   - only the time changed: the frame is drawn again as it was, its time
//     and camera uniforms rewritten (FramePath::repeated);
//   - objects, transforms, materials (values, textures, keywords, queue),
//     lights or the camera changed, in a forward scene without shadows,
//     image effects, GrabPasses, reflection probes or a sky background: the
//     objects and draw list are built again and drawn with the targets,
//     pipelines, descriptor pools and uniform buffers kept, which it only
//     adds to for draws it has not seen (FramePath::updated);
//   - anything else (the size, the environment, shadows, ...): prepared
//     anew, as render_scene does, and RenderStats::prepared_because says why.
// Shaders are kept as a ShaderStore keeps them, and reloaded when their
// files change. The renderer holds GPU objects of its Context: destroy it
// first. One render at a time; see docs/runtime.md.
class Renderer {
 public:
  // Errors (a ShaderStore of another Context, the command buffers) go to
  // `diags`.
  static Result<std::unique_ptr<Renderer>> create(Context& context, RendererOptions options, Diagnostics& diags);
  ~Renderer();
  Renderer(const Renderer&) = delete;
  Renderer& operator=(const Renderer&) = delete;

  // Draws `scene` into `out`, whose buffers are reused (nothing in it is
  // kept: it is cleared first). On an error the kept frame is dropped (the
  // next render prepares anew) and `diags` gets the errors: located ones
  // point into `sources`, to which the files they name are added (a
  // shader's files, the scene file) unless it holds them with the same text
  // already (SourceMap::add_file_version).
  Result<void> render(const Scene& scene, RenderedFrame& out, const FrameOptions& options, SourceMap& sources,
                      Diagnostics& diags);

 private:
  struct State;
  explicit Renderer(std::unique_ptr<State> state);
  // render's work; its errors point into the ShaderLibrary's report_sources().
  Result<void, Diagnostics> draw(const Scene& scene, RenderedFrame& out, const FrameOptions& options);
  std::unique_ptr<State> state_;
};

// Writes through a temporary file and a rename: no partial file on failure
// (output_unwritable).
Result<void> write_png(const RenderedFrame& frame, const std::string& path, Diagnostics& diags);
Result<void> write_exr(const RenderedFrame& frame, const std::string& path, Diagnostics& diags);

// One line per draw, as `facet render --explain` prints them.
std::string explain_text(const RenderedFrame& frame);

// The variant collection of a frame (Unity's ShaderVariantCollection, as
// `facetc --variants` reads it): per shader name, per pass, every keyword set
// a draw used, sorted, as JSON. `facet render --emit-variants` writes it. A
// shader loaded from one of `scene_shaders` (the .shader files the scene
// names) gets that path as "source", which `facetc --scene` builds; the
// renderer's own shaders (skies, shadow and deferred light passes) get none.
std::string variant_collection_json(const RenderedFrame& frame, const std::vector<std::string>& scene_shaders = {});

}  // namespace facet::runtime
