// "did you mean" for misspelt names (the distance is common/suggest.h's) and
// small text helpers of sema.
#include "facet/support/suggest.h"
#include "lower.h"

namespace facet::sema {
namespace {

char lower(char c) { return (c >= 'A' && c <= 'Z') ? char(c - 'A' + 'a') : c; }

}  // namespace

bool iequals(std::string_view a, std::string_view b) {
  if (a.size() != b.size()) return false;
  for (size_t i = 0; i < a.size(); ++i) {
    if (lower(a[i]) != lower(b[i])) return false;
  }
  return true;
}

std::optional<std::string_view> suggest(std::string_view word, std::span<const std::string_view> candidates) {
  return closest_name(word, candidates);
}

std::string join(std::span<const std::string_view> words) {
  std::string out;
  for (std::string_view w : words) {
    if (!out.empty()) out += ", ";
    out += w;
  }
  return out;
}

}  // namespace facet::sema
