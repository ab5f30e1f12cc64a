#include <OpenImageIO/imageio.h>
#include <fmt/format.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <new>
#include <vector>

#include "image_io/exr_header.h"
#include "image_io/jpeg_header.h"
#include "image_io/png_header.h"
#include "image_io/image_io.h"

namespace facet::runtime {
namespace {

Result<void, std::string> write(const std::string& path, int width, int height, OIIO::TypeDesc type, const void* pixels) {
  auto out = OIIO::ImageOutput::create(path);
  if (!out) return unexpected(std::string("no image writer for this extension"));
  OIIO::ImageSpec spec(width, height, 4, type);
  if (!out->open(path, spec) || !out->write_image(type, pixels) || !out->close()) return unexpected(out->geterror());
  return {};
}

// OpenEXR and libpng trust their headers' sizes, OpenImageIO decodes RLE
// BMPs and a JPEG's IPTC block and allocates a GIF's canvas while opening them (exr_header.h,
// png_header.h, jpeg_header.h): those headers are checked first; other
// formats go to OpenImageIO as they are.
std::optional<std::string> header_problem(const std::string& path, const ImageLimits& limits) {
  std::ifstream file(path, std::ios::binary);
  if (!file) return std::nullopt;
  std::error_code error;
  const uintmax_t size = std::filesystem::file_size(path, error);
  if (error) return std::nullopt;
  if (std::optional<std::string> problem = bmp_header_problem(file, limits)) return problem;
  file.clear();
  file.seekg(0);
  if (std::optional<std::string> problem = gif_header_problem(file, limits)) return problem;
  file.clear();
  file.seekg(0);
  if (std::optional<std::string> problem = jpeg_marker_problem(file)) return problem;
  file.clear();
  file.seekg(0);
  if (std::optional<std::string> problem = png_chunk_problem(file, size)) return problem;
  file.clear();
  file.seekg(0);
  if (!is_exr(file)) return std::nullopt;
  file.seekg(0);
  return exr_header_problem(file, size, limits);
}

Result<DecodedImage, std::string> decode(const std::string& path, const ImageLimits& limits);

}  // namespace

// OpenImageIO's readers may throw (a length_error from a corrupt file's
// declared size): any exception is a clear error, never a crash.
Result<DecodedImage, std::string> read_image_file(const std::string& path, const ImageLimits& limits) {
  if (std::optional<std::string> problem = header_problem(path, limits)) return unexpected(*problem);
  try {
    return decode(path, limits);
  } catch (const std::exception& e) {
    return unexpected(fmt::format("cannot read the image ({})", e.what()));
  }
}

namespace {

// Reads the first `image.channels` channels into `image.pixels` as floats.
// Asked for any type but the file's own (TypeDesc::UNKNOWN), OpenImageIO
// converts through a 64 MB buffer, however small the image; so the pixels
// are read in the file's type into a buffer of the image's size, and
// OpenImageIO's converter turns them into floats (the conversion it would
// have made: integers normalised to [0, 1]). Files whose channels differ in
// type take the converting read.
bool read_as_float(OIIO::ImageInput& input, DecodedImage& image) {
  const OIIO::ImageSpec& spec = input.spec();
  if (!spec.channelformats.empty()) {
    return input.read_image(0, 0, 0, image.channels, OIIO::TypeDesc::FLOAT, image.pixels.data());
  }
  if (spec.format == OIIO::TypeDesc::FLOAT) {
    return input.read_image(0, 0, 0, image.channels, OIIO::TypeDesc::UNKNOWN, image.pixels.data());
  }
  std::vector<std::byte> native;
  try {
    native.resize(image.pixels.size() * spec.format.size());
  } catch (const std::bad_alloc&) {
    return false;
  }
  if (!input.read_image(0, 0, 0, image.channels, OIIO::TypeDesc::UNKNOWN, native.data())) return false;
  return OIIO::convert_pixel_values(spec.format, native.data(), OIIO::TypeDesc::FLOAT, image.pixels.data(),
                                    int(image.pixels.size()));
}

// The reader the file's extension names, opened on the file. Not
// ImageInput::open(path): when that reader fails, it tries every reader
// OpenImageIO has (camera RAW, JPEG 2000, DICOM, FFmpeg's video formats...)
// on the same bytes, so one corrupt texture would reach every decoder the
// system has. Like Unity's importers, a texture is read as what its name says.
Result<std::unique_ptr<OIIO::ImageInput>, std::string> open_by_extension(const std::string& path) {
  const std::string extension = std::filesystem::path(path).extension().string();
  if (extension.size() < 2) return unexpected(std::string("the file name has no extension naming its image format"));
  std::unique_ptr<OIIO::ImageInput> input = OIIO::ImageInput::create(extension.substr(1));
  if (!input) {
    (void)OIIO::geterror();  // consumed: the message below says it
    return unexpected(fmt::format("no image reader for '{}' files", extension));
  }
  OIIO::ImageSpec spec;
  if (!input->open(path, spec)) {
    return unexpected(fmt::format("cannot read the image as {} ({})", input->format_name(), input->geterror()));
  }
  return input;
}

Result<DecodedImage, std::string> decode(const std::string& path, const ImageLimits& limits) {
  auto opened = open_by_extension(path);
  if (!opened) return unexpected(opened.error());
  std::unique_ptr<OIIO::ImageInput> input = std::move(*opened);
  const OIIO::ImageSpec& spec = input->spec();
  if (spec.depth > 1) return unexpected(fmt::format("the file holds a 3D image ({} slices); textures are 2D", spec.depth));
  if (spec.width <= 0 || spec.height <= 0 || spec.nchannels < 1) return unexpected(std::string("empty image"));
  if (std::optional<std::string> problem = image_size_problem(uint64_t(spec.width), uint64_t(spec.height), limits)) {
    return unexpected(*problem);
  }
  DecodedImage image{uint32_t(spec.width), uint32_t(spec.height), std::min(spec.nchannels, 4),
                     spec.format.is_floating_point()};
  try {
    image.pixels.resize(size_t(image.width) * image.height * image.channels);
  } catch (const std::bad_alloc&) {
    return unexpected(fmt::format("not enough memory to decode {}x{} pixels", image.width, image.height));
  }
  if (!read_as_float(*input, image)) return unexpected(fmt::format("cannot read the pixels ({})", input->geterror()));
  return image;
}

}  // namespace

Result<void, std::string> write_image_file(const std::string& path, int width, int height, const uint8_t* rgba8) {
  return write(path, width, height, OIIO::TypeDesc::UINT8, rgba8);
}

Result<void, std::string> write_image_file(const std::string& path, int width, int height, const float* rgba32f) {
  return write(path, width, height, OIIO::TypeDesc::FLOAT, rgba32f);
}

std::string image_io_name() { return "OpenImageIO " OIIO_VERSION_STRING; }

}  // namespace facet::runtime
