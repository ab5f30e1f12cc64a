// `facet bench <study>`: the benchmarks that are part of the tool (so far
// the accuracy-versus-cost study of the lighting library).
#include <ostream>
#include <string>
#include <vector>

#include "facet/commands.h"
#include "facet/runtime/accuracy.h"

namespace facet::tool {

int bench_command(int argc, const char* const* argv, std::ostream& out, std::ostream& err) {
  if (argc < 2 || std::string(argv[1]) != "accuracy") {
    err << "usage: facet bench accuracy [--device D] [--width W --height H] [-K N] [--frames N] [--no-gpu] "
           "[--validation] [--from study.json] --out report.html|report.json|chart.svg\n";
    return 2;
  }
  std::vector<std::string> args(argv + 2, argv + argc);
  return runtime::accuracy::run_accuracy_command(args, out, err);
}

}  // namespace facet::tool
