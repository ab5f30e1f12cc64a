// Arbitrary bytes as a .shader file through the ShaderLab lexer and parser,
// semantic analysis and the variant stages (keyword spaces, counting, a
// small enumeration), then the diagnostic printers. No glslang.
#include "facet/diagnostics.h"
#include "facet/sema.h"
#include "facet/shaderlab.h"
#include "facet/source.h"
#include "facet/variants.h"
#include "fuzz_support.h"

namespace {

using namespace facet;

// A small limit, so that a pass declaring 2^40 variants costs a diagnostic,
// not the fuzzer's memory.
constexpr uint64_t kMaxVariants = 256;

void enumerate_program(const ir::Program& program, Diagnostics& diags) {
  auto space = variants::build_keyword_space(program, diags);
  if (!space) return;
  (void)variants::count_variants(*space);
  (void)variants::enumerate(*space, {.max_variants = kMaxVariants}, diags);
  (void)variants::enumerate(*space, {.stage = Stage::fragment, .max_variants = kMaxVariants}, diags);
  (void)variants::dump_keyword_space(*space);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  SourceMap sources;
  Diagnostics diags;
  FileId file = sources.add_file("fuzz.shader", std::string(fuzz::as_text(data, size)));
  auto ast = shaderlab::parse(file, sources, {}, diags);
  if (ast) {
    (void)shaderlab::ast_to_json(*ast, sources);
    auto shader = sema::analyze(*ast, sources, {}, diags);
    if (shader) {
      (void)sema::ir_to_json(*shader);
      for (const ir::SubShader& sub : shader->subshaders) {
        for (const ir::Pass& pass : sub.passes) {
          if (pass.program) enumerate_program(*pass.program, diags);
        }
        for (const ir::SurfaceProgram& sp : sub.surface_programs) enumerate_program(sp.program, diags);
      }
    }
  }
  // Every diagnostic's span is turned into line:column and a caret line.
  (void)render_text(diags, sources);
  (void)render_json(diags, sources);
  return 0;
}
