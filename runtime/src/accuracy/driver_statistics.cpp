// measure_driver_statistics: each row's one-evaluation kernel built into a
// pipeline that captures statistics, read through
// VK_KHR_pipeline_executable_properties, and the costs the driver names.
#include "accuracy/driver_statistics.h"

#include <fmt/format.h>

#include "facet/backend.h"
#include "facet/runtime/compute.h"
#include "facet/runtime/pipeline_statistics.h"
#include "facet/runtime/vulkan_context.h"

namespace facet::runtime::accuracy {
namespace {

// The executables of the kernel of one row.
Result<std::vector<PipelineExecutable>> kernel_statistics(const Context& context, const std::string& includes,
                                                          const std::string& hlsl, Diagnostics& diags) {
  Result<ComputePipeline> pipeline = kernel_pipeline(context, includes, hlsl, true, diags);
  FACET_TRY(pipeline);
  VkResultOf<std::vector<PipelineExecutable>> executables = pipeline_statistics(context, pipeline->handle());
  if (!executables) return failure(describe(executables.error()));
  return std::move(*executables);
}

std::optional<uint32_t> minus(std::optional<uint64_t> value, std::optional<uint64_t> null_value) {
  if (!value) return std::nullopt;
  uint64_t base = null_value.value_or(0);
  return uint32_t(*value > base ? *value - base : 0);
}

void fill_row(StudyRow& row, const std::vector<PipelineExecutable>& executables, const DriverCosts& null_costs) {
  DriverCosts costs = driver_costs(executables);
  row.driver_instructions = minus(costs.instructions, null_costs.instructions);
  row.driver_code_bytes = minus(costs.code_bytes, null_costs.code_bytes);
  if (costs.registers) row.driver_registers = uint32_t(*costs.registers);
  row.driver_statistics.clear();
  for (const PipelineExecutable& e : executables) {
    // One executable (a compute pipeline's usual case): the names alone.
    std::string prefix = executables.size() > 1 ? e.name + ": " : std::string();
    for (const DriverStatistic& s : e.statistics) row.driver_statistics.emplace_back(prefix + s.name, s.value);
  }
}

}  // namespace

Result<ComputePipeline> kernel_pipeline(const Context& context, const std::string& includes, const std::string& hlsl,
                                        bool capture, Diagnostics& diags) {
  backend::BackendOptions options;
  options.target = backend::TargetEnv::vulkan1_1;
  auto spirv = backend::compile_hlsl_compute(single_kernel(includes, hlsl), "main", options, diags);
  FACET_TRY(spirv);
  VkResultOf<ComputePipeline> pipeline =
      create_compute_pipeline(context, *spirv, {.entry = "main", .storage_buffers = 2, .capture_statistics = capture});
  if (!pipeline) return failure(describe(pipeline.error()));
  return std::move(*pipeline);
}

Result<void> measure_driver_statistics(const Context& context, const std::vector<RowSpec>& specs, Study& study,
                                       Diagnostics& diags) {
  study.driver_statistics_offered = context.pipeline_statistics();
  if (!context.pipeline_statistics()) return {};
  auto null_model = kernel_statistics(context, "", kNullModel, diags);
  if (!null_model) {
    diags.add(DiagId::driver_bad_option, {},
              "driver statistics of the null kernel: " + null_model.error().reason +
                  " (--no-driver-statistics leaves them out)");
    return failure("driver statistics");
  }
  const DriverCosts null_costs = driver_costs(*null_model);
  for (size_t i = 0; i < specs.size(); ++i) {
    auto executables = kernel_statistics(context, specs[i].includes, specs[i].hlsl, diags);
    if (!executables) {
      diags.add(DiagId::driver_bad_option, {},
                fmt::format("driver statistics of the accuracy row '{}': {} (--no-driver-statistics leaves them out)",
                            specs[i].row.id, executables.error().reason));
      return failure("driver statistics");
    }
    fill_row(study.rows[i], *executables, null_costs);
  }
  return {};
}

}  // namespace facet::runtime::accuracy
