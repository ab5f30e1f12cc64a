#pragma once

#include <cstdint>
#include <string>

#include "facet/compiler.h"
#include "facet/diagnostics.h"
#include "facet/result.h"

namespace facet {

// Reads a whole file; refuses directories and files over `max_bytes`.
inline Result<std::string> read_text_file(const std::string& path, uint64_t max_bytes, Diagnostics& diags) {
  return read_file(path, max_bytes, diags);
}

}  // namespace facet
