// How the renderer's parts fail: with facet's Diagnostics, as the compiler's
// stages do. A span, where there is one, points into the ShaderLibrary's
// report_sources() (a shader that does not compile, a scene value);
// Renderer::render hands the diagnostics to its caller rebased into the
// caller's SourceMap.
#pragma once

#include <string>
#include <utility>

#include "facet/diagnostics.h"
#include "facet/result.h"
#include "facet/runtime/scene.h"
#include "scene/json_locate.h"

namespace facet::runtime {

// One error, as a failed Result's payload.
inline Diagnostics render_error(std::string message, DiagId id = DiagId::render_invalid, SourceSpan span = {}) {
  Diagnostics diags;
  diags.add(id, span, std::move(message));
  return diags;
}

// `diags` with a first error that says which object or pass it concerns
// ("scene.json: objects[3]: the shader does not load") before the
// diagnostics that say why.
inline Diagnostics render_error_in(std::string context, DiagId id, const Diagnostics& why) {
  Diagnostics out = render_error(std::move(context), id);
  out.append(why);
  return out;
}

// An error about the scene's value at `json_path`: located at that value in
// the scene file (read into `report`, the ShaderLibrary's report_sources())
// when the scene has one, else named by the file and the path; `why` (a
// shader's compile errors, say) follows it.
inline Diagnostics scene_error(SourceMap& report, const Scene& scene, const std::string& json_path, DiagId id,
                               const std::string& what, const Diagnostics& why = {}) {
  SourceSpan span = scene_value_span(report, scene.path, json_path);
  std::string where = span.has_location() || scene.path.empty() ? json_path : scene.path + ": " + json_path;
  Diagnostics out = render_error(where + ": " + what, id, span);
  out.append(why);
  return out;
}

}  // namespace facet::runtime
