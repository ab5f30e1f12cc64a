#include "facet/runtime/submission.h"

#include <utility>

#include "facet/runtime/vulkan_context.h"

namespace facet::runtime {
namespace {

VkResultOf<void> allocate(VkDevice device, VkCommandPool pool, VkCommandBuffer& commands, VkFence& fence) {
  VkCommandBufferAllocateInfo allocate{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
  allocate.commandPool = pool;
  allocate.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
  allocate.commandBufferCount = 1;
  if (VkResult r = vkAllocateCommandBuffers(device, &allocate, &commands); r != VK_SUCCESS) {
    commands = VK_NULL_HANDLE;
    return vk_failure(VkErrorCode::submit_failed, "cannot allocate a command buffer", r);
  }
  VkFenceCreateInfo fence_info{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
  if (VkResult r = vkCreateFence(device, &fence_info, nullptr, &fence); r != VK_SUCCESS) {
    fence = VK_NULL_HANDLE;
    return vk_failure(VkErrorCode::submit_failed, "cannot create a fence", r);
  }
  return {};
}

}  // namespace

VkResultOf<Submission> Submission::create(const Context& context) {
  Submission s;
  s.device_ = context.device();
  s.queue_ = context.queue();
  VkCommandPoolCreateInfo pool{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
  pool.flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
  pool.queueFamilyIndex = context.queue_family();
  if (VkResult r = vkCreateCommandPool(s.device_, &pool, nullptr, &s.pool_); r != VK_SUCCESS) {
    s.pool_ = VK_NULL_HANDLE;
    return vk_failure(VkErrorCode::object_failed, "cannot create a command pool", r);
  }
  s.owns_pool_ = true;
  FACET_TRY(allocate(s.device_, s.pool_, s.commands_, s.fence_));
  return s;
}

Submission::Submission(Submission&& other) noexcept { *this = std::move(other); }

Submission& Submission::operator=(Submission&& other) noexcept {
  if (this == &other) return *this;
  release();
  device_ = std::exchange(other.device_, VK_NULL_HANDLE);
  queue_ = std::exchange(other.queue_, VK_NULL_HANDLE);
  pool_ = std::exchange(other.pool_, VK_NULL_HANDLE);
  owns_pool_ = std::exchange(other.owns_pool_, false);
  commands_ = std::exchange(other.commands_, VK_NULL_HANDLE);
  fence_ = std::exchange(other.fence_, VK_NULL_HANDLE);
  used_ = std::exchange(other.used_, false);
  pending_ = std::exchange(other.pending_, false);
  return *this;
}

Submission::~Submission() { release(); }

void Submission::release() {
  if (!device_) return;
  if (pending_) vkQueueWaitIdle(queue_);  // the fence and command buffer may not go while the queue uses them
  if (fence_) vkDestroyFence(device_, fence_, nullptr);
  if (owns_pool_ && pool_) {
    vkDestroyCommandPool(device_, pool_, nullptr);  // frees its command buffer
  } else if (commands_) {
    vkFreeCommandBuffers(device_, pool_, 1, &commands_);
  }
  device_ = VK_NULL_HANDLE;
}

VkResultOf<void> Submission::submit(const std::function<void(VkCommandBuffer)>& record, const SubmitOptions& options) {
  // Only a pool of its own lets the buffer be reset; the context's transient one serves a single submission.
  if (used_ && !owns_pool_) return vk_failure(VkErrorCode::invalid_argument, "a one-off submission submitted twice");
  if (pending_) return vk_failure(VkErrorCode::submit_failed, "the previous submission did not finish");
  VkResult r = used_ ? vkResetCommandBuffer(commands_, 0) : VK_SUCCESS;
  if (r == VK_SUCCESS) r = vkResetFences(device_, 1, &fence_);
  used_ = true;
  VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
  begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
  if (r == VK_SUCCESS) r = vkBeginCommandBuffer(commands_, &begin);
  if (r != VK_SUCCESS) return vk_failure(VkErrorCode::submit_failed, "cannot begin the command buffer", r);
  record(commands_);
  if (r = vkEndCommandBuffer(commands_); r != VK_SUCCESS) {
    return vk_failure(VkErrorCode::submit_failed, "cannot end the command buffer", r);
  }
  VkSubmitInfo submit{VK_STRUCTURE_TYPE_SUBMIT_INFO};
  submit.commandBufferCount = 1;
  submit.pCommandBuffers = &commands_;
  r = vkQueueSubmit(queue_, 1, &submit, fence_);
  if (options.submitted) *options.submitted = std::chrono::steady_clock::now();
  if (r != VK_SUCCESS) return vk_failure(VkErrorCode::submit_failed, "vkQueueSubmit failed", r);
  pending_ = true;
  if (r = vkWaitForFences(device_, 1, &fence_, VK_TRUE, options.timeout_ns); r != VK_SUCCESS) {
    return vk_failure(VkErrorCode::submit_failed, "waiting for the queue failed", r);
  }
  pending_ = false;
  return {};
}

VkResultOf<void> submit_and_wait(const Context& context, const std::function<void(VkCommandBuffer)>& record,
                                 const SubmitOptions& options) {
  Submission once;
  once.device_ = context.device();
  once.queue_ = context.queue();
  once.pool_ = context.command_pool();
  FACET_TRY(allocate(once.device_, once.pool_, once.commands_, once.fence_));
  return once.submit(record, options);
}

}  // namespace facet::runtime
