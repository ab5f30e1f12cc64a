#include "render/screen_shadows.h"

#include <fmt/format.h>

#include <algorithm>

#include "facet/runtime/vulkan_context.h"
#include "render/post.h"
#include "render/program.h"
#include "render/targets.h"

namespace facet::runtime {
namespace {

}  // namespace

ScreenShadows::~ScreenShadows() {
  if (!device) return;
  vkDeviceWaitIdle(device);
  for (VkFramebuffer f : framebuffers) vkDestroyFramebuffer(device, f, nullptr);
  if (render_pass) vkDestroyRenderPass(device, render_pass, nullptr);
}

const Image* ScreenShadows::mask_of(const LightValues* light) const {
  if (!light) return nullptr;
  for (size_t i = 0; i < list.draws.size(); ++i) {
    if (list.draws[i].light == light->scene_light()) return &masks[i];
  }
  return nullptr;
}

bool ScreenShadows::owns(const Image* image) const {
  return std::any_of(masks.begin(), masks.end(), [&](const Image& m) { return &m == image; });
}

bool reads_screen_shadows(const Draw& draw) {
  const std::vector<std::string>& k = draw.variant->keywords;
  return std::find(k.begin(), k.end(), "SHADOWS_SCREEN") != k.end() && samples(draw, "_ShadowMapTexture");
}

std::vector<const LightValues*> screen_shadowed_lights(const std::vector<const std::vector<Draw>*>& receivers) {
  std::vector<const LightValues*> lights;
  for (const std::vector<Draw>* list : receivers) {
    for (const Draw& d : *list) {
      if (!d.light || !reads_screen_shadows(d)) continue;
      const LightValues* light = d.light->scene_light();
      if (std::find(lights.begin(), lights.end(), light) == lights.end()) lights.push_back(light);
    }
  }
  return lights;
}

Result<void, Diagnostics> prepare_screen_shadows(const Context& context, const Scene& scene, ShaderLibrary& library,
                                                 const CameraMatrices& camera,
                                                 const std::vector<const LightValues*>& lights, uint32_t width,
                                                 uint32_t height, VkPipelineCache cache, ScreenShadows& out,
                                                 uint64_t& pipelines_created) {
  if (lights.empty()) return {};
  out.device = context.device();
  FACET_TRY(make_screen_pass_object(context, scene, library, camera, "Internal-ScreenSpaceShadows.shader",
                                    "the screen-space shadow pass", "lights", out.screen));
  ObjectState& object = out.screen.objects.back();

  constexpr VkFormat kMask = VK_FORMAT_R8_UNORM;
  Result<VkRenderPass, Diagnostics> pass = make_single_pass(
      out.device, {attachment(kMask, false, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL)},
      false, "screen-space shadow");
  if (!pass) return unexpected(pass.error());
  out.render_pass = *pass;
  for (const LightValues* light : lights) {
    size_t index = size_t(std::find_if(scene.lights.begin(), scene.lights.end(),
                                       [&](const SceneLight& l) { return l.json_path == light->json_path; }) -
                          scene.lights.begin());
    DrawRecord record = pass_record(object, 0);
    record.object = "screen-space shadows";
    record.light = index < scene.lights.size() ? light_description(scene, index) : light->json_path;
    record.why = "the light's shadow map looked up at every pixel of the camera depth texture, for the draws whose "
                 "variant has SHADOWS_SCREEN";
    FACET_TRY(add_draw(context, scene, library, object, 0, light, {}, std::move(record), out.list));
    VkResultOf<Image> mask =
        create_image(context, {.width = width, .height = height, .format = kMask,
                               .usage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT});
    if (!mask) return unexpected(render_error(describe(mask.error()), DiagId::vulkan_failed));
    out.masks.push_back(std::move(*mask));
    Result<VkFramebuffer, Diagnostics> fb =
        make_framebuffer(out.device, out.render_pass, {out.masks.back().view()}, width, height);
    if (!fb) return unexpected(fb.error());
    out.framebuffers.push_back(*fb);
    const Draw& d = out.list.draws.back();
    bool created = false;
    Result<VkPipeline, std::string> p =
        get_pipeline(context, *d.variant->program, d.state, false, out.render_pass, cache, &created);
    if (!p) return unexpected(render_error(fmt::format("{}: {}: {}", scene.path, d.record.object, p.error())));
    out.pipelines.push_back(*p);
    pipelines_created += created;
  }
  return {};
}

}  // namespace facet::runtime
