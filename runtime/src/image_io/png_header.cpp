#include "image_io/png_header.h"

#include <fmt/format.h>

#include <array>
#include <cctype>
#include <cstring>

namespace facet::runtime {
namespace {

constexpr std::array<unsigned char, 8> kSignature = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
constexpr uint64_t kMaxChunkLength = 0x7FFFFFFF;  // PNG's limit (ISO/IEC 15948, 5.3)
constexpr uint64_t kChunkFraming = 12;             // length, type, CRC

// The type as text when its four bytes are letters (as every chunk's are),
// else as hex.
std::string chunk_name(const unsigned char* type) {
  bool letters = true;
  for (int i = 0; i < 4; ++i) letters = letters && std::isalpha(type[i]);
  if (letters) return fmt::format("'{}'", std::string(reinterpret_cast<const char*>(type), 4));
  return fmt::format("0x{:02x}{:02x}{:02x}{:02x}", type[0], type[1], type[2], type[3]);
}

}  // namespace

std::optional<std::string> png_chunk_problem(std::istream& file, uint64_t file_size) {
  std::array<unsigned char, 8> signature{};
  if (!file.read(reinterpret_cast<char*>(signature.data()), signature.size()) || signature != kSignature) {
    return std::nullopt;
  }
  for (uint64_t at = signature.size(); at + 8 <= file_size;) {
    unsigned char head[8];
    if (!file.read(reinterpret_cast<char*>(head), sizeof(head))) return std::nullopt;
    const uint64_t length = uint64_t(head[0]) << 24 | uint64_t(head[1]) << 16 | uint64_t(head[2]) << 8 | head[3];
    if (length > kMaxChunkLength) {
      return fmt::format("the PNG's chunk {} at byte {} declares {} bytes, more than PNG allows ({})",
                         chunk_name(head + 4), at, length, kMaxChunkLength);
    }
    const uint64_t room = file_size - at >= kChunkFraming ? file_size - at - kChunkFraming : 0;
    if (length > room) {
      return fmt::format("the PNG's chunk {} at byte {} declares {} bytes of data, past the end of the {}-byte file",
                         chunk_name(head + 4), at, length, file_size);
    }
    if (std::memcmp(head + 4, "IEND", 4) == 0) break;
    at += kChunkFraming + length;
    if (!file.seekg(std::streamoff(at))) return std::nullopt;
  }
  return std::nullopt;
}

}  // namespace facet::runtime
