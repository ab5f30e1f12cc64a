// Bounded whole-file reads, shared by every stage that reads a user's file.
#pragma once

#include <cstdint>
#include <string>

#include "facet/diagnostics.h"
#include "facet/result.h"

namespace facet {

// Reads a whole file as bytes; refuses directories and files over `max_bytes`
// with an io_* diagnostic.
Result<std::string> read_file(const std::string& path, uint64_t max_bytes, Diagnostics& diags);

}  // namespace facet
