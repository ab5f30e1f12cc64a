// Runs facetc on parsed arguments: one input at a time, outputs written only
// when the input compiled without errors (atomically, never half-written).
#pragma once

#include <istream>
#include <ostream>
#include <string>
#include <vector>

#include "args.h"

namespace facet::tools {

struct Console {
  std::ostream& out;  // standard output: text outputs and '-o -'
  std::ostream& err;  // diagnostics, --stats
  std::istream* in = nullptr;  // standard input: the input '-' (none: '-' is refused)
};

// Exit code: 0 success, 1 compile errors (or warnings under -Werror), 2 usage
// errors found only after reading an input (e.g. --emit=spirv matching
// several stages).
int run_facetc(const FacetcArgs& args, Console& console);

}  // namespace facet::tools
