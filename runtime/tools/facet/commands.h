// The `facet` tool's subcommands. Each takes its own arguments (argv[0] is
// the subcommand's name) and the streams to print to, and returns the exit
// code, so that tests run them without a process. main.cpp's table maps
// names to these; a new subcommand adds one line there.
#pragma once

#include <iosfwd>

namespace facet::tool {

int render_command(int argc, const char* const* argv, std::ostream& out, std::ostream& err);
// `facet brdf ...` (docs/brdf-explorer.md).
int brdf_command(int argc, const char* const* argv, std::ostream& out, std::ostream& err);
// `facet bench accuracy ...` (docs/accuracy.md).
int bench_command(int argc, const char* const* argv, std::ostream& out, std::ostream& err);

}  // namespace facet::tool
