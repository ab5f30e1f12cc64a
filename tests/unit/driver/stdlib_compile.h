// Helpers for the stdlib tests: compile an in-memory .shader with the
// library API and check every SPIR-V blob of the package with spirv-val.
#pragma once

#include <gtest/gtest.h>

#include <optional>
#include <string>

#include "facet/compiler.h"

namespace facet::stdlib_test {

struct Compiled {
  bool ok = false;
  std::string log;  // diagnostics, rendered
  std::optional<CompiledShader> shader;
};

inline Compiled compile_text(const std::string& name, const std::string& text, CompileOptions options = {}) {
  Compiler compiler;
  SourceMap sources;
  Diagnostics diags;
  Compiled out;
  auto shader = compiler.load_source(name, text, sources, diags);
  if (shader) {
    auto compiled = compiler.compile(*shader, options, sources, diags);
    if (compiled && !diags.has_errors()) {
      out.ok = true;
      out.shader = std::move(*compiled);
    }
  }
  out.log = render_text(diags, sources);
  return out;
}

// Every blob of the package passes spirv-val; returns how many were checked.
inline size_t expect_valid_spirv(const package::Package& pkg) {
  for (const std::vector<uint32_t>& spirv : pkg.spirv_blobs) {
    Diagnostics check;
    SourceMap none;
    EXPECT_TRUE(backend::validate(spirv, backend::TargetEnv::vulkan1_1, check)) << render_text(check, none);
  }
  return pkg.spirv_blobs.size();
}

}  // namespace facet::stdlib_test
