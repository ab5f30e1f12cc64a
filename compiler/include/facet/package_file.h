// A .facetpkg on disk: what an engine's runtime reads without the compiler.
#pragma once

#include <cstdint>
#include <string>

#include "facet/diagnostics.h"
#include "facet/package.h"
#include "facet/result.h"

namespace facet {

// The largest .facetpkg read.
inline constexpr uint64_t kMaxPackageBytes = 1ull << 30;

// Reads and validates a .facetpkg (at most kMaxPackageBytes); its problems
// name the file.
Result<package::Package> read_package_file(const std::string& path, Diagnostics& diags);

}  // namespace facet
