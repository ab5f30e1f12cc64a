// Compiler::load*: text in, validated ShaderIr out.
#include "files.h"
#include "facet/backend.h"
#include "facet/compiler.h"
#include "facet/sema.h"
#include "facet/shaderlab.h"
#include "facet/surface.h"
#include "link.h"

namespace facet {
namespace {

// The shader as written: parsed, checked and its surface programs lowered.
Result<ir::Shader> load_written(const backend::Backend& backend, const std::string& path, std::string text,
                                SourceMap& sources, Diagnostics& diags, const CompileOptions& options) {
  FileId file = sources.add_file(path, std::move(text));
  auto ast = shaderlab::parse(file, sources, {}, diags);
  FACET_TRY(ast);
  auto shader = sema::analyze(*ast, sources, {}, diags);
  FACET_TRY(shader);
  auto analyze = [&backend, &options](const ir::Shader& s, const ir::Program& program, SourceMap& sm, Diagnostics& d) {
    return backend.analyze_program(s, program, {}, options.backend, sm, d);
  };
  auto lowered = surface::lower_surface_shaders(*shader, analyze, sources, diags);
  FACET_TRY(lowered);
  return shader;
}

}  // namespace

Result<ir::Shader> Compiler::load(const std::string& path, SourceMap& sources, Diagnostics& diags,
                                  const CompileOptions& options) const {
  auto text = read_text_file(path, kMaxShaderBytes, diags);
  FACET_TRY(text);
  return load_source(path, std::move(*text), sources, diags, options);
}

Result<ir::Shader> Compiler::load_source(const std::string& path, std::string text, SourceMap& sources,
                                         Diagnostics& diags, const CompileOptions& options) const {
  auto shader = load_written(backend_, path, std::move(text), sources, diags, options);
  FACET_TRY(shader);
  const std::string stdlib = options.backend.stdlib_dir.empty() ? default_stdlib_dir() : options.backend.stdlib_dir;
  LoadWrittenShader load_other = [&](const std::string& other, Diagnostics& other_diags) -> Result<ir::Shader> {
    auto other_text = read_text_file(other, kMaxShaderBytes, other_diags);
    FACET_TRY(other_text);
    return load_written(backend_, other, std::move(*other_text), sources, other_diags, options);
  };
  link_shader(*shader, shader_search_dirs(path, options.backend.include_dirs, stdlib), load_other, diags);
  return shader;
}

}  // namespace facet
