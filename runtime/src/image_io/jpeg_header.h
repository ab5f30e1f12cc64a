// A JPEG's Photoshop IPTC block (APP13), checked before OpenImageIO opens the
// file: OpenImageIO 2.4 decodes it while opening, trusting the block's own
// declared sizes (the IPTC data size and each record's length) without
// comparing them with the marker's length, and reads past the marker's data
// when they are larger (found by fuzz_image).
#pragma once

#include <istream>
#include <optional>
#include <string>

namespace facet::runtime {

// Why the IPTC block of the JPEG in `file` (read from its start) cannot be
// right, or nullopt when it fits its marker or there is none, or `file` is
// not a JPEG. Only the markers before the scan are read.
std::optional<std::string> jpeg_iptc_problem(std::istream& file);

}  // namespace facet::runtime
