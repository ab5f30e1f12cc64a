// Keywords implied by Toggle / ToggleOff / KeywordEnum property values.
#include <algorithm>
#include <cctype>
#include <cmath>

#include "facet/variants.h"

namespace facet::variants {
namespace {

std::string upper_keyword(std::string_view s) {
  std::string out;
  for (char c : s) out += c == ' ' ? '_' : char(std::toupper(static_cast<unsigned char>(c)));
  return out;
}

bool same_name(std::string_view a, std::string_view b) {
  return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
           return std::tolower(static_cast<unsigned char>(x)) == std::tolower(static_cast<unsigned char>(y));
         });
}

float value_of(const ir::Property& p, const std::vector<PropertyValue>& values) {
  for (const PropertyValue& v : values) {
    if (v.name == p.name) return v.value;
  }
  return p.default_value[0];
}

// The keyword one attribute implies for `value`, or "" for none.
std::string implied(const ir::Property& p, const ir::PropertyAttribute& a, float value) {
  bool on = value != 0 && !std::isnan(value);
  if (same_name(a.name, "Toggle")) {
    if (!on) return {};
    return a.args.empty() || a.args[0].empty() ? upper_keyword(p.name) + "_ON" : a.args[0];
  }
  if (same_name(a.name, "ToggleOff")) {
    if (on) return {};
    return a.args.empty() || a.args[0].empty() ? upper_keyword(p.name) + "_OFF" : a.args[0];
  }
  if (same_name(a.name, "KeywordEnum") && !a.args.empty()) {
    float index = std::isnan(value) ? 0.0f : std::clamp(std::trunc(value), 0.0f, float(a.args.size() - 1));
    return upper_keyword(p.name) + "_" + upper_keyword(a.args[size_t(index)]);
  }
  return {};
}

}  // namespace

KeywordList keywords_from_properties(const std::vector<ir::Property>& properties,
                                     const std::vector<PropertyValue>& values) {
  KeywordList out;
  for (const ir::Property& p : properties) {
    for (const ir::PropertyAttribute& a : p.attributes) {
      std::string keyword = implied(p, a, value_of(p, values));
      if (!keyword.empty() && std::find(out.begin(), out.end(), keyword) == out.end()) out.push_back(keyword);
    }
  }
  return out;
}

}  // namespace facet::variants
