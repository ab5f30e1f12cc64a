// Compute pipelines from SPIR-V and one-shot dispatches. A pipeline's layout
// is fixed: storage buffers at set 0, bindings 0..N-1, and an optional push
// constant block. dispatch() records one command buffer, submits it, waits
// for it, and times the dispatch with timestamp queries where the queue has
// them.
//
//   auto pipeline = runtime::create_compute_pipeline(*context, spirv, {.entry = "main", .storage_buffers = 2});
//   auto timing = runtime::dispatch(*context, *pipeline, {.buffers = {&in, &out}, .groups_x = n / 64});
#pragma once

#include <vulkan/vulkan.h>

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "facet/runtime/buffer.h"
#include "facet/runtime/vk_error.h"

namespace facet::runtime {

class Context;

struct ComputeLayout {
  std::string entry = "main";       // the SPIR-V entry point name
  uint32_t storage_buffers = 0;     // set 0, bindings 0..storage_buffers-1
  uint32_t push_constant_bytes = 0; // 0: none; else a multiple of 4, at most 128
  // VK_PIPELINE_CREATE_CAPTURE_STATISTICS_BIT_KHR, so that pipeline_statistics()
  // (facet/runtime/pipeline_statistics.h) can read the driver's statistics;
  // needs a context with pipeline_statistics() on.
  bool capture_statistics = false;
};

// Move-only owner of the shader module, layouts, pipeline and its one
// descriptor set (rewritten by each dispatch, which waits for completion).
class ComputePipeline {
 public:
  ComputePipeline() = default;
  ~ComputePipeline();
  ComputePipeline(ComputePipeline&& other) noexcept;
  ComputePipeline& operator=(ComputePipeline&& other) noexcept;
  ComputePipeline(const ComputePipeline&) = delete;
  ComputePipeline& operator=(const ComputePipeline&) = delete;

  VkPipeline handle() const { return pipeline_; }
  VkPipelineLayout layout() const { return layout_; }
  VkDescriptorSet descriptor_set() const { return set_; }
  const ComputeLayout& interface() const { return interface_; }

 private:
  friend VkResultOf<ComputePipeline> create_compute_pipeline(const Context& context,
                                                             const std::vector<uint32_t>& spirv,
                                                             const ComputeLayout& layout);
  void reset();

  VkDevice device_ = VK_NULL_HANDLE;
  VkShaderModule module_ = VK_NULL_HANDLE;
  VkDescriptorSetLayout set_layout_ = VK_NULL_HANDLE;
  VkPipelineLayout layout_ = VK_NULL_HANDLE;
  VkPipeline pipeline_ = VK_NULL_HANDLE;
  VkDescriptorPool pool_ = VK_NULL_HANDLE;
  VkDescriptorSet set_ = VK_NULL_HANDLE;  // owned by pool_
  ComputeLayout interface_;
};

VkResultOf<ComputePipeline> create_compute_pipeline(const Context& context, const std::vector<uint32_t>& spirv,
                                                    const ComputeLayout& layout);

struct DispatchArgs {
  std::vector<const Buffer*> buffers;       // one per storage buffer binding, in order
  std::vector<std::byte> push_constants;    // exactly push_constant_bytes, or empty when none
  uint32_t groups_x = 1, groups_y = 1, groups_z = 1;
};

struct DispatchTiming {
  std::optional<uint64_t> gpu_ns;  // nullopt when the queue has no timestamps
};

// Binds, dispatches, makes the shader's writes visible to the host, waits.
VkResultOf<DispatchTiming> dispatch(const Context& context, const ComputePipeline& pipeline, const DispatchArgs& args);

}  // namespace facet::runtime
