#include "find_shaders.h"

#include <fmt/format.h>

#include <algorithm>
#include <filesystem>
#include <set>

namespace facet::tools {
namespace fs = std::filesystem;

std::vector<std::string> find_shaders(const std::vector<std::string>& inputs, std::vector<std::string>& errors) {
  std::vector<std::string> out;
  std::set<std::string> seen;
  auto add = [&](const std::string& path) {
    if (seen.insert(fs::path(path).lexically_normal().string()).second) out.push_back(path);
  };
  for (const std::string& input : inputs) {
    std::error_code ec;
    fs::file_status status = fs::status(input, ec);
    if (!fs::exists(status)) {
      errors.push_back(fmt::format("'{}' does not exist", input));
      continue;
    }
    if (!fs::is_directory(status)) {
      add(input);  // a file named on the command line is checked whatever its extension
      continue;
    }
    std::vector<std::string> found;
    for (auto it = fs::recursive_directory_iterator(input, ec); !ec && it != fs::recursive_directory_iterator();
         it.increment(ec)) {
      std::error_code file_ec;
      if (it->path().extension() == ".shader" && it->is_regular_file(file_ec)) found.push_back(it->path().string());
    }
    if (ec) {
      errors.push_back(fmt::format("cannot read the folder '{}': {}", input, ec.message()));
      continue;
    }
    if (found.empty()) {
      errors.push_back(fmt::format("no .shader files under '{}'", input));
      continue;
    }
    std::sort(found.begin(), found.end());
    for (const std::string& f : found) add(f);
  }
  return out;
}

}  // namespace facet::tools
