// Golden-friendly JSON text shared by the stages' dumps (ast, ir).
#pragma once

#include <nlohmann/json.hpp>

#include <string>

namespace facet {

// Like dump(2), but an array of numbers or strings stays on one line, so a
// colour or a tag pair reads as one line in golden files. Never throws, even
// on text that is not UTF-8. Ends with a newline.
std::string pretty_json(const nlohmann::ordered_json& j);

}  // namespace facet
