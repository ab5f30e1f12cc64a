// The PNG-only image I/O (-DFACET_IMAGE_IO=png) through libpng's simplified API.
#include <fmt/format.h>
#include <png.h>

#include <filesystem>
#include <fstream>
#include <new>

#include "image_io/image_io.h"
#include "image_io/png_header.h"

namespace facet::runtime {
namespace {

bool is_png(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  for (char& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
  return ext == ".png";
}

}  // namespace

Result<DecodedImage, std::string> read_image_file(const std::string& path, const ImageLimits& limits) {
  std::error_code error;
  const uintmax_t size = std::filesystem::file_size(path, error);
  if (std::ifstream file(path, std::ios::binary); file && !error) {
    if (std::optional<std::string> problem = png_chunk_problem(file, size)) return unexpected(*problem);
  }
  png_image png{};
  png.version = PNG_IMAGE_VERSION;
  if (!png_image_begin_read_from_file(&png, path.c_str())) {
    std::string why = png.message;
    png_image_free(&png);
    return unexpected(fmt::format("cannot read the image ({}; this build reads PNG files only)", why));
  }
  // The header is read, no pixel yet: refused here, PNG_IMAGE_SIZE (32-bit
  // arithmetic) cannot overflow and no bomb is inflated.
  if (std::optional<std::string> problem = image_size_problem(png.width, png.height, limits)) {
    png_image_free(&png);
    return unexpected(*problem);
  }
  // 8-bit RGBA whatever the file holds; libpng converts 16-bit files (which
  // it takes to be linear) to sRGB-encoded 8 bits on the way.
  png.format = PNG_FORMAT_RGBA;
  DecodedImage image{png.width, png.height, 4, false};
  std::vector<png_byte> bytes;
  try {
    bytes.resize(PNG_IMAGE_SIZE(png));
    image.pixels.resize(bytes.size());
  } catch (const std::bad_alloc&) {
    png_image_free(&png);
    return unexpected(fmt::format("not enough memory to decode {}x{} pixels", image.width, image.height));
  }
  if (!png_image_finish_read(&png, nullptr, bytes.data(), 0, nullptr)) {
    std::string why = png.message;
    png_image_free(&png);
    return unexpected(fmt::format("cannot read the pixels ({})", why));
  }
  for (size_t i = 0; i < bytes.size(); ++i) image.pixels[i] = float(bytes[i]) / 255.0f;
  return image;
}

Result<void, std::string> write_image_file(const std::string& path, int width, int height, const uint8_t* rgba8) {
  if (!is_png(path)) return unexpected(std::string("this build writes PNG files only (-DFACET_IMAGE_IO=png)"));
  png_image png{};
  png.version = PNG_IMAGE_VERSION;
  png.width = png_uint_32(width);
  png.height = png_uint_32(height);
  png.format = PNG_FORMAT_RGBA;
  if (!png_image_write_to_file(&png, path.c_str(), 0, rgba8, 0, nullptr)) {
    std::string why = png.message;
    png_image_free(&png);
    return unexpected(why);
  }
  return {};
}

Result<void, std::string> write_image_file(const std::string&, int, int, const float*) {
  return unexpected(std::string("EXR output needs OpenImageIO (this build has libpng only)"));
}

std::string image_io_name() { return "libpng " PNG_LIBPNG_VER_STRING " (PNG only)"; }

}  // namespace facet::runtime
