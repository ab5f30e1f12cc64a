// The frame-overhead benchmark (issue 4): facet's frame time for a scene
// against a bare Vulkan program drawing the same meshes with the same SPIR-V,
// state, uniform bytes and textures (bare_renderer.h), side by side in one
// run. facet's frame is all it does again per frame: the camera and time uniforms
// recomputed, the uniform members that come from them rewritten in every
// kept block, recording, submission and the wait; the bare frame is
// recording, submission and the wait. Both copy the colour target to a host buffer. The two alternate
// frame by frame (RenderOptions::after_frame) so that drift on a shared
// machine hits both; the first frame of each round is dropped. It also
// checks that the two images are identical.
//
//   facet_frame_bench [--device SEL] [--frames N] [--rounds R] [--width W --height H]
//                     [--validation] [scene.json ...]   (default: the example scenes; a
//                     scene with image effects, shadow maps or a camera depth texture is
//                     listed as skipped: the bare loop draws one render pass)
#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <glm/gtc/packing.hpp>
#include <iostream>
#include <optional>

#include "../render_calls.h"
#include "bare_renderer.h"
#include "facet/runtime/frame_capture.h"
#include "facet/runtime/renderer.h"
#include "facet/runtime/scene.h"
#include "facet/runtime/shader_compiler.h"
#include "facet/runtime/vulkan_context.h"

namespace fs = std::filesystem;
using namespace facet;

namespace {

struct Options {
  std::vector<std::string> scenes;
  std::string device;
  int frames = 60, rounds = 3, width = 0, height = 0;
  bool validation = false;
};

struct Samples {
  std::vector<double> host, gpu;
  void add(std::span<const double> h, std::span<const double> g) {
    host.insert(host.end(), h.begin(), h.end());
    gpu.insert(gpu.end(), g.begin(), g.end());
  }
};

double median(std::vector<double> v) {
  if (v.empty()) return 0;
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

std::vector<std::string> default_scenes() {
  std::vector<std::string> out;
  for (const auto& e : fs::directory_iterator(fs::path(FACET_SOURCE_DIR) / "examples/scenes")) {
    if (e.path().extension() != ".json") continue;
    auto scene = bench::load_scene(e.path().string());
    if (scene) out.push_back(e.path().string());
  }
  std::sort(out.begin(), out.end());
  return out;
}

// The largest difference between facet's image (exposure applied) and the bare one.
double max_difference(const runtime::RenderedFrame& facet_frame, const std::vector<uint16_t>& bare, float exposure) {
  double worst = 0;
  for (size_t i = 0; i < bare.size(); ++i) {
    float value = glm::unpackHalf1x16(bare[i]) * (i % 4 == 3 ? 1.0f : exposure);
    worst = std::max(worst, double(std::abs(value - facet_frame.hdr[i])));
  }
  return worst;
}

// A scene the bare loop cannot draw (image effects, shadow maps, the camera
// depth texture: passes the capture does not cover) is skipped, not failed.
struct Skipped {
  std::string why;
};

struct Row {
  std::string scene;
  int width = 0, height = 0;
  size_t draws = 0;
  double facet_ms = 0, bare_ms = 0, facet_gpu = 0, bare_gpu = 0, max_diff = 0;
};

bool capture_refused(const std::string& message) {
  return message.find("a frame capture does not cover") != std::string::npos;
}

Result<Row, std::string> measure(runtime::Context& context, const std::string& path, const Options& o, Skipped& skipped) {
  auto scene = bench::load_scene(path);
  if (!scene) return unexpected(scene.error());
  runtime::RenderOptions render{.width = o.width, .height = o.height, .shader_compiler = runtime::make_shader_compiler()};
  runtime::FrameCapture capture;
  render.capture = &capture;
  auto first = bench::render_scene(context, *scene, render);
  if (!first && capture_refused(first.error())) {
    skipped.why = first.error().substr(first.error().find("a frame capture"));
    return Row{};
  }
  if (!first) return unexpected(first.error());
  bench::BareRenderer bare(context, capture);
  FACET_TRY(bare.prepare());
  if (auto f = bare.render_frame(); !f) return unexpected(f.error());
  Row row{fs::path(path).filename().string(), first->width, first->height, capture.draws.size()};
  row.max_diff = max_difference(*first, bare.pixels(), scene->camera.exposure);
  render.capture = nullptr;
  render.frames = o.frames + 1;
  Samples facet_samples, bare_samples;
  std::optional<std::string> bare_failed;
  render.after_frame = [&](int f) {
    auto frame = bare.render_frame();
    if (!frame) bare_failed = frame.error();
    if (!frame || f == 0) return;
    bare_samples.host.push_back(frame->host_ms);
    bare_samples.gpu.push_back(frame->gpu_ms);
  };
  for (int r = 0; r < o.rounds; ++r) {
    auto frames = bench::render_scene(context, *scene, render);
    if (!frames) return unexpected(frames.error());
    if (bare_failed) return unexpected(*bare_failed);
    const runtime::RenderStats& st = frames->stats;
    facet_samples.add(std::span(st.frame_ms).subspan(1),
                      st.frame_gpu_ms.empty() ? std::span<const double>() : std::span(st.frame_gpu_ms).subspan(1));
  }
  row.facet_ms = median(facet_samples.host);
  row.bare_ms = median(bare_samples.host);
  row.facet_gpu = median(facet_samples.gpu);
  row.bare_gpu = median(bare_samples.gpu);
  return row;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"facet's frame time against a bare Vulkan program drawing the same frame", "facet_frame_bench"};
  Options o;
  app.add_option("scenes", o.scenes, "scene files (default: every example scene; those the bare loop cannot draw are skipped)");
  app.add_option("--device", o.device, "Vulkan device: index or name part (default: lavapipe)");
  app.add_option("--frames", o.frames, "timed frames per round")->check(CLI::Range(1, 100000));
  app.add_option("--rounds", o.rounds, "rounds (facet loads and compiles the scene once per round)")->check(CLI::Range(1, 1000));
  app.add_option("--width", o.width, "override the scenes' width")->check(CLI::Range(1, 16384));
  app.add_option("--height", o.height, "override the scenes' height")->check(CLI::Range(1, 16384));
  app.add_flag("--validation", o.validation, "enable the validation layer; any message fails the run");
  CLI11_PARSE(app, argc, argv);
  if (o.scenes.empty()) o.scenes = default_scenes();
  auto context = runtime::create_context({.device = o.device, .validation = o.validation});
  if (!context) {
    std::cerr << "facet_frame_bench: " << runtime::describe(context.error()) << "\n";
    return 1;
  }
  std::cout << fmt::format("device: {}\n{} timed frames x {} rounds each; medians; overhead = facet / bare - 1\n\n",
                           runtime::describe((*context)->device_info()), o.frames, o.rounds);
  std::cout << fmt::format("{:<24} {:>10} {:>5} {:>11} {:>11} {:>9} {:>10} {:>10} {:>9}\n", "scene", "size", "draws",
                           "facet ms", "bare ms", "overhead", "facet GPU", "bare GPU", "max diff");
  int status = 0;
  for (const std::string& path : o.scenes) {
    Skipped skipped;
    auto row = measure(**context, path, o, skipped);
    if (!row) {
      std::cerr << path << ": " << row.error() << "\n";
      status = 1;
      continue;
    }
    if (!skipped.why.empty()) {
      std::cout << fmt::format("{:<24} skipped: {}\n", fs::path(path).filename().string(), skipped.why);
      continue;
    }
    std::cout << fmt::format("{:<24} {:>10} {:>5} {:>11.3f} {:>11.3f} {:>8.1f}% {:>10.3f} {:>10.3f} {:>9.2g}\n", row->scene,
                             fmt::format("{}x{}", row->width, row->height), row->draws, row->facet_ms, row->bare_ms,
                             100 * (row->facet_ms / row->bare_ms - 1), row->facet_gpu, row->bare_gpu, row->max_diff)
              << std::flush;
  }
  if (o.validation && !(*context)->messages().empty()) {
    std::cerr << "the validation layer reported:\n" << (*context)->messages_text();
    return 1;
  }
  return status;
}
