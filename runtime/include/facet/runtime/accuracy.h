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

// A row's error in one of the study's test scenes, against the Monte Carlo
// reference render (docs/accuracy.md, "Image-level error"): linear radiance,
// where the white furnace renders 1 (tone-mapping and encoding rows: display
// values in [0, 1]).
struct ImageError {
  std::string scene;     // "directional", "uniform" or "sky"
  double rmse = 0;       // over the pixels the spheres cover
  double max_error = 0;  // the largest |approximation - reference|
  double noise = 0;      // the RMS standard error of that difference: below it, rmse is noise
};

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
  std::vector<ImageError> image;      // per test scene; empty for reference rows
  std::string image_how;              // how the row enters the scenes, in words

  // Driver statistics (VK_KHR_pipeline_executable_properties) of the same
  // one-evaluation kernel the SPIR-V count reads; empty where the device does
  // not report them (Study::driver_statistics_offered) or does not name the cost
  // (facet/runtime/pipeline_statistics.h lists the names read).
  std::optional<uint32_t> driver_instructions;  // minus the null kernel's
  std::optional<uint32_t> driver_registers;     // the kernel's own: a register count does not subtract
  std::optional<uint32_t> driver_code_bytes;    // minus the null kernel's
  std::vector<std::pair<std::string, double>> driver_statistics;  // every statistic as the driver names it, raw

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
  uint32_t image_samples = 256;  // per pixel of the Monte Carlo reference; 0: no image errors
  bool driver_statistics = true;  // read them where the device offers VK_KHR_pipeline_executable_properties
};

// The row's worst scene by RMSE, or nullptr without image errors.
const ImageError* worst_image_error(const StudyRow& row);

struct Study {
  std::string device;       // the device's description, "" without GPU timing
  std::string device_type;  // "cpu", "discrete-gpu", ... (device_type_name); "" when not recorded
  StudyOptions options;
  std::vector<StudyRow> rows;
  // Whether the device offered VK_KHR_pipeline_executable_properties (the rows'
  // driver_* fields); nullopt when not recorded (no GPU, or an older study).
  std::optional<bool> driver_statistics_offered;
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
// Fills each row's image errors: the study's test scenes rendered by the
// Monte Carlo reference (facet/reference/monte_carlo.h) with the row's term
// and with its exact form, `samples` directions per pixel. Reference rows
// get none.
void compute_image_errors(std::vector<StudyRow>& rows, uint32_t samples);

// ---- Choosing by budget (`--budget E`) ----
// A combination of the stdlib's D, V, F and diffuse terms (row ids; "F_exact"
// is the exact Fresnel, a dielectric blended with a conductor by metallic),
// or one of Unity's Standard tiers, with its image error on the test scenes
// against the exact model and its cost.
struct TermCombination {
  std::string name;               // "D_GGX + V_SchlickGGX + F_Schlick + Fd_Lambert", or "BRDF2_Unity_PBS"
  std::vector<std::string> rows;  // the study rows whose costs add up to `cost`
  double image_rmse = 0;          // the worst scene's RMSE
  std::string worst_scene;
  double cost = 0;                // in the search's cost_unit
};
struct BudgetSearch {
  std::string device;     // where the costs were measured ("" without GPU times)
  std::string device_type;
  std::string cost_unit;  // "ps/eval" (the rows' GPU times) or "SPIR-V instr." (without them)
  uint32_t samples = 0;   // per pixel of the Monte Carlo reference
  std::vector<TermCombination> combinations;  // every combination, cheapest first
  std::vector<TermCombination> unity_tiers;   // BRDF1..3, measured the same way
};
// Renders every combination and tier from the same samples; costs are the
// sums of the study's per-row costs.
BudgetSearch search_term_combinations(const Study& costs, uint32_t samples);
// The cheapest combination whose image RMSE is at most `budget`, or nullptr.
const TermCombination* cheapest_within(const BudgetSearch& search, double budget);
// The answers as a markdown table (one row per budget), then Unity's tiers.
std::string budget_answers(const BudgetSearch& search, const std::vector<double>& budgets);
// The combinations' Pareto front and Unity's tiers on one chart (image
// RMSE against cost, log-log), the answers marked; or a page with it.
std::string budget_chart_svg(const BudgetSearch& search, const std::vector<double>& budgets);
std::string budget_html(const BudgetSearch& search, const std::vector<double>& budgets);
std::string budget_json(const BudgetSearch& search, const std::vector<double>& budgets);

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
//  [--no-gpu] [--no-driver-statistics] [--validation] [--image-samples N] [--from study.json]
//  [--budget E ...] --out report.html|report.json|chart.svg`;
// --from redraws a study written before instead of measuring; --budget
// answers for each budget E (the output is then the budget search). Returns
// the exit code.
int run_accuracy_command(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);

}  // namespace facet::runtime::accuracy
