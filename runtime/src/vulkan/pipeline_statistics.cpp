// Driver statistics of compiled pipelines (facet/runtime/pipeline_statistics.h):
// the two queries of VK_KHR_pipeline_executable_properties, the decoding of
// their values and the costs found by name.
#include "facet/runtime/pipeline_statistics.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>

#include "facet/runtime/vulkan_context.h"
#include "facet/support/text.h"

namespace facet::runtime {
namespace {

constexpr std::array<std::string_view, 2> kInstructionNames{"Instructions", "Instruction Count"};
constexpr std::array<std::string_view, 5> kRegisterNames{"Register Count", "Registers", "VGPRs", "numUsedVgprs",
                                                         "GRF registers"};
constexpr std::array<std::string_view, 2> kCodeSizeNames{"Binary Size", "Code size"};

// A fixed-size char array from the driver, up to its first NUL.
std::string text_of(const char (&chars)[VK_MAX_DESCRIPTION_SIZE]) {
  return std::string(chars, strnlen(chars, VK_MAX_DESCRIPTION_SIZE));
}

// The value of the first statistic whose name is in `names` (in the order of
// `names`), when it is a usable count.
std::optional<uint64_t> find_count(const PipelineExecutable& executable, std::span<const std::string_view> names) {
  for (std::string_view wanted : names) {
    for (const DriverStatistic& s : executable.statistics) {
      if (!iequals(trim(s.name), wanted)) continue;
      if (s.format == VK_PIPELINE_EXECUTABLE_STATISTIC_FORMAT_BOOL32_KHR) continue;
      if (!std::isfinite(s.value) || s.value < 0) continue;
      return uint64_t(std::llround(s.value));
    }
  }
  return std::nullopt;
}

void add(std::optional<uint64_t>& total, std::optional<uint64_t> value) {
  if (value) total = total.value_or(0) + *value;
}

VkResultOf<std::vector<VkPipelineExecutablePropertiesKHR>> executable_properties(const Context& context,
                                                                                VkPipeline pipeline) {
  auto get = reinterpret_cast<PFN_vkGetPipelineExecutablePropertiesKHR>(
      vkGetDeviceProcAddr(context.device(), "vkGetPipelineExecutablePropertiesKHR"));
  if (!get) return vk_failure(VkErrorCode::extension_missing, "vkGetPipelineExecutablePropertiesKHR is not available");
  VkPipelineInfoKHR info{VK_STRUCTURE_TYPE_PIPELINE_INFO_KHR};
  info.pipeline = pipeline;
  uint32_t count = 0;
  if (VkResult r = get(context.device(), &info, &count, nullptr); r != VK_SUCCESS) {
    return vk_failure(VkErrorCode::object_failed, "cannot count the pipeline's executables", r);
  }
  std::vector<VkPipelineExecutablePropertiesKHR> properties(count, {VK_STRUCTURE_TYPE_PIPELINE_EXECUTABLE_PROPERTIES_KHR});
  VkResult r = count ? get(context.device(), &info, &count, properties.data()) : VK_SUCCESS;
  if (r != VK_SUCCESS && r != VK_INCOMPLETE) {
    return vk_failure(VkErrorCode::object_failed, "cannot read the pipeline's executables", r);
  }
  properties.resize(count);
  return properties;
}

VkResultOf<std::vector<VkPipelineExecutableStatisticKHR>> executable_statistics(const Context& context,
                                                                               VkPipeline pipeline, uint32_t index) {
  auto get = reinterpret_cast<PFN_vkGetPipelineExecutableStatisticsKHR>(
      vkGetDeviceProcAddr(context.device(), "vkGetPipelineExecutableStatisticsKHR"));
  if (!get) return vk_failure(VkErrorCode::extension_missing, "vkGetPipelineExecutableStatisticsKHR is not available");
  VkPipelineExecutableInfoKHR info{VK_STRUCTURE_TYPE_PIPELINE_EXECUTABLE_INFO_KHR};
  info.pipeline = pipeline;
  info.executableIndex = index;
  uint32_t count = 0;
  if (VkResult r = get(context.device(), &info, &count, nullptr); r != VK_SUCCESS) {
    return vk_failure(VkErrorCode::object_failed, fmt::format("cannot count the statistics of executable {}", index), r);
  }
  std::vector<VkPipelineExecutableStatisticKHR> statistics(count, {VK_STRUCTURE_TYPE_PIPELINE_EXECUTABLE_STATISTIC_KHR});
  VkResult r = count ? get(context.device(), &info, &count, statistics.data()) : VK_SUCCESS;
  if (r != VK_SUCCESS && r != VK_INCOMPLETE) {
    return vk_failure(VkErrorCode::object_failed, fmt::format("cannot read the statistics of executable {}", index), r);
  }
  statistics.resize(count);
  return statistics;
}

}  // namespace

std::optional<double> statistic_value(const VkPipelineExecutableStatisticKHR& statistic) {
  switch (statistic.format) {
    case VK_PIPELINE_EXECUTABLE_STATISTIC_FORMAT_BOOL32_KHR: return statistic.value.b32 ? 1.0 : 0.0;
    case VK_PIPELINE_EXECUTABLE_STATISTIC_FORMAT_INT64_KHR: return double(statistic.value.i64);
    case VK_PIPELINE_EXECUTABLE_STATISTIC_FORMAT_UINT64_KHR: return double(statistic.value.u64);
    case VK_PIPELINE_EXECUTABLE_STATISTIC_FORMAT_FLOAT64_KHR: return statistic.value.f64;
    default: return std::nullopt;
  }
}

std::vector<DriverStatistic> decode_statistics(std::span<const VkPipelineExecutableStatisticKHR> statistics) {
  std::vector<DriverStatistic> out;
  for (const VkPipelineExecutableStatisticKHR& s : statistics) {
    std::optional<double> value = statistic_value(s);
    if (!value) continue;
    out.push_back({.name = std::string(trim(text_of(s.name))), .value = *value, .format = s.format});
  }
  return out;
}

std::span<const std::string_view> instruction_statistic_names() { return kInstructionNames; }
std::span<const std::string_view> register_statistic_names() { return kRegisterNames; }
std::span<const std::string_view> code_size_statistic_names() { return kCodeSizeNames; }

DriverCosts driver_costs(std::span<const PipelineExecutable> executables) {
  DriverCosts costs;
  for (const PipelineExecutable& e : executables) {
    add(costs.instructions, find_count(e, kInstructionNames));
    add(costs.code_bytes, find_count(e, kCodeSizeNames));
    if (std::optional<uint64_t> registers = find_count(e, kRegisterNames)) {
      costs.registers = std::max(costs.registers.value_or(0), *registers);
    }
  }
  return costs;
}

VkResultOf<std::vector<PipelineExecutable>> pipeline_statistics(const Context& context, VkPipeline pipeline) {
  if (!context.pipeline_statistics()) {
    return vk_failure(VkErrorCode::invalid_argument, fmt::format("pipeline statistics are off on {} (no "
                                                                 "VK_KHR_pipeline_executable_properties)",
                                                                 context.device_info().name));
  }
  VkResultOf<std::vector<VkPipelineExecutablePropertiesKHR>> properties = executable_properties(context, pipeline);
  if (!properties) return unexpected(properties.error());
  std::vector<PipelineExecutable> out;
  for (uint32_t i = 0; i < properties->size(); ++i) {
    VkResultOf<std::vector<VkPipelineExecutableStatisticKHR>> statistics = executable_statistics(context, pipeline, i);
    if (!statistics) return unexpected(statistics.error());
    const VkPipelineExecutablePropertiesKHR& p = (*properties)[i];
    out.push_back({.name = std::string(trim(text_of(p.name))), .description = text_of(p.description),
                   .stages = p.stages, .statistics = decode_statistics(*statistics)});
  }
  return out;
}

}  // namespace facet::runtime
