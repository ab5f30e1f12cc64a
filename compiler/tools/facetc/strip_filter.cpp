// Strip filter files (docs/stripping.md):
//   {"strip": [{"deny": ["FOG_EXP", "_ALPHABLEND_ON"]},
//              {"allow": ["FOG_EXP", "_ALPHABLEND_ON", "_EMISSION"]},
//              {"always_on": ["FOG_LINEAR"], "pass": "FORWARD"},
//              {"always_off": ["_DETAIL_MULX2"]}]}
#include <fmt/format.h>

#include <algorithm>
#include <map>

#include "json_input.h"
#include "strip_filter.h"

namespace facet::tools {
namespace {

using Json = nlohmann::json;

const std::map<std::string, variants::StripKind> kKinds = {{"deny", variants::StripKind::deny},
                                                          {"allow", variants::StripKind::allow},
                                                          {"always_on", variants::StripKind::always_on},
                                                          {"always_off", variants::StripKind::always_off}};

void read_rule(const Json& r, const std::string& where, JsonInputErrors& errors, variants::StripFilter& out) {
  if (!r.is_object()) return errors.add(where, "expected an object");
  std::optional<variants::StripRule> rule;
  std::string pass;
  for (auto it = r.begin(); it != r.end(); ++it) {
    std::string at = where + "." + it.key();
    if (it.key() == "pass") {
      if (it.value().is_string()) pass = it.value().get<std::string>();
      else if (it.value().is_number_unsigned()) pass = std::to_string(it.value().get<uint64_t>());
      else return errors.add(at, "expected a pass name or index");
      continue;
    }
    auto kind = kKinds.find(it.key());
    if (kind == kKinds.end()) return errors.add(at, "unknown key; a rule has one of 'deny', 'allow', 'always_on', 'always_off', and optionally 'pass'");
    if (rule) return errors.add(at, "a rule has one kind; split it into two rules");
    if (!it.value().is_array() || it.value().empty()) return errors.add(at, "expected a non-empty array of keywords");
    rule = variants::StripRule{.kind = kind->second};
    for (size_t i = 0; i < it.value().size(); ++i) {
      if (!it.value()[i].is_string()) return errors.add(fmt::format("{}[{}]", at, i), "expected a keyword string");
      rule->keywords.push_back(it.value()[i].get<std::string>());
    }
  }
  if (!rule) return errors.add(where, "a rule needs one of 'deny', 'allow', 'always_on', 'always_off'");
  rule->pass = pass;
  out.rules.push_back(std::move(*rule));
}

}  // namespace

Result<variants::StripFilter> read_strip_filter(const std::string& path, SourceMap& sources, Diagnostics& diags) {
  auto doc = read_json_input(path, sources, diags);
  FACET_TRY(doc);
  JsonInputErrors errors{doc->file, diags};
  const Json& root = doc->json;
  if (!root.is_object() || !root.contains("strip") || !root["strip"].is_array()) {
    errors.add("$", "expected an object with a 'strip' array of rules");
    return failure("bad filter");
  }
  variants::StripFilter filter;
  for (size_t i = 0; i < root["strip"].size(); ++i) read_rule(root["strip"][i], fmt::format("strip[{}]", i), errors, filter);
  if (errors.failed) return failure("bad filter");
  return filter;
}

std::string strip_filter_json(const variants::StripFilter& filter) {
  nlohmann::ordered_json rules = nlohmann::ordered_json::array();
  for (const variants::StripRule& rule : filter.rules) {
    auto kind = std::find_if(kKinds.begin(), kKinds.end(), [&](const auto& k) { return k.second == rule.kind; });
    nlohmann::ordered_json r = {{kind->first, rule.keywords}};
    bool index = !rule.pass.empty() && rule.pass.size() < 10 &&
                 std::all_of(rule.pass.begin(), rule.pass.end(), [](char c) { return c >= '0' && c <= '9'; });
    if (index) r["pass"] = std::stoul(rule.pass);
    else if (!rule.pass.empty()) r["pass"] = rule.pass;
    rules.push_back(std::move(r));
  }
  return nlohmann::ordered_json{{"strip", rules}}.dump(2) + "\n";
}

}  // namespace facet::tools
