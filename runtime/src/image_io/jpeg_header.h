// A JPEG's metadata markers, checked before OpenImageIO opens the file:
// OpenImageIO 2.4 compares the start of each APP1, APP2 and APP13 marker
// with an identifier ("Exif", the XMP namespace, "ICC_PROFILE", "Photoshop
// 3.0") by strcmp, which reads past a marker holding no NUL; and it decodes
// a Photoshop IPTC block (APP13) while opening, trusting the block's
// declared size of its records without comparing it with the marker's
// length, so reads past the marker's data when it is larger. Both were
// found by fuzz_image.
#pragma once

#include <istream>
#include <optional>
#include <string>

namespace facet::runtime {

// Why an APP1, APP2 or APP13 marker of the JPEG in `file` (read from its
// start) cannot be right, or nullopt when each holds a NUL and each IPTC
// block fits its marker, or `file` is not a JPEG. Every marker up to the end
// of the image is read.
std::optional<std::string> jpeg_marker_problem(std::istream& file);

}  // namespace facet::runtime
