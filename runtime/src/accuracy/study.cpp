// run_study: errors on the CPU, SPIR-V instruction counts, GPU timings.
#include <fmt/format.h>

#include <algorithm>
#include <random>

#include "accuracy/catalogue.h"
#include "accuracy/driver_statistics.h"
#include "accuracy/fp16_rows.h"
#include "facet/backend.h"
#include "facet/runtime/evaluator.h"
#include "facet/runtime/vulkan_context.h"

namespace facet::runtime::accuracy {
namespace {

constexpr int kInputs = 8;

std::string load_inputs() {
  std::string out;
  for (int i = 0; i < kInputs; ++i) out += fmt::format("  float p{} = facet_in[base + {}];\n", i, i);
  return out;
}

}  // namespace

// One evaluation, inputs from a buffer, the value to a buffer: what the
// instruction count measures (and the driver statistics, driver_statistics.cpp).
std::string single_kernel(const std::string& includes, const std::string& hlsl) {
  return includes + "StructuredBuffer<float> facet_in : register(t0);\n"
                    "RWStructuredBuffer<float> facet_out : register(u1);\n"
                    "[numthreads(64, 1, 1)] void main(uint3 id : SV_DispatchThreadID) {\n"
                    "  uint base = id.x * " + std::to_string(kInputs) + ";\n" + load_inputs() +
         "  float value = 0;\n  {\n" + hlsl + "\n  }\n  facet_out[id.x] = value;\n}\n";
}

namespace {

// Instructions inside function bodies (OpFunction .. OpFunctionEnd).
uint32_t body_instructions(const std::vector<uint32_t>& spirv) {
  uint32_t count = 0;
  bool inside = false;
  for (size_t i = 5; i < spirv.size();) {
    uint32_t words = spirv[i] >> 16, opcode = spirv[i] & 0xffff;
    if (words == 0) break;
    if (opcode == 54) inside = true;   // OpFunction
    if (inside) ++count;
    if (opcode == 56) inside = false;  // OpFunctionEnd
    i += words;
  }
  return count;
}

Result<uint32_t> instruction_count(const std::string& includes, const std::string& hlsl, Diagnostics& diags) {
  backend::BackendOptions options;
  options.target = backend::TargetEnv::vulkan1_1;
  auto spirv = backend::compile_hlsl_compute(single_kernel(includes, hlsl), "main", options, diags);
  FACET_TRY(spirv);
  return body_instructions(*spirv);
}

// K evaluations per invocation; each one's inputs depend on the running sum,
// so nothing is hoisted out of the loop or shared between iterations.
EvalFunction timed_function(const std::string& includes, const std::string& hlsl, uint32_t evaluations) {
  std::string body = "float acc = 0;\n[loop] for (uint k = 0; k < " + std::to_string(evaluations) + "; ++k) {\n"
                     "  float s = acc * 1e-30;\n";
  for (int i = 0; i < kInputs; ++i) body += fmt::format("  float p{} = x[{}] + s;\n", i, i);
  body += "  float value = 0;\n  {\n" + hlsl + "\n  }\n  acc += value;\n}\nr.x = acc;";
  return {.includes = includes, .hlsl = body, .input_count = kInputs, .output_count = 1};
}

std::vector<float> varying_inputs(uint32_t points) {
  std::mt19937 rng(20261201);
  std::uniform_real_distribution<float> dist(0.05f, 1.0f);
  std::vector<float> out(size_t(points) * kInputs);
  for (float& v : out) v = dist(rng);
  return out;
}

Result<double> median_gpu_ns(const Context& context, const FunctionEvaluator& evaluator, size_t function,
                             const std::vector<float>& points, uint32_t count, uint32_t frames, Diagnostics& diags) {
  std::vector<double> times;
  for (uint32_t f = 0; f < frames + 1; ++f) {
    auto result = evaluate(context, evaluator, function, points, count);
    if (!result || !result->gpu_ns) {
      diags.add(DiagId::driver_bad_option, {}, "the device gives no timestamps for the accuracy study's passes");
      return failure("no timing");
    }
    if (f > 0) times.push_back(double(*result->gpu_ns));  // the first dispatch warms up
  }
  std::nth_element(times.begin(), times.begin() + times.size() / 2, times.end());
  return times[times.size() / 2];
}

// ---- the fp16 columns: real 16-bit arithmetic (fp16_rows.h) ----------------

constexpr const char* kHalfIntrinsics = "#include \"FacetHalf.hlsl\"\n";

// The inputs converted to half once; then the fp32 pass's loop, in half.
EvalFunction timed_fp16_function(const std::string& includes, const std::string& hlsl, uint32_t evaluations) {
  std::string body;
  for (int i = 0; i < kInputs; ++i) body += fmt::format("half h{} = (half)x[{}];\n", i, i);
  body += "float acc = 0;\n[loop] for (uint k = 0; k < " + std::to_string(evaluations) + "; ++k) {\n"
          "  half s = (half)(acc * 1e-30);\n";
  for (int i = 0; i < kInputs; ++i) body += fmt::format("  half p{} = h{} + s;\n", i, i);
  body += "  half value = 0.0h;\n  {\n" + backend::to_half_precision(hlsl) + "\n  }\n  acc += (float)value;\n}\nr.x = acc;";
  return {.includes = kHalfIntrinsics + includes, .hlsl = body, .input_count = kInputs, .output_count = 1};
}

// One evaluation at the point's inputs, in half; the value back as float.
EvalFunction fp16_error_function(const std::string& includes, const std::string& hlsl) {
  std::string body;
  for (int i = 0; i < kInputs; ++i) body += fmt::format("half p{} = (half)x[{}];\n", i, i);
  body += "half value = 0.0h;\n{\n" + backend::to_half_precision(hlsl) + "\n}\nr.x = (float)value;";
  return {.includes = kHalfIntrinsics + includes, .hlsl = body, .input_count = kInputs, .output_count = 1};
}

EvaluatorOptions fp16_evaluator_options() {
  EvaluatorOptions options;
  options.backend.stdlib_dir = backend::default_stdlib_dir();
  options.backend.hlsl_16bit_types = true;
  options.backend.resolver = backend::half_precision_stdlib(options.backend.stdlib_dir);
  return options;
}

std::vector<float> flat_points(const std::vector<Inputs>& points) {
  std::vector<float> out;
  for (const Inputs& p : points) out.insert(out.end(), p.begin(), p.end());
  return out;
}

// Fills fp16_error, fp16_ns_per_eval and fp16_domain of the rows fp16_rows()
// names; nothing (and study.shader_float16 = false) without shaderFloat16.
Result<void> measure_fp16(const Context& context, const StudyOptions& options, const std::vector<RowSpec>& specs,
                          Study& study, Diagnostics& diags) {
  study.shader_float16 = context.shader_float16();
  if (!context.shader_float16()) return {};
  std::vector<Fp16Row> rows = fp16_rows();
  std::vector<size_t> at;  // rows[i] is study.rows[at[i]]
  std::vector<EvalFunction> functions{timed_fp16_function("", kNullModel, options.evaluations)};
  for (const Fp16Row& row : rows) {
    auto spec = std::find_if(specs.begin(), specs.end(), [&](const RowSpec& s) { return s.row.id == row.id; });
    if (spec == specs.end()) FACET_ICE(("fp16 row '" + row.id + "' is not in the catalogue").c_str());
    at.push_back(size_t(spec - specs.begin()));
    functions.push_back(timed_fp16_function(spec->includes, spec->hlsl, options.evaluations));
    functions.push_back(fp16_error_function(spec->includes, row.hlsl.empty() ? spec->hlsl : row.hlsl));
  }
  auto evaluator = compile_evaluator(context, functions, fp16_evaluator_options(), diags);
  if (!evaluator) return failure("the fp16 passes did not compile");
  const uint32_t points = options.width * options.height;
  const std::vector<float> inputs = varying_inputs(points);
  auto null_ns = median_gpu_ns(context, *evaluator, 0, inputs, points, options.frames, diags);
  FACET_TRY(null_ns);
  const double evaluations = double(points) * options.evaluations;
  for (size_t i = 0; i < rows.size(); ++i) {
    StudyRow& row = study.rows[at[i]];
    auto ns = median_gpu_ns(context, *evaluator, 1 + 2 * i, inputs, points, options.frames, diags);
    FACET_TRY(ns);
    row.fp16_ns_per_eval = std::max(0.0, *ns - *null_ns) / evaluations;
    std::vector<float> domain = flat_points(rows[i].points);
    auto values = evaluate(context, *evaluator, 2 + 2 * i, domain, uint32_t(rows[i].points.size()));
    if (!values) {
      diags.add(DiagId::driver_bad_option, {}, "the fp16 row '" + row.id + "' did not run: " + describe(values.error()));
      return failure("fp16 evaluation");
    }
    row.fp16_error = max_relative_error(values->values, rows[i]);
    row.fp16_domain = rows[i].domain;
  }
  return {};
}

// ---- end of the fp16 columns ------------------------------------------------

Result<void> measure_gpu(const StudyOptions& options, const std::vector<RowSpec>& specs, Study& study,
                         Diagnostics& diags) {
  auto context = create_context(
      {.device = options.device, .validation = options.validation, .pipeline_statistics = options.driver_statistics});
  if (!context) {
    diags.add(DiagId::driver_bad_option, {}, "no Vulkan device for the accuracy study: " + describe(context.error()));
    return failure("no device");
  }
  study.device = (*context)->device_info().name;
  study.device_type = std::string(device_type_name((*context)->device_info().type));
  if (options.driver_statistics) FACET_TRY(measure_driver_statistics(**context, specs, study, diags));
  std::vector<EvalFunction> functions{timed_function("", kNullModel, options.evaluations)};
  for (const RowSpec& s : specs) functions.push_back(timed_function(s.includes, s.hlsl, options.evaluations));
  auto evaluator = compile_evaluator(**context, functions, {}, diags);
  if (!evaluator) return failure("the timed passes did not compile");
  const uint32_t points = options.width * options.height;
  const std::vector<float> inputs = varying_inputs(points);
  auto null_ns = median_gpu_ns(**context, *evaluator, 0, inputs, points, options.frames, diags);
  FACET_TRY(null_ns);
  const double evaluations = double(points) * options.evaluations;
  for (size_t i = 0; i < specs.size(); ++i) {
    auto ns = median_gpu_ns(**context, *evaluator, i + 1, inputs, points, options.frames, diags);
    FACET_TRY(ns);
    study.rows[i].ns_per_eval = std::max(0.0, *ns - *null_ns) / evaluations;
  }
  FACET_TRY(measure_fp16(**context, options, specs, study, diags));
  if (options.validation && !(*context)->messages().empty()) {
    diags.add(DiagId::driver_bad_option, {}, "validation layers reported: " + (*context)->messages()[0].text);
    return failure("validation");
  }
  return {};
}

}  // namespace

const ImageError* worst_image_error(const StudyRow& row) {
  const ImageError* worst = nullptr;
  for (const ImageError& e : row.image) {
    if (!worst || !(e.rmse <= worst->rmse)) worst = &e;
  }
  return worst;
}

std::vector<StudyRow> compute_errors() {
  std::vector<StudyRow> rows;
  for (const RowSpec& s : catalogue()) {
    StudyRow row = s.row;
    if (s.measure) s.measure(row);
    rows.push_back(std::move(row));
  }
  return rows;
}

Result<Study> run_study(const StudyOptions& options, Diagnostics& diags) {
  Study study{.options = options, .rows = compute_errors()};
  const std::vector<RowSpec> specs = catalogue();
  auto null_count = instruction_count("", kNullModel, diags);
  FACET_TRY(null_count);
  for (size_t i = 0; i < specs.size(); ++i) {
    auto count = instruction_count(specs[i].includes, specs[i].hlsl, diags);
    if (!count) {
      diags.add(DiagId::driver_bad_option, {}, "the accuracy row '" + specs[i].row.id + "' does not compile");
      return failure("row does not compile");
    }
    study.rows[i].spirv_instructions = *count > *null_count ? *count - *null_count : 0;
  }
  if (options.gpu) {
    auto measured = measure_gpu(options, specs, study, diags);
    FACET_TRY(measured);
  }
  // Last: the CPU's longest part, after everything that can fail.
  if (options.image_samples > 0) compute_image_errors(study.rows, options.image_samples);
  return study;
}

}  // namespace facet::runtime::accuracy
