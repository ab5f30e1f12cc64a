// Compute pipelines and one-shot dispatches (facet/runtime/compute.h).
#include "facet/runtime/compute.h"

#include <fmt/format.h>

#include <utility>

#include "facet/runtime/submission.h"
#include "facet/runtime/vulkan_context.h"

namespace facet::runtime {
namespace {

// Long enough for a slow dispatch on lavapipe under ASan; a hang still ends.
constexpr uint64_t kFenceTimeoutNs = 120'000'000'000ull;

VkResultOf<void> check_args(const ComputePipeline& pipeline, const DispatchArgs& args) {
  const ComputeLayout& layout = pipeline.interface();
  if (!pipeline.handle()) return vk_failure(VkErrorCode::invalid_argument, "dispatch of an empty pipeline");
  if (args.buffers.size() != layout.storage_buffers) {
    return vk_failure(VkErrorCode::invalid_argument, fmt::format("the pipeline takes {} buffers, the dispatch gives {}",
                                                                 layout.storage_buffers, args.buffers.size()));
  }
  for (const Buffer* buffer : args.buffers) {
    if (!buffer || !buffer->handle()) return vk_failure(VkErrorCode::invalid_argument, "dispatch with an empty buffer");
  }
  if (args.push_constants.size() != layout.push_constant_bytes) {
    return vk_failure(VkErrorCode::invalid_argument, fmt::format("the pipeline takes {} push constant bytes, the "
                                                                 "dispatch gives {}",
                                                                 layout.push_constant_bytes, args.push_constants.size()));
  }
  return {};
}

void write_descriptors(const Context& context, const ComputePipeline& pipeline, const DispatchArgs& args) {
  std::vector<VkDescriptorBufferInfo> infos;
  infos.reserve(args.buffers.size());  // the writes point into it
  std::vector<VkWriteDescriptorSet> writes;
  for (uint32_t i = 0; i < args.buffers.size(); ++i) {
    infos.push_back({args.buffers[i]->handle(), 0, VK_WHOLE_SIZE});
    VkWriteDescriptorSet write{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
    write.dstSet = pipeline.descriptor_set();
    write.dstBinding = i;
    write.descriptorCount = 1;
    write.descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
    write.pBufferInfo = &infos.back();
    writes.push_back(write);
  }
  if (!writes.empty()) vkUpdateDescriptorSets(context.device(), uint32_t(writes.size()), writes.data(), 0, nullptr);
}

void record_dispatch(const Context& context, const ComputePipeline& pipeline, const DispatchArgs& args,
                     VkCommandBuffer commands) {
  VkQueryPool queries = context.timestamp_pool();
  if (queries) {
    vkCmdResetQueryPool(commands, queries, 0, 2);
    vkCmdWriteTimestamp(commands, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, queries, 0);
  }
  vkCmdBindPipeline(commands, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline.handle());
  VkDescriptorSet set = pipeline.descriptor_set();
  if (set) {
    vkCmdBindDescriptorSets(commands, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline.layout(), 0, 1, &set, 0, nullptr);
  }
  if (!args.push_constants.empty()) {
    vkCmdPushConstants(commands, pipeline.layout(), VK_SHADER_STAGE_COMPUTE_BIT, 0, uint32_t(args.push_constants.size()),
                       args.push_constants.data());
  }
  vkCmdDispatch(commands, args.groups_x, args.groups_y, args.groups_z);
  if (queries) vkCmdWriteTimestamp(commands, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, queries, 1);
  VkMemoryBarrier barrier{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
  barrier.srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT;
  barrier.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
  vkCmdPipelineBarrier(commands, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 1, &barrier, 0,
                       nullptr, 0, nullptr);
}

VkResultOf<std::optional<uint64_t>> read_timing(const Context& context) {
  VkQueryPool queries = context.timestamp_pool();
  if (!queries) return std::optional<uint64_t>();
  uint64_t ticks[2] = {0, 0};
  VkResult r = vkGetQueryPoolResults(context.device(), queries, 0, 2, sizeof(ticks), ticks, sizeof(uint64_t),
                                     VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT);
  if (r != VK_SUCCESS) return vk_failure(VkErrorCode::submit_failed, "cannot read the timestamp queries", r);
  uint32_t bits = context.device_info().timestamp_valid_bits;
  uint64_t mask = bits >= 64 ? ~0ull : (1ull << bits) - 1;
  uint64_t elapsed = ((ticks[1] & mask) - (ticks[0] & mask)) & mask;
  return std::optional<uint64_t>(uint64_t(double(elapsed) * context.device_info().timestamp_period_ns));
}

}  // namespace

ComputePipeline::~ComputePipeline() { reset(); }

ComputePipeline::ComputePipeline(ComputePipeline&& other) noexcept { *this = std::move(other); }

ComputePipeline& ComputePipeline::operator=(ComputePipeline&& other) noexcept {
  if (this != &other) {
    reset();
    device_ = std::exchange(other.device_, VK_NULL_HANDLE);
    module_ = std::exchange(other.module_, VK_NULL_HANDLE);
    set_layout_ = std::exchange(other.set_layout_, VK_NULL_HANDLE);
    layout_ = std::exchange(other.layout_, VK_NULL_HANDLE);
    pipeline_ = std::exchange(other.pipeline_, VK_NULL_HANDLE);
    pool_ = std::exchange(other.pool_, VK_NULL_HANDLE);
    set_ = std::exchange(other.set_, VK_NULL_HANDLE);
    interface_ = std::exchange(other.interface_, {});
  }
  return *this;
}

void ComputePipeline::reset() {
  if (!device_) return;
  if (pool_) vkDestroyDescriptorPool(device_, pool_, nullptr);  // frees set_
  if (pipeline_) vkDestroyPipeline(device_, pipeline_, nullptr);
  if (layout_) vkDestroyPipelineLayout(device_, layout_, nullptr);
  if (set_layout_) vkDestroyDescriptorSetLayout(device_, set_layout_, nullptr);
  if (module_) vkDestroyShaderModule(device_, module_, nullptr);
  device_ = VK_NULL_HANDLE;
  module_ = VK_NULL_HANDLE;
  set_layout_ = VK_NULL_HANDLE;
  layout_ = VK_NULL_HANDLE;
  pipeline_ = VK_NULL_HANDLE;
  pool_ = VK_NULL_HANDLE;
  set_ = VK_NULL_HANDLE;
  interface_ = {};
}

VkResultOf<DispatchTiming> dispatch(const Context& context, const ComputePipeline& pipeline, const DispatchArgs& args) {
  FACET_TRY(check_args(pipeline, args));
  write_descriptors(context, pipeline, args);
  FACET_TRY(submit_and_wait(
      context, [&](VkCommandBuffer commands) { record_dispatch(context, pipeline, args, commands); },
      {.timeout_ns = kFenceTimeoutNs}));
  VkResultOf<std::optional<uint64_t>> ns = read_timing(context);
  if (!ns) return unexpected(ns.error());
  return DispatchTiming{*ns};
}

}  // namespace facet::runtime
