// Unity's render queues by name, and the number a Queue tag's value names:
// sema checks the tag with it, and the runtime orders a package's passes by
// it (a package keeps the tags as written).
#pragma once

#include <charconv>
#include <climits>
#include <optional>
#include <string_view>
#include <vector>

#include "facet/support/text.h"

namespace facet {

struct NamedQueue {
  std::string_view name;
  int number;
};
inline constexpr NamedQueue kRenderQueues[] = {
    {"Background", 1000}, {"Geometry", 2000}, {"AlphaTest", 2450}, {"Transparent", 3000}, {"Overlay", 4000}};

inline std::vector<std::string_view> render_queue_names() {
  std::vector<std::string_view> names;
  for (const NamedQueue& q : kRenderQueues) names.push_back(q.name);
  return names;
}

// "Geometry" (2000), "Geometry+1", "Transparent-100", "2450"; nullopt when
// the value names no queue.
inline std::optional<int> queue_number(std::string_view value) {
  auto integer = [](std::string_view s) -> std::optional<int> {
    int n = 0;
    auto [ptr, ec] = std::from_chars(s.data(), s.data() + s.size(), n);
    if (s.empty() || ec != std::errc() || ptr != s.data() + s.size()) return std::nullopt;
    return n;
  };
  value = trim(value);
  if (std::optional<int> number = integer(value)) return number;
  size_t sign = value.find_first_of("+-");
  std::string_view name = trim(value.substr(0, sign));
  int offset = 0;
  if (sign != std::string_view::npos) {
    std::string_view digits = trim(value.substr(sign + 1));
    std::optional<int> magnitude = digits.empty() || digits[0] == '-' || digits[0] == '+' ? std::nullopt : integer(digits);
    if (!magnitude) return std::nullopt;
    offset = value[sign] == '-' ? -*magnitude : *magnitude;
  }
  for (const NamedQueue& q : kRenderQueues) {
    if (!iequals(q.name, name)) continue;
    long long queue = (long long)q.number + offset;  // no int overflow for "Overlay+2147483647"
    if (queue < INT_MIN || queue > INT_MAX) return std::nullopt;
    return int(queue);
  }
  return std::nullopt;
}

}  // namespace facet
