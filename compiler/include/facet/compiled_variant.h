// One stage program of one variant, compiled: what the backend returns, what
// the cache stores under the program's key, and what the driver assembles
// into the package. Plain data.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "facet/reflection.h"
#include "facet/stage.h"

namespace facet {

struct CompiledVariant {
  std::vector<uint32_t> spirv;
  StageReflection reflection;               // its `stage` is the program's stage
  std::vector<std::string> included_files;  // every file opened, transitively, sorted

  Stage stage() const { return reflection.stage; }
};

}  // namespace facet
