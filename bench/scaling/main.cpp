// The scaling benchmark: what facet costs the host per object as a scene
// grows from 10 to 100,000 objects, on repeated frames, against the bare
// Vulkan loop of bench/frame_overhead drawing the same frame (the same
// meshes, SPIR-V, state and uniform bytes, everything prepared up front),
// side by side in one run: the two alternate frame by frame.
//
// Per object count it prints
//   - CPU µs per draw: the host's work for a frame (facet: the frame
//     uniforms, every kept block's frame members, recording and submission;
//     bare: recording and submission), without the wait for the GPU, over the
//     draws of the frame; the median over the timed frames;
//   - frame ms: the whole frame to the fence, the GPU's (or lavapipe's) work
//     included;
//   - host KB per object: the growth of the process's resident memory from
//     before the render to its last frame (facet's own render, without the
//     capture or the bare loop), over the objects; what each object added
//     since the previous count (the fixed part, pipelines and the driver's,
//     left out); and malloc's bytes in use, grown likewise, over the objects.
// Each count is measured twice: the objects drawn one by one, and with GPU
// instancing (the material's "instancing": up to 128 objects a draw, each
// with its own colour either way); a table compares the two per object.
// The last table is an engine's loop through one Renderer (docs/rendering.md,
// "Frames kept between renders"), objects drawn one by one: the host time of
// a whole render call without the wait for the GPU, per draw, when the
// scene is the same as the last frame's (repeated) and when every object's
// colour changed (updated), and the GPU objects those frames created.
//
//   facet_scaling_bench [--device SEL] [--counts 10,100,1000,10000,100000]
//                       [--frames N] [--shader PATH] [--validation]
#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <fstream>
#include <malloc.h>
#include <iostream>
#include <optional>
#include <string>

#include "../frame_overhead/bare_renderer.h"
#include "../render_calls.h"
#include "facet/runtime/frame_capture.h"
#include "facet/runtime/renderer.h"
#include "facet/runtime/scene.h"
#include "facet/runtime/shader_compiler.h"
#include "facet/runtime/vulkan_context.h"

using namespace facet;

namespace {

struct Options {
  std::string device, shader = std::string(FACET_SOURCE_DIR) + "/examples/shaders/Instanced.shader";
  std::vector<int> counts = {10, 100, 1000, 10000, 100000};
  int frames = 20;
  bool validation = false;
};

double median(std::vector<double> v) {
  if (v.empty()) return 0;
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

// The process's resident memory, in bytes (VmRSS of /proc/self/status).
double resident_bytes() {
  std::ifstream status("/proc/self/status");
  std::string line;
  while (std::getline(status, line)) {
    if (line.rfind("VmRSS:", 0) == 0) return std::stod(line.substr(6)) * 1024;
  }
  return 0;
}

// `count` small cubes in a square grid facing the camera, each with its own
// _Color, one directional light: one ForwardBase draw per object, or per
// 128 objects with `instancing`.
runtime::Scene grid_scene(const std::string& shader, int count, bool instancing) {
  runtime::Scene scene;
  scene.path = fmt::format("grid of {}", count);
  scene.width = 160;
  scene.height = 120;
  scene.camera.transform.position = {0, 0, -12};
  scene.camera.transform.look_at = runtime::Vec3{0, 0, 0};
  scene.camera.fov = 45;
  runtime::SceneLight sun;
  sun.json_path = "lights[0]";
  sun.transform.rotation = {40, -30, 0};
  scene.lights.push_back(sun);
  const int side = int(std::ceil(std::sqrt(double(count))));
  const float step = 10.0f / float(side);
  scene.objects.reserve(size_t(count));
  for (int i = 0; i < count; ++i) {
    runtime::SceneObject o;
    o.json_path = fmt::format("objects[{}]", i);
    o.mesh = "cube";
    o.transform.position = {(float(i % side) - float(side - 1) / 2) * step,
                            (float(i / side) - float(side - 1) / 2) * step, 0};
    o.transform.rotation = {30, 45, 0};
    o.transform.scale = {step * 0.6f, step * 0.6f, step * 0.6f};
    o.material.shader = shader;
    o.material.json_path = o.json_path + ".material";
    o.material.instancing = instancing;
    const float phase = float(i) * 0.07f;
    o.material.properties.push_back({.name = "_Color",
                                     .json_path = o.material.json_path + ".properties._Color",
                                     .numbers = {0.5f + 0.5f * std::sin(phase), 0.5f + 0.5f * std::sin(phase + 2.1f),
                                                 0.5f + 0.5f * std::sin(phase + 4.2f), 1}});
    scene.objects.push_back(std::move(o));
  }
  return scene;
}

struct Row {
  int objects = 0;
  size_t draws = 0;
  double facet_cpu_us = 0, bare_cpu_us = 0;  // per draw
  double facet_frame_ms = 0, bare_frame_ms = 0;
  double kb_per_object = 0;
  double growth_bytes = 0;  // of resident memory, the whole render
  double heap_bytes = 0;    // of malloc's bytes in use (facet's and the driver's allocations)
};

Result<Row, std::string> measure(runtime::Context& context, const Options& o, int count, bool instancing) {
  const runtime::Scene scene = grid_scene(o.shader, count, instancing);
  auto shaders = runtime::make_shader_store();
  runtime::RenderOptions render{.shader_compiler = runtime::make_shader_compiler(), .shaders = shaders};
  // Compiled once into the store, so that the measured renders load nothing.
  if (auto warm = bench::render_scene(context, grid_scene(o.shader, 1, instancing), render); !warm) {
    return unexpected(warm.error());
  }
  Row row{.objects = count};
  // Memory: facet's render alone, sampled at its last frame.
  const double before = resident_bytes();
  const double heap_before = double(mallinfo2().uordblks);
  double during = before, heap_during = heap_before;
  render.frames = 3;
  render.after_frame = [&](int f) {
    if (f != render.frames - 1) return;
    during = resident_bytes();
    heap_during = double(mallinfo2().uordblks);
  };
  if (auto r = bench::render_scene(context, scene, render); !r) return unexpected(r.error());
  row.growth_bytes = std::max(0.0, during - before);
  row.heap_bytes = std::max(0.0, heap_during - heap_before);
  row.kb_per_object = row.growth_bytes / 1024 / count;
  // The bare loop draws facet's first frame, captured.
  runtime::FrameCapture capture;
  render.frames = 1;
  render.after_frame = nullptr;
  render.capture = &capture;
  auto first = bench::render_scene(context, scene, render);
  if (!first) return unexpected(first.error());
  row.draws = capture.draws.size();
  bench::BareRenderer bare(context, capture);
  FACET_TRY(bare.prepare());
  // Timing: facet's repeated frames, each followed by a bare frame.
  std::vector<double> bare_cpu, bare_frame;
  std::optional<std::string> bare_failed;
  render.capture = nullptr;
  render.frames = o.frames + 1;  // the first writes every draw's descriptors: not timed
  render.after_frame = [&](int f) {
    auto frame = bare.render_frame();
    if (!frame) bare_failed = frame.error();
    if (!frame || f == 0) return;
    bare_cpu.push_back(frame->cpu_ms);
    bare_frame.push_back(frame->host_ms);
  };
  auto timed = bench::render_scene(context, scene, render);
  if (!timed) return unexpected(timed.error());
  if (bare_failed) return unexpected(*bare_failed);
  const runtime::RenderStats& st = timed->stats;
  std::vector<double> facet_cpu(st.frame_cpu_ms.begin() + 1, st.frame_cpu_ms.end());
  std::vector<double> facet_frame(st.frame_ms.begin() + 1, st.frame_ms.end());
  row.facet_cpu_us = median(facet_cpu) * 1000 / double(row.draws);
  row.bare_cpu_us = median(bare_cpu) * 1000 / double(row.draws);
  row.facet_frame_ms = median(facet_frame);
  row.bare_frame_ms = median(bare_frame);
  return row;
}

struct RendererRow {
  int objects = 0;
  double repeated_us = 0, updated_us = 0;  // per draw
  uint64_t created = 0;                    // GPU objects made by the timed frames
};

// Every object's colour, moved along by `frame`.
void recolour(runtime::Scene& scene, int frame) {
  for (size_t i = 0; i < scene.objects.size(); ++i) {
    const float phase = float(i) * 0.07f + float(frame) * 0.3f;
    scene.objects[i].material.properties[0].numbers = {0.5f + 0.5f * std::sin(phase), 0.5f + 0.5f * std::cos(phase),
                                                       0.5f, 1};
  }
}

Result<RendererRow, std::string> measure_renderer(runtime::Context& context, const Options& o, int count) {
  runtime::Scene scene = grid_scene(o.shader, count, false);
  auto renderer = bench::create_renderer(context, {.shader_compiler = runtime::make_shader_compiler()});
  if (!renderer) return unexpected(renderer.error());
  runtime::RenderedFrame frame;
  const runtime::FrameOptions loop{.records = false, .read_back = false};
  // The host's part of one render call: the call less its wait for the GPU.
  auto host_ms = [&]() -> Result<double, std::string> {
    auto start = std::chrono::steady_clock::now();
    if (auto r = bench::render(**renderer, scene, frame, loop); !r) return unexpected(r.error());
    double call = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    return call - (frame.stats.frame_ms[0] - frame.stats.frame_cpu_ms[0]);
  };
  auto created = [&] {
    const runtime::RenderStats& s = frame.stats;
    return s.pipelines + s.meshes_loaded + s.textures_loaded + s.descriptor_pools_created + s.uniform_buffers_created;
  };
  // Prepared, then updated once: the frames after make nothing new.
  for (int warm = 0; warm < 2; ++warm) {
    recolour(scene, warm);
    FACET_TRY(host_ms());
  }
  RendererRow row{.objects = count};
  std::vector<double> repeated, updated;
  for (int f = 0; f < o.frames; ++f) {
    auto ms = host_ms();
    if (!ms) return unexpected(ms.error());
    if (frame.stats.frame_path != runtime::FramePath::repeated) return unexpected(std::string("not a repeated frame"));
    repeated.push_back(*ms);
    row.created += created();
  }
  for (int f = 0; f < o.frames; ++f) {
    recolour(scene, f + 2);
    auto ms = host_ms();
    if (!ms) return unexpected(ms.error());
    if (frame.stats.frame_path != runtime::FramePath::updated) {
      return unexpected("not an updated frame: " + frame.stats.prepared_because);
    }
    updated.push_back(*ms);
    row.created += created();
  }
  row.repeated_us = median(repeated) * 1000 / double(frame.stats.draws);
  row.updated_us = median(updated) * 1000 / double(frame.stats.draws);
  return row;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"facet's CPU time per draw and host memory per object, 10 to 100,000 objects, against a bare Vulkan loop",
               "facet_scaling_bench"};
  Options o;
  app.add_option("--device", o.device, "Vulkan device: index or name part (default: lavapipe)");
  app.add_option("--counts", o.counts, "object counts")->delimiter(',')->check(CLI::Range(1, 10000000));
  app.add_option("--frames", o.frames, "timed frames per count")->check(CLI::Range(1, 100000));
  app.add_option("--shader", o.shader, "the objects' shader (.shader or .facetpkg)");
  app.add_flag("--validation", o.validation, "enable the validation layer; any message fails the run");
  CLI11_PARSE(app, argc, argv);
  auto context = runtime::create_context({.device = o.device, .validation = o.validation});
  if (!context) {
    std::cerr << "facet_scaling_bench: " << runtime::describe(context.error()) << "\n";
    return 1;
  }
  std::cout << fmt::format("device: {}\nshader: {}\n{} timed frames per count, medians; CPU = the host's work per frame "
                           "without the wait, per draw\n\n",
                           runtime::describe((*context)->device_info()), o.shader, o.frames);
  std::vector<Row> rows[2];
  for (bool instancing : {false, true}) {
    std::cout << (instancing ? "\nGPU instancing (up to 128 objects a draw)\n" : "separate draws\n");
    std::cout << fmt::format("{:>8} {:>8} {:>14} {:>13} {:>11} {:>14} {:>13} {:>11} {:>13} {:>12}\n", "objects", "draws",
                             "facet CPU µs", "bare CPU µs", "facet/bare", "facet frame ms", "bare frame ms",
                             "host KB/obj", "KB/obj added", "heap KB/obj");
    for (int count : o.counts) {
      auto row = measure(**context, o, count, instancing);
      if (!row) {
        std::cerr << fmt::format("{} objects: {}\n", count, row.error());
        return 1;
      }
      // What each object added to memory since the previous count: the
      // per-object cost without the fixed part (pipelines, the driver).
      std::string added = "";
      if (const std::vector<Row>& done = rows[instancing]; !done.empty()) {
        added = fmt::format("{:.2f}", (row->growth_bytes - done.back().growth_bytes) / 1024 /
                                          double(row->objects - done.back().objects));
      }
      std::cout << fmt::format("{:>8} {:>8} {:>14.3f} {:>13.3f} {:>11.2f} {:>14.3f} {:>13.3f} {:>11.2f} {:>13} {:>12.2f}\n",
                               row->objects, row->draws, row->facet_cpu_us, row->bare_cpu_us,
                               row->facet_cpu_us / row->bare_cpu_us, row->facet_frame_ms, row->bare_frame_ms,
                               row->kb_per_object, added, row->heap_bytes / 1024 / row->objects)
                << std::flush;
      rows[instancing].push_back(*row);
    }
  }
  std::cout << "\nper object: facet's CPU µs drawn separately / instanced\n";
  std::cout << fmt::format("{:>8} {:>12} {:>12} {:>8}\n", "objects", "separate", "instanced", "ratio");
  for (size_t i = 0; i < rows[0].size(); ++i) {
    auto per_object = [](const Row& r) { return r.facet_cpu_us * double(r.draws) / double(r.objects); };
    double separate = per_object(rows[0][i]), instanced = per_object(rows[1][i]);
    std::cout << fmt::format("{:>8} {:>12.3f} {:>12.3f} {:>7.1f}x\n", rows[0][i].objects, separate, instanced,
                             separate / instanced);
  }
  std::cout << "\nan engine's loop through one Renderer, separate draws: host µs per draw of a whole render call "
               "(no wait, no read-back)\n";
  std::cout << fmt::format("{:>8} {:>14} {:>14} {:>22}\n", "objects", "repeated µs", "updated µs",
                           "GPU objects created");
  for (int count : o.counts) {
    auto row = measure_renderer(**context, o, count);
    if (!row) {
      std::cerr << fmt::format("{} objects, Renderer: {}\n", count, row.error());
      return 1;
    }
    std::cout << fmt::format("{:>8} {:>14.3f} {:>14.3f} {:>22}\n", row->objects, row->repeated_us, row->updated_us,
                             row->created)
              << std::flush;
  }
  if (o.validation && !(*context)->messages().empty()) {
    std::cerr << "the validation layer reported:\n" << (*context)->messages_text();
    return 1;
  }
  return 0;
}
