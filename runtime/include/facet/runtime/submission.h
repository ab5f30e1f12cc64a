// Recording, submitting and waiting for commands on a context's queue: the
// one path by which facet runs GPU work. A Submission keeps its command
// buffer and fence for submission after submission (a Renderer's frames:
// nothing is allocated per frame); submit_and_wait runs a single one (an
// upload, a read-back, a compute dispatch).
#pragma once

#include <vulkan/vulkan.h>

#include <chrono>
#include <cstdint>
#include <functional>

#include "facet/runtime/vk_error.h"

namespace facet::runtime {

class Context;

struct SubmitOptions {
  // How long to wait for the queue: work that does not finish in time (a
  // hung kernel) is an error (submit_failed), not a hang.
  uint64_t timeout_ns = UINT64_MAX;
  // Set when vkQueueSubmit returns, before the wait (a frame's CPU time).
  std::chrono::steady_clock::time_point* submitted = nullptr;
};

class Submission {
 public:
  // A command pool of its own on the context's queue family, with one
  // command buffer reset before each submission, and a fence. The context
  // must outlive it.
  static VkResultOf<Submission> create(const Context& context);
  Submission(Submission&& other) noexcept;
  Submission& operator=(Submission&& other) noexcept;
  ~Submission();

  // Records with `record`, submits, and waits until the queue has run it.
  // A wait that fails or times out leaves the work on the queue: the
  // Submission refuses further submissions, and its destruction waits for
  // the queue before freeing what the work uses.
  VkResultOf<void> submit(const std::function<void(VkCommandBuffer)>& record, const SubmitOptions& options = {});

 private:
  friend VkResultOf<void> submit_and_wait(const Context&, const std::function<void(VkCommandBuffer)>&,
                                          const SubmitOptions&);
  Submission() = default;
  void release();

  VkDevice device_ = VK_NULL_HANDLE;
  VkQueue queue_ = VK_NULL_HANDLE;
  VkCommandPool pool_ = VK_NULL_HANDLE;
  bool owns_pool_ = false;  // else its command buffer is the context's, from its transient pool, used once
  VkCommandBuffer commands_ = VK_NULL_HANDLE;
  VkFence fence_ = VK_NULL_HANDLE;
  bool used_ = false;
  bool pending_ = false;  // submitted and not known to be done
};

// One submission: a command buffer from the context's own pool, recorded
// with `record`, submitted and waited for, then freed.
VkResultOf<void> submit_and_wait(const Context& context, const std::function<void(VkCommandBuffer)>& record,
                                 const SubmitOptions& options = {});

}  // namespace facet::runtime
