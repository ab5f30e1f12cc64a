// The accuracy-versus-cost study (`facet bench accuracy`, docs/accuracy.md):
// for each approximation in the lighting library, its error against the
// exact reference (computed on the CPU twins in double precision), its
// static cost (SPIR-V instructions after spirv-opt) and its measured cost
// (GPU timestamps of a compute pass over a full-screen grid that evaluates
// it K times per invocation with per-invocation inputs, minus a null pass).
#pragma once

#include <cstdint>
#include <optional>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

#include "facet/diagnostics.h"
#include "facet/result.h"

namespace facet::runtime::accuracy {

struct StudyRow {
  std::string id;         // "V_SmithGGXCorrelatedFast"
  std::string group;      // "V", "F", "diffuse", "specular", "Standard", "IBL", "tonemap", "sRGB"
  std::string name;       // what is measured, in words
  std::string reference;  // what it is measured against
  std::string metric;     // what `error` is
  double error = 0;       // the headline error (0 for reference rows)
  std::string detail;     // further numbers
  std::string anchor;     // the measured anchor (docs/accuracy.md, "Agreement with the measured anchors"), "" when none
  uint32_t spirv_instructions = 0;    // one evaluation, after spirv-opt, minus the null kernel
  std::optional<double> ns_per_eval;  // GPU time per evaluation, minus the null pass

  // Driver statistics (VK_KHR_pipeline_executable_properties) of the same
  // one-evaluation kernel the SPIR-V count reads; empty where the device does
  // not report them (Study::driver_statistics_offered) or does not name the cost
  // (facet/runtime/pipeline_statistics.h lists the names read).
  std::optional<uint32_t> driver_instructions;  // minus the null kernel's
  std::optional<uint32_t> driver_registers;     // the kernel's own: a register count does not subtract
  std::optional<uint32_t> driver_code_bytes;    // minus the null kernel's
  std::vector<std::pair<std::string, double>> driver_statistics;  // every statistic as the driver names it, raw
};

struct StudyOptions {
  std::string device;            // runtime device selector ("" = lavapipe)
  bool validation = false;
  uint32_t width = 256, height = 256;  // the invocation grid of the timed pass
  uint32_t evaluations = 8;      // K: evaluations per invocation
  uint32_t frames = 11;          // timed dispatches; the median is reported
  bool gpu = true;               // false: CPU errors and static cost only
  bool driver_statistics = true;  // read them where the device offers VK_KHR_pipeline_executable_properties
};

struct Study {
  std::string device;       // the device's description, "" without GPU timing
  std::string device_type;  // "cpu", "discrete-gpu", ... (device_type_name); "" when not recorded
  StudyOptions options;
  std::vector<StudyRow> rows;
  // Whether the device offered VK_KHR_pipeline_executable_properties (the rows'
  // driver_* fields); nullopt when not recorded (no GPU, or an older study).
  std::optional<bool> driver_statistics_offered;
};

// True when the times come from a CPU implementation of Vulkan (lavapipe,
// SwiftShader): the device type says so, or, for a study that did not
// record it, the device's name does. Such times rank rows only.
bool timed_on_cpu(const Study& study);

// What a row's error measures; the chart draws one panel per kind.
enum class ErrorKind {
  none,       // a reference row (metric "-")
  lobe,       // relative L1 of a lobe against the reference lobe
  energy,     // directional albedo above 1, or energy lost
  pointwise,  // the largest absolute difference over the input range
  fp16,       // the largest relative error of a half-precision form
};
// From the row's metric text (so that studies read from JSON classify too).
ErrorKind error_kind(const StudyRow& row);

// Every row of the catalogue, errors computed, costs measured. Errors
// (no device, a kernel that does not compile) are diagnostics.
Result<Study> run_study(const StudyOptions& options, Diagnostics& diags);

// The CPU part only (errors), for tests: no Vulkan, no compiles.
std::vector<StudyRow> compute_errors();

std::string study_json(const Study& study);
// A study written by study_json (device_type may be missing: older files).
Result<Study> study_from_json(const std::string& text);
// The Pareto chart as one SVG: one panel per ErrorKind (error against GPU
// time per evaluation, log-log, all panels on the same time axis), points
// coloured by the row's group (its model family), filled where Pareto-optimal
// within the family and panel, every point labelled without overlaps
// (facet/runtime/chart.h), and a caveat line when timed_on_cpu. Without
// timed rows: a one-line SVG that says so.
std::string study_chart_svg(const Study& study);
// One self-contained page: the chart and the table.
std::string study_html(const Study& study);

// `facet bench accuracy [--device D] [--width W --height H] [-K N] [--frames N]
//  [--no-gpu] [--no-driver-statistics] [--validation] [--from study.json] --out report.html|report.json|chart.svg`;
// --from redraws a study written before instead of measuring. Returns the exit code.
int run_accuracy_command(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);

}  // namespace facet::runtime::accuracy
