#include "render/scene_targets.h"

#include "render/targets.h"

#include "facet/runtime/vk_error.h"
#include "facet/runtime/vulkan_context.h"

namespace facet::runtime {
namespace {

}  // namespace

SceneTargets::~SceneTargets() {
  if (!device) return;
  vkDeviceWaitIdle(device);
  if (framebuffer) vkDestroyFramebuffer(device, framebuffer, nullptr);
  for (VkRenderPass p : {render_pass, first_part, middle_part, last_part}) {
    if (p) vkDestroyRenderPass(device, p, nullptr);
  }
}

VkFormat depth_format(const Context& context, bool sampled) {
  VkFormatProperties p{};
  vkGetPhysicalDeviceFormatProperties(context.physical_device(), VK_FORMAT_D32_SFLOAT_S8_UINT, &p);
  VkFormatFeatureFlags needs = VK_FORMAT_FEATURE_DEPTH_STENCIL_ATTACHMENT_BIT |
                               (sampled ? VK_FORMAT_FEATURE_SAMPLED_IMAGE_BIT : 0);
  return (p.optimalTilingFeatures & needs) == needs ? VK_FORMAT_D32_SFLOAT_S8_UINT : VK_FORMAT_D32_SFLOAT;
}

Result<VkRenderPass, Diagnostics> make_render_pass(VkDevice device, VkFormat depth, const PassEnds& ends) {
  VkAttachmentDescription attachments[2]{};
  attachments[0].format = VK_FORMAT_R16G16B16A16_SFLOAT;
  attachments[0].samples = VK_SAMPLE_COUNT_1_BIT;
  attachments[0].loadOp = ends.load ? VK_ATTACHMENT_LOAD_OP_LOAD : VK_ATTACHMENT_LOAD_OP_CLEAR;
  attachments[0].storeOp = VK_ATTACHMENT_STORE_OP_STORE;
  attachments[0].stencilLoadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
  attachments[0].stencilStoreOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
  attachments[0].initialLayout = ends.load ? VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL : VK_IMAGE_LAYOUT_UNDEFINED;
  attachments[0].finalLayout = ends.sampled && !ends.to_grab ? VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL
                                                             : VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;
  attachments[1] = attachments[0];
  attachments[1].format = depth;
  bool keep_depth = ends.to_grab || ends.depth_sampled;
  attachments[1].storeOp = keep_depth ? VK_ATTACHMENT_STORE_OP_STORE : VK_ATTACHMENT_STORE_OP_DONT_CARE;
  attachments[1].stencilLoadOp = ends.load ? VK_ATTACHMENT_LOAD_OP_LOAD : VK_ATTACHMENT_LOAD_OP_CLEAR;
  attachments[1].stencilStoreOp = ends.to_grab ? VK_ATTACHMENT_STORE_OP_STORE : VK_ATTACHMENT_STORE_OP_DONT_CARE;
  attachments[1].initialLayout = ends.load ? VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL : VK_IMAGE_LAYOUT_UNDEFINED;
  attachments[1].finalLayout = ends.depth_sampled && !ends.to_grab ? VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL
                                                                   : VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL;
  VkAttachmentReference color{0, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL};
  VkAttachmentReference depth_ref{1, VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL};
  VkSubpassDescription subpass{};
  subpass.pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
  subpass.colorAttachmentCount = 1;
  subpass.pColorAttachments = &color;
  subpass.pDepthStencilAttachment = &depth_ref;
  VkSubpassDependency after{};
  after.srcSubpass = 0;
  after.dstSubpass = VK_SUBPASS_EXTERNAL;
  after.srcStageMask = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT | VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT;
  after.dstStageMask = VK_PIPELINE_STAGE_TRANSFER_BIT | VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT;
  after.srcAccessMask = VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT | VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT;
  after.dstAccessMask = VK_ACCESS_TRANSFER_READ_BIT | VK_ACCESS_SHADER_READ_BIT;
  VkRenderPassCreateInfo info{VK_STRUCTURE_TYPE_RENDER_PASS_CREATE_INFO};
  info.attachmentCount = 2;
  info.pAttachments = attachments;
  info.subpassCount = 1;
  info.pSubpasses = &subpass;
  info.dependencyCount = 1;
  info.pDependencies = &after;
  VkRenderPass pass = VK_NULL_HANDLE;
  if (VkResult r = vkCreateRenderPass(device, &info, nullptr, &pass); r != VK_SUCCESS) {
    return unexpected(render_error("cannot create the render pass: " + vk_result_name(r), DiagId::vulkan_failed));
  }
  return pass;
}

Result<void, Diagnostics> make_scene_targets(const Context& context, uint32_t width, uint32_t height, bool post,
                                             bool depth_readable, const PassEnds& last_part, SceneTargets& out) {
  out.device = context.device();
  out.depth_format = depth_format(context, depth_readable);
  VkResultOf<Image> color = create_image(context, {.width = width, .height = height,
                                                   .format = VK_FORMAT_R16G16B16A16_SFLOAT,
                                                   .usage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT |
                                                            (post ? VkImageUsageFlags(VK_IMAGE_USAGE_SAMPLED_BIT) : 0u)});
  if (!color) return unexpected(render_error(describe(color.error()), DiagId::vulkan_failed));
  out.color = std::move(*color);
  VkResultOf<Image> depth = create_image(context, {.width = width, .height = height,
                                                   .format = out.depth_format,
                                                   .usage = VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT |
                                                            (depth_readable ? VkImageUsageFlags(VK_IMAGE_USAGE_SAMPLED_BIT) : 0u)});
  if (!depth) return unexpected(render_error(describe(depth.error()), DiagId::vulkan_failed));
  out.depth = std::move(*depth);
  Result<VkRenderPass, Diagnostics> pass = make_render_pass(context.device(), out.depth_format, last_part);
  if (!pass) return unexpected(pass.error());
  out.render_pass = *pass;
  Result<VkFramebuffer, Diagnostics> framebuffer =
      make_framebuffer(context.device(), out.render_pass, {out.color.view(), out.depth.view()}, width, height);
  if (!framebuffer) return unexpected(framebuffer.error());
  out.framebuffer = *framebuffer;
  return {};
}

Result<void, Diagnostics> make_post_targets(const Context& context, PostTargets& t, int width, int height) {
  t.device = context.device();
  VkAttachmentDescription a{};
  a.format = VK_FORMAT_R16G16B16A16_SFLOAT;
  a.samples = VK_SAMPLE_COUNT_1_BIT;
  a.loadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;  // every step covers every pixel
  a.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
  a.stencilLoadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
  a.stencilStoreOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
  a.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
  a.finalLayout = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
  VkAttachmentReference color{0, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL};
  VkSubpassDescription subpass{};
  subpass.pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
  subpass.colorAttachmentCount = 1;
  subpass.pColorAttachments = &color;
  // Before: the image was the source of the step before last (write after read).
  // After: the next step samples it, or the readback copies it.
  VkSubpassDependency deps[2]{};
  deps[0].srcSubpass = VK_SUBPASS_EXTERNAL;
  deps[0].dstSubpass = 0;
  deps[0].srcStageMask = VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT;
  deps[0].dstStageMask = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT;
  deps[0].srcAccessMask = VK_ACCESS_SHADER_READ_BIT;
  deps[0].dstAccessMask = VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT;
  deps[1].srcSubpass = 0;
  deps[1].dstSubpass = VK_SUBPASS_EXTERNAL;
  deps[1].srcStageMask = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT;
  deps[1].dstStageMask = VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT | VK_PIPELINE_STAGE_TRANSFER_BIT;
  deps[1].srcAccessMask = VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT;
  deps[1].dstAccessMask = VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_TRANSFER_READ_BIT;
  VkRenderPassCreateInfo info{VK_STRUCTURE_TYPE_RENDER_PASS_CREATE_INFO};
  info.attachmentCount = 1;
  info.pAttachments = &a;
  info.subpassCount = 1;
  info.pSubpasses = &subpass;
  info.dependencyCount = 2;
  info.pDependencies = deps;
  if (VkResult r = vkCreateRenderPass(t.device, &info, nullptr, &t.render_pass); r != VK_SUCCESS) {
    t.render_pass = VK_NULL_HANDLE;
    return unexpected(
        render_error("cannot create the image-effect render pass: " + vk_result_name(r), DiagId::vulkan_failed));
  }
  VkSamplerCreateInfo sampler{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
  sampler.magFilter = sampler.minFilter = VK_FILTER_NEAREST;
  sampler.mipmapMode = VK_SAMPLER_MIPMAP_MODE_NEAREST;
  sampler.addressModeU = sampler.addressModeV = sampler.addressModeW = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
  if (VkResult r = vkCreateSampler(t.device, &sampler, nullptr, &t.point_sampler); r != VK_SUCCESS) {
    t.point_sampler = VK_NULL_HANDLE;
    return unexpected(
        render_error("cannot create the depth texture's sampler: " + vk_result_name(r), DiagId::vulkan_failed));
  }
  for (size_t i = 0; i < 2; ++i) {
    VkResultOf<Image> image = create_image(context, {.width = uint32_t(width), .height = uint32_t(height),
                                                     .format = VK_FORMAT_R16G16B16A16_SFLOAT,
                                                     .usage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT |
                                                              VK_IMAGE_USAGE_TRANSFER_SRC_BIT});
    if (!image) return unexpected(render_error(describe(image.error()), DiagId::vulkan_failed));
    t.images[i] = std::move(*image);
    VkImageView view = t.images[i].view();
    VkFramebufferCreateInfo fb{VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO};
    fb.renderPass = t.render_pass;
    fb.attachmentCount = 1;
    fb.pAttachments = &view;
    fb.width = uint32_t(width);
    fb.height = uint32_t(height);
    fb.layers = 1;
    if (VkResult r = vkCreateFramebuffer(t.device, &fb, nullptr, &t.framebuffers[i]); r != VK_SUCCESS) {
      t.framebuffers[i] = VK_NULL_HANDLE;
      return unexpected(
          render_error("cannot create an image-effect framebuffer: " + vk_result_name(r), DiagId::vulkan_failed));
    }
  }
  return {};
}

}  // namespace facet::runtime
