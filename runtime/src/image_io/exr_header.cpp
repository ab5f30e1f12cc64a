#include "image_io/exr_header.h"

#include <fmt/format.h>

#include <array>

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

}  // namespace

bool is_exr(std::istream& file) {
  std::optional<uint32_t> magic = read_u32(file);
  return magic && *magic == 20000630;  // 76 2f 31 01
}

std::optional<std::string> exr_header_problem(std::istream& file, uint64_t file_size) {
  if (!is_exr(file)) return std::string("not an OpenEXR file");
  std::optional<uint32_t> version = read_u32(file);
  if (!version) return std::string("the EXR file ends inside its version field");
  const size_t max_name = (*version & kLongNames) ? 255 : 31;
  const bool multi_part = (*version & kMultiPart) != 0;
  for (int part = 0;; ++part) {
    int attributes = 0;
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
      file.seekg(declared, std::ios::cur);
    }
    // A single-part header ends at its first empty name; a multi-part file's
    // list of headers ends with an empty header.
    if (!multi_part || attributes == 0) return std::nullopt;
  }
}

}  // namespace facet::runtime
