// The ladder's columns that hold data for a pass, for the text and HTML
// tables (the JSON form keeps every key).
#pragma once

#include <string>
#include <vector>

#include "facet/report.h"

namespace facet::report {

struct LadderColumn {
  const char* short_header;  // text: "after skip"
  const char* long_header;   // HTML: "after skip_variants"
  std::string (*value)(const Ladder&);
};

// The material rung only with manifests, the compiled rungs only when the
// pass was enumerated.
std::vector<LadderColumn> ladder_columns(const PassReport& pass);

}  // namespace facet::report
