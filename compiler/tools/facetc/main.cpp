// facetc: the glslc-style command-line compiler (docs/cli.md).
#include <filesystem>
#include <iostream>

#include "args.h"
#include "run.h"

int main(int argc, char** argv) {
  std::vector<std::string> arguments(argv + 1, argv + argc);
  facet::tools::ParsedArgs parsed = facet::tools::parse_args(arguments);
  if (!parsed.args) {
    (parsed.exit_code == 0 ? std::cout : std::cerr) << parsed.text;
    return parsed.exit_code;
  }
  std::error_code ec;
  auto self = std::filesystem::read_symlink("/proc/self/exe", ec);
  if (!ec) parsed.args->facetc_path = self.string();
  facet::tools::Console console{std::cout, std::cerr, &std::cin};
  return facet::tools::run_facetc(*parsed.args, console);
}
