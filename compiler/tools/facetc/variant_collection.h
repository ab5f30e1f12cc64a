// facetc --variants FILE: a variant collection, Unity's ShaderVariantCollection
// as JSON: the exact pass x keyword sets to build, per shader. `facet render
// --emit-variants` writes one with every variant a scene draws.
//
//   {"shaders": [{"shader": "Examples/PhongMultiLight",
//                 "source": "shaders/PhongMultiLight.shader",   (optional)
//                 "passes": [{"pass": 1, "name": "FORWARD_DELTA", "variants": [["POINT"], ["SPOT"]]}]}]}
#pragma once

#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "facet/compiler.h"

namespace facet::tools {

struct CollectedPass {
  std::string name;                              // "" when the collection gives none
  std::set<std::vector<std::string>> variants;  // each keyword set sorted
};

// Shader name ("Shader" line) -> pass index in its SubShader -> variants.
struct VariantCollection {
  std::map<std::string, std::map<size_t, CollectedPass>> shaders;
  std::map<std::string, std::string> sources;  // shader name -> the .shader it was drawn from, where given
};

Result<VariantCollection> read_variant_collection(const std::string& path, SourceMap& sources, Diagnostics& diags);

// Why `shader` cannot be built from `collection` (it is not listed, or a
// listed pass is not its pass of that index and name), or nullopt.
std::optional<std::string> collection_problem(const VariantCollection& collection, const ir::Shader& shader);

// Builds only the collection's passes of `shader` and, of each, only the
// listed keyword sets.
void apply_collection(CompileOptions& options, const VariantCollection& collection, const ir::Shader& shader);

}  // namespace facet::tools
