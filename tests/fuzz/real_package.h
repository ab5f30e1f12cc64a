// Real compiler output for the seeds of the binary decoders (-write_seeds):
// an example shader compiled into a package, all its variants.
#pragma once

#include <cstdio>
#include <cstdlib>
#include <string>

#include "facet/compiler.h"

namespace facet::fuzz {

// Compiles `shader_path` (relative to the source tree) or aborts with the
// diagnostics: seeds come from shaders that are known to compile.
inline CompiledShader compile_example(const std::string& shader_path) {
  const std::string path = std::string(FACET_SOURCE_DIR) + "/" + shader_path;
  Compiler compiler;
  SourceMap sources;
  Diagnostics diags;
  CompileOptions options;
  options.jobs = 1;
  auto shader = compiler.load(path, sources, diags);
  if (shader) {
    auto compiled = compiler.compile(*shader, options, sources, diags);
    if (compiled) return std::move(*compiled);
  }
  std::fprintf(stderr, "%s", render_text(diags, sources).c_str());
  std::abort();
}

}  // namespace facet::fuzz
