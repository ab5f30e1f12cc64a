// Compiler::load*: text in, validated ShaderIr out.
#include "files.h"
#include "facet/backend.h"
#include "facet/compiler.h"
#include "facet/sema.h"
#include "facet/shaderlab.h"
#include "facet/surface.h"

namespace facet {

Result<ir::Shader> Compiler::load(const std::string& path, SourceMap& sources, Diagnostics& diags,
                                  const CompileOptions& options) const {
  auto text = read_text_file(path, kMaxShaderBytes, diags);
  FACET_TRY(text);
  return load_source(path, std::move(*text), sources, diags, options);
}

Result<ir::Shader> Compiler::load_source(const std::string& path, std::string text, SourceMap& sources,
                                         Diagnostics& diags, const CompileOptions& options) const {
  FileId file = sources.add_file(path, std::move(text));
  auto ast = shaderlab::parse(file, sources, {}, diags);
  FACET_TRY(ast);
  auto shader = sema::analyze(*ast, sources, {}, diags);
  FACET_TRY(shader);
  auto analyze = [this, &options](const ir::Shader& s, const ir::Program& program, SourceMap& sm, Diagnostics& d) {
    return backend_.analyze_program(s, program, {}, options.backend, sm, d);
  };
  auto lowered = surface::lower_surface_shaders(*shader, analyze, sources, diags);
  FACET_TRY(lowered);
  return shader;
}

}  // namespace facet
