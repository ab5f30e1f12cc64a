// The shader files that facetc's FILE and DIR arguments name, for the modes
// that take folders (--check, --report).
#pragma once

#include <string>
#include <vector>

namespace facet::tools {

// The shaders the arguments name: FILE arguments as given, each DIR's
// .shader files (recursively) sorted by path; duplicates once. A path that
// does not exist, or a folder without .shader files, is an error line in
// `errors`.
std::vector<std::string> find_shaders(const std::vector<std::string>& inputs, std::vector<std::string>& errors);

}  // namespace facet::tools
