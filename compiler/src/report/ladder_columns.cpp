#include "ladder_columns.h"

#include <algorithm>

namespace facet::report {

std::vector<LadderColumn> ladder_columns(const PassReport& p) {
  std::vector<LadderColumn> columns = {
      {"full", "full", [](const Ladder& l) { return l.full.to_string(); }},
      {"after skip", "after skip_variants", [](const Ladder& l) { return l.after_skip.to_string(); }}};
  bool materials = std::any_of(p.ladders.begin(), p.ladders.end(), [](const Ladder& l) { return l.has_materials; });
  if (materials) {
    columns.push_back({"materials", "after materials", [](const Ladder& l) { return l.after_materials.to_string(); }});
  }
  columns.push_back({"reachable", "reachable", [](const Ladder& l) { return l.reachable.to_string(); }});
  if (p.enumerated) {
    columns.push_back({"after strip", "after keyword_rule + --strip",
                       [](const Ladder& l) { return std::to_string(l.after_strip); }});
    columns.push_back({"programs", "programs", [](const Ladder& l) { return std::to_string(l.programs); }});
    columns.push_back({"unique pp", "unique after preprocessing",
                       [](const Ladder& l) { return std::to_string(l.unique_tokens); }});
    columns.push_back({"unique spv", "unique SPIR-V", [](const Ladder& l) { return std::to_string(l.unique_spirv); }});
  }
  return columns;
}

}  // namespace facet::report
