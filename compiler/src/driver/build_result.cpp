// Compiler::open_* and build*: the step calls, with the result owning the
// source map and the messages.
#include "facet/compiler.h"

namespace facet {

std::string OpenedShader::messages(const RenderOptions& options) const { return render_text(diagnostics, sources, options); }

std::string BuildResult::messages(const RenderOptions& options) const {
  return render_text(diagnostics, sources, options);
}

std::string BuildResult::messages_json() const { return render_json(diagnostics, sources); }

OpenedShader Compiler::open_file(const std::string& path, const CompileOptions& options) const {
  OpenedShader r;
  auto shader = load(path, r.sources, r.diagnostics, options);
  if (shader) r.shader = std::move(*shader);
  return r;
}

OpenedShader Compiler::open_source(const std::string& path, std::string text, const CompileOptions& options) const {
  OpenedShader r;
  auto shader = load_source(path, std::move(text), r.sources, r.diagnostics, options);
  if (shader) r.shader = std::move(*shader);
  return r;
}

BuildResult Compiler::build(OpenedShader loaded, const CompileOptions& options) const {
  BuildResult r;
  r.sources = std::move(loaded.sources);
  r.diagnostics = std::move(loaded.diagnostics);
  if (!loaded.shader) return r;
  auto compiled = compile(*loaded.shader, options, r.sources, r.diagnostics);
  if (compiled) r.compiled = std::move(*compiled);
  return r;
}

BuildResult Compiler::build_file(const std::string& path, const CompileOptions& options) const {
  return build(open_file(path, options), options);
}

BuildResult Compiler::build_source(const std::string& path, std::string text, const CompileOptions& options) const {
  return build(open_source(path, std::move(text), options), options);
}

}  // namespace facet
