#include "render/submission.h"

#include "facet/runtime/vulkan_context.h"

namespace facet::runtime {
namespace {

RenderError error(std::string message) { return RenderError{std::move(message)}; }

}  // namespace

Submitter::~Submitter() {
  if (!context_) return;
  if (fence_) vkDestroyFence(context_->device(), fence_, nullptr);
  if (pool_) vkDestroyCommandPool(context_->device(), pool_, nullptr);
}

Result<void, RenderError> Submitter::create(const Context& context) {
  context_ = &context;
  VkCommandPoolCreateInfo pool{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
  pool.flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
  pool.queueFamilyIndex = context.queue_family();
  if (VkResult r = vkCreateCommandPool(context.device(), &pool, nullptr, &pool_); r != VK_SUCCESS) {
    pool_ = VK_NULL_HANDLE;
    return unexpected(error("cannot create a command pool: " + vk_result_name(r)));
  }
  VkCommandBufferAllocateInfo allocate{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
  allocate.commandPool = pool_;
  allocate.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
  allocate.commandBufferCount = 1;
  if (VkResult r = vkAllocateCommandBuffers(context.device(), &allocate, &commands_); r != VK_SUCCESS) {
    return unexpected(error("cannot allocate a command buffer: " + vk_result_name(r)));
  }
  VkFenceCreateInfo fence{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
  if (VkResult r = vkCreateFence(context.device(), &fence, nullptr, &fence_); r != VK_SUCCESS) {
    fence_ = VK_NULL_HANDLE;
    return unexpected(error("cannot create a fence: " + vk_result_name(r)));
  }
  return {};
}

VkResultOf<void> Submitter::submit(const std::function<void(VkCommandBuffer)>& record,
                                   std::chrono::steady_clock::time_point* submitted) {
  VkDevice device = context_->device();
  VkResult r = vkResetCommandBuffer(commands_, 0);
  VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
  begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
  if (r == VK_SUCCESS) r = vkBeginCommandBuffer(commands_, &begin);
  if (r != VK_SUCCESS) return vk_failure(VkErrorCode::submit_failed, "cannot begin the command buffer", r);
  record(commands_);
  r = vkEndCommandBuffer(commands_);
  VkSubmitInfo submit{VK_STRUCTURE_TYPE_SUBMIT_INFO};
  submit.commandBufferCount = 1;
  submit.pCommandBuffers = &commands_;
  if (r == VK_SUCCESS) r = vkQueueSubmit(context_->queue(), 1, &submit, fence_);
  if (submitted) *submitted = std::chrono::steady_clock::now();
  if (r == VK_SUCCESS) r = vkWaitForFences(device, 1, &fence_, VK_TRUE, UINT64_MAX);
  if (r == VK_SUCCESS) r = vkResetFences(device, 1, &fence_);
  if (r != VK_SUCCESS) return vk_failure(VkErrorCode::submit_failed, "recording, submitting or waiting failed", r);
  return {};
}

}  // namespace facet::runtime
