// What the driver's compiler says about a pipeline it built, through
// VK_KHR_pipeline_executable_properties: each executable (one per stage for
// a compute pipeline) with its statistics as named numbers, and the three
// costs that compare across drivers (instructions, registers, code size),
// found by the names the drivers give them. The decoding and the name
// matching are pure functions, tested without a device that has the
// extension; lavapipe has none.
//
//   auto context = runtime::create_context({.device = "NVIDIA", .pipeline_statistics = true});
//   if ((*context)->pipeline_statistics()) {
//     auto pipeline = runtime::create_compute_pipeline(**context, spirv,
//                                                      {.storage_buffers = 2, .capture_statistics = true});
//     auto executables = runtime::pipeline_statistics(**context, pipeline->handle());
//     runtime::DriverCosts costs = runtime::driver_costs(*executables);  // costs.registers, ...
//   }
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "facet/runtime/vk_error.h"

namespace facet::runtime {

class Context;

// One statistic: its name as the driver spells it (trimmed) and its value.
struct DriverStatistic {
  std::string name;
  double value = 0;  // bool32 as 0 or 1; int64, uint64 (exact below 2^53) and float64 as numbers
  VkPipelineExecutableStatisticFormatKHR format = VK_PIPELINE_EXECUTABLE_STATISTIC_FORMAT_UINT64_KHR;
};

// One executable of a pipeline, its statistics in the driver's order.
struct PipelineExecutable {
  std::string name;         // "Compute Shader", "CS SIMD16", ...
  std::string description;
  VkShaderStageFlags stages = 0;
  std::vector<DriverStatistic> statistics;
};

// The value of one statistic as a number, read from the union member its
// format names; nullopt for a format this version of the API does not define.
std::optional<double> statistic_value(const VkPipelineExecutableStatisticKHR& statistic);

// Every statistic with a known format, in order (others are left out).
std::vector<DriverStatistic> decode_statistics(std::span<const VkPipelineExecutableStatisticKHR> statistics);

// The statistic names each cost is read from, compared without case after
// trimming, whole names only ("Spilled VGPRs" is not "VGPRs"). The first
// name in a list that an executable has wins.
//   instructions: "Instructions" (RADV, recent ANV), "Instruction Count" (older ANV)
//   registers:    "Register Count" (NVIDIA), "Registers" (a spelling no driver above uses, kept
//                 for others), "VGPRs" (RADV), "numUsedVgprs" (AMDVLK), "GRF registers" (ANV):
//                 per-thread (vector) registers
//   code bytes:   "Binary Size" (NVIDIA), "Code size" (RADV, ANV)
std::span<const std::string_view> instruction_statistic_names();
std::span<const std::string_view> register_statistic_names();
std::span<const std::string_view> code_size_statistic_names();

// The costs of a pipeline: instructions and code bytes summed over its
// executables, registers their largest. nullopt where no executable has a
// statistic of that kind (bool32 statistics and negative or non-finite values
// never count).
struct DriverCosts {
  std::optional<uint64_t> instructions;
  std::optional<uint64_t> registers;
  std::optional<uint64_t> code_bytes;
};
DriverCosts driver_costs(std::span<const PipelineExecutable> executables);

// The executables of `pipeline` with their statistics. The pipeline must
// have been created with ComputeLayout::capture_statistics (or the flag) on a
// context whose pipeline_statistics() is true. Errors: invalid_argument (the
// context has them off), extension_missing (no entry points), object_failed.
VkResultOf<std::vector<PipelineExecutable>> pipeline_statistics(const Context& context, VkPipeline pipeline);

}  // namespace facet::runtime
