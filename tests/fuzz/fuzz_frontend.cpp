// Arbitrary bytes as a .shader file through the whole front end: loading
// (parse, sema, surface-shader lowering), pass and variant selection, and
// glslang's preprocessing of every stage program, which is what decides the
// distinct programs of a build (program_jobs, facet/build_farm.h). Nothing is compiled
// to SPIR-V. #include reads regular files only: the shader is named inside
// the target's empty temporary folder, so relative includes find nothing
// but the stdlib.
#include "facet/build_farm.h"
#include "facet/compiler.h"
#include "fuzz_support.h"

namespace {

using namespace facet;

const Compiler& compiler() {
  static const Compiler instance;  // glslang's process initialisation, once
  return instance;
}

CompileOptions fuzz_options() {
  CompileOptions options;
  // A small limit: a large variant space is refused with a diagnostic, and
  // each input preprocesses a bounded number of programs.
  options.max_variants_per_pass = 16;
  options.jobs = 1;
  return options;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static const CompileOptions options = fuzz_options();
  static const std::string path = fuzz::TempDir::get().file("fuzz.shader");
  SourceMap sources;
  Diagnostics diags;
  auto shader = compiler().load_source(path, std::string(fuzz::as_text(data, size)), sources, diags, options);
  if (shader) (void)facet::program_jobs(compiler(), *shader, options, sources, diags);
  (void)render_text(diags, sources);
  return 0;
}
