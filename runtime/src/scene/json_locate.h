// Where a value of a JSON document is, by the path the scene reader names it
// with ("objects[2].material.properties._Color"): nlohmann's DOM keeps no
// positions, so a located message scans the text again.
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "facet/source.h"

namespace facet::runtime {

struct JsonExtent {
  size_t begin = 0, end = 0;  // the value's bytes, [begin, end)
};

// The extent of the value at `path` ("" is the whole document); nullopt when
// the text has no such value or is not JSON that far.
std::optional<JsonExtent> locate_json_value(std::string_view text, std::string_view path);

// The span of the value at `path` in the scene file `scene_path`: its text
// read now and added to `sources` unless that text is there already under
// its name; a file that cannot be read is located in what `sources` holds
// under its name. A scene built in code (no path) has no location: an empty
// span.
SourceSpan scene_value_span(SourceMap& sources, const std::string& scene_path, std::string_view path);

}  // namespace facet::runtime
