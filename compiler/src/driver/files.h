#pragma once

#include <cstdint>
#include <string>

#include "facet/diagnostics.h"
#include "facet/result.h"

namespace facet {

inline constexpr uint64_t kMaxShaderBytes = 64ull << 20;

// Reads a whole file; refuses directories and files over `max_bytes`.
Result<std::string> read_text_file(const std::string& path, uint64_t max_bytes, Diagnostics& diags);

}  // namespace facet
