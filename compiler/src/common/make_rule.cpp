#include "facet/support/make_rule.h"

namespace facet {
namespace {

std::string escape_for_make(const std::string& path) {
  std::string out;
  for (char c : path) {
    if (c == ' ' || c == '#') out += '\\';
    if (c == '$') out += '$';
    out += c;
  }
  return out;
}

}  // namespace

std::string make_rule(const std::string& target, const std::vector<std::string>& deps) {
  std::string rule = escape_for_make(target) + ":";
  for (const std::string& dep : deps) rule += " \\\n  " + escape_for_make(dep);
  return rule + "\n";
}

}  // namespace facet
