#include "facet/runtime/buffer.h"

#include <fmt/format.h>

#include <optional>
#include <utility>

#include "facet/runtime/vulkan_context.h"

namespace facet::runtime {
namespace {

constexpr VkMemoryPropertyFlags kHostMemory = VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT;

std::optional<uint32_t> memory_type(VkPhysicalDevice device, uint32_t allowed, VkMemoryPropertyFlags wanted) {
  VkPhysicalDeviceMemoryProperties properties{};
  vkGetPhysicalDeviceMemoryProperties(device, &properties);
  for (uint32_t i = 0; i < properties.memoryTypeCount; ++i) {
    if ((allowed & (1u << i)) && (properties.memoryTypes[i].propertyFlags & wanted) == wanted) return i;
  }
  return std::nullopt;
}

}  // namespace

Buffer::~Buffer() { reset(); }

Buffer::Buffer(Buffer&& other) noexcept
    : device_(std::exchange(other.device_, VK_NULL_HANDLE)),
      buffer_(std::exchange(other.buffer_, VK_NULL_HANDLE)),
      memory_(std::exchange(other.memory_, VK_NULL_HANDLE)),
      size_(std::exchange(other.size_, 0)),
      mapped_(std::exchange(other.mapped_, nullptr)) {}

Buffer& Buffer::operator=(Buffer&& other) noexcept {
  if (this != &other) {
    reset();
    device_ = std::exchange(other.device_, VK_NULL_HANDLE);
    buffer_ = std::exchange(other.buffer_, VK_NULL_HANDLE);
    memory_ = std::exchange(other.memory_, VK_NULL_HANDLE);
    size_ = std::exchange(other.size_, 0);
    mapped_ = std::exchange(other.mapped_, nullptr);
  }
  return *this;
}

void Buffer::reset() {
  if (!device_) return;
  if (buffer_) vkDestroyBuffer(device_, buffer_, nullptr);
  if (memory_) vkFreeMemory(device_, memory_, nullptr);  // unmaps implicitly
  device_ = VK_NULL_HANDLE;
  buffer_ = VK_NULL_HANDLE;
  memory_ = VK_NULL_HANDLE;
  mapped_ = nullptr;
  size_ = 0;
}

VkResultOf<Buffer> create_storage_buffer(const Context& context, VkDeviceSize size) {
  if (size == 0) return vk_failure(VkErrorCode::invalid_argument, "a storage buffer needs a size above 0");
  return create_buffer(context, size,
                       VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT |
                           VK_BUFFER_USAGE_TRANSFER_DST_BIT);
}

VkResultOf<Buffer> create_buffer(const Context& context, VkDeviceSize size, VkBufferUsageFlags usage) {
  if (size == 0) return vk_failure(VkErrorCode::invalid_argument, "a buffer needs a size above 0");
  Buffer buffer;
  buffer.device_ = context.device();
  buffer.size_ = size;
  VkBufferCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
  info.size = size;
  info.usage = usage;
  info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
  if (VkResult result = vkCreateBuffer(buffer.device_, &info, nullptr, &buffer.buffer_); result != VK_SUCCESS) {
    return vk_failure(VkErrorCode::object_failed, fmt::format("cannot create a {}-byte buffer", size), result);
  }
  VkMemoryRequirements needs{};
  vkGetBufferMemoryRequirements(buffer.device_, buffer.buffer_, &needs);
  std::optional<uint32_t> type = memory_type(context.physical_device(), needs.memoryTypeBits, kHostMemory);
  if (!type) return vk_failure(VkErrorCode::out_of_memory, "the device has no host-visible coherent memory for buffers");
  VkMemoryAllocateInfo allocate{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
  allocate.allocationSize = needs.size;
  allocate.memoryTypeIndex = *type;
  if (VkResult result = vkAllocateMemory(buffer.device_, &allocate, nullptr, &buffer.memory_); result != VK_SUCCESS) {
    return vk_failure(VkErrorCode::out_of_memory, fmt::format("cannot allocate {} bytes", needs.size), result);
  }
  if (VkResult result = vkBindBufferMemory(buffer.device_, buffer.buffer_, buffer.memory_, 0); result != VK_SUCCESS) {
    return vk_failure(VkErrorCode::object_failed, "cannot bind buffer memory", result);
  }
  if (VkResult result = vkMapMemory(buffer.device_, buffer.memory_, 0, VK_WHOLE_SIZE, 0, &buffer.mapped_);
      result != VK_SUCCESS) {
    return vk_failure(VkErrorCode::object_failed, "cannot map buffer memory", result);
  }
  return buffer;
}

}  // namespace facet::runtime
