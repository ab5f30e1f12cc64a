// The scene's own render targets: its colour and depth images, the render
// passes that draw into them (split at GrabPasses), the framebuffer, and the
// image-effect chain's ping-pong images. Each struct owns its Vulkan objects
// and destroys them, after the device is idle, when it goes.
#pragma once

#include <vulkan/vulkan.h>

#include <array>

#include "facet/runtime/image.h"
#include "facet/runtime/renderer.h"
#include "render/failure.h"

namespace facet::runtime {

class Context;

// Vulkan objects of the scene's pass, destroyed in reverse order.
struct SceneTargets {
  VkDevice device = VK_NULL_HANDLE;
  Image color, depth;  // RGBA16F and D32(S8)
  VkFormat depth_format = VK_FORMAT_UNDEFINED;
  VkRenderPass render_pass = VK_NULL_HANDLE;
  // With GrabPasses: the parts before the first grab and between grabs
  // (the last part is render_pass with its colour loaded).
  VkRenderPass first_part = VK_NULL_HANDLE, middle_part = VK_NULL_HANDLE, last_part = VK_NULL_HANDLE;
  VkFramebuffer framebuffer = VK_NULL_HANDLE;
  SceneTargets() = default;
  SceneTargets(const SceneTargets&) = delete;
  SceneTargets& operator=(const SceneTargets&) = delete;
  ~SceneTargets();
};

// D32 with stencil where the device has it (and, for a depth the frame
// samples, can sample it), else D32 without stencil.
VkFormat depth_format(const Context& context, bool sampled);

// How a render pass of the scene begins and ends. A frame with GrabPasses
// is drawn in parts split at each grab (grab.h): every part but the first
// loads what the one before left, every part but the last leaves the colour
// ready to be copied and keeps the depth.
struct PassEnds {
  bool load = false;     // continue the previous part (else clear)
  bool to_grab = false;  // a grab follows: colour to TRANSFER_SRC_OPTIMAL, depth stored
  // The last part: the colour (and with `depth_sampled` the depth) ends in
  // SHADER_READ_ONLY_OPTIMAL for the image-effect chain instead of being read back.
  bool sampled = false;
  bool depth_sampled = false;
};

Result<VkRenderPass, Diagnostics> make_render_pass(VkDevice device, VkFormat depth, const PassEnds& ends);

// The colour and depth images (`post`: the colour is sampled by the chain;
// `depth_readable`: the depth is sampled), the last part's render pass and
// the framebuffer.
Result<void, Diagnostics> make_scene_targets(const Context& context, uint32_t width, uint32_t height, bool post,
                                             bool depth_readable, const PassEnds& last_part, SceneTargets& out);

// The image-effect chain's two ping-pong images, its colour-only render pass
// and a framebuffer per image.
struct PostTargets {
  VkDevice device = VK_NULL_HANDLE;
  VkRenderPass render_pass = VK_NULL_HANDLE;
  std::array<Image, 2> images;
  std::array<VkFramebuffer, 2> framebuffers{};
  VkSampler point_sampler = VK_NULL_HANDLE;  // the camera depth texture's, as Unity's: point, clamp
  PostTargets() = default;
  PostTargets(const PostTargets&) = delete;
  PostTargets& operator=(const PostTargets&) = delete;
  ~PostTargets() {
    if (!device) return;
    vkDeviceWaitIdle(device);
    if (point_sampler) vkDestroySampler(device, point_sampler, nullptr);
    for (VkFramebuffer f : framebuffers)
      if (f) vkDestroyFramebuffer(device, f, nullptr);
    if (render_pass) vkDestroyRenderPass(device, render_pass, nullptr);
  }
};

Result<void, Diagnostics> make_post_targets(const Context& context, PostTargets& t, int width, int height);

}  // namespace facet::runtime
