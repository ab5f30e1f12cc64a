// The function evaluator: one compute shader for a list of HLSL functions
// (facet/runtime/evaluator.h).
#include "facet/runtime/evaluator.h"

#include <fmt/format.h>

#include <algorithm>
#include <cstring>
#include <set>

#include "facet/runtime/vulkan_context.h"

namespace facet::runtime {
namespace {

// The push constants; the shader's FacetEvalParams has the same layout.
struct EvalParams {
  uint32_t count = 0;
  uint32_t function = 0;
  uint32_t input_stride = 0;
  uint32_t output_stride = 0;
};

constexpr const char* kInterface = R"(
[[vk::push_constant]] cbuffer FacetEvalParams {
  uint facet_eval_count;
  uint facet_eval_function;
  uint facet_eval_input_stride;
  uint facet_eval_output_stride;
};
[[vk::binding(0, 0)]] StructuredBuffer<float> facet_eval_in;
[[vk::binding(1, 0)]] RWStructuredBuffer<float> facet_eval_out;
)";

// Include lines once each, in first-seen order; other lines as they come.
std::string merged_includes(const std::vector<EvalFunction>& functions) {
  std::string out;
  std::set<std::string> seen;
  for (const EvalFunction& f : functions) {
    size_t pos = 0;
    while (pos < f.includes.size()) {
      size_t eol = f.includes.find('\n', pos);
      std::string line = f.includes.substr(pos, eol == std::string::npos ? std::string::npos : eol - pos);
      pos = eol == std::string::npos ? f.includes.size() : eol + 1;
      bool include = line.find("#include") != std::string::npos;
      if (include && !seen.insert(line).second) continue;
      out += line + "\n";
    }
  }
  return out;
}

std::string function_source(const EvalFunction& f, size_t index) {
  return fmt::format("float4 facet_eval_function_{}(float x[16]) {{\n  float4 r = 0;\n  {{\n{}\n  }}\n  return r;\n}}\n",
                     index, f.hlsl);
}

std::string main_source(size_t function_count) {
  std::string cases;
  for (size_t i = 0; i < function_count; ++i) {
    cases += fmt::format("    case {0}u: r = facet_eval_function_{0}(x); break;\n", i);
  }
  return fmt::format(R"([numthreads({0}, 1, 1)]
void {1}(uint3 id : SV_DispatchThreadID) {{
  uint i = id.x;
  if (i >= facet_eval_count) return;
  float x[16];
  for (uint k = 0; k < 16; ++k) x[k] = 0;
  for (uint k = 0; k < facet_eval_input_stride; ++k) x[k] = facet_eval_in[i * facet_eval_input_stride + k];
  float4 r = 0;
  switch (facet_eval_function) {{
{2}    default: break;
  }}
  for (uint k = 0; k < facet_eval_output_stride; ++k) facet_eval_out[i * facet_eval_output_stride + k] = r[k];
}}
)",
                     kEvalGroupSize, kEvalEntry, cases);
}

VkResultOf<void> check_functions(const std::vector<EvalFunction>& functions) {
  if (functions.empty()) return vk_failure(VkErrorCode::invalid_argument, "the evaluator needs at least one function");
  for (size_t i = 0; i < functions.size(); ++i) {
    const EvalFunction& f = functions[i];
    if (f.input_count < 1 || f.input_count > kMaxEvalInputs || f.output_count < 1 || f.output_count > kMaxEvalOutputs) {
      return vk_failure(VkErrorCode::invalid_argument,
                        fmt::format("function {} has {} inputs and {} outputs; 1..{} and 1..{} are allowed", i,
                                    f.input_count, f.output_count, kMaxEvalInputs, kMaxEvalOutputs));
    }
  }
  return {};
}

VkResultOf<Buffer> filled_buffer(const Context& context, std::span<const float> values, size_t floats) {
  VkResultOf<Buffer> buffer = create_storage_buffer(context, std::max<size_t>(floats, 1) * sizeof(float));
  if (buffer && !values.empty()) std::memcpy(buffer->data(), values.data(), values.size_bytes());
  return buffer;
}

}  // namespace

std::string evaluator_source(const std::vector<EvalFunction>& functions) {
  std::string source = fmt::format("// facet function evaluator: {} function(s)\n", functions.size());
  source += merged_includes(functions);
  source += kInterface;
  for (size_t i = 0; i < functions.size(); ++i) source += function_source(functions[i], i);
  source += main_source(functions.size());
  return source;
}

VkResultOf<FunctionEvaluator> compile_evaluator(const Context& context, const std::vector<EvalFunction>& functions,
                                                const EvaluatorOptions& options, Diagnostics& diags) {
  FACET_TRY(check_functions(functions));
  backend::BackendOptions backend = options.backend;
  // SPIR-V 1.3: glslang 12 decorates HLSL structured buffers BufferBlock,
  // which SPIR-V 1.4+ (the vulkan1_2 target) forbids.
  backend.target = backend::TargetEnv::vulkan1_1;
  if (backend.stdlib_dir.empty()) backend.stdlib_dir = backend::default_stdlib_dir();
  Result<std::vector<uint32_t>> spirv = backend::compile_hlsl_compute(evaluator_source(functions), kEvalEntry, backend, diags);
  if (!spirv) return vk_failure(VkErrorCode::compile_failed, "the evaluator shader did not compile: " + spirv.error().reason);
  VkResultOf<ComputePipeline> pipeline = create_compute_pipeline(
      context, *spirv, {.entry = kEvalEntry, .storage_buffers = 2, .push_constant_bytes = sizeof(EvalParams)});
  if (!pipeline) return unexpected(pipeline.error());
  return FunctionEvaluator{std::move(*pipeline), functions};
}

VkResultOf<Evaluation> evaluate(const Context& context, const FunctionEvaluator& evaluator, size_t function,
                                std::span<const float> points, uint32_t point_count) {
  if (function >= evaluator.functions.size()) {
    return vk_failure(VkErrorCode::invalid_argument,
                      fmt::format("function {} of an evaluator of {}", function, evaluator.functions.size()));
  }
  const EvalFunction& f = evaluator.functions[function];
  if (points.size() != size_t(point_count) * size_t(f.input_count)) {
    return vk_failure(VkErrorCode::invalid_argument, fmt::format("{} points of {} inputs need {} floats, got {}",
                                                                 point_count, f.input_count,
                                                                 size_t(point_count) * f.input_count, points.size()));
  }
  VkResultOf<Buffer> in = filled_buffer(context, points, points.size());
  if (!in) return unexpected(in.error());
  size_t out_floats = size_t(point_count) * size_t(f.output_count);
  VkResultOf<Buffer> out = filled_buffer(context, {}, out_floats);
  if (!out) return unexpected(out.error());

  EvalParams params{point_count, uint32_t(function), uint32_t(f.input_count), uint32_t(f.output_count)};
  DispatchArgs args;
  args.buffers = {&*in, &*out};
  args.push_constants.resize(sizeof(params));
  std::memcpy(args.push_constants.data(), &params, sizeof(params));
  args.groups_x = std::max<uint32_t>(1, (point_count + kEvalGroupSize - 1) / kEvalGroupSize);
  VkResultOf<DispatchTiming> timing = dispatch(context, evaluator.pipeline, args);
  if (!timing) return unexpected(timing.error());

  Evaluation result;
  result.gpu_ns = timing->gpu_ns;
  result.values.resize(out_floats);
  if (out_floats) std::memcpy(result.values.data(), out->data(), out_floats * sizeof(float));
  return result;
}

}  // namespace facet::runtime
