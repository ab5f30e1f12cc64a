#include "facet/support/output_paths.h"

#include <filesystem>

namespace facet::support {
namespace fs = std::filesystem;

bool same_file(const std::string& a, const std::string& b) {
  std::error_code ec;
  const bool a_exists = fs::exists(a, ec), b_exists = fs::exists(b, ec);
  // A character device or a FIFO is written in place (atomic_file.h):
  // naming one twice (`-o /dev/null -MF /dev/null`) destroys nothing.
  if (a_exists && b_exists) return fs::is_regular_file(a, ec) && fs::equivalent(a, b, ec) && !ec;
  if (a_exists != b_exists) return false;
  fs::path canonical_a = fs::weakly_canonical(fs::absolute(a, ec), ec);
  if (ec) return false;
  fs::path canonical_b = fs::weakly_canonical(fs::absolute(b, ec), ec);
  return !ec && canonical_a.lexically_normal() == canonical_b.lexically_normal();
}

std::optional<std::pair<std::string, std::string>> repeated_output(const std::vector<std::string>& outputs) {
  auto is_file = [](const std::string& path) { return !path.empty() && path != "-"; };
  for (size_t i = 0; i < outputs.size(); ++i) {
    if (!is_file(outputs[i])) continue;
    for (size_t j = i + 1; j < outputs.size(); ++j) {
      if (is_file(outputs[j]) && same_file(outputs[i], outputs[j])) return std::make_pair(outputs[i], outputs[j]);
    }
  }
  return std::nullopt;
}

}  // namespace facet::support
