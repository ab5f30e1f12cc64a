// facetc --report: the variant report of every input (files or folders of
// .shader files), with material manifests for the material rung.
#pragma once

#include <nlohmann/json.hpp>

#include "args.h"
#include "facet/compiler.h"
#include "run.h"

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

int run_report(const FacetcArgs& args, const Compiler& compiler, Console& console, nlohmann::json& json_diagnostics);

}  // namespace facet::tools
