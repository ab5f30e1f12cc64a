// facet: the runtime's command-line tool. `facet <subcommand> ...`; the
// table below is the whole dispatch.
#include <cstring>
#include <iostream>

#include "facet/commands.h"
#include "facet/compiler.h"

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
  os << "\n`facet help <subcommand>` (or `facet <subcommand> --help`) lists its options;\n"
        "`facet --version` prints the version.\n";
  return 1;
}

const Subcommand* find_subcommand(const char* name) {
  for (const Subcommand& s : kSubcommands) {
    if (!std::strcmp(name, s.name)) return &s;
  }
  return nullptr;
}

int unknown_subcommand(const char* name) {
  std::cerr << "facet: unknown subcommand '" << name << "'\n";
  return usage(std::cerr);
}

// `facet help`, `facet help <subcommand>`.
int help(int argc, char** argv) {
  if (argc < 3) {
    usage(std::cout);
    return 0;
  }
  const Subcommand* s = find_subcommand(argv[2]);
  if (!s) return unknown_subcommand(argv[2]);
  const char* args[] = {s->name, "--help"};
  return s->run(2, args, std::cout, std::cerr);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) return usage(std::cerr);
  if (!std::strcmp(argv[1], "--help") || !std::strcmp(argv[1], "-h")) {
    usage(std::cout);
    return 0;
  }
  if (!std::strcmp(argv[1], "--version") || !std::strcmp(argv[1], "version")) {
    std::cout << facet::version_string() << "\n";
    return 0;
  }
  if (!std::strcmp(argv[1], "help")) return help(argc, argv);
  if (const Subcommand* s = find_subcommand(argv[1])) return s->run(argc - 1, argv + 1, std::cout, std::cerr);
  return unknown_subcommand(argv[1]);
}
