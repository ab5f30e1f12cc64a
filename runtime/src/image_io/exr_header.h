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

#include "image_io/image_io.h"

namespace facet::runtime {

// True when `file` starts with OpenEXR's magic number.
bool is_exr(std::istream& file);

// Why the EXR header in `file` (of `file_size` bytes, read from its start)
// cannot be right, or nullopt when every attribute of every part's header
// fits in the file: a negative size, a value running past the end, a value
// whose declared size is not what OpenEXR reads for its type (a channel
// list, a preview image, or a fixed-size type such as box2i: OpenEXR reads
// those by their own layout, so a wrong size moves its reading of the rest
// of the header away from this walk's), a name without its terminating NUL
// within OpenEXR's length limit, a
// dataWindow that is empty or larger than `limits` (OpenEXR allocates for
// the data window when the file opens, before any pixel is read), or a
// header where this walk finds no dataWindow (every header has one: OpenEXR
// read such a header otherwise, and its data window went unchecked).
std::optional<std::string> exr_header_problem(std::istream& file, uint64_t file_size, const ImageLimits& limits);

// The same for a BMP's declared size (OpenImageIO decodes RLE-compressed
// BMPs when it opens them), and its bits per pixel and compression, which
// must be a pairing BMP defines; nullopt for a file that is not a BMP.
std::optional<std::string> bmp_header_problem(std::istream& file, const ImageLimits& limits);

// The same for a GIF's logical screen (OpenImageIO's GIF reader allocates
// the canvas at that size when it opens the file: an 800-byte file
// declaring 16000 x 16000 took 1.5 GB); nullopt for a file that is not a GIF.
std::optional<std::string> gif_header_problem(std::istream& file, const ImageLimits& limits);

}  // namespace facet::runtime
