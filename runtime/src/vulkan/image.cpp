#include "facet/runtime/image.h"

#include <fmt/format.h>

#include <algorithm>
#include <cstring>
#include <utility>

#include "facet/runtime/buffer.h"
#include "facet/runtime/vulkan_context.h"

namespace facet::runtime {
namespace {

std::optional<uint32_t> find_memory(VkPhysicalDevice device, uint32_t allowed, VkMemoryPropertyFlags wanted) {
  VkPhysicalDeviceMemoryProperties properties{};
  vkGetPhysicalDeviceMemoryProperties(device, &properties);
  for (uint32_t i = 0; i < properties.memoryTypeCount; ++i) {
    if ((allowed & (1u << i)) && (properties.memoryTypes[i].propertyFlags & wanted) == wanted) return i;
  }
  return std::nullopt;
}

VkImageType image_type(const ImageDesc& desc) {
  return desc.view == VK_IMAGE_VIEW_TYPE_3D ? VK_IMAGE_TYPE_3D : VK_IMAGE_TYPE_2D;
}

VkImageAspectFlags aspect_of(VkFormat format) {
  if (format == VK_FORMAT_D24_UNORM_S8_UINT || format == VK_FORMAT_D32_SFLOAT_S8_UINT) {
    return VK_IMAGE_ASPECT_DEPTH_BIT | VK_IMAGE_ASPECT_STENCIL_BIT;
  }
  return is_depth_format(format) ? VK_IMAGE_ASPECT_DEPTH_BIT : VK_IMAGE_ASPECT_COLOR_BIT;
}

// What may touch an image in a layout, for barriers in and out of it.
std::pair<VkAccessFlags, VkPipelineStageFlags> layout_access(VkImageLayout layout) {
  switch (layout) {
    case VK_IMAGE_LAYOUT_UNDEFINED: return {0, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT};
    case VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL: return {VK_ACCESS_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT};
    case VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL: return {VK_ACCESS_TRANSFER_READ_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT};
    case VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL:
      return {VK_ACCESS_SHADER_READ_BIT, VK_PIPELINE_STAGE_VERTEX_SHADER_BIT | VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT};
    case VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL:
      return {VK_ACCESS_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT,
              VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT};
    case VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL:
      return {VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_READ_BIT | VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT,
              VK_PIPELINE_STAGE_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT};
    default: return {VK_ACCESS_MEMORY_READ_BIT | VK_ACCESS_MEMORY_WRITE_BIT, VK_PIPELINE_STAGE_ALL_COMMANDS_BIT};
  }
}

VkResultOf<Buffer> staging(const Context& context, VkDeviceSize bytes) {
  return create_buffer(context, bytes, VK_BUFFER_USAGE_TRANSFER_SRC_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT);
}

uint32_t mip_extent(uint32_t size, uint32_t mip) { return std::max(1u, size >> mip); }

// Vulkan leaves an image past the device's limits undefined behaviour (the
// validation layer reports it, lavapipe crashes on a 1 x 10^6 image), so the
// sizes are checked against the limits, and then against what the device
// allows for this format and usage, before vkCreateImage.
VkResultOf<void> check_device_limits(const Context& context, const ImageDesc& desc, const VkImageCreateInfo& info) {
  VkPhysicalDeviceProperties properties{};
  vkGetPhysicalDeviceProperties(context.physical_device(), &properties);
  const VkPhysicalDeviceLimits& limits = properties.limits;
  bool cube = desc.view == VK_IMAGE_VIEW_TYPE_CUBE || desc.view == VK_IMAGE_VIEW_TYPE_CUBE_ARRAY;
  bool volume = desc.view == VK_IMAGE_VIEW_TYPE_3D;
  uint32_t max_side = volume ? limits.maxImageDimension3D : cube ? limits.maxImageDimensionCube : limits.maxImageDimension2D;
  const char* limit = volume ? "maxImageDimension3D" : cube ? "maxImageDimensionCube" : "maxImageDimension2D";
  if (desc.width > max_side || desc.height > max_side || (volume && desc.depth > max_side)) {
    return vk_failure(VkErrorCode::invalid_argument,
                      fmt::format("a {}x{} image is larger than this device's {} ({})", desc.width, desc.height, limit,
                                  max_side));
  }
  if (!volume && desc.depth != 1) return vk_failure(VkErrorCode::invalid_argument, "only a 3D image has a depth");
  if (desc.layers > limits.maxImageArrayLayers) {
    return vk_failure(VkErrorCode::invalid_argument, fmt::format("{} layers are more than this device's maxImageArrayLayers ({})",
                                                                 desc.layers, limits.maxImageArrayLayers));
  }
  uint32_t full_chain = 1;  // mips of a full chain: floor(log2(largest side)) + 1
  for (uint32_t side = std::max({desc.width, desc.height, desc.depth}); side > 1; side >>= 1) ++full_chain;
  if (desc.mips > full_chain) {
    return vk_failure(VkErrorCode::invalid_argument, fmt::format("{} mips are more than a {}x{} image has ({})", desc.mips,
                                                                 desc.width, desc.height, full_chain));
  }
  VkImageFormatProperties format{};
  VkResult r = vkGetPhysicalDeviceImageFormatProperties(context.physical_device(), info.format, info.imageType,
                                                        info.tiling, info.usage, info.flags, &format);
  if (r != VK_SUCCESS) return vk_failure(VkErrorCode::invalid_argument, "the device has no such image format", r);
  if (desc.width > format.maxExtent.width || desc.height > format.maxExtent.height ||
      desc.depth > format.maxExtent.depth || desc.mips > format.maxMipLevels || desc.layers > format.maxArrayLayers) {
    return vk_failure(VkErrorCode::invalid_argument,
                      fmt::format("a {}x{}x{} image of {} mips and {} layers is beyond what the device allows for its "
                                  "format ({}x{}x{}, {} mips, {} layers)",
                                  desc.width, desc.height, desc.depth, desc.mips, desc.layers, format.maxExtent.width,
                                  format.maxExtent.height, format.maxExtent.depth, format.maxMipLevels,
                                  format.maxArrayLayers));
  }
  return {};
}

}  // namespace

Image::~Image() { reset(); }

Image::Image(Image&& other) noexcept
    : device_(std::exchange(other.device_, VK_NULL_HANDLE)),
      image_(std::exchange(other.image_, VK_NULL_HANDLE)),
      memory_(std::exchange(other.memory_, VK_NULL_HANDLE)),
      view_(std::exchange(other.view_, VK_NULL_HANDLE)),
      depth_view_(std::exchange(other.depth_view_, VK_NULL_HANDLE)),
      desc_(other.desc_) {}

Image& Image::operator=(Image&& other) noexcept {
  if (this != &other) {
    reset();
    device_ = std::exchange(other.device_, VK_NULL_HANDLE);
    image_ = std::exchange(other.image_, VK_NULL_HANDLE);
    memory_ = std::exchange(other.memory_, VK_NULL_HANDLE);
    view_ = std::exchange(other.view_, VK_NULL_HANDLE);
    depth_view_ = std::exchange(other.depth_view_, VK_NULL_HANDLE);
    desc_ = other.desc_;
  }
  return *this;
}

void Image::reset() {
  if (!device_) return;
  if (view_) vkDestroyImageView(device_, view_, nullptr);
  if (depth_view_) vkDestroyImageView(device_, depth_view_, nullptr);
  if (image_) vkDestroyImage(device_, image_, nullptr);
  if (memory_) vkFreeMemory(device_, memory_, nullptr);
  device_ = VK_NULL_HANDLE;
  view_ = VK_NULL_HANDLE;
  depth_view_ = VK_NULL_HANDLE;
  image_ = VK_NULL_HANDLE;
  memory_ = VK_NULL_HANDLE;
}

VkImageAspectFlags Image::aspect() const { return aspect_of(desc_.format); }

bool is_depth_format(VkFormat format) {
  return format == VK_FORMAT_D32_SFLOAT || format == VK_FORMAT_D16_UNORM || format == VK_FORMAT_D24_UNORM_S8_UINT ||
         format == VK_FORMAT_D32_SFLOAT_S8_UINT;
}

std::optional<uint32_t> texel_bytes(VkFormat format) {
  switch (format) {
    case VK_FORMAT_R8G8B8A8_UNORM:
    case VK_FORMAT_R8G8B8A8_SRGB:
    case VK_FORMAT_D32_SFLOAT:
    case VK_FORMAT_R32_SFLOAT: return 4;
    case VK_FORMAT_R16G16B16A16_SFLOAT: return 8;
    case VK_FORMAT_R32G32B32A32_SFLOAT: return 16;
    default: return std::nullopt;
  }
}

VkResultOf<Image> create_image(const Context& context, const ImageDesc& desc) {
  if (!desc.width || !desc.height || !desc.depth || !desc.layers || !desc.mips) {
    return vk_failure(VkErrorCode::invalid_argument, "an image needs sizes, layers and mips above 0");
  }
  Image image;
  image.device_ = context.device();
  image.desc_ = desc;
  VkImageCreateInfo info{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
  if (desc.view == VK_IMAGE_VIEW_TYPE_CUBE || desc.view == VK_IMAGE_VIEW_TYPE_CUBE_ARRAY) {
    info.flags = VK_IMAGE_CREATE_CUBE_COMPATIBLE_BIT;
  }
  info.imageType = image_type(desc);
  info.format = desc.format;
  info.extent = {desc.width, desc.height, desc.depth};
  info.mipLevels = desc.mips;
  info.arrayLayers = desc.layers;
  info.samples = VK_SAMPLE_COUNT_1_BIT;
  info.tiling = VK_IMAGE_TILING_OPTIMAL;
  info.usage = desc.usage;
  info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
  info.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
  if (VkResultOf<void> fits = check_device_limits(context, desc, info); !fits) return unexpected(fits.error());
  if (VkResult r = vkCreateImage(image.device_, &info, nullptr, &image.image_); r != VK_SUCCESS) {
    return vk_failure(VkErrorCode::object_failed, fmt::format("cannot create a {}x{} image", desc.width, desc.height), r);
  }
  VkMemoryRequirements needs{};
  vkGetImageMemoryRequirements(image.device_, image.image_, &needs);
  std::optional<uint32_t> type =
      find_memory(context.physical_device(), needs.memoryTypeBits, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
  if (!type) type = find_memory(context.physical_device(), needs.memoryTypeBits, 0);
  if (!type) return vk_failure(VkErrorCode::out_of_memory, "no memory type for an image");
  VkMemoryAllocateInfo allocate{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
  allocate.allocationSize = needs.size;
  allocate.memoryTypeIndex = *type;
  if (VkResult r = vkAllocateMemory(image.device_, &allocate, nullptr, &image.memory_); r != VK_SUCCESS) {
    return vk_failure(VkErrorCode::out_of_memory, fmt::format("cannot allocate {} bytes for an image", needs.size), r);
  }
  if (VkResult r = vkBindImageMemory(image.device_, image.image_, image.memory_, 0); r != VK_SUCCESS) {
    return vk_failure(VkErrorCode::object_failed, "cannot bind image memory", r);
  }
  VkImageViewCreateInfo view{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
  view.image = image.image_;
  view.viewType = desc.view;
  view.format = desc.format;
  view.subresourceRange = {aspect_of(desc.format), 0, desc.mips, 0, desc.layers};
  if (VkResult r = vkCreateImageView(image.device_, &view, nullptr, &image.view_); r != VK_SUCCESS) {
    return vk_failure(VkErrorCode::object_failed, "cannot create an image view", r);
  }
  const bool depth_stencil = aspect_of(desc.format) == (VK_IMAGE_ASPECT_DEPTH_BIT | VK_IMAGE_ASPECT_STENCIL_BIT);
  if (depth_stencil && (desc.usage & VK_IMAGE_USAGE_SAMPLED_BIT)) {
    view.subresourceRange.aspectMask = VK_IMAGE_ASPECT_DEPTH_BIT;
    if (VkResult r = vkCreateImageView(image.device_, &view, nullptr, &image.depth_view_); r != VK_SUCCESS) {
      return vk_failure(VkErrorCode::object_failed, "cannot create a depth view", r);
    }
  }
  return image;
}

void transition(VkCommandBuffer commands, const Image& image, VkImageLayout from, VkImageLayout to) {
  auto [src_access, src_stage] = layout_access(from);
  auto [dst_access, dst_stage] = layout_access(to);
  VkImageMemoryBarrier barrier{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER};
  barrier.srcAccessMask = src_access;
  barrier.dstAccessMask = dst_access;
  barrier.oldLayout = from;
  barrier.newLayout = to;
  barrier.srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  barrier.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  barrier.image = image.handle();
  barrier.subresourceRange = {image.aspect(), 0, image.desc().mips, 0, image.desc().layers};
  vkCmdPipelineBarrier(commands, src_stage, dst_stage, 0, 0, nullptr, 0, nullptr, 1, &barrier);
}

VkResultOf<void> upload_image(const Context& context, const Image& image,
                              const std::vector<std::span<const std::byte>>& mips) {
  const ImageDesc& d = image.desc();
  std::optional<uint32_t> texel = texel_bytes(d.format);
  if (!texel || mips.size() != d.mips) {
    return vk_failure(VkErrorCode::invalid_argument, "upload_image: unknown format or wrong number of mips");
  }
  VkDeviceSize total = 0;
  for (uint32_t m = 0; m < d.mips; ++m) {
    VkDeviceSize want = VkDeviceSize(mip_extent(d.width, m)) * mip_extent(d.height, m) * mip_extent(d.depth, m) *
                        d.layers * *texel;
    if (mips[m].size() != want) {
      return vk_failure(VkErrorCode::invalid_argument,
                        fmt::format("upload_image: mip {} has {} bytes, expected {}", m, mips[m].size(), want));
    }
    total += want;
  }
  VkResultOf<Buffer> buffer = staging(context, total);
  if (!buffer) return unexpected(buffer.error());
  std::vector<VkBufferImageCopy> regions;
  VkDeviceSize offset = 0;
  for (uint32_t m = 0; m < d.mips; ++m) {
    std::memcpy(static_cast<std::byte*>(buffer->data()) + offset, mips[m].data(), mips[m].size());
    VkBufferImageCopy region{};
    region.bufferOffset = offset;
    region.imageSubresource = {image.aspect(), m, 0, d.layers};
    region.imageExtent = {mip_extent(d.width, m), mip_extent(d.height, m), mip_extent(d.depth, m)};
    regions.push_back(region);
    offset += mips[m].size();
  }
  return submit_and_wait(context, [&](VkCommandBuffer commands) {
    transition(commands, image, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL);
    vkCmdCopyBufferToImage(commands, buffer->handle(), image.handle(), VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                           uint32_t(regions.size()), regions.data());
    transition(commands, image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
  });
}

VkResultOf<std::vector<std::byte>> read_image(const Context& context, const Image& image, VkImageLayout layout) {
  const ImageDesc& d = image.desc();
  std::optional<uint32_t> texel = texel_bytes(d.format);
  if (!texel) return vk_failure(VkErrorCode::invalid_argument, "read_image: unknown format");
  VkDeviceSize bytes = VkDeviceSize(d.width) * d.height * d.depth * *texel;
  VkResultOf<Buffer> buffer = staging(context, bytes);
  if (!buffer) return unexpected(buffer.error());
  VkResultOf<void> done = submit_and_wait(context, [&](VkCommandBuffer commands) {
    transition(commands, image, layout, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL);
    VkBufferImageCopy region{};
    region.imageSubresource = {image.aspect(), 0, 0, 1};
    region.imageExtent = {d.width, d.height, d.depth};
    vkCmdCopyImageToBuffer(commands, image.handle(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, buffer->handle(), 1, &region);
    transition(commands, image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, layout);
    VkMemoryBarrier host{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
    host.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
    host.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
    vkCmdPipelineBarrier(commands, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 1, &host, 0, nullptr,
                         0, nullptr);
  });
  if (!done) return unexpected(done.error());
  std::vector<std::byte> out(bytes);
  std::memcpy(out.data(), buffer->data(), bytes);
  return out;
}

}  // namespace facet::runtime
