// Image files for the renderer: texture files in, PNG and EXR frames out.
// Two builds: through OpenImageIO (the default: every format it reads), or
// with -DFACET_IMAGE_IO=png through libpng alone, PNG only, for machines
// that lack OpenImageIO's ~260 shared libraries (the GPU machine of
// docs/performance.md).
#pragma once

#include <fmt/format.h>

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "facet/result.h"

namespace facet::runtime {

// What an image file may declare, checked on its header before any pixel
// is decoded: a 68-byte PNG can declare 10^6 x 10^6 pixels, and a small
// IDAT can inflate to gigabytes. Decoding keeps 16 bytes a pixel (RGBA
// floats) several times over (the file's pixels, the linear copy, the mip
// chain), so the default budget of 2^26 pixels (8192 x 8192) is about 1 GiB
// a copy. docs/runtime.md lists these limits.
struct ImageLimits {
  uint32_t max_side = 16384;                 // pixels of the wider side
  uint64_t max_pixels = uint64_t(1) << 26;  // width x height
  // Where max_side comes from, for the message: facet's own limit or, when
  // the device allows less, "this device's maxImageDimension2D".
  std::string_view side_source = "facet's limit";
};

// Why an image of these sizes (as the header declares them) is refused, or
// nullopt when it is within `limits`.
inline std::optional<std::string> image_size_problem(uint64_t width, uint64_t height, const ImageLimits& limits) {
  if (width == 0 || height == 0) return std::string("empty image");
  if (width > limits.max_side || height > limits.max_side) {
    return fmt::format("the image is {}x{} pixels; a side may have at most {} ({})", width, height, limits.max_side,
                       limits.side_source);
  }
  if (width * height > limits.max_pixels) {  // both are <= max_side, so the product fits
    return fmt::format("the image is {}x{} pixels ({} in all); at most {} are decoded (facet's pixel budget)", width,
                       height, width * height, limits.max_pixels);
  }
  return std::nullopt;
}

struct DecodedImage {
  uint32_t width = 0, height = 0;
  int channels = 0;       // floats per pixel in `pixels`
  bool floating = false;  // the file holds floating-point data (linear, not sRGB-encoded)
  std::vector<float> pixels;  // row 0 at the top; 8- and 16-bit data scaled to 0..1
};

// At most 4 channels are read (the first ones: RGBA); images over `limits`
// are refused from their header; errors give the reason only.
Result<DecodedImage, std::string> read_image_file(const std::string& path, const ImageLimits& limits = {});

// RGBA pixels, row 0 at the top, in the format `path`'s extension names;
// errors give the reason only (the caller names the file).
Result<void, std::string> write_image_file(const std::string& path, int width, int height, const uint8_t* rgba8);
Result<void, std::string> write_image_file(const std::string& path, int width, int height, const float* rgba32f);

// "OpenImageIO 2.4.7" or "libpng 1.6.39 (PNG only)", for --help and messages.
std::string image_io_name();

}  // namespace facet::runtime
