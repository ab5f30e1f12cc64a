// Submission: one command buffer and fence, reused by every frame of a
// renderer; each frame is recorded, submitted and waited for.
#pragma once

#include <vulkan/vulkan.h>

#include <chrono>
#include <functional>

#include "facet/runtime/renderer.h"
#include "facet/runtime/vk_error.h"

namespace facet::runtime {

class Context;

class Submitter {
 public:
  Submitter() = default;
  Submitter(const Submitter&) = delete;
  Submitter& operator=(const Submitter&) = delete;
  ~Submitter();

  // The command pool, buffer and fence on `context`'s queue family.
  Result<void, RenderError> create(const Context& context);
  // Records with `record`, submits and waits. `submitted`: set when
  // vkQueueSubmit returns, before the wait.
  VkResultOf<void> submit(const std::function<void(VkCommandBuffer)>& record,
                          std::chrono::steady_clock::time_point* submitted = nullptr);

 private:
  const Context* context_ = nullptr;
  VkCommandPool pool_ = VK_NULL_HANDLE;
  VkCommandBuffer commands_ = VK_NULL_HANDLE;
  VkFence fence_ = VK_NULL_HANDLE;
};

}  // namespace facet::runtime
