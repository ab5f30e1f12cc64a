// `facet bench accuracy`: the arguments, the study, the output file.
#include <CLI/CLI.hpp>
#include <fmt/format.h>


#include "facet/runtime/accuracy.h"
#include "facet/support/atomic_file.h"

namespace facet::runtime::accuracy {
namespace {

bool write_report(const std::string& path, const std::string& text, std::ostream& err) {
  if (Result<void, std::string> written = support::write_file_atomically(path, text); !written) {
    err << fmt::format("facet bench accuracy: cannot write '{}': {}\n", path, written.error());
    return false;
  }
  return true;
}

}  // namespace

int run_accuracy_command(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
  CLI::App app{"The accuracy-versus-cost study of facet's lighting library", "facet bench accuracy"};
  StudyOptions options;
  std::string output;
  bool no_gpu = false;
  app.add_option("--out,-o", output, "report.html or report.json")->required();
  app.add_option("--device", options.device, "Vulkan device: index or name part (default: lavapipe)");
  app.add_option("--width", options.width, "invocation grid width")->check(CLI::Range(1u, 8192u));
  app.add_option("--height", options.height, "invocation grid height")->check(CLI::Range(1u, 8192u));
  app.add_option("-K,--evaluations", options.evaluations, "evaluations per invocation")->check(CLI::Range(1u, 1024u));
  app.add_option("--frames", options.frames, "timed dispatches (median)")->check(CLI::Range(1u, 10000u));
  app.add_flag("--no-gpu", no_gpu, "errors and instruction counts only");
  app.add_flag("--validation", options.validation, "Vulkan validation layers on");
  std::vector<std::string> reversed(args.rbegin(), args.rend());
  try {
    app.parse(reversed);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) {
      out << app.help();
      return 0;
    }
    err << "facet bench accuracy: " << e.what() << "\n";
    return 2;
  }
  options.gpu = !no_gpu;
  bool json = output.ends_with(".json");
  if (!json && !output.ends_with(".html")) {
    err << fmt::format("facet bench accuracy: --out '{}' must end in .html or .json\n", output);
    return 2;
  }
  Diagnostics diags;
  auto study = run_study(options, diags);
  if (!study) {
    for (const Diagnostic& d : diags.all()) err << "facet bench accuracy: " << d.message << "\n";
    return 1;
  }
  if (!write_report(output, json ? study_json(*study) : study_html(*study), err)) return 1;
  out << fmt::format("facet bench accuracy: {} rows on {} -> {}\n", study->rows.size(),
                     study->device.empty() ? "no GPU" : study->device, output);
  return 0;
}

}  // namespace facet::runtime::accuracy
