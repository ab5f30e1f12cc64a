// `facet bench accuracy`: the arguments, the study, the output file.
#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <algorithm>
#include <fstream>
#include <sstream>

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

// The study read back from a file that study_json wrote.
Result<Study> read_study(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return failure(fmt::format("cannot read '{}'", path));
  std::ostringstream text;
  text << in.rdbuf();
  Result<Study> study = study_from_json(text.str());
  if (!study) return failure(fmt::format("'{}': {}", path, study.error().reason));
  return study;
}

std::string budget_report_of(const BudgetSearch& search, const std::vector<double>& budgets, const std::string& output) {
  if (output.ends_with(".json")) return budget_json(search, budgets);
  if (output.ends_with(".svg")) return budget_chart_svg(search, budgets);
  return budget_html(search, budgets);
}

std::string report_of(const Study& study, const std::string& output) {
  if (output.ends_with(".json")) return study_json(study);
  if (output.ends_with(".svg")) return study_chart_svg(study);
  return study_html(study);
}

}  // namespace

int run_accuracy_command(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
  CLI::App app{"The accuracy-versus-cost study of facet's lighting library", "facet bench accuracy"};
  StudyOptions options;
  std::string output, from;
  bool no_gpu = false, no_driver_statistics = false;
  std::vector<double> budgets;
  app.add_option("--out,-o", output, "report.html, report.json or chart.svg (the Pareto chart alone)")->required();
  app.add_option("--from", from, "redraw a study that --out report.json wrote, instead of measuring");
  app.add_option("--device", options.device, "Vulkan device: index or name part (default: lavapipe)");
  app.add_option("--width", options.width, "invocation grid width")->check(CLI::Range(1u, 8192u));
  app.add_option("--height", options.height, "invocation grid height")->check(CLI::Range(1u, 8192u));
  app.add_option("-K,--evaluations", options.evaluations, "evaluations per invocation")->check(CLI::Range(1u, 1024u));
  app.add_option("--frames", options.frames, "timed dispatches (median)")->check(CLI::Range(1u, 10000u));
  app.add_option("--image-samples", options.image_samples,
                 "samples per pixel of the Monte Carlo reference render (0: no image errors)")
      ->check(CLI::Range(0u, 1u << 20));
  app.add_option("--budget", budgets,
                 "an image-RMSE budget: name the cheapest combination of D, V, F and diffuse terms within it "
                 "(repeatable; --out then holds the budget search)")
      ->check(CLI::PositiveNumber);
  app.add_flag("--no-gpu", no_gpu, "errors and instruction counts only");
  app.add_flag("--validation", options.validation, "Vulkan validation layers on");
  app.add_flag("--no-driver-statistics", no_driver_statistics,
               "leave out the driver's statistics (VK_KHR_pipeline_executable_properties)");
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
  options.driver_statistics = !no_driver_statistics;
  if (!output.ends_with(".json") && !output.ends_with(".html") && !output.ends_with(".svg")) {
    err << fmt::format("facet bench accuracy: --out '{}' must end in .html, .json or .svg\n", output);
    return 2;
  }
  Result<Study> study = failure();
  if (!from.empty()) {
    study = read_study(from);
    if (!study) {
      err << "facet bench accuracy: " << study.error().reason << "\n";
      return 1;
    }
  } else {
    Diagnostics diags;
    study = run_study(options, diags);
    if (!study) {
      for (const Diagnostic& d : diags.all()) err << "facet bench accuracy: " << d.message << "\n";
      return 1;
    }
  }
  if (!budgets.empty()) {
    const uint32_t samples = options.image_samples > 0 ? options.image_samples : 256;
    BudgetSearch search = search_term_combinations(*study, samples);
    if (!write_report(output, budget_report_of(search, budgets, output), err)) return 1;
    out << budget_answers(search, budgets);
    out << fmt::format("facet bench accuracy: {} combinations, costs from {} -> {}\n", search.combinations.size(),
                       search.device.empty() ? std::string("SPIR-V instruction counts") : search.device, output);
    return 0;
  }
  if (!write_report(output, report_of(*study, output), err)) return 1;
  out << fmt::format("facet bench accuracy: {} rows on {} -> {}\n", study->rows.size(),
                     study->device.empty() ? "no GPU" : study->device, output);
  if (study->shader_float16) {
    size_t half_rows = std::count_if(study->rows.begin(), study->rows.end(), [](const StudyRow& r) { return r.fp16_error.has_value(); });
    out << (*study->shader_float16
                ? fmt::format("facet bench accuracy: fp16 columns: {} rows in real 16-bit arithmetic\n", half_rows)
                : std::string("facet bench accuracy: fp16 columns empty: the device has no shaderFloat16\n"));
  }
  return 0;
}

}  // namespace facet::runtime::accuracy
