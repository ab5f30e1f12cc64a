// "did you mean" for misspelt names (the distance is facet/support/suggest.h's) and
// small text helpers of sema.
#include "facet/support/suggest.h"
#include "lower.h"

namespace facet::sema {

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
