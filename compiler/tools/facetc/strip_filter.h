// facetc --strip FILE: a declarative strip filter (docs/stripping.md).
#pragma once

#include "facet/compiler.h"

namespace facet::tools {

Result<variants::StripFilter> read_strip_filter(const std::string& path, SourceMap& sources, Diagnostics& diags);

// The file read_strip_filter reads back as `filter` (a rule's pass as an
// index number when it is all digits).
std::string strip_filter_json(const variants::StripFilter& filter);

}  // namespace facet::tools
