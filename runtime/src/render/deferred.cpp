#include "render/deferred.h"

#include <fmt/format.h>

#include "facet/runtime/vulkan_context.h"
#include "render/post.h"
#include "render/shadows.h"
#include "render/targets.h"

namespace facet::runtime {
namespace {

constexpr std::array<VkFormat, 3> kGBufferFormats = {VK_FORMAT_R8G8B8A8_UNORM, VK_FORMAT_R8G8B8A8_UNORM,
                                                     VK_FORMAT_A2B10G10R10_UNORM_PACK32};

}  // namespace

DeferredTargets::~DeferredTargets() {
  if (!device) return;
  vkDeviceWaitIdle(device);
  for (VkFramebuffer f : {gbuffer_framebuffer, light_framebuffer}) {
    if (f) vkDestroyFramebuffer(device, f, nullptr);
  }
  for (VkRenderPass p : {gbuffer_pass, light_pass}) {
    if (p) vkDestroyRenderPass(device, p, nullptr);
  }
}

Result<void, Diagnostics> make_deferred_targets(const Context& context, const Image& color, const Image& depth,
                                                uint32_t width, uint32_t height, DeferredTargets& out) {
  out.device = context.device();
  std::vector<VkAttachmentDescription> gbuffer;
  std::vector<VkImageView> views;
  for (size_t i = 0; i < kGBufferFormats.size(); ++i) {
    VkResultOf<Image> image =
        create_image(context, {.width = width, .height = height, .format = kGBufferFormats[i],
                               .usage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT});
    if (!image) return unexpected(render_error(describe(image.error()), DiagId::vulkan_failed));
    out.gbuffer[i] = std::move(*image);
    gbuffer.push_back(attachment(kGBufferFormats[i], false, VK_IMAGE_LAYOUT_UNDEFINED,
                                 VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL));
    views.push_back(out.gbuffer[i].view());
  }
  gbuffer.push_back(attachment(color.desc().format, false, VK_IMAGE_LAYOUT_UNDEFINED,
                               VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL));
  gbuffer.push_back(attachment(depth.desc().format, false, VK_IMAGE_LAYOUT_UNDEFINED,
                               VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL));
  // The stencil, cleared here, is kept for the forward part's Stencil blocks.
  gbuffer.back().stencilLoadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
  gbuffer.back().stencilStoreOp = VK_ATTACHMENT_STORE_OP_STORE;
  views.push_back(color.view());
  views.push_back(depth.view());
  Result<VkRenderPass, Diagnostics> pass = make_single_pass(out.device, gbuffer, true, "G-buffer");
  if (!pass) return unexpected(pass.error());
  out.gbuffer_pass = *pass;
  Result<VkFramebuffer, Diagnostics> fb = make_framebuffer(out.device, out.gbuffer_pass, views, width, height);
  if (!fb) return unexpected(fb.error());
  out.gbuffer_framebuffer = *fb;

  std::vector<VkAttachmentDescription> light = {attachment(color.desc().format, true,
                                                           VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                                                           VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL)};
  pass = make_single_pass(out.device, light, false, "deferred light");
  if (!pass) return unexpected(pass.error());
  out.light_pass = *pass;
  fb = make_framebuffer(out.device, out.light_pass, {color.view()}, width, height);
  if (!fb) return unexpected(fb.error());
  out.light_framebuffer = *fb;
  return {};
}

std::map<std::string, const Image*> gbuffer_textures(const DeferredTargets& targets, const Image& depth) {
  return {{"_CameraGBufferTexture0", &targets.gbuffer[0]},
          {"_CameraGBufferTexture1", &targets.gbuffer[1]},
          {"_CameraGBufferTexture2", &targets.gbuffer[2]},
          {"_CameraDepthTexture", &depth}};
}

Result<std::unique_ptr<DeferredLights>, Diagnostics> build_deferred_lights(const Context& context, const Scene& scene,
                                                                           ShaderLibrary& library,
                                                                           const LightSetup& lights,
                                                                           const CameraMatrices& camera) {
  auto out = std::make_unique<DeferredLights>();
  if (scene.camera.projection != Projection::perspective) {
    return unexpected(
        render_error(scene.path + ": camera.rendering_path: the deferred path needs a perspective camera"));
  }
  FACET_TRY(make_screen_pass_object(context, scene, library, camera, "Internal-DeferredShading.shader",
                                    "the deferred light pass", "camera.rendering_path", out->screen));
  ObjectState& object = out->screen.objects.back();
  for (size_t i = 0; i < scene.lights.size(); ++i) {
    const LightValues& light = lights.lights[i];
    if (light.brightness <= 0) continue;
    std::vector<std::string> global = {light.keyword, "UNITY_HDR_ON"};
    DrawRecord record = pass_record(object, 0);
    record.object = "deferred light pass";
    record.light = light_description(scene, i);
    record.additive = true;
    record.why = "deferred: the light added from the G-buffer over the whole screen";
    if (light.shadowed) {
      std::vector<std::string> shadows = shadow_keywords(scene.lights[i]);
      global.insert(global.end(), shadows.begin(), shadows.end());
      record.why += "; its shadows: " + fmt::format("{}", fmt::join(shadows, " "));
    }
    FACET_TRY(add_draw(context, scene, library, object, 0, &light, global, std::move(record), out->list));
  }
  return out;
}

}  // namespace facet::runtime
