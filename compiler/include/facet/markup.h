// Text for HTML and SVG output (the variant report, BRDF figures, the
// accuracy report): the characters that markup gives a meaning escaped.
#pragma once

#include <string>
#include <string_view>

namespace facet {

// & < > " as entities; everything else as it is.
std::string xml_escape(std::string_view text);

}  // namespace facet
