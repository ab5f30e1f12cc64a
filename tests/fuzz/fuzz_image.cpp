// Arbitrary bytes as a texture file through the runtime's image reader
// (runtime/src/image_io/: OpenImageIO, or libpng alone). The reader takes a
// path and picks the format by its extension, so each input is written over
// one file in the target's temporary folder, named after the format its
// first bytes announce (TGA, which has no signature, otherwise).
#include "fuzz_support.h"
#include "image_io/image_io.h"

namespace {

std::string_view extension_for(std::string_view bytes) {
  if (bytes.starts_with("\x89PNG")) return "png";
  if (bytes.starts_with("\xff\xd8")) return "jpg";
  if (bytes.starts_with(std::string_view("\x76\x2f\x31\x01", 4))) return "exr";
  if (bytes.starts_with("#?")) return "hdr";
  if (bytes.starts_with("BM")) return "bmp";
  return "tga";
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  std::string_view bytes = facet::fuzz::as_text(data, size);
  const std::string path = facet::fuzz::TempDir::get().file(std::string("texture.") + std::string(extension_for(bytes)));
  facet::fuzz::write_bytes(path, bytes);
  // Far smaller than the renderer's budget: the same size checks run, and a
  // header declaring a large image is refused instead of decoded (decoding a
  // megapixel under ASan costs more than a hundred small inputs).
  const facet::runtime::ImageLimits limits{.max_side = 1024, .max_pixels = uint64_t(1) << 12};
  (void)facet::runtime::read_image_file(path, limits);
  std::remove(path.c_str());
  return 0;
}
