// Semantic analysis: checks a parsed ShaderLab AST and lowers it into the
// ShaderIr (facet/ir.h) that every later stage reads.
//
//   auto ast = shaderlab::parse(file, sources, {}, diags);
//   if (!ast) return ...;
//   Result<ir::Shader> shader = sema::analyze(*ast, sources, {}, diags);
//
// What it does, in order: properties (types, defaults, duplicates), render
// state (values canonicalised: "lequal" -> "LEqual"; `[_Prop]` kept
// symbolic), tags (Queue checked, a SubShader-level LightMode copied into
// its passes with a warning), Category flattening, and program blocks
// (includes in scope attached, #pragma lines collected, entry points and
// shader target filled). Keyword pragmas are left for facet::variants.
#pragma once

#include <cstdint>
#include <string>

#include "facet/diagnostics.h"
#include "facet/ir.h"
#include "facet/result.h"
#include "facet/shaderlab.h"
#include "facet/source.h"

namespace facet::sema {

struct SemaOptions {
  // Copy a LightMode tag written at SubShader level into each of its passes
  // (after warning), as the book's chapter 5-6 listings expect.
  bool propagate_subshader_lightmode = true;
  // Every program copies the include blocks in its scope; a small file with a
  // large CGINCLUDE and many passes could otherwise make the IR huge. Past
  // this many bytes of program text in total, analysis fails.
  uint64_t max_program_bytes = uint64_t(1) << 28;
};

// Fails when any error was reported; warnings and notes survive a success.
Result<ir::Shader> analyze(const shaderlab::ast::Shader& shader, const SourceMap& sources,
                           const SemaOptions& options, Diagnostics& diags);

// A stable, indented JSON dump of the IR (spans as "begin-end" byte
// offsets), used by `facetc --dump=ir` and golden tests.
std::string ir_to_json(const ir::Shader& shader);

}  // namespace facet::sema
