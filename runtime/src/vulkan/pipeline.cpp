// create_compute_pipeline: shader module -> set layout (N storage buffers)
// -> pipeline layout (+ push constants) -> pipeline -> descriptor set.
#include <fmt/format.h>

#include "facet/runtime/compute.h"
#include "facet/runtime/vulkan_context.h"

namespace facet::runtime {
namespace {

constexpr uint32_t kMaxPushConstantBytes = 128;  // Vulkan's guaranteed minimum

VkResultOf<void> check_layout(const std::vector<uint32_t>& spirv, const ComputeLayout& layout) {
  if (spirv.size() < 5 || spirv[0] != 0x07230203u) {
    return vk_failure(VkErrorCode::invalid_argument, "the shader is not SPIR-V (no magic number)");
  }
  if (layout.push_constant_bytes % 4 != 0 || layout.push_constant_bytes > kMaxPushConstantBytes) {
    return vk_failure(VkErrorCode::invalid_argument,
                      fmt::format("push constants must be a multiple of 4 bytes, at most {}; got {}",
                                  kMaxPushConstantBytes, layout.push_constant_bytes));
  }
  return {};
}

}  // namespace

// A friend of ComputePipeline: fills its handles one by one, so that a
// failure part-way leaves an object whose destructor frees what exists.
VkResultOf<ComputePipeline> create_compute_pipeline(const Context& context, const std::vector<uint32_t>& spirv,
                                                    const ComputeLayout& layout) {
  FACET_TRY(check_layout(spirv, layout));
  if (layout.capture_statistics && !context.pipeline_statistics()) {
    return vk_failure(VkErrorCode::invalid_argument, "capture_statistics needs a context with pipeline statistics on "
                                                     "(VK_KHR_pipeline_executable_properties)");
  }
  ComputePipeline p;
  p.device_ = context.device();
  p.interface_ = layout;
  VkShaderModuleCreateInfo module{VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
  module.codeSize = spirv.size() * sizeof(uint32_t);
  module.pCode = spirv.data();
  if (VkResult r = vkCreateShaderModule(p.device_, &module, nullptr, &p.module_); r != VK_SUCCESS) {
    return vk_failure(VkErrorCode::object_failed, "cannot create the shader module", r);
  }

  std::vector<VkDescriptorSetLayoutBinding> bindings;
  for (uint32_t i = 0; i < layout.storage_buffers; ++i) {
    bindings.push_back({i, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, VK_SHADER_STAGE_COMPUTE_BIT, nullptr});
  }
  VkDescriptorSetLayoutCreateInfo set_layout{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
  set_layout.bindingCount = uint32_t(bindings.size());
  set_layout.pBindings = bindings.data();
  if (VkResult r = vkCreateDescriptorSetLayout(p.device_, &set_layout, nullptr, &p.set_layout_); r != VK_SUCCESS) {
    return vk_failure(VkErrorCode::object_failed, "cannot create the descriptor set layout", r);
  }

  VkPushConstantRange push{VK_SHADER_STAGE_COMPUTE_BIT, 0, layout.push_constant_bytes};
  VkPipelineLayoutCreateInfo pipeline_layout{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
  pipeline_layout.setLayoutCount = 1;
  pipeline_layout.pSetLayouts = &p.set_layout_;
  pipeline_layout.pushConstantRangeCount = layout.push_constant_bytes ? 1 : 0;
  pipeline_layout.pPushConstantRanges = &push;
  if (VkResult r = vkCreatePipelineLayout(p.device_, &pipeline_layout, nullptr, &p.layout_); r != VK_SUCCESS) {
    return vk_failure(VkErrorCode::object_failed, "cannot create the pipeline layout", r);
  }

  VkComputePipelineCreateInfo info{VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO};
  info.stage = {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO};
  info.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT;
  info.stage.module = p.module_;
  info.stage.pName = p.interface_.entry.c_str();
  info.layout = p.layout_;
  if (layout.capture_statistics) info.flags |= VK_PIPELINE_CREATE_CAPTURE_STATISTICS_BIT_KHR;
  if (VkResult r = vkCreateComputePipelines(p.device_, VK_NULL_HANDLE, 1, &info, nullptr, &p.pipeline_);
      r != VK_SUCCESS) {
    p.pipeline_ = VK_NULL_HANDLE;
    return vk_failure(VkErrorCode::object_failed, fmt::format("cannot create the compute pipeline '{}'", layout.entry), r);
  }

  if (layout.storage_buffers == 0) return p;
  VkDescriptorPoolSize size{VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, layout.storage_buffers};
  VkDescriptorPoolCreateInfo pool{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
  pool.maxSets = 1;
  pool.poolSizeCount = 1;
  pool.pPoolSizes = &size;
  if (VkResult r = vkCreateDescriptorPool(p.device_, &pool, nullptr, &p.pool_); r != VK_SUCCESS) {
    return vk_failure(VkErrorCode::object_failed, "cannot create the descriptor pool", r);
  }
  VkDescriptorSetAllocateInfo allocate{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
  allocate.descriptorPool = p.pool_;
  allocate.descriptorSetCount = 1;
  allocate.pSetLayouts = &p.set_layout_;
  if (VkResult r = vkAllocateDescriptorSets(p.device_, &allocate, &p.set_); r != VK_SUCCESS) {
    return vk_failure(VkErrorCode::object_failed, "cannot allocate the descriptor set", r);
  }
  return p;
}

}  // namespace facet::runtime
