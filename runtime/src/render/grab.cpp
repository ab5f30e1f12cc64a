#include "render/grab.h"

#include <fmt/format.h>

#include <set>

#include "render/post.h"

namespace facet::runtime {

Result<GrabPlan, Diagnostics> plan_grabs(const Context& context, const Scene& scene, const std::vector<Draw>& draws,
                                         uint32_t width, uint32_t height) {
  GrabPlan plan;
  std::set<std::string> declared = {kGrabTexture};
  for (const Draw& d : draws) declared.insert(d.grab_before.begin(), d.grab_before.end());
  std::set<std::string> filled;
  for (size_t i = 0; i < draws.size(); ++i) {
    const Draw& d = draws[i];
    GrabPoint point{.draw = i};
    for (const std::string& name : d.grab_before) {
      bool named = name != kGrabTexture;
      if (named && filled.count(name)) continue;  // a named grab happens once a frame
      if (std::find(point.names.begin(), point.names.end(), name) == point.names.end()) point.names.push_back(name);
      filled.insert(name);
    }
    if (!point.names.empty()) plan.points.push_back(std::move(point));
    for (const std::string& name : declared) {
      if (samples(d, name) && !filled.count(name)) {
        return unexpected(render_error(
            fmt::format("{}: {}: pass '{}' samples {}, but no GrabPass copied the screen into it before this draw",
                        scene.path, d.record.object, d.record.pass, name)));
      }
    }
  }
  for (const std::string& name : filled) {
    VkResultOf<Image> image = create_image(context, {.width = width, .height = height,
                                                     .format = VK_FORMAT_R16G16B16A16_SFLOAT,
                                                     .usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT});
    if (!image) {
      return unexpected(render_error(fmt::format("the GrabPass texture {}: {}", name, describe(image.error())),
                                     DiagId::vulkan_failed));
    }
    plan.images.emplace(name, std::move(*image));
  }
  return plan;
}

void record_grab(VkCommandBuffer commands, const Image& color, const GrabPoint& point, GrabPlan& plan,
                 std::map<std::string, bool>& grabbed) {
  for (const std::string& name : point.names) {
    const Image& target = plan.images.at(name);
    bool again = grabbed[name];
    transition(commands, target, again ? VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL : VK_IMAGE_LAYOUT_UNDEFINED,
               VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL);
    VkImageCopy region{};
    region.srcSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    region.dstSubresource = region.srcSubresource;
    region.extent = {color.desc().width, color.desc().height, 1};
    vkCmdCopyImage(commands, color.handle(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, target.handle(),
                   VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
    transition(commands, target, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
    grabbed[name] = true;
  }
  transition(commands, color, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL);
  VkMemoryBarrier depth{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
  depth.srcAccessMask = VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT;
  depth.dstAccessMask = VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_READ_BIT | VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT;
  vkCmdPipelineBarrier(commands, VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT,
                       VK_PIPELINE_STAGE_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT, 0, 1,
                       &depth, 0, nullptr, 0, nullptr);
}

}  // namespace facet::runtime
