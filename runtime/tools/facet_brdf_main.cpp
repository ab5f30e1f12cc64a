// facet-brdf: `facet brdf` as a standalone tool (docs/brdf-explorer.md).
#include <iostream>

#include "facet/runtime/brdf.h"

int main(int argc, char** argv) {
  return facet::brdf::run_brdf_command(std::vector<std::string>(argv + 1, argv + argc), std::cout, std::cerr);
}
