// Image files for the renderer: texture files in, PNG and EXR frames out.
// Two builds: through OpenImageIO (the default: every format it reads), or
// with -DFACET_IMAGE_IO=png through libpng alone, PNG only, for machines
// that lack OpenImageIO's ~260 shared libraries (the GPU machine of
// docs/performance.md).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "facet/result.h"

namespace facet::runtime {

struct DecodedImage {
  uint32_t width = 0, height = 0;
  int channels = 0;       // floats per pixel in `pixels`
  bool floating = false;  // the file holds floating-point data (linear, not sRGB-encoded)
  std::vector<float> pixels;  // row 0 at the top; 8- and 16-bit data scaled to 0..1
};

Result<DecodedImage, std::string> read_image_file(const std::string& path);

// RGBA pixels, row 0 at the top, in the format `path`'s extension names;
// errors give the reason only (the caller names the file).
Result<void, std::string> write_image_file(const std::string& path, int width, int height, const uint8_t* rgba8);
Result<void, std::string> write_image_file(const std::string& path, int width, int height, const float* rgba32f);

// "OpenImageIO 2.4.7" or "libpng 1.6.39 (PNG only)", for --help and messages.
std::string image_io_name();

}  // namespace facet::runtime
