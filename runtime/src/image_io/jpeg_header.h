// A JPEG's Photoshop IPTC block (APP13), checked before OpenImageIO opens the
// file: OpenImageIO 2.4 decodes it while opening, trusting the block's
// declared size of its records without comparing it with the marker's
// length, and reads past the marker's data when it is larger (found by
// fuzz_image); it also compares the marker's start with "Photoshop 3.0" by
// strcmp, which reads past a marker holding part of that text and no NUL.
#pragma once

#include <istream>
#include <optional>
#include <string>

namespace facet::runtime {

// Why an IPTC block of the JPEG in `file` (read from its start) cannot be
// right, or nullopt when each fits its marker or there is none, or `file` is
// not a JPEG. Every marker up to the end of the image is read.
std::optional<std::string> jpeg_iptc_problem(std::istream& file);

}  // namespace facet::runtime
