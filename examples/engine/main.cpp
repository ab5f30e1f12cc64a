// An engine's render loop over facet::runtime, the runtime without the
// compiler: it loads a package that facetc built, places a grid of objects,
// and on every frame changes each object's colour and turns a keyword on or
// off, then writes the last frame.
//
//   facet_engine PACKAGE OUT.png [--objects N] [--frames F] [--validation]
//
// The package must be of examples/shaders/Keywords.shader (its _Color,
// _EmissionColor and _EMISSION). Variants are selected strictly: a keyword
// set the package lacks is an error. One Renderer draws every frame: it
// keeps the package, meshes, targets, pipelines, descriptor pools and
// uniform buffers, and updates the kept frame for each frame's changes; it
// prints what the frames after the first created.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "facet/runtime/renderer.h"
#include "facet/runtime/scene.h"
#include "facet/runtime/vulkan_context.h"

namespace {

using namespace facet::runtime;

struct Args {
  std::string package, out;
  int objects = 1000, frames = 300;
  bool validation = false;
};

bool parse(int argc, char** argv, Args& a) {
  std::vector<std::string> positional;
  for (int i = 1; i < argc; ++i) {
    std::string arg = argv[i];
    if (arg == "--validation") {
      a.validation = true;
    } else if ((arg == "--objects" || arg == "--frames") && i + 1 < argc) {
      int value = std::atoi(argv[++i]);
      if (value < 1) return false;
      (arg == "--objects" ? a.objects : a.frames) = value;
    } else {
      positional.push_back(arg);
    }
  }
  if (positional.size() != 2) return false;
  a.package = positional[0];
  a.out = positional[1];
  return true;
}

// A square grid of small cubes facing a camera, lit by one directional light.
Scene grid_scene(const std::string& package, int objects) {
  Scene scene;
  scene.path = "examples/engine";
  scene.width = 160;
  scene.height = 120;
  scene.camera.transform.position = {0, 0, -12};
  scene.camera.transform.look_at = Vec3{0, 0, 0};
  scene.camera.fov = 45;
  scene.camera.clear_color = {0.05f, 0.05f, 0.08f, 1};
  SceneLight sun;
  sun.json_path = "lights[0]";
  sun.transform.rotation = {40, -30, 0};
  scene.lights.push_back(sun);
  const int side = int(std::ceil(std::sqrt(double(objects))));
  const float step = 10.0f / float(side);
  for (int i = 0; i < objects; ++i) {
    SceneObject o;
    o.json_path = "objects[" + std::to_string(i) + "]";
    o.mesh = "cube";
    o.transform.position = {(float(i % side) - float(side - 1) / 2) * step, (float(i / side) - float(side - 1) / 2) * step, 0};
    o.transform.rotation = {30, 45, 0};
    o.transform.scale = {step * 0.6f, step * 0.6f, step * 0.6f};
    o.material.shader = package;
    o.material.json_path = o.json_path + ".material";
    scene.objects.push_back(std::move(o));
  }
  return scene;
}

SceneProperty property(const SceneObject& o, const std::string& name, std::vector<float> numbers) {
  return SceneProperty{.name = name, .json_path = o.material.json_path + ".properties." + name, .numbers = std::move(numbers)};
}

// What frame `frame` changes: every object's colour, and _EMISSION on for
// the objects of one diagonal band that moves along the grid.
void animate(Scene& scene, int frame) {
  scene.time = float(frame) / 60;
  for (size_t i = 0; i < scene.objects.size(); ++i) {
    SceneObject& o = scene.objects[i];
    const float phase = float(i) * 0.07f + float(frame) * 0.05f;
    o.material.properties = {property(o, "_Color", {0.5f + 0.5f * std::sin(phase), 0.5f + 0.5f * std::sin(phase + 2.1f),
                                                    0.5f + 0.5f * std::sin(phase + 4.2f), 1})};
    o.material.keywords.clear();
    if ((i + size_t(frame)) % 7 == 0) {
      o.material.keywords.push_back("_EMISSION");
      o.material.properties.push_back(property(o, "_EmissionColor", {0.8f, 0.7f, 0.2f, 1}));
    }
  }
}

}  // namespace

int main(int argc, char** argv) {
  Args args;
  if (!parse(argc, argv, args)) {
    std::fprintf(stderr, "usage: facet_engine PACKAGE OUT.png [--objects N] [--frames F] [--validation]\n");
    return 2;
  }
  auto context = create_context({.validation = args.validation});
  if (!context) {
    std::fprintf(stderr, "facet_engine: %s\n", describe(context.error()).c_str());
    return 1;
  }
  Scene scene = grid_scene(args.package, args.objects);
  // Errors are facet's diagnostics, printed as the compiler prints them.
  facet::SourceMap sources;
  facet::Diagnostics diags;
  auto renderer = Renderer::create(**context, {.strict_variants = true}, diags);
  if (!renderer) {
    std::fputs(facet::render_text(diags, sources).c_str(), stderr);
    return 1;
  }
  RenderedFrame last;
  uint64_t compiled = 0, loaded = 0, created_after_first = 0, updated = 0;
  for (int frame = 0; frame < args.frames; ++frame) {
    animate(scene, frame);
    if (!(*renderer)->render(scene, last, {.records = false}, sources, diags)) {
      std::fprintf(stderr, "facet_engine: frame %d:\n%s", frame, facet::render_text(diags, sources).c_str());
      return 1;
    }
    const RenderStats& stats = last.stats;
    compiled += stats.variants_compiled;
    loaded += stats.shaders_loaded;
    updated += stats.frame_path == FramePath::updated;
    if (frame > 0) {
      created_after_first += stats.pipelines + stats.descriptor_pools_created + stats.uniform_buffers_created +
                             stats.meshes_loaded + stats.textures_loaded;
    }
  }
  if (!write_png(last, args.out, diags)) {
    std::fputs(facet::render_text(diags, sources).c_str(), stderr);
    return 1;
  }
  std::printf("frames: %d, objects: %d, draws in the last frame: %zu, shaders loaded: %llu, variants compiled: %llu\n",
              args.frames, args.objects, size_t(last.stats.draws), (unsigned long long)loaded,
              (unsigned long long)compiled);
  std::printf("frames updated in place: %llu, GPU objects created after the first frame: %llu\n",
              (unsigned long long)updated, (unsigned long long)created_after_first);
  if (args.validation) {
    std::printf("validation messages: %zu\n", (*context)->messages().size());
    if (!(*context)->messages().empty()) {
      std::fprintf(stderr, "%s", (*context)->messages_text().c_str());
      return 1;
    }
  }
  return 0;
}
