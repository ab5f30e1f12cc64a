// facetc --strip FILE: a declarative strip filter (docs/stripping.md).
#pragma once

#include "facet/compiler.h"

namespace facet::tools {

Result<variants::StripFilter> read_strip_filter(const std::string& path, SourceMap& sources, Diagnostics& diags);

}  // namespace facet::tools
