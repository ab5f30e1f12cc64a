#include <OpenImageIO/imageio.h>
#include <fmt/format.h>

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

}  // namespace

Result<DecodedImage, std::string> read_image_file(const std::string& path) {
  auto input = OIIO::ImageInput::open(path);
  if (!input) return unexpected(fmt::format("cannot read the image ({})", OIIO::geterror()));
  const OIIO::ImageSpec& spec = input->spec();
  DecodedImage image{uint32_t(std::max(spec.width, 0)), uint32_t(std::max(spec.height, 0)), spec.nchannels,
                     spec.format.is_floating_point()};
  if (image.width == 0 || image.height == 0 || image.channels < 1) return unexpected(std::string("empty image"));
  image.pixels.resize(size_t(image.width) * image.height * image.channels);
  if (!input->read_image(0, 0, 0, image.channels, OIIO::TypeDesc::FLOAT, image.pixels.data())) {
    return unexpected(fmt::format("cannot read the pixels ({})", input->geterror()));
  }
  return image;
}

Result<void, std::string> write_image_file(const std::string& path, int width, int height, const uint8_t* rgba8) {
  return write(path, width, height, OIIO::TypeDesc::UINT8, rgba8);
}

Result<void, std::string> write_image_file(const std::string& path, int width, int height, const float* rgba32f) {
  return write(path, width, height, OIIO::TypeDesc::FLOAT, rgba32f);
}

std::string image_io_name() { return "OpenImageIO " OIIO_VERSION_STRING; }

}  // namespace facet::runtime
