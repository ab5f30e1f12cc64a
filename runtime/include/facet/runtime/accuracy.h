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

  // Real 16-bit arithmetic on the GPU (docs/accuracy.md, "The fp16 columns"):
  // the row's HLSL and the stdlib with half for float, on a device with
  // shaderFloat16. Empty for rows not evaluated in half, without GPU timing,
  // and on devices without shaderFloat16.
  std::optional<double> fp16_error;        // max relative error against the fp64 twin over fp16_domain; inf: overflow
  std::optional<double> fp16_ns_per_eval;  // as ns_per_eval: the half kernel minus the half null pass
  std::string fp16_domain;                 // the inputs fp16_error is taken over, in words
};

struct StudyOptions {
  std::string device;            // runtime device selector ("" = lavapipe)
  bool validation = false;
  uint32_t width = 256, height = 256;  // the invocation grid of the timed pass
  uint32_t evaluations = 8;      // K: evaluations per invocation
  uint32_t frames = 11;          // timed dispatches; the median is reported
  bool gpu = true;               // false: CPU errors and static cost only
};

struct Study {
  std::string device;       // the device's description, "" without GPU timing
  std::string device_type;  // "cpu", "discrete-gpu", ... (device_type_name); "" when not recorded
  StudyOptions options;
  std::vector<StudyRow> rows;
  // Whether the device ran the fp16 columns' 16-bit kernels (shaderFloat16);
  // nullopt when not recorded (no GPU, or a study written before them).
  std::optional<bool> shader_float16;
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
//  [--no-gpu] [--validation] [--from study.json] --out report.html|report.json|chart.svg`;
// --from redraws a study written before instead of measuring. Returns the exit code.
int run_accuracy_command(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);

}  // namespace facet::runtime::accuracy
