#include "image_io/exr_header.h"

#include <fmt/format.h>

#include <array>
#include <string_view>
#include <cstdint>

namespace facet::runtime {
namespace {

// The version field's flags (OpenEXR's file layout document).
constexpr uint32_t kLongNames = 0x400;
constexpr uint32_t kMultiPart = 0x1000;

std::optional<uint32_t> read_u32(std::istream& file) {
  std::array<unsigned char, 4> b{};
  if (!file.read(reinterpret_cast<char*>(b.data()), 4)) return std::nullopt;
  return uint32_t(b[0]) | uint32_t(b[1]) << 8 | uint32_t(b[2]) << 16 | uint32_t(b[3]) << 24;
}

// A NUL-terminated name of at most `max_length` characters, or nullopt.
std::optional<std::string> read_name(std::istream& file, size_t max_length) {
  std::string name;
  for (char c; file.get(c);) {
    if (c == '\0') return name;
    if (name.size() == max_length) return std::nullopt;
    name += c;
  }
  return std::nullopt;
}

// The box2i value of a dataWindow (xMin, yMin, xMax, yMax), read past.
std::optional<std::string> data_window_problem(std::istream& file, const ImageLimits& limits) {
  int64_t box[4];
  for (int64_t& v : box) {
    std::optional<uint32_t> word = read_u32(file);
    if (!word) return std::string("the EXR file ends inside its dataWindow");
    v = int32_t(*word);
  }
  const int64_t width = box[2] - box[0] + 1, height = box[3] - box[1] + 1;
  if (width <= 0 || height <= 0) {
    return fmt::format("the EXR dataWindow ({}, {}) - ({}, {}) is empty", box[0], box[1], box[2], box[3]);
  }
  if (std::optional<std::string> problem = image_size_problem(uint64_t(width), uint64_t(height), limits)) {
    return "the EXR dataWindow: " + *problem;
  }
  return std::nullopt;
}

// The size OpenEXR reads for a value of `type` whatever the header declares
// (its readValueFrom reads these types by their own layout), or nullopt for
// types whose reader follows the declared size.
std::optional<int64_t> fixed_size(const std::string& type) {
  static const std::pair<const char*, int64_t> kSizes[] = {
      {"box2i", 16}, {"box2f", 16}, {"chromaticities", 32}, {"compression", 1}, {"double", 8},
      {"envmap", 1}, {"float", 4},  {"int", 4},             {"keycode", 28},    {"lineOrder", 1},
      {"m33f", 36},  {"m33d", 72},  {"m44f", 64},           {"m44d", 128},      {"rational", 8},
      {"tiledesc", 9}, {"timecode", 8}, {"v2i", 8},         {"v2f", 8},         {"v2d", 16},
      {"v3i", 12},   {"v3f", 12},   {"v3d", 24},            {"deepImageState", 1}};
  for (const auto& [name, size] : kSizes) {
    if (type == name) return size;
  }
  return std::nullopt;
}

// The bytes a channel list takes as OpenEXR reads it: entries (a name, then
// 16 bytes) up to an empty name, whatever size the header declared.
std::optional<int64_t> channel_list_size(std::istream& file, size_t max_name, int64_t declared) {
  const std::streamoff start = file.tellg();
  int64_t used = 0;
  for (;;) {
    std::optional<std::string> name = read_name(file, max_name);
    if (!name) return std::nullopt;
    used += int64_t(name->size()) + 1;
    if (name->empty() || used > declared) break;
    file.seekg(16, std::ios::cur);
    used += 16;
  }
  file.clear();
  file.seekg(start);
  return used;
}

// A preview image: width and height, then width x height RGBA bytes, which
// OpenEXR allocates from the two numbers alone.
std::optional<int64_t> preview_size(std::istream& file) {
  const std::streamoff start = file.tellg();
  std::optional<uint32_t> w = read_u32(file), h = read_u32(file);
  file.clear();
  file.seekg(start);
  if (!w || !h) return std::nullopt;
  // Up to 2^64 pixels: a count no declared size (an int32) can match.
  const uint64_t pixels = uint64_t(*w) * uint64_t(*h);
  if (pixels > uint64_t(INT32_MAX)) return INT64_MAX;
  return 8 + int64_t(pixels) * 4;
}

// Why the value of attribute `name` of `type` does not take the `declared`
// bytes OpenEXR will read for it (fuzz_image: a channel list declaring 17
// bytes that holds 19 shifted OpenEXR's reading of the rest of the header
// away from this walk's, onto a string declaring 1.98 GB).
std::optional<std::string> layout_problem(std::istream& file, const std::string& name, const std::string& type,
                                          int64_t declared, size_t max_name) {
  std::optional<int64_t> takes;
  if (type == "chlist") {
    takes = channel_list_size(file, max_name, declared);
  } else if (type == "preview") {
    takes = preview_size(file);
  } else {
    takes = fixed_size(type);
  }
  if (!takes) {
    if (type == "chlist" || type == "preview") return fmt::format("the EXR attribute '{}' ({}) is cut short", name, type);
    return std::nullopt;
  }
  if (*takes != declared) {
    return fmt::format("the EXR attribute '{}' declares {} bytes, but OpenEXR reads {} bytes for its {} value", name,
                       declared, *takes, type);
  }
  return std::nullopt;
}

// A BITMAPINFOHEADER's planes, bits per pixel and compression, read after
// its height. OpenImageIO 2.4 decodes any pairing and reads far out of
// bounds on one that BMP does not define (RLE8 at 24 bits, found by
// fuzz_image): only BMP's own pairings pass.
std::optional<std::string> bmp_format_problem(std::istream& file) {
  std::array<unsigned char, 4> planes_bits{};
  if (!file.read(reinterpret_cast<char*>(planes_bits.data()), 4)) return std::string("the BMP file ends inside its header");
  const uint32_t planes = planes_bits[0] | uint32_t(planes_bits[1]) << 8;
  const uint32_t bits = planes_bits[2] | uint32_t(planes_bits[3]) << 8;
  std::optional<uint32_t> compression = read_u32(file);
  if (!compression) return std::string("the BMP file ends inside its header");
  if (planes != 1) return fmt::format("the BMP header declares {} planes (BMP has 1)", planes);
  constexpr uint32_t kRgb = 0, kRle8 = 1, kRle4 = 2, kBitfields = 3;
  bool valid = false;
  switch (*compression) {
    case kRgb: valid = bits == 1 || bits == 4 || bits == 8 || bits == 16 || bits == 24 || bits == 32; break;
    case kRle8: valid = bits == 8; break;
    case kRle4: valid = bits == 4; break;
    case kBitfields: valid = bits == 16 || bits == 32; break;
    default: return fmt::format("the BMP header declares compression {}, which facet does not read", *compression);
  }
  if (!valid) return fmt::format("the BMP header declares {} bits a pixel with compression {}, a pairing BMP does not define", bits, *compression);
  return std::nullopt;
}

}  // namespace

std::optional<std::string> bmp_header_problem(std::istream& file, const ImageLimits& limits) {
  char magic[2] = {};
  if (!file.read(magic, 2) || magic[0] != 'B' || magic[1] != 'M') return std::nullopt;
  file.seekg(14);
  std::optional<uint32_t> header_size = read_u32(file);
  std::optional<uint32_t> w = read_u32(file), h = read_u32(file);
  if (!header_size || !w || !h) return std::string("the BMP file ends inside its header");
  int64_t width = 0, height = 0;
  if (*header_size == 12) {  // OS/2 BITMAPCOREHEADER: 16-bit sides
    width = *w & 0xffff;
    height = (*w >> 16) & 0xffff;
  } else {
    width = int32_t(*w);
    height = int32_t(*h);
  }
  height = height < 0 ? -height : height;  // negative: stored top-down
  if (width <= 0 || height <= 0) return fmt::format("the BMP header declares {}x{} pixels", width, height);
  if (std::optional<std::string> problem = image_size_problem(uint64_t(width), uint64_t(height), limits)) {
    return "the BMP header: " + *problem;
  }
  return *header_size == 12 ? std::nullopt : bmp_format_problem(file);
}

std::optional<std::string> gif_header_problem(std::istream& file, const ImageLimits& limits) {
  std::array<unsigned char, 10> header{};
  if (!file.read(reinterpret_cast<char*>(header.data()), 10)) return std::nullopt;
  const std::string_view magic(reinterpret_cast<const char*>(header.data()), 6);
  if (magic != "GIF87a" && magic != "GIF89a") return std::nullopt;
  // The logical screen: giflib allocates the canvas at this size on opening.
  const uint64_t width = header[6] | uint64_t(header[7]) << 8, height = header[8] | uint64_t(header[9]) << 8;
  if (std::optional<std::string> problem = image_size_problem(width, height, limits)) {
    return "the GIF header: " + *problem;
  }
  return std::nullopt;
}

bool is_exr(std::istream& file) {
  std::optional<uint32_t> magic = read_u32(file);
  return magic && *magic == 20000630;  // 76 2f 31 01
}

std::optional<std::string> exr_header_problem(std::istream& file, uint64_t file_size, const ImageLimits& limits) {
  if (!is_exr(file)) return std::string("not an OpenEXR file");
  std::optional<uint32_t> version = read_u32(file);
  if (!version) return std::string("the EXR file ends inside its version field");
  const size_t max_name = (*version & kLongNames) ? 255 : 31;
  const bool multi_part = (*version & kMultiPart) != 0;
  for (int part = 0;; ++part) {
    int attributes = 0;
    bool data_window = false;
    for (;; ++attributes) {
      std::optional<std::string> name = read_name(file, max_name);
      if (!name) {
        return fmt::format("the EXR header of part {} has an attribute name without its end (at most {} characters)",
                           part, max_name);
      }
      if (name->empty()) break;
      std::optional<std::string> type = read_name(file, max_name);
      if (!type) return fmt::format("the EXR attribute '{}' has a type name without its end", *name);
      std::optional<uint32_t> size = read_u32(file);
      if (!size) return fmt::format("the EXR file ends inside the size of its attribute '{}'", *name);
      const int64_t declared = int32_t(*size);
      const std::streamoff here = file.tellg();
      const uint64_t left = here < 0 ? 0 : file_size - uint64_t(here);
      if (declared < 0 || uint64_t(declared) > left) {
        return fmt::format("the EXR attribute '{}' declares {} bytes; the file has {} left", *name, declared, left);
      }
      if (std::optional<std::string> problem = layout_problem(file, *name, *type, declared, max_name)) return problem;
      if (*name == "dataWindow" && *type == "box2i" && declared == 16) {
        if (std::optional<std::string> problem = data_window_problem(file, limits)) return problem;
        data_window = true;
        continue;
      }
      file.seekg(declared, std::ios::cur);
    }
    // A single-part header ends at its first empty name; a multi-part file's
    // list of headers ends with an empty header.
    if (multi_part && attributes == 0) return std::nullopt;
    // Every header has a dataWindow. Without one where this walk finds it,
    // OpenEXR read the header otherwise (fuzz_image: a file whose dataWindow
    // only OpenEXR found, 50 million pixels wide), so its size is unchecked.
    if (!data_window) return fmt::format("the EXR header of part {} has no dataWindow (box2i) attribute", part);
    if (!multi_part) return std::nullopt;
  }
}

}  // namespace facet::runtime
