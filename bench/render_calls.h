// The runtime's calls as the benchmarks use them: a failure ends the
// benchmark with the errors printed as facet prints them.
#pragma once

#include <memory>
#include <string>
#include <utility>

#include "facet/diagnostics.h"
#include "facet/runtime/renderer.h"
#include "facet/runtime/scene.h"

namespace facet::bench {

inline Result<runtime::Scene, std::string> load_scene(const std::string& path) {
  SourceMap sources;
  Diagnostics diags;
  Result<runtime::Scene> scene = runtime::load_scene(path, sources, diags);
  if (!scene) return unexpected(render_text(diags, sources));
  return std::move(*scene);
}

inline Result<runtime::RenderedFrame, std::string> render_scene(runtime::Context& context, const runtime::Scene& scene,
                                                                const runtime::RenderOptions& options) {
  SourceMap sources;
  Diagnostics diags;
  Result<runtime::RenderedFrame> frame = runtime::render_scene(context, scene, options, sources, diags);
  if (!frame) return unexpected(render_text(diags, sources));
  return std::move(*frame);
}

inline Result<std::unique_ptr<runtime::Renderer>, std::string> create_renderer(runtime::Context& context,
                                                                               runtime::RendererOptions options) {
  Diagnostics diags;
  Result<std::unique_ptr<runtime::Renderer>> renderer = runtime::Renderer::create(context, std::move(options), diags);
  if (!renderer) return unexpected(render_text(diags, {}));
  return std::move(*renderer);
}

inline Result<void, std::string> render(runtime::Renderer& renderer, const runtime::Scene& scene,
                                        runtime::RenderedFrame& out, const runtime::FrameOptions& options) {
  SourceMap sources;
  Diagnostics diags;
  if (!renderer.render(scene, out, options, sources, diags)) return unexpected(render_text(diags, sources));
  return {};
}

}  // namespace facet::bench
