#include "render/shadow_pass.h"

#include <fmt/format.h>

#include <algorithm>

#include "facet/runtime/vulkan_context.h"
#include "render/program.h"

namespace facet::runtime {
namespace {

RenderError error(std::string message) { return RenderError{std::move(message)}; }

// Depth, cleared to the far plane, left for the receivers' fragment stage;
// and an R8 colour attachment that nothing writes or keeps, there because
// casters' fragment stages write SV_Target (a fragment output without an
// attachment is a validation warning).
Result<VkRenderPass, RenderError> make_depth_pass(VkDevice device) {
  VkAttachmentDescription attachments[2]{};
  VkAttachmentDescription& depth = attachments[0];
  depth.format = VK_FORMAT_D32_SFLOAT;
  depth.samples = VK_SAMPLE_COUNT_1_BIT;
  depth.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
  depth.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
  depth.stencilLoadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
  depth.stencilStoreOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
  depth.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
  depth.finalLayout = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
  VkAttachmentDescription& unused = attachments[1];
  unused = depth;
  unused.format = VK_FORMAT_R8_UNORM;
  unused.loadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
  unused.storeOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
  unused.finalLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
  VkAttachmentReference ref{0, VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL};
  VkAttachmentReference color_ref{1, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL};
  VkSubpassDescription subpass{};
  subpass.pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
  subpass.colorAttachmentCount = 1;
  subpass.pColorAttachments = &color_ref;
  subpass.pDepthStencilAttachment = &ref;
  // Before: the last frame's receivers read the map. After: this frame's do.
  VkSubpassDependency deps[2]{};
  deps[0] = {VK_SUBPASS_EXTERNAL, 0, VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT,
             VK_PIPELINE_STAGE_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT,
             VK_ACCESS_SHADER_READ_BIT, VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT, 0};
  deps[1] = {0, VK_SUBPASS_EXTERNAL, VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT, VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT,
             VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT, VK_ACCESS_SHADER_READ_BIT, 0};
  VkRenderPassCreateInfo info{VK_STRUCTURE_TYPE_RENDER_PASS_CREATE_INFO};
  info.attachmentCount = 2;
  info.pAttachments = attachments;
  info.subpassCount = 1;
  info.pSubpasses = &subpass;
  info.dependencyCount = 2;
  info.pDependencies = deps;
  VkRenderPass pass = VK_NULL_HANDLE;
  if (VkResult r = vkCreateRenderPass(device, &info, nullptr, &pass); r != VK_SUCCESS) {
    return unexpected(error("cannot create the shadow-map render pass: " + vk_result_name(r)));
  }
  return pass;
}

bool light_is_sampled(const LightValues* light, const std::vector<Draw>& draws) {
  return std::any_of(draws.begin(), draws.end(),
                     [&](const Draw& d) {
                       return d.light && d.light->scene_light() == light && samples_shadow_map(d.record.keywords);
                     });
}

Result<void, RenderError> make_target(const Context& context, VkRenderPass pass, ShadowMap& map) {
  VkResultOf<Image> depth = create_image(context, {.width = map.width, .height = map.height, .format = VK_FORMAT_D32_SFLOAT,
                                                   .usage = VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT |
                                                            VK_IMAGE_USAGE_SAMPLED_BIT});
  if (!depth) return unexpected(error(describe(depth.error())));
  map.depth = std::move(*depth);
  VkResultOf<Image> unused = create_image(context, {.width = map.width, .height = map.height, .format = VK_FORMAT_R8_UNORM,
                                                    .usage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT});
  if (!unused) return unexpected(error(describe(unused.error())));
  map.unused_color = std::move(*unused);
  VkImageView views[2] = {map.depth.view(), map.unused_color.view()};
  VkFramebufferCreateInfo fb{VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO};
  fb.renderPass = pass;
  fb.attachmentCount = 2;
  fb.pAttachments = views;
  fb.width = map.width;
  fb.height = map.height;
  fb.layers = 1;
  if (vkCreateFramebuffer(context.device(), &fb, nullptr, &map.framebuffer) != VK_SUCCESS) {
    return unexpected(error("cannot create a shadow-map framebuffer"));
  }
  return {};
}

Result<void, RenderError> make_pipelines(const Context& context, const Scene& scene, const std::vector<ObjectState>& objects,
                                         VkRenderPass pass, VkPipelineCache cache, ShadowMap& map,
                                         uint64_t& pipelines_created) {
  for (const Draw& d : map.casters.draws) {
    bool created = false;
    PipelineState state = d.state;
    state.color_mask = 0;
    state.offset_factor += map.view.slope_bias;
    Result<VkPipeline, std::string> p =
        get_pipeline(context, *d.variant->program, state, objects[d.object].mirrored, pass, cache, &created);
    if (!p) return unexpected(error(fmt::format("{}: {}: {}", scene.path, d.record.object, p.error())));
    map.pipelines.push_back(*p);
    pipelines_created += created;
  }
  return {};
}

Result<void, RenderError> ensure_render_pass(VkDevice device, ShadowPasses& out) {
  if (out.render_pass) return {};
  Result<VkRenderPass, RenderError> pass = make_depth_pass(device);
  if (!pass) return unexpected(pass.error());
  out.render_pass = *pass;
  return {};
}

}  // namespace

ShadowPasses::~ShadowPasses() {
  if (!device) return;
  vkDeviceWaitIdle(device);
  for (auto& map : maps) {
    if (map->framebuffer) vkDestroyFramebuffer(device, map->framebuffer, nullptr);
  }
  if (render_pass) vkDestroyRenderPass(device, render_pass, nullptr);
}

const Image* ShadowPasses::map_of(const LightValues* light) const {
  for (const auto& map : maps) {
    if (light && map->light == light->scene_light()) return &map->depth;
  }
  return nullptr;
}

const ShadowMap* ShadowPasses::camera_depth() const {
  for (const auto& map : maps) {
    if (!map->light) return map.get();
  }
  return nullptr;
}

Result<void, RenderError> prepare_shadow_maps(const Context& context, const Scene& scene, std::vector<ObjectState>& objects,
                                              const LightSetup& lights, const std::vector<ShadowView>& views,
                                              const std::vector<Draw>& draws, ShaderLibrary& library,
                                              VkPipelineCache cache, ShadowPasses& out, uint64_t& pipelines_created) {
  out.device = context.device();
  uint32_t size = uint32_t(scene.shadow_resolution);
  for (const ShadowView& view : views) {
    const LightValues* light = &lights.lights[view.light];
    if (!light_is_sampled(light, draws)) continue;
    FACET_TRY(ensure_render_pass(context.device(), out));
    auto map = std::make_unique<ShadowMap>();
    map->view = view;
    map->light = light;
    map->width = map->height = size;
    Result<DrawListResult, RenderError> casters = build_caster_draws(context, scene, objects, *light, view, library);
    if (!casters) return unexpected(casters.error());
    map->casters = std::move(*casters);
    Scene seen_from_light = scene;
    seen_from_light.camera = view.lens;
    // Casters read depth only: the flat ambient's SH stands in for the environment's.
    map->frame = frame_uniforms(seen_from_light, view.camera, int(size), int(size), ambient_sh(scene));
    FACET_TRY(make_target(context, out.render_pass, *map));
    FACET_TRY(make_pipelines(context, scene, objects, out.render_pass, cache, *map, pipelines_created));
    out.maps.push_back(std::move(map));
  }
  return {};
}

Result<void, RenderError> prepare_camera_depth(const Context& context, const Scene& scene,
                                               std::vector<ObjectState>& objects, const LightValues& no_light,
                                               const CameraMatrices& camera, uint32_t width, uint32_t height, ShaderLibrary& library,
                                               VkPipelineCache cache, ShadowPasses& out, uint64_t& pipelines_created) {
  out.device = context.device();
  FACET_TRY(ensure_render_pass(context.device(), out));
  auto map = std::make_unique<ShadowMap>();
  map->view.camera = camera;
  map->view.lens = scene.camera;
  map->width = width;
  map->height = height;
  Result<DrawListResult, RenderError> casters =
      caster_draws(context, scene, objects, no_light, [](const ObjectState& o) { return o.queue <= 2500; }, "",
                   "the camera depth texture", library);
  if (!casters) return unexpected(casters.error());
  map->casters = std::move(*casters);
  FACET_TRY(make_target(context, out.render_pass, *map));
  FACET_TRY(make_pipelines(context, scene, objects, out.render_pass, cache, *map, pipelines_created));
  out.maps.push_back(std::move(map));
  return {};
}

Result<uint64_t, RenderError> record_shadow_maps(VkCommandBuffer commands, const ShadowPasses& passes,
                                                 const std::vector<ObjectState>& objects, const BindDraw& bind,
                                                 const UniformValues& camera_frame) {
  uint64_t triangles = 0;
  for (const auto& map : passes.maps) {
    VkClearValue clear{};
    clear.depthStencil = {1.0f, 0};
    VkRenderPassBeginInfo begin{VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO};
    begin.renderPass = passes.render_pass;
    begin.framebuffer = map->framebuffer;
    begin.renderArea = {{0, 0}, {map->width, map->height}};
    begin.clearValueCount = 1;
    begin.pClearValues = &clear;
    vkCmdBeginRenderPass(commands, &begin, VK_SUBPASS_CONTENTS_INLINE);
    VkViewport viewport{0, 0, float(map->width), float(map->height), 0, 1};
    vkCmdSetViewport(commands, 0, 1, &viewport);
    vkCmdSetScissor(commands, 0, 1, &begin.renderArea);
    Result<void, RenderError> bound;
    for (size_t i = 0; i < map->casters.draws.size() && bound; ++i) {
      const Draw& d = map->casters.draws[i];
      const ObjectState& object = objects[d.object];
      vkCmdBindPipeline(commands, VK_PIPELINE_BIND_POINT_GRAPHICS, map->pipelines[i]);
      bound = bind(commands, d, map->light ? map->frame : camera_frame);
      if (!bound) break;
      VkBuffer vb = object.mesh->vertices.handle();
      VkDeviceSize offset = 0;
      vkCmdBindVertexBuffers(commands, 0, 1, &vb, &offset);
      vkCmdBindIndexBuffer(commands, object.mesh->indices.handle(), 0, VK_INDEX_TYPE_UINT32);
      vkCmdDrawIndexed(commands, object.mesh->index_count, 1, 0, 0, 0);
      triangles += object.mesh->index_count / 3;
    }
    vkCmdEndRenderPass(commands);
    if (!bound) return unexpected(bound.error());
  }
  return triangles;
}

}  // namespace facet::runtime
