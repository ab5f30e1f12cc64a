// facetc --report: the variant report of every input (files or folders of
// .shader files), with material manifests for the material rung.
#pragma once

#include <nlohmann/json.hpp>

#include "args.h"
#include "facet/compiler.h"
#include "run.h"
#include "variant_collection.h"

namespace facet::tools {

// A material as a manifest lists it (docs/reports.md).
struct ManifestMaterial {
  std::string name;
  std::string shader;                 // the Shader "..." name it uses
  std::vector<std::string> keywords;  // explicit keywords
  std::vector<variants::PropertyValue> properties;
};

// Reads a manifest; problems are diagnostics located in `sources`.
Result<std::vector<ManifestMaterial>> read_material_manifest(const std::string& path, SourceMap& sources,
                                                             Diagnostics& diags);

// The stripping inputs of a run: --materials manifests, --strip filters and
// --variants collections.
struct StripInputs {
  std::optional<std::vector<ManifestMaterial>> materials;  // nullopt without --materials
  variants::StripFilter filter;
  std::optional<VariantCollection> collection;  // nullopt without --variants
};

// The keyword lists of the manifest materials that use `shader` (explicit
// keywords plus those their property values imply).
std::vector<variants::KeywordList> material_keywords(const std::vector<ManifestMaterial>& materials,
                                                     const ir::Shader& shader);

// Compile options with the stripping inputs applied for `shader`.
CompileOptions stripped_options(CompileOptions options, const StripInputs& strip, const ir::Shader& shader);

// Prints diagnostics as the run asks (text now, or into the JSON array).
void show_diagnostics(const FacetcArgs& args, const Diagnostics& raw, const SourceMap& sources, Console& console,
                      nlohmann::json& json_diagnostics);

int run_report(const FacetcArgs& args, const Compiler& compiler, const StripInputs& strip, Console& console,
               nlohmann::json& json_diagnostics);

}  // namespace facet::tools
