// Evaluates HLSL functions on many input points with a compute shader, so
// that shader code can be compared with its CPU twin (the reference case
// table of reference/include/facet/reference/cases.h has this shape).
//
// Each function is HLSL statements that read the point from `float x[16]`
// and assign `float4 r`, after its `includes`. Several functions compile into
// one shader (the includes once, each body in its own function) and a push
// constant picks the function per dispatch, so a table of cases costs one
// compile instead of one per case.
//
//   std::vector<runtime::EvalFunction> fns = {{.hlsl = "r.x = x[0] * x[0] + 1;", .input_count = 1}};
//   Diagnostics diags;
//   auto evaluator = runtime::compile_evaluator(*context, fns, {}, diags);
//   auto result = runtime::evaluate(*context, *evaluator, 0, points, point_count);
//   // result->values[i * output_count + k]
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "facet/backend.h"
#include "facet/diagnostics.h"
#include "facet/runtime/compute.h"
#include "facet/runtime/vk_error.h"

namespace facet::runtime {

inline constexpr int kMaxEvalInputs = 16;
inline constexpr int kMaxEvalOutputs = 4;
inline constexpr uint32_t kEvalGroupSize = 64;  // [numthreads(64,1,1)]
inline constexpr const char* kEvalEntry = "facet_eval_main";

struct EvalFunction {
  std::string includes;  // #include lines (or any declarations at file scope)
  std::string hlsl;      // statements reading `float x[16]`, assigning `float4 r` (starts at 0)
  int input_count = 1;   // floats per point, 1..16; x[input_count..15] are 0
  int output_count = 1;  // components of r stored, 1..4
};

struct EvaluatorOptions {
  // stdlib_dir empty: backend::default_stdlib_dir(). The target is forced to
  // vulkan1_1 (SPIR-V 1.3, which the 1.2 context runs).
  backend::BackendOptions backend;
};

// A compiled shader for a list of functions (indices as given).
struct FunctionEvaluator {
  ComputePipeline pipeline;
  std::vector<EvalFunction> functions;
};

// The compute shader's HLSL for `functions` (exposed for tests and for
// reading compile errors). Include lines that repeat are kept once.
std::string evaluator_source(const std::vector<EvalFunction>& functions);

// Compiles and creates the pipeline. Errors: invalid_argument (counts out of
// range, no functions), compile_failed (the reasons are in `diags`), or a
// pipeline creation error.
VkResultOf<FunctionEvaluator> compile_evaluator(const Context& context, const std::vector<EvalFunction>& functions,
                                                const EvaluatorOptions& options, Diagnostics& diags);

struct Evaluation {
  std::vector<float> values;      // point_count * output_count, point-major
  std::optional<uint64_t> gpu_ns;  // the dispatch's GPU time, when measurable
};

// Runs function `function` on `points` (point_count * input_count floats, point-major).
VkResultOf<Evaluation> evaluate(const Context& context, const FunctionEvaluator& evaluator, size_t function,
                                std::span<const float> points, uint32_t point_count);

}  // namespace facet::runtime
