// `facet brdf MODEL... --view V -o FILE`: the BRDF Explorer views (docs/brdf-explorer.md).
#include <ostream>
#include <string>
#include <vector>

#include "facet/commands.h"
#include "facet/runtime/brdf.h"

namespace facet::tool {

int brdf_command(int argc, const char* const* argv, std::ostream& out, std::ostream& err) {
  return brdf::run_brdf_command(std::vector<std::string>(argv + 1, argv + argc), out, err);
}

}  // namespace facet::tool
