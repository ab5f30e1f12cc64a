// Storage buffers in host-visible, host-coherent memory, mapped for their
// whole life: the host writes inputs and reads results through data(). One
// allocation per buffer is enough for the evaluator's handful of buffers.
#pragma once

#include <vulkan/vulkan.h>

#include <cstddef>

#include "facet/runtime/vk_error.h"

namespace facet::runtime {

class Context;

// Move-only owner of a VkBuffer and its memory.
class Buffer {
 public:
  Buffer() = default;
  ~Buffer();
  Buffer(Buffer&& other) noexcept;
  Buffer& operator=(Buffer&& other) noexcept;
  Buffer(const Buffer&) = delete;
  Buffer& operator=(const Buffer&) = delete;

  VkBuffer handle() const { return buffer_; }
  VkDeviceSize size() const { return size_; }
  void* data() const { return mapped_; }

 private:
  friend VkResultOf<Buffer> create_buffer(const Context& context, VkDeviceSize size, VkBufferUsageFlags usage);
  void reset();

  VkDevice device_ = VK_NULL_HANDLE;
  VkBuffer buffer_ = VK_NULL_HANDLE;
  VkDeviceMemory memory_ = VK_NULL_HANDLE;
  VkDeviceSize size_ = 0;
  void* mapped_ = nullptr;
};

// A storage buffer of `size` bytes (> 0), mapped, contents undefined.
VkResultOf<Buffer> create_storage_buffer(const Context& context, VkDeviceSize size);
// The same for any usage (vertex, index, uniform, transfer): the renderer's
// buffers are small enough that host-visible memory costs nothing on lavapipe.
VkResultOf<Buffer> create_buffer(const Context& context, VkDeviceSize size, VkBufferUsageFlags usage);

}  // namespace facet::runtime
