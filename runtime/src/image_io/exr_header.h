// OpenEXR's header walk, done before OpenImageIO opens the file: OpenEXR
// allocates each attribute's value at the size the header declares, so a
// 600-byte file declaring a 1.7 GB attribute makes it allocate 1.7 GB before
// it finds that the file ends. The walk reads only names and sizes and skips
// the values.
#pragma once

#include <cstdint>
#include <istream>
#include <optional>
#include <string>

namespace facet::runtime {

// True when `file` starts with OpenEXR's magic number.
bool is_exr(std::istream& file);

// Why the EXR header in `file` (of `file_size` bytes, read from its start)
// cannot be right, or nullopt when every attribute of every part's header
// fits in the file: a negative size, a value running past the end, a name
// without its terminating NUL within OpenEXR's length limit.
std::optional<std::string> exr_header_problem(std::istream& file, uint64_t file_size);

}  // namespace facet::runtime
