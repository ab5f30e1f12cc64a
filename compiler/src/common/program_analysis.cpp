#include "facet/program_analysis.h"

#include <algorithm>

namespace facet {

bool AnalyzedParam::reads(std::string_view member) const {
  return whole_read || std::binary_search(members_read.begin(), members_read.end(), member);
}

bool AnalyzedParam::writes(std::string_view member) const {
  return whole_written || std::binary_search(members_written.begin(), members_written.end(), member);
}

const AnalyzedFunction* ProgramAnalysis::find(std::string_view name) const {
  for (auto it = functions.rbegin(); it != functions.rend(); ++it) {
    if (it->name == name) return &*it;
  }
  return nullptr;
}

const std::vector<AnalyzedField>* ProgramAnalysis::find_struct(std::string_view name) const {
  auto it = structs.find(std::string(name));
  return it == structs.end() ? nullptr : &it->second;
}

}  // namespace facet
