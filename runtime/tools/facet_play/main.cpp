// facet-play: renders a scene whose shaders are packages (.facetpkg, built
// offline by facetc) with the runtime alone: facet_render and facet_runtime,
// no compiler, so no glslang, SPIRV-Tools, SPIRV-Cross, TBB, curl or OpenSSL
// is linked. A scene naming a .shader is an error that names it.
//
//   facet-play scene.json -o out.png [--device SEL] [--strict-variants] [--validation]
#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <iostream>
#include <string>

#include "facet/runtime/renderer.h"
#include "facet/runtime/scene_inputs.h"
#include "facet/runtime/vulkan_context.h"

namespace {

struct PlayArgs {
  std::string scene, png, device;
  bool strict_variants = false, validation = false;
};

int play(const PlayArgs& a) {
  using namespace facet;
  SourceMap sources;
  Diagnostics diags;
  auto scene = runtime::load_scene(a.scene, sources, diags);
  if (!scene) {
    std::cerr << render_text(diags, sources);
    return 1;
  }
  if (auto clash = runtime::output_clash("facet-play", {a.png}, runtime::scene_inputs(a.scene, *scene))) {
    std::cerr << *clash << "\n";
    return 1;
  }
  auto context = runtime::create_context({.device = a.device, .validation = a.validation});
  if (!context) {
    std::cerr << "facet-play: " << runtime::describe(context.error()) << "\n";
    return 1;
  }
  auto frame = runtime::render_scene(**context, *scene, {.strict_variants = a.strict_variants}, sources, diags);
  if (!frame) {
    std::cerr << render_text(diags, sources);
    return 1;
  }
  for (const std::string& miss : frame->variant_misses) std::cerr << "facet-play: warning: " << miss << "\n";
  if (!runtime::write_png(*frame, a.png, diags)) {
    std::cerr << render_text(diags, sources);
    return 1;
  }
  if (a.validation && !(*context)->messages().empty()) {
    std::cerr << "facet-play: the validation layer reported:\n" << (*context)->messages_text();
    return 1;
  }
  std::cout << fmt::format("{}: {}x{}, {} draws, {} pipelines, variants compiled: {}\n", a.png, frame->width,
                           frame->height, frame->stats.draws, frame->stats.pipelines, frame->stats.variants_compiled);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Render a scene of packages (.facetpkg) with the runtime alone, no compiler", "facet-play"};
  PlayArgs a;
  app.add_option("scene", a.scene, "the scene file (docs/scene-format.md); its shaders must be .facetpkg")->required();
  app.add_option("-o,--output", a.png, "PNG output (tone-mapped, sRGB)")->required();
  app.add_option("--device", a.device, "Vulkan device: index or name part (default: lavapipe)");
  app.add_flag("--strict-variants", a.strict_variants,
               "a draw whose keywords have no exact variant in a package is an error");
  app.add_flag("--validation", a.validation, "enable the Vulkan validation layer; any message fails the run");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? 0 : 1;
  }
  return play(a);
}
