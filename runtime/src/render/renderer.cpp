// Renderer and render_scene: a frame prepared (render/scene_frame.h), kept
// and updated between renders, drawn, read back and tone-mapped on the host.
#include "facet/runtime/renderer.h"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cstring>
#include <glm/gtc/packing.hpp>

#include "facet/runtime/submission.h"
#include "facet/runtime/vulkan_context.h"
#include "facet/reference/color.h"
#include "facet/reference/tonemap.h"
#include "render/scene_frame.h"

namespace facet::runtime {
namespace {

using Clock = std::chrono::steady_clock;
double ms_since(Clock::time_point t) { return std::chrono::duration<double, std::milli>(Clock::now() - t).count(); }

double median(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  return values[values.size() / 2];
}

// The scene's tone curve: the stdlib's (FacetTonemap.hlsl) through its CPU twin.
glm::dvec3 tonemap(const glm::dvec3& c, Tonemap mode) {
  if (mode == Tonemap::reinhard) return reference::FacetTonemapReinhard(c);
  if (mode == Tonemap::aces) return reference::FacetTonemapACESNarkowicz(c);  // Narkowicz's fit of the ACES filmic curve
  return reference::saturate(c);
}

void finish_image(RenderedFrame& frame, const std::byte* halves, const Scene& scene) {
  size_t n = size_t(frame.width) * frame.height;
  frame.hdr.resize(n * 4);
  frame.ldr.resize(n * 4);
  float exposure = scene.camera.exposure;
  for (size_t i = 0; i < n * 4; ++i) {
    uint16_t h;
    std::memcpy(&h, halves + 2 * i, 2);
    frame.hdr[i] = glm::unpackHalf1x16(h) * (i % 4 == 3 ? 1.0f : exposure);
  }
  for (size_t p = 0; p < n; ++p) {
    glm::dvec3 c = tonemap({frame.hdr[4 * p], frame.hdr[4 * p + 1], frame.hdr[4 * p + 2]}, scene.tonemap);
    for (int k = 0; k < 3; ++k) frame.ldr[4 * p + k] = uint8_t(std::lround(reference::FacetLinearToSRGB(c[k]) * 255.0));
    frame.ldr[4 * p + 3] = 255;
  }
}

}  // namespace

std::string_view frame_path_name(FramePath path) {
  switch (path) {
    case FramePath::prepared: return "prepared";
    case FramePath::updated: return "updated";
    case FramePath::repeated: return "repeated";
  }
  return "?";
}

struct Renderer::State {
  State(Context& context, RendererOptions options) : context(context), options(std::move(options)) {}
  Context& context;
  RendererOptions options;
  std::shared_ptr<ShaderStore> store;
  std::optional<Submission> submission;  // the frames' command buffer and fence
  std::unique_ptr<SceneFrame> frame;
  uint64_t frame_library_generation = 0;  // ShaderLibrary::forgotten_total when the frame was built
  std::vector<std::string> frame_misses;  // the variant misses of the frame's draw lists
};

Renderer::Renderer(std::unique_ptr<State> state) : state_(std::move(state)) {}
Renderer::~Renderer() = default;

Result<std::unique_ptr<Renderer>> Renderer::create(Context& context, RendererOptions options, Diagnostics& diags) {
  auto state = std::make_unique<State>(context, std::move(options));
  state->store = state->options.shaders ? state->options.shaders : make_shader_store();
  ShaderStore& store = *state->store;
  if (store.context && store.context != &context) {
    diags.add(DiagId::render_invalid, SourceSpan{},
              "the ShaderStore holds GPU programs of another Context: give each Context its own");
    return failure();
  }
  store.context = &context;
  if (!store.library) store.library = std::make_unique<ShaderLibrary>(state->options.shader_compiler);
  VkResultOf<Submission> submission = Submission::create(context);
  if (!submission) {
    diags.add(DiagId::vulkan_failed, SourceSpan{}, describe(submission.error()));
    return failure();
  }
  state->submission = std::move(*submission);
  return std::unique_ptr<Renderer>(new Renderer(std::move(state)));
}

Result<void> Renderer::render(const Scene& scene, RenderedFrame& out, const FrameOptions& options, SourceMap& sources,
                              Diagnostics& diags) {
  Result<void, Diagnostics> drawn = draw(scene, out, options);
  if (drawn) return {};
  diags.append(rebase_diagnostics(drawn.error(), state_->store->library->report_sources(), sources));
  return failure();
}

Result<void, Diagnostics> Renderer::draw(const Scene& scene, RenderedFrame& out, const FrameOptions& options) {
  Clock::time_point start = Clock::now();
  State& s = *state_;
  out.draws.clear();
  out.compiled.clear();
  out.shader_files.clear();
  out.variant_misses.clear();
  out.stats = RenderStats{};
  out.width = options.width ? options.width : scene.width;
  out.height = options.height ? options.height : scene.height;
  if (options.frames < 1) return unexpected(render_error("frames must be at least 1"));
  if (out.width < 1 || out.height < 1 || int64_t(out.width) * out.height > kMaxFramePixels) {
    return unexpected(render_error(fmt::format("a frame of {} x {} is outside 1 to {} pixels (4096 x 4096)", out.width,
                                               out.height, kMaxFramePixels)));
  }
  if (options.capture && !scene.post.empty()) {
    return unexpected(render_error(scene.path + ": a frame capture does not cover image effects"));
  }
  if (options.target) {
    if (std::string problem = target_problem(s.context, *options.target); !problem.empty()) {
      return unexpected(render_error(problem));
    }
  }
  ShaderLibrary& library = *s.store->library;
  library.set_compiler(s.options.shader_compiler);
  library.set_strict_variants(s.options.strict_variants);
  out.stats.shaders_reloaded = library.forget_changed();
  // Whatever fails from here leaves no frame to keep.
  std::unique_ptr<SceneFrame> kept = std::move(s.frame);
  const size_t textures_at_start = kept ? kept->resources.textures_loaded() : 0;  // an update may load some
  std::string because;
  FramePath path = FramePath::prepared;
  if (!kept) {
    because = "";
  } else if (library.forgotten_total() != s.frame_library_generation) {
    because = "a shader changed on disk";
  } else if (options.capture) {
    because = "a frame capture";
  } else if (!kept->kept_scene) {
    because = "the renderer keeps no scene (RendererOptions::one_render)";
  } else if (out.width == kept->width && out.height == kept->height &&
             (kept->kept_scene->time = scene.time, *kept->kept_scene == scene)) {  // the kept time is redrawn anyway
    path = FramePath::repeated;
  } else if (because = update_blocker(*kept, scene, out.width, out.height); because.empty()) {
    Result<std::string, Diagnostics> updated = update_frame(*kept, scene);
    if (!updated) return unexpected(updated.error());
    because = *updated;
    if (because.empty()) path = FramePath::updated;
  }
  if (path == FramePath::prepared) {
    kept.reset();  // its GPU objects go before the new frame's are made
    RenderOptions probe_options{.shader_compiler = s.options.shader_compiler,
                                .strict_variants = s.options.strict_variants,
                                .shaders = s.store};
    Result<std::unique_ptr<SceneFrame>, Diagnostics> prepared = prepare_frame(s.context, scene, library,
                                                                              {.width = out.width,
                                                                               .height = out.height,
                                                                               .capture = options.capture,
                                                                               .keep_scene = !s.options.one_render,
                                                                               .probe_options = probe_options});
    if (!prepared) return unexpected(prepared.error());
    kept = std::move(*prepared);
  }
  SceneFrame& frame = *kept;
  if (path != FramePath::repeated) {
    s.frame_library_generation = library.forgotten_total();
    s.frame_misses = library.misses();
  }
  // Counted from the frame's own creation when it was prepared by this render.
  const bool fresh = path == FramePath::prepared;
  const size_t pools_before = fresh ? 0 : frame.binder.pools.pools_created();
  const size_t buffers_before = fresh ? 0 : frame.binder.arena.buffers_created();
  const size_t textures_before = fresh ? 0 : textures_at_start;
  VkQueryPool queries = s.context.timestamp_pool();
  for (int f = 0; f < options.frames; ++f) {
    Clock::time_point frame_start = Clock::now();
    out.stats.triangles = 0;
    out.stats.grabs = 0;
    if (f > 0 || path == FramePath::repeated) refresh_frame_values(frame, scene);
    Clock::time_point submit_returned = frame_start;
    std::optional<Diagnostics> failed;
    // Only the render that asked for it (and so prepared the frame) captures.
    const bool capturing = f == 0 && options.capture != nullptr;
    VkResultOf<void> submitted = s.submission->submit(
        [&](VkCommandBuffer c) {
          // After the first frame the target is in the layout the frame before left it in.
          std::optional<ImageTarget> target = options.target;
          if (target && f > 0) target->layout = target->final_layout;
          const FrameOutput output{target ? &*target : nullptr, options.read_back};
          if (Result<void, Diagnostics> recorded = record_frame(frame, c, capturing, output, out.stats); !recorded) {
            failed = recorded.error();
          }
        },
        {.submitted = &submit_returned});
    out.stats.frame_ms.push_back(ms_since(frame_start));
    out.stats.frame_cpu_ms.push_back(std::chrono::duration<double, std::milli>(submit_returned - frame_start).count());
    if (failed) return unexpected(*failed);
    if (!submitted) return unexpected(render_error(describe(submitted.error()), DiagId::vulkan_failed));
    uint64_t stamps[2] = {0, 0};
    if (queries && vkGetQueryPoolResults(s.context.device(), queries, 0, 2, sizeof(stamps), stamps, sizeof(uint64_t),
                                         VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT) == VK_SUCCESS) {
      out.stats.frame_gpu_ms.push_back(double(stamps[1] - stamps[0]) * s.context.device_info().timestamp_period_ns / 1e6);
    }
    if (f == 0) frame.binder.done_making_sets();
    if (options.after_frame) options.after_frame(f);
  }
  if (!out.stats.frame_gpu_ms.empty()) out.stats.gpu_ms = median(out.stats.frame_gpu_ms);
  if (options.read_back) {
    finish_image(out, static_cast<const std::byte*>(frame.readback->data()), scene);
  } else {
    out.hdr.clear();
    out.ldr.clear();
  }
  collect_records(frame, out, options.records, path != FramePath::repeated);
  out.stats.instanced_away = frame.instanced_away;
  out.stats.frame_path = path;
  out.stats.prepared_because = because;
  out.stats.pipelines = path == FramePath::repeated ? 0 : frame.pipelines_created;
  out.stats.meshes_loaded = path == FramePath::repeated ? 0 : frame.meshes_loaded;
  out.stats.descriptor_pools_created = frame.binder.pools.pools_created() - pools_before;
  out.stats.uniform_buffers_created = frame.binder.arena.buffers_created() - buffers_before;
  out.stats.shaders_loaded = path == FramePath::repeated ? 0 : library.loaded();
  out.shader_files = library.files_read();
  out.variant_misses = s.frame_misses;
  out.stats.textures_loaded = frame.resources.textures_loaded() - textures_before;
  out.stats.compile_ms = path == FramePath::repeated ? 0 : library.seconds() * 1000;
  out.stats.total_ms = ms_since(start);
  s.frame = std::move(kept);
  return {};
}

Result<RenderedFrame> render_scene(Context& context, const Scene& scene, const RenderOptions& options,
                                   SourceMap& sources, Diagnostics& diags) {
  Result<std::unique_ptr<Renderer>> renderer = Renderer::create(context,
                                                                {.shader_compiler = options.shader_compiler,
                                                                 .strict_variants = options.strict_variants,
                                                                 .shaders = options.shaders,
                                                                 .one_render = true},
                                                                diags);
  if (!renderer) return failure();
  RenderedFrame frame;
  FACET_TRY((*renderer)->render(scene, frame,
                                {.width = options.width,
                                 .height = options.height,
                                 .frames = options.frames,
                                 .capture = options.capture,
                                 .after_frame = options.after_frame},
                                sources, diags));
  return frame;
}

}  // namespace facet::runtime
