// pretty_json: see common/json_print.h.
#include "facet/support/json_print.h"

#include <algorithm>

namespace facet {
namespace {

using Json = nlohmann::ordered_json;

void print(const Json& j, int indent, std::string& out) {
  auto scalar = [](const Json& x) { return !x.is_object() && !x.is_array(); };
  const std::string pad(size_t(indent) + 2, ' ');
  if (j.is_object() && !j.empty()) {
    out += "{\n";
    bool first = true;
    for (auto it = j.begin(); it != j.end(); ++it) {
      if (!first) out += ",\n";
      first = false;
      out += pad + Json(it.key()).dump(-1, ' ', false, Json::error_handler_t::replace) + ": ";
      print(it.value(), indent + 2, out);
    }
    out += "\n" + std::string(size_t(indent), ' ') + "}";
  } else if (j.is_array() && !j.empty() && !std::all_of(j.begin(), j.end(), scalar)) {
    out += "[\n";
    for (size_t i = 0; i < j.size(); ++i) {
      if (i > 0) out += ",\n";
      out += pad;
      print(j[i], indent + 2, out);
    }
    out += "\n" + std::string(size_t(indent), ' ') + "]";
  } else if (j.is_array() && !j.empty()) {
    out += "[";
    for (size_t i = 0; i < j.size(); ++i) {
      if (i > 0) out += ", ";
      out += j[i].dump(-1, ' ', false, Json::error_handler_t::replace);
    }
    out += "]";
  } else {
    // `replace` never throws, even on text that is not UTF-8.
    out += j.dump(-1, ' ', false, Json::error_handler_t::replace);
  }
}

}  // namespace

std::string pretty_json(const Json& j) {
  std::string out;
  print(j, 0, out);
  return out + "\n";
}

}  // namespace facet
