// facet render scene.json -o out.png [--exr out.exr] [--width W --height H]
//   [--device SEL] [--stats] [--frames N] [--explain] [--validation] [--cache DIR] [--depfile FILE]
//   [--emit-variants FILE]
#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <algorithm>
#include <filesystem>
#include <optional>
#include <ostream>
#include <set>

#include "facet/commands.h"
#include "facet/runtime/renderer.h"
#include "facet/runtime/scene_inputs.h"
#include "facet/runtime/shader_compiler.h"
#include "facet/runtime/vulkan_context.h"
#include "facet/support/atomic_file.h"
#include "facet/support/make_rule.h"

namespace facet::tool {
namespace {

struct RenderArgs {
  std::string scene, png, exr, device, cache, depfile, variants, packages;
  std::vector<std::string> include_dirs, shader_dirs;
  int width = 0, height = 0, frames = 1;
  bool stats = false, explain = false, validation = false, strict_variants = false;
};

void print_stats(std::ostream& out, const runtime::RenderedFrame& f, const runtime::Context& context) {
  std::string gpu = f.stats.gpu_ms ? fmt::format("{:.3f} ms", *f.stats.gpu_ms) : std::string("n/a (no timestamps)");
  out << fmt::format("device: {}\n", runtime::describe(context.device_info()));
  out << fmt::format("frame: {}x{}, GPU time {}, total {:.1f} ms (shader load + compile {:.1f} ms)\n", f.width, f.height,
                     gpu, f.stats.total_ms, f.stats.compile_ms);
  out << fmt::format("draws: {} ({} additive), triangles: {}, pipelines: {}, variants compiled: {}, shaders: {}, "
                     "textures from files: {}\n",
                     f.stats.draws, f.stats.additive_draws, f.stats.triangles, f.stats.pipelines,
                     f.stats.variants_compiled, f.stats.shaders_loaded, f.stats.textures_loaded);
  if (f.stats.shadow_maps || f.stats.depth_texture_draws) {
    out << fmt::format("shadow maps: {} ({} caster draws), camera depth texture: {} draws, screen-space shadow "
                       "masks: {}\n",
                       f.stats.shadow_maps, f.stats.shadow_draws, f.stats.depth_texture_draws,
                       f.stats.screen_shadow_masks);
  }
  if (f.stats.gbuffer_draws) {
    out << fmt::format("deferred: {} G-buffer draws, {} light draws\n", f.stats.gbuffer_draws, f.stats.deferred_lights);
  }
  if (f.stats.grabs) out << fmt::format("GrabPass copies of the screen: {}\n", f.stats.grabs);
  if (f.stats.frame_ms.size() > 1) {
    std::vector<double> host = f.stats.frame_ms, gpu_frames = f.stats.frame_gpu_ms;
    std::sort(host.begin(), host.end());
    std::sort(gpu_frames.begin(), gpu_frames.end());
    out << fmt::format("frames: {}, frame time median {:.3f} ms (min {:.3f}, max {:.3f})", host.size(),
                       host[host.size() / 2], host.front(), host.back());
    if (!gpu_frames.empty()) out << fmt::format(", GPU median {:.3f} ms", gpu_frames[gpu_frames.size() / 2]);
    out << "\n";
  }
  for (const std::string& v : f.compiled) out << "  compiled: " << v << "\n";
}

// The make rule of the image: the scene, its meshes, textures, environment
// and shaders, and every file the shaders included (what a build system
// re-renders on).
std::string depfile_rule(const RenderArgs& a, const runtime::Scene& scene, const runtime::RenderedFrame& frame) {
  std::set<std::string> deps(frame.shader_files.begin(), frame.shader_files.end());
  for (const runtime::SceneInput& input : runtime::scene_inputs(a.scene, scene)) deps.insert(input.path);
  return make_rule(a.png.empty() ? a.exr : a.png, {deps.begin(), deps.end()});
}

// --packages: each .shader the scene names is drawn from DIR/<its stem>.facetpkg
// where that package exists (as `facetc --scene` or `--out-dir` name them).
void use_packages(runtime::Scene& scene, const std::string& dir) {
  auto swap = [&](runtime::SceneMaterial& material) {
    std::filesystem::path path(material.shader);
    if (path.extension() != ".shader") return;
    std::filesystem::path package = std::filesystem::path(dir) / path.stem();
    package += ".facetpkg";
    std::error_code ec;
    if (std::filesystem::is_regular_file(package, ec)) material.shader = package.string();
  };
  for (runtime::SceneObject& o : scene.objects) swap(o.material);
  for (runtime::ScenePostEffect& p : scene.post) swap(p.material);
}

int run(const RenderArgs& a, std::ostream& out, std::ostream& err) {
  if (a.png.empty() && a.exr.empty()) {
    err << "facet render: nothing to write: give -o out.png and/or --exr out.exr\n";
    return 1;
  }
  SourceMap sources;
  Diagnostics diags;
  auto scene = runtime::load_scene(a.scene, sources, diags);
  if (!scene) {
    err << render_text(diags, sources);
    return 1;
  }
  if (!a.packages.empty()) use_packages(*scene, a.packages);
  if (auto clash = runtime::output_clash("facet render", {a.png, a.exr, a.depfile, a.variants},
                                          runtime::scene_inputs(a.scene, *scene))) {
    err << *clash << "\n";
    return 1;
  }
  if (!a.variants.empty()) {
    // A package's passes are numbered in the package, which skips what the
    // build left out: only a .shader gives the SubShader's indices facetc reads.
    for (const runtime::SceneInput& input : runtime::scene_inputs(a.scene, *scene)) {
      if (input.what == "a shader of the scene" && input.path.ends_with(".facetpkg")) {
        err << fmt::format("facet render: error: --emit-variants needs the scene's .shader files, not the package "
                           "'{}' (a package's pass numbers are not its SubShader's); nothing was written\n",
                           input.path);
        return 1;
      }
    }
  }
  auto context = runtime::create_context({.device = a.device, .validation = a.validation});
  if (!context) {
    err << "facet render: " << runtime::describe(context.error()) << "\n";
    return 1;
  }
  auto frame = runtime::render_scene(**context, *scene,
                                     {.width = a.width, .height = a.height,
                                      .shader_compiler = runtime::make_shader_compiler(
                                          {.cache_dir = a.cache,
                                           .include_dirs = a.include_dirs,
                                           .shader_dirs = a.shader_dirs}),
                                      .frames = a.frames, .strict_variants = a.strict_variants},
                                     sources, diags);
  if (!frame) {
    err << render_text(diags, sources);
    return 1;
  }
  for (const std::string& miss : frame->variant_misses) err << "facet render: warning: " << miss << "\n";
  // The shaders' includes and the shaders a UsePass or Fallback named are
  // known only now: no output may replace one of them either.
  std::vector<runtime::SceneInput> read = runtime::scene_inputs(a.scene, *scene);
  for (const std::string& file : frame->shader_files) read.push_back({file, "a file a shader of the scene read"});
  if (auto clash = runtime::output_clash("facet render", {a.png, a.exr, a.depfile, a.variants}, read)) {
    err << *clash << "\n";
    return 1;
  }
  std::string rule = a.depfile.empty() ? std::string() : depfile_rule(a, *scene, *frame);
  if (a.explain) out << runtime::explain_text(*frame);
  if (a.stats) print_stats(out, *frame, **context);
  if (!a.png.empty()) {
    if (!runtime::write_png(*frame, a.png, diags)) {
      err << render_text(diags, sources);
      return 1;
    }
  }
  if (!a.exr.empty()) {
    if (!runtime::write_exr(*frame, a.exr, diags)) {
      err << render_text(diags, sources);
      return 1;
    }
  }
  if (!a.variants.empty()) {
    std::vector<std::string> scene_shaders;
    for (const runtime::SceneInput& input : runtime::scene_inputs(a.scene, *scene)) {
      if (input.what == "a shader of the scene") scene_shaders.push_back(input.path);
    }
    if (auto w = support::write_file_atomically(a.variants, runtime::variant_collection_json(*frame, scene_shaders)); !w) {
      err << fmt::format("facet render: error: cannot write the variant collection '{}': {}\n", a.variants, w.error());
      return 1;
    }
  }
  if (!rule.empty()) {
    if (auto w = support::write_file_atomically(a.depfile, rule); !w) {
      err << fmt::format("facet render: error: cannot write the depfile '{}': {}\n", a.depfile, w.error());
      return 1;
    }
  }
  if (a.validation && !(*context)->messages().empty()) {
    err << "facet render: the validation layer reported:\n" << (*context)->messages_text();
    return 1;
  }
  return 0;
}

}  // namespace

int render_command(int argc, const char* const* argv, std::ostream& out, std::ostream& err) {
  CLI::App app{"Render a JSON scene (docs/scene-format.md) with Unity's forward passes", "facet render"};
  RenderArgs a;
  app.add_option("scene", a.scene, "the scene file")->required();
  app.add_option("-o,--output", a.png, "PNG output (tone-mapped, sRGB)");
  app.add_option("--exr", a.exr, "EXR output (linear HDR, exposure applied)");
  app.add_option("--width", a.width, "override the scene's width")->check(CLI::Range(1, 16384));
  app.add_option("--height", a.height, "override the scene's height")->check(CLI::Range(1, 16384));
  app.add_option("--device", a.device, "Vulkan device: index or name part (default: lavapipe)");
  app.add_option("--cache", a.cache, "compile cache folder");
  app.add_flag("--stats", a.stats, "print GPU time and counts");
  app.add_option("--frames", a.frames, "render the frame N times after compiling once; --stats prints the median frame time")
      ->check(CLI::Range(1, 100000));
  app.add_option("-I,--include-dir", a.include_dirs, "add a folder to the #include search path of the scene's shaders");
  app.add_option("--shader-dir", a.shader_dirs,
                 "a folder searched (with its subfolders) for the .shader a package was built from, by the shader's "
                 "name: a variant the package lacks is compiled from it on demand (not with --strict-variants)")
      ->check(CLI::ExistingDirectory);
  app.add_option("--packages", a.packages,
                 "draw each .shader the scene names from the package of the same name in this folder, where one "
                 "exists (as facetc --scene --out-dir builds them)")
      ->check(CLI::ExistingDirectory);
  app.add_option("--emit-variants", a.variants,
                 "also write the variant collection of the frame (JSON: every pass and keyword set drawn, per shader) "
                 "for facetc --variants");
  app.add_option("--depfile", a.depfile, "also write a make rule of every file the render read (scene, meshes, textures, shaders, includes)");
  app.add_flag("--explain", a.explain, "list every draw with its pass, variant keywords and why");
  app.add_flag("--strict-variants", a.strict_variants,
               "a draw whose keywords have no exact variant in a shader's package is an error");
  app.add_flag("--validation", a.validation, "enable the Vulkan validation layer; any message fails the run");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    int code = app.exit(e, out, err);
    return code == 0 ? 0 : 1;
  }
  return run(a, out, err);
}

}  // namespace facet::tool
