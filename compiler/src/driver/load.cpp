// Compiler::load*: text in, validated ShaderIr out.
#include "driver/files.h"
#include "facet/compiler.h"
#include "facet/sema.h"
#include "facet/shaderlab.h"

namespace facet {

Result<ir::Shader> Compiler::load(const std::string& path, SourceMap& sources, Diagnostics& diags) const {
  auto text = read_text_file(path, kMaxShaderBytes, diags);
  FACET_TRY(text);
  return load_source(path, std::move(*text), sources, diags);
}

Result<ir::Shader> Compiler::load_source(const std::string& path, std::string text, SourceMap& sources,
                                         Diagnostics& diags) const {
  FileId file = sources.add_file(path, std::move(text));
  auto ast = shaderlab::parse(file, sources, {}, diags);
  FACET_TRY(ast);
  return sema::analyze(*ast, sources, {}, diags);
}

}  // namespace facet
