#include "image_io/jpeg_header.h"

#include <fmt/format.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <vector>

namespace facet::runtime {
namespace {

constexpr uint8_t kApp1 = 0xE1, kApp2 = 0xE2, kApp13 = 0xED;
constexpr uint8_t kEndOfImage = 0xD9;

size_t big_endian16(const uint8_t* p) { return size_t(p[0]) << 8 | p[1]; }

// OpenImageIO 2.4 compares the start of every APP1 (Exif, XMP), APP2 (ICC
// profile) and APP13 (Photoshop) marker it keeps with an identifier by
// strcmp, as a C string: a marker whose data holds no NUL is read past its
// end (fuzz_image, with ASan's strict string checks: an APP1 of 6 bytes and
// no NUL; a marker holding "Exif" or part of "Photoshop 3.0" without the NUL
// is read past even by a lenient strcmp). Every identifier these markers
// carry ends with a NUL, so such a marker is refused.
std::optional<std::string> identifier_problem(uint8_t marker, const std::vector<uint8_t>& data) {
  if (std::find(data.begin(), data.end(), uint8_t(0)) != data.end()) return std::nullopt;
  if (data.empty()) return fmt::format("the JPEG has an empty APP{} marker", marker - 0xE0);
  return fmt::format("the JPEG's APP{} marker holds {} bytes and no NUL-terminated identifier (such as \"Exif\")",
                     marker - 0xE0, data.size());
}

// The IPTC block of an APP13 marker's data as OpenImageIO 2.4 reads it
// (jpeg_decode_iptc): "Photoshop 3.0\0", "8BIM", resource 0x0404, 4 bytes,
// then a 2-byte size of the records that follow, which it reads without
// comparing with the marker's length. (Each record's own length is clamped
// to that size, so the size is what must fit.) `data` holds a NUL.
std::optional<std::string> iptc_problem(const std::vector<uint8_t>& data) {
  static constexpr char kPhotoshop[] = "Photoshop 3.0";  // and its NUL: 14 bytes
  constexpr size_t kHeader = sizeof(kPhotoshop) + 4 + 2 + 4 + 2;  // 26: the records start here
  if (data.size() < sizeof(kPhotoshop) || std::memcmp(data.data(), kPhotoshop, sizeof(kPhotoshop)) != 0) {
    return std::nullopt;
  }
  if (data.size() < kHeader) {
    return fmt::format("the JPEG's IPTC block (APP13) ends at byte {} of its {}-byte header", data.size(), kHeader);
  }
  const uint8_t* resource = data.data() + sizeof(kPhotoshop);
  if (std::memcmp(resource, "8BIM", 4) != 0 || big_endian16(resource + 4) != 0x0404) return std::nullopt;
  const size_t declared = big_endian16(resource + 10);
  const size_t available = data.size() - kHeader;
  if (declared > available) {
    return fmt::format("the JPEG's IPTC block (APP13) declares {} bytes of records, but its marker holds {}", declared,
                       available);
  }
  return std::nullopt;
}

}  // namespace

// The markers are read as libjpeg reads them: bytes before a marker's 0xFF
// are skipped (scan data, or garbage with a warning), a length below 2 holds
// no data (the marker is still kept), and a file that ends inside a marker
// is padded with end-of-image markers. Markers after the first scan count too: for a progressive or
// multi-scan file, libjpeg reads the whole file before OpenImageIO looks at
// the saved markers.
std::optional<std::string> jpeg_marker_problem(std::istream& file) {
  uint8_t soi[2] = {};
  if (!file.read(reinterpret_cast<char*>(soi), 2) || soi[0] != 0xFF || soi[1] != 0xD8) return std::nullopt;
  for (;;) {
    int marker = 0;
    while (marker == 0) {  // 0xFF 0x00 is a stuffed byte of scan data, not a marker
      int byte = file.get();
      while (byte != EOF && byte != 0xFF) byte = file.get();
      while (byte == 0xFF) byte = file.get();
      if (byte == EOF) return std::nullopt;
      marker = byte;
    }
    if (marker == kEndOfImage) return std::nullopt;
    if ((marker >= 0xD0 && marker <= 0xD7) || marker == 0x01) continue;  // markers without a length
    uint8_t size[2] = {};
    if (!file.read(reinterpret_cast<char*>(size), 2)) return std::nullopt;
    const size_t length = std::max<size_t>(big_endian16(size), 2);  // libjpeg: a length below 2 holds no data
    if (marker != kApp1 && marker != kApp2 && marker != kApp13) {  // the start of scan's header too; its data follows it
      file.seekg(std::streamoff(length - 2), std::ios::cur);
      continue;
    }
    std::vector<uint8_t> data(length - 2);  // at most 65533 bytes
    file.read(reinterpret_cast<char*>(data.data()), std::streamsize(data.size()));
    const size_t read = size_t(file.gcount());
    for (size_t i = read; i < data.size(); ++i) data[i] = (i - read) % 2 == 0 ? 0xFF : kEndOfImage;
    if (std::optional<std::string> problem = identifier_problem(uint8_t(marker), data)) return problem;
    if (marker == kApp13) {
      if (std::optional<std::string> problem = iptc_problem(data)) return problem;
    }
    if (!file) return std::nullopt;
  }
}

}  // namespace facet::runtime
