// facet: the runtime's command-line tool. `facet <subcommand> ...`; the
// table below is the whole dispatch.
#include <cstring>
#include <iostream>

#include "facet/commands.h"

namespace {

struct Subcommand {
  const char* name;
  const char* summary;
  int (*run)(int argc, const char* const* argv, std::ostream& out, std::ostream& err);
};

constexpr Subcommand kSubcommands[] = {
    {"render", "render a JSON scene to PNG/EXR (facet render scene.json -o out.png)", facet::tool::render_command},
#ifndef FACET_NO_BRDF_TOOL  // the PNG-only build (FACET_IMAGE_IO=png) has no BRDF Explorer
    {"brdf", "BRDF Explorer views: lit-sphere, polar, slice, albedo (facet brdf ggx:roughness=0.3 --view polar -o p.svg)",
     facet::tool::brdf_command},
#endif
    {"bench", "the accuracy-versus-cost study (facet bench accuracy --out report.html)", facet::tool::bench_command},
};

int usage(std::ostream& os) {
  os << "usage: facet <subcommand> [options]\n\nsubcommands:\n";
  for (const Subcommand& s : kSubcommands) os << "  " << s.name << "  " << s.summary << "\n";
  os << "\n`facet <subcommand> --help` lists its options.\n";
  return 1;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) return usage(std::cerr);
  if (!std::strcmp(argv[1], "--help") || !std::strcmp(argv[1], "-h")) {
    usage(std::cout);
    return 0;
  }
  for (const Subcommand& s : kSubcommands) {
    if (!std::strcmp(argv[1], s.name)) return s.run(argc - 1, argv + 1, std::cout, std::cerr);
  }
  std::cerr << "facet: unknown subcommand '" << argv[1] << "'\n";
  return usage(std::cerr);
}
