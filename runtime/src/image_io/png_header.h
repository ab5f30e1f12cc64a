// A PNG's chunk walk, done before the file is decoded: libpng allocates each
// chunk's buffer at the length the chunk declares before it reads the data,
// so a 284-byte file whose tEXt chunk declares 1.1 GB made it allocate that
// much (found by fuzz_image) before finding that the file ends. The walk
// reads only lengths and types and skips the data.
#pragma once

#include <cstdint>
#include <istream>
#include <optional>
#include <string>

namespace facet::runtime {

// Why the chunks of the PNG in `file` (of `file_size` bytes, read from its
// start) cannot be right, or nullopt when each one up to IEND fits in the
// file, or `file` is not a PNG: a length over PNG's limit of 2^31 - 1, or
// data running past the end of the file. A file that ends between chunks is
// left to the decoder (it allocates nothing for it).
std::optional<std::string> png_chunk_problem(std::istream& file, uint64_t file_size);

}  // namespace facet::runtime
