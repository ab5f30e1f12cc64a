// Images (2D, cube, 3D, arrays) with their own memory and a view, one-shot
// command submission, uploads and readbacks: what the renderer needs beyond
// the compute core. Layout transitions are the caller's, except where a
// function says it leaves an image in a layout.
//
//   auto target = runtime::create_image(context, {.width = 64, .height = 64,
//       .format = VK_FORMAT_R16G16B16A16_SFLOAT,
//       .usage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT});
#pragma once

#include <vulkan/vulkan.h>

#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <vector>

#include "facet/runtime/submission.h"  // submit_and_wait, with which uploads and read-backs run
#include "facet/runtime/vk_error.h"

namespace facet::runtime {

class Context;

struct ImageDesc {
  uint32_t width = 1, height = 1, depth = 1;
  uint32_t layers = 1;  // 6 for a cube
  uint32_t mips = 1;
  VkFormat format = VK_FORMAT_R8G8B8A8_UNORM;
  VkImageUsageFlags usage = VK_IMAGE_USAGE_SAMPLED_BIT;
  VkImageViewType view = VK_IMAGE_VIEW_TYPE_2D;
};

// Move-only owner of a VkImage, its memory (device-local where there is
// such memory) and a view of every mip and layer.
class Image {
 public:
  Image() = default;
  ~Image();
  Image(Image&& other) noexcept;
  Image& operator=(Image&& other) noexcept;
  Image(const Image&) = delete;
  Image& operator=(const Image&) = delete;

  VkImage handle() const { return image_; }
  VkImageView view() const { return view_; }
  // The view to sample through: for a sampled depth-stencil image its depth
  // alone (a sampled view has one aspect); otherwise view().
  VkImageView sample_view() const { return depth_view_ ? depth_view_ : view_; }
  const ImageDesc& desc() const { return desc_; }
  VkImageAspectFlags aspect() const;

 private:
  friend VkResultOf<Image> create_image(const Context& context, const ImageDesc& desc);
  void reset();

  VkDevice device_ = VK_NULL_HANDLE;
  VkImage image_ = VK_NULL_HANDLE;
  VkDeviceMemory memory_ = VK_NULL_HANDLE;
  VkImageView view_ = VK_NULL_HANDLE;
  VkImageView depth_view_ = VK_NULL_HANDLE;
  ImageDesc desc_;
};

VkResultOf<Image> create_image(const Context& context, const ImageDesc& desc);

// Bytes per texel of the formats the runtime uses; nullopt for others.
std::optional<uint32_t> texel_bytes(VkFormat format);
bool is_depth_format(VkFormat format);

// A pipeline barrier moving every mip and layer of `image` between layouts,
// with access masks that cover what the runtime does in each layout.
void transition(VkCommandBuffer commands, const Image& image, VkImageLayout from, VkImageLayout to);

// Uploads tightly packed texels, one span per mip (layers consecutive within
// it), and leaves the image in SHADER_READ_ONLY_OPTIMAL. The image needs
// TRANSFER_DST usage.
VkResultOf<void> upload_image(const Context& context, const Image& image,
                              const std::vector<std::span<const std::byte>>& mips);

// Copies mip 0, layer 0 of an image in `layout` (needs TRANSFER_SRC usage)
// into host memory, tightly packed, and puts it back into `layout`.
VkResultOf<std::vector<std::byte>> read_image(const Context& context, const Image& image, VkImageLayout layout);

}  // namespace facet::runtime
