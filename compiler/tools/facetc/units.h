// The text outputs of one shader (-E, -S/--emit, --reflect): one unit per
// selected pass x variant x stage, each produced by the back end.
#pragma once

#include <string>

#include "args.h"
#include "facet/compiler.h"

namespace facet::tools {

struct UnitsOutput {
  std::string bytes;
  // The request matched a number of units its output form cannot hold
  // (binary SPIR-V is one module): a usage error, already in diags.
  bool usage_error = false;
};

// The compile options the arguments ask for. `one_variant_by_default`: with
// neither --keywords nor --all-variants, the variant for no keywords.
CompileOptions compile_options(const FacetcArgs& args, bool one_variant_by_default);

Result<UnitsOutput> produce_units(const FacetcArgs& args, const Compiler& compiler, const ir::Shader& shader,
                                  SourceMap& sources, Diagnostics& diags);

}  // namespace facet::tools
