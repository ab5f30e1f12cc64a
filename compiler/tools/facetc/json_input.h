// JSON input files of facetc (material manifests, strip filters): read with
// located errors, never an exception past this boundary.
#pragma once

#include <nlohmann/json.hpp>

#include <string>

#include "facet/compiler.h"

namespace facet::tools {

struct JsonInput {
  nlohmann::json json;
  FileId file = kNoFile;
};

// Reads and parses `path` (added to `sources`); invalid JSON is an error at
// its position, nesting over 64 levels is refused before parsing.
Result<JsonInput> read_json_input(const std::string& path, SourceMap& sources, Diagnostics& diags);

// Schema problems: the JSON path says where, since values carry no position.
struct JsonInputErrors {
  FileId file;
  Diagnostics& diags;
  bool failed = false;
  void add(const std::string& where, const std::string& what);
};

}  // namespace facet::tools
