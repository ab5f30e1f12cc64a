#include "render/shadow_pass.h"

#include "render/targets.h"

#include <fmt/format.h>

#include <algorithm>
#include <initializer_list>
#include <span>

#include "facet/runtime/vulkan_context.h"
#include "render/program.h"

namespace facet::runtime {
namespace {

Result<VkRenderPass, VkResult> create_pass(VkDevice device, std::span<const VkAttachmentDescription> attachments,
                                          const VkSubpassDescription& subpass, VkPipelineStageFlags written_stages,
                                          VkAccessFlags written_access) {
  // Before: the last frame's receivers read the map, and the pass before
  // (another face of the same cube) wrote the attachments this one clears.
  // After: this frame's receivers read it.
  VkSubpassDependency deps[2]{};
  deps[0] = {VK_SUBPASS_EXTERNAL, 0, VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT | written_stages, written_stages,
             VK_ACCESS_SHADER_READ_BIT | written_access, written_access, 0};
  deps[1] = {0, VK_SUBPASS_EXTERNAL, written_stages, VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT, written_access,
             VK_ACCESS_SHADER_READ_BIT, 0};
  VkRenderPassCreateInfo info{VK_STRUCTURE_TYPE_RENDER_PASS_CREATE_INFO};
  info.attachmentCount = uint32_t(attachments.size());
  info.pAttachments = attachments.data();
  info.subpassCount = 1;
  info.pSubpasses = &subpass;
  info.dependencyCount = 2;
  info.pDependencies = deps;
  VkRenderPass pass = VK_NULL_HANDLE;
  if (VkResult r = vkCreateRenderPass(device, &info, nullptr, &pass); r != VK_SUCCESS) return unexpected(r);
  return pass;
}

VkAttachmentDescription cleared(VkFormat format, VkAttachmentStoreOp store, VkImageLayout final_layout) {
  VkAttachmentDescription a{};
  a.format = format;
  a.samples = VK_SAMPLE_COUNT_1_BIT;
  a.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
  a.storeOp = store;
  a.stencilLoadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
  a.stencilStoreOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
  a.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
  a.finalLayout = final_layout;
  return a;
}

// Depth, cleared to the far plane, left for the receivers' fragment stage;
// and an R8 colour attachment that nothing writes or keeps, there because
// casters' fragment stages write SV_Target (a fragment output without an
// attachment is a validation warning).
Result<VkRenderPass, Diagnostics> make_depth_pass(VkDevice device) {
  VkAttachmentDescription attachments[2] = {
      cleared(VK_FORMAT_D32_SFLOAT, VK_ATTACHMENT_STORE_OP_STORE, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL),
      cleared(VK_FORMAT_R8_UNORM, VK_ATTACHMENT_STORE_OP_DONT_CARE, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL)};
  attachments[1].loadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
  VkAttachmentReference ref{0, VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL};
  VkAttachmentReference color_ref{1, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL};
  VkSubpassDescription subpass{};
  subpass.pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
  subpass.colorAttachmentCount = 1;
  subpass.pColorAttachments = &color_ref;
  subpass.pDepthStencilAttachment = &ref;
  Result<VkRenderPass, VkResult> pass =
      create_pass(device, attachments, subpass,
                  VK_PIPELINE_STAGE_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT,
                  VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT);
  if (!pass) {
    return unexpected(render_error("cannot create the shadow-map render pass: " + vk_result_name(pass.error()),
                                   DiagId::vulkan_failed));
  }
  return *pass;
}

// A cube face: the casters' distances (R32F, cleared far beyond any range),
// kept for the receivers, with a depth buffer that only orders the casters.
Result<VkRenderPass, Diagnostics> make_cube_pass(VkDevice device) {
  VkAttachmentDescription attachments[2] = {
      cleared(VK_FORMAT_R32_SFLOAT, VK_ATTACHMENT_STORE_OP_STORE, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL),
      cleared(VK_FORMAT_D32_SFLOAT, VK_ATTACHMENT_STORE_OP_DONT_CARE, VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL)};
  VkAttachmentReference color_ref{0, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL};
  VkAttachmentReference depth_ref{1, VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL};
  VkSubpassDescription subpass{};
  subpass.pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
  subpass.colorAttachmentCount = 1;
  subpass.pColorAttachments = &color_ref;
  subpass.pDepthStencilAttachment = &depth_ref;
  Result<VkRenderPass, VkResult> pass =
      create_pass(device, attachments, subpass,
                  VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT | VK_PIPELINE_STAGE_EARLY_FRAGMENT_TESTS_BIT |
                      VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT,
                  VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT | VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT);
  if (!pass) {
    return unexpected(render_error("cannot create the shadow-cube render pass: " + vk_result_name(pass.error()),
                                   DiagId::vulkan_failed));
  }
  return *pass;
}

bool light_is_sampled(const LightValues* light, const std::vector<const std::vector<Draw>*>& receivers) {
  return std::any_of(receivers.begin(), receivers.end(), [&](const std::vector<Draw>* draws) {
    return std::any_of(draws->begin(), draws->end(), [&](const Draw& d) {
      return d.light && d.light->scene_light() == light && samples_shadow_map(d.record.keywords);
    });
  });
}

Result<void, Diagnostics> make_target(const Context& context, VkRenderPass pass, ShadowMap& map) {
  VkResultOf<Image> depth = create_image(context, {.width = map.width, .height = map.height, .format = VK_FORMAT_D32_SFLOAT,
                                                   .usage = VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT |
                                                            VK_IMAGE_USAGE_SAMPLED_BIT});
  if (!depth) return unexpected(render_error(describe(depth.error()), DiagId::vulkan_failed));
  map.depth = std::move(*depth);
  VkResultOf<Image> unused = create_image(context, {.width = map.width, .height = map.height, .format = VK_FORMAT_R8_UNORM,
                                                    .usage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT});
  if (!unused) return unexpected(render_error(describe(unused.error()), DiagId::vulkan_failed));
  map.unused_color = std::move(*unused);
  Result<VkFramebuffer, Diagnostics> fb =
      make_framebuffer(context.device(), pass, {map.depth.view(), map.unused_color.view()}, map.width, map.height);
  if (!fb) return unexpected(fb.error());
  map.framebuffer = *fb;
  return {};
}

Result<std::shared_ptr<CubeTarget>, Diagnostics> make_cube_target(const Context& context, uint32_t size) {
  auto cube = std::make_shared<CubeTarget>();
  cube->device = context.device();
  VkResultOf<Image> color = create_image(context, {.width = size, .height = size, .layers = 6,
                                                   .format = VK_FORMAT_R32_SFLOAT,
                                                   .usage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT,
                                                   .view = VK_IMAGE_VIEW_TYPE_CUBE});
  if (!color) return unexpected(render_error(describe(color.error()), DiagId::vulkan_failed));
  cube->color = std::move(*color);
  VkResultOf<Image> depth = create_image(context, {.width = size, .height = size, .format = VK_FORMAT_D32_SFLOAT,
                                                   .usage = VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT});
  if (!depth) return unexpected(render_error(describe(depth.error()), DiagId::vulkan_failed));
  cube->depth = std::move(*depth);
  for (uint32_t face = 0; face < 6; ++face) {
    VkImageViewCreateInfo info{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
    info.image = cube->color.handle();
    info.viewType = VK_IMAGE_VIEW_TYPE_2D;
    info.format = VK_FORMAT_R32_SFLOAT;
    info.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, face, 1};
    if (VkResult r = vkCreateImageView(context.device(), &info, nullptr, &cube->faces[face]); r != VK_SUCCESS) {
      return unexpected(
          render_error("cannot create a shadow-cube face view: " + vk_result_name(r), DiagId::vulkan_failed));
    }
  }
  return cube;
}

Result<void, Diagnostics> make_pipelines(const Context& context, const Scene& scene,
                                         const std::vector<ObjectState>& objects, VkRenderPass pass,
                                         VkPipelineCache cache, ShadowMap& map, uint64_t& pipelines_created) {
  for (const Draw& d : map.casters.draws) {
    bool created = false;
    PipelineState state = d.state;
    if (!map.cube) state.color_mask = 0;  // a cube keeps the distances the casters write
    state.offset_factor += map.view.slope_bias;
    Result<VkPipeline, std::string> p =
        get_pipeline(context, *d.variant->program, state, objects[d.object].mirrored, pass, cache, &created);
    if (!p) return unexpected(render_error(fmt::format("{}: {}: {}", scene.path, d.record.object, p.error())));
    map.pipelines.push_back(*p);
    pipelines_created += created;
  }
  return {};
}

Result<void, Diagnostics> ensure_render_pass(VkDevice device, ShadowPasses& out) {
  if (out.render_pass) return {};
  Result<VkRenderPass, Diagnostics> pass = make_depth_pass(device);
  if (!pass) return unexpected(pass.error());
  out.render_pass = *pass;
  return {};
}

Result<void, Diagnostics> ensure_cube_pass(VkDevice device, ShadowPasses& out) {
  if (out.cube_pass) return {};
  Result<VkRenderPass, Diagnostics> pass = make_cube_pass(device);
  if (!pass) return unexpected(pass.error());
  out.cube_pass = *pass;
  return {};
}

// The frame uniforms of the scene seen through `camera` with the light's lens.
UniformValues light_frame(const Scene& scene, const ShadowView& view, const CameraMatrices& camera, uint32_t size) {
  Scene seen_from_light = scene;
  seen_from_light.camera = view.lens;
  // Casters read depth or distance only: the flat ambient's SH stands in for the environment's.
  return frame_uniforms(seen_from_light, camera, int(size), int(size), ambient_sh(scene));
}

// One entry a cascade: the first makes the atlas and begins its render
// pass, the others draw into their squares of it in the same pass.
Result<void, Diagnostics> prepare_cascades(const Context& context, const Scene& scene,
                                           std::vector<ObjectState>& objects, const LightValues* light,
                                           const ShadowView& view, ShaderLibrary& library, VkPipelineCache cache,
                                           ShadowPasses& out, uint64_t& pipelines_created) {
  FACET_TRY(ensure_render_pass(context.device(), out));
  for (size_t c = 0; c < view.cascades.size(); ++c) {
    const ShadowCascade& cascade = view.cascades[c];
    auto map = std::make_unique<ShadowMap>();
    map->view = view;
    map->view.camera = cascade.camera;
    map->view.lens = cascade.lens;
    map->view.caster_bias = cascade.caster_bias;
    map->light = light;
    map->width = view.width;
    map->height = view.height;
    map->area = {{int32_t(cascade.x), int32_t(cascade.y)}, {cascade.size, cascade.size}};
    map->continues = c > 0;
    map->caster_light = std::make_unique<LightValues>(*light);
    map->caster_light->source = light;
    const glm::vec4& bias = cascade.caster_bias;
    map->caster_light->values.set_vector("unity_LightShadowBias", bias.x, bias.y, bias.z, 0);
    Result<DrawListResult, Diagnostics> casters =
        build_caster_draws(context, scene, objects, *map->caster_light, map->view, library);
    if (!casters) return unexpected(casters.error());
    map->casters = std::move(*casters);
    map->frame = light_frame(scene, map->view, cascade.camera, cascade.size);
    if (c == 0) FACET_TRY(make_target(context, out.render_pass, *map));
    FACET_TRY(make_pipelines(context, scene, objects, out.render_pass, cache, *map, pipelines_created));
    out.maps.push_back(std::move(map));
  }
  return {};
}

// Six entries, one a face, sharing one cube target.
Result<void, Diagnostics> prepare_cube(const Context& context, const Scene& scene, std::vector<ObjectState>& objects,
                                       const LightValues* light, const ShadowView& view, ShaderLibrary& library,
                                       VkPipelineCache cache, ShadowPasses& out, uint64_t& pipelines_created) {
  const uint32_t size = uint32_t(scene.shadow_resolution);
  FACET_TRY(ensure_cube_pass(context.device(), out));
  Result<std::shared_ptr<CubeTarget>, Diagnostics> cube = make_cube_target(context, size);
  if (!cube) return unexpected(cube.error());
  for (int face = 0; face < 6; ++face) {
    auto map = std::make_unique<ShadowMap>();
    map->view = view;
    map->view.camera = view.faces[size_t(face)];
    map->light = light;
    map->width = map->height = size;
    map->cube = *cube;
    map->face = face;
    // Each face draws its own copy: a draw's uniforms hold one camera.
    Result<DrawListResult, Diagnostics> casters = build_caster_draws(context, scene, objects, *light, view, library);
    if (!casters) return unexpected(casters.error());
    map->casters = std::move(*casters);
    map->frame = light_frame(scene, view, map->view.camera, size);
    Result<VkFramebuffer, Diagnostics> fb = make_framebuffer(
        context.device(), out.cube_pass, {map->cube->faces[size_t(face)], map->cube->depth.view()}, size, size);
    if (!fb) return unexpected(fb.error());
    map->framebuffer = *fb;
    FACET_TRY(make_pipelines(context, scene, objects, out.cube_pass, cache, *map, pipelines_created));
    out.maps.push_back(std::move(map));
  }
  return {};
}

}  // namespace

CubeTarget::~CubeTarget() {
  for (VkImageView view : faces) {
    if (view) vkDestroyImageView(device, view, nullptr);
  }
}

ShadowPasses::~ShadowPasses() {
  if (!device) return;
  vkDeviceWaitIdle(device);
  for (auto& map : maps) {
    if (map->framebuffer) vkDestroyFramebuffer(device, map->framebuffer, nullptr);
  }
  if (render_pass) vkDestroyRenderPass(device, render_pass, nullptr);
  if (cube_pass) vkDestroyRenderPass(device, cube_pass, nullptr);
}

const Image* ShadowPasses::map_of(const LightValues* light) const {
  for (const auto& map : maps) {
    if (light && map->light == light->scene_light()) return map->cube ? &map->cube->color : &map->depth;
  }
  return nullptr;
}

bool ShadowPasses::is_cube(const Image* image) const {
  return std::any_of(maps.begin(), maps.end(), [&](const auto& m) { return m->cube && &m->cube->color == image; });
}

size_t ShadowPasses::light_maps() const {
  return size_t(std::count_if(maps.begin(), maps.end(),
                              [](const auto& m) { return m->light && m->face == 0 && !m->continues; }));
}

const ShadowMap* ShadowPasses::camera_depth() const {
  for (const auto& map : maps) {
    if (!map->light) return map.get();
  }
  return nullptr;
}

Result<void, Diagnostics> prepare_shadow_maps(const Context& context, const Scene& scene,
                                              std::vector<ObjectState>& objects, const LightSetup& lights,
                                              const std::vector<ShadowView>& views,
                                              const std::vector<const std::vector<Draw>*>& receivers,
                                              ShaderLibrary& library, VkPipelineCache cache, ShadowPasses& out,
                                              uint64_t& pipelines_created) {
  out.device = context.device();
  uint32_t size = uint32_t(scene.shadow_resolution);
  for (const ShadowView& view : views) {
    const LightValues* light = &lights.lights[view.light];
    if (!light_is_sampled(light, receivers)) continue;
    if (!view.faces.empty()) {
      FACET_TRY(prepare_cube(context, scene, objects, light, view, library, cache, out, pipelines_created));
      continue;
    }
    if (!view.cascades.empty()) {
      FACET_TRY(prepare_cascades(context, scene, objects, light, view, library, cache, out, pipelines_created));
      continue;
    }
    FACET_TRY(ensure_render_pass(context.device(), out));
    auto map = std::make_unique<ShadowMap>();
    map->view = view;
    map->light = light;
    map->width = map->height = size;
    Result<DrawListResult, Diagnostics> casters = build_caster_draws(context, scene, objects, *light, view, library);
    if (!casters) return unexpected(casters.error());
    map->casters = std::move(*casters);
    map->frame = light_frame(scene, view, view.camera, size);
    FACET_TRY(make_target(context, out.render_pass, *map));
    FACET_TRY(make_pipelines(context, scene, objects, out.render_pass, cache, *map, pipelines_created));
    out.maps.push_back(std::move(map));
  }
  return {};
}

Result<void, Diagnostics> prepare_camera_depth(const Context& context, const Scene& scene,
                                               std::vector<ObjectState>& objects, const LightValues& no_light,
                                               const CameraMatrices& camera, uint32_t width, uint32_t height,
                                               ShaderLibrary& library, VkPipelineCache cache, ShadowPasses& out,
                                               uint64_t& pipelines_created) {
  out.device = context.device();
  FACET_TRY(ensure_render_pass(context.device(), out));
  auto map = std::make_unique<ShadowMap>();
  map->view.camera = camera;
  map->view.lens = scene.camera;
  map->width = width;
  map->height = height;
  Result<DrawListResult, Diagnostics> casters = caster_draws(
      context, scene, objects, no_light, [](const ObjectState& o) { return o.queue <= 2500; }, "",
      "the camera depth texture", "SHADOWS_DEPTH", library);
  if (!casters) return unexpected(casters.error());
  map->casters = std::move(*casters);
  FACET_TRY(make_target(context, out.render_pass, *map));
  FACET_TRY(make_pipelines(context, scene, objects, out.render_pass, cache, *map, pipelines_created));
  out.maps.push_back(std::move(map));
  return {};
}

namespace {

void begin_pass(VkCommandBuffer commands, const ShadowPasses& passes, const ShadowMap& map) {
  // A depth map clears its depth (attachment 0); a cube face its distances
  // (attachment 0, far beyond any range) and its depth (attachment 1).
  VkClearValue clears[2]{};
  if (map.cube) {
    clears[0].color = {{1e30f, 1e30f, 1e30f, 1e30f}};
    clears[1].depthStencil = {1.0f, 0};
  } else {
    clears[0].depthStencil = {1.0f, 0};
  }
  VkRenderPassBeginInfo begin{VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO};
  begin.renderPass = map.cube ? passes.cube_pass : passes.render_pass;
  begin.framebuffer = map.framebuffer;
  begin.renderArea = {{0, 0}, {map.width, map.height}};
  begin.clearValueCount = map.cube ? 2 : 1;
  begin.pClearValues = clears;
  vkCmdBeginRenderPass(commands, &begin, VK_SUBPASS_CONTENTS_INLINE);
}

}  // namespace

Result<uint64_t, Diagnostics> record_shadow_maps(VkCommandBuffer commands, const ShadowPasses& passes,
                                                 const std::vector<ObjectState>& objects, const BindDraw& bind,
                                                 const UniformValues& camera_frame) {
  uint64_t triangles = 0;
  bool open = false;
  for (const auto& map : passes.maps) {
    if (!map->continues) {
      if (open) vkCmdEndRenderPass(commands);
      begin_pass(commands, passes, *map);
      open = true;
    }
    const VkRect2D area = map->area.extent.width ? map->area : VkRect2D{{0, 0}, {map->width, map->height}};
    VkViewport viewport{float(area.offset.x), float(area.offset.y), float(area.extent.width), float(area.extent.height),
                        0, 1};
    vkCmdSetViewport(commands, 0, 1, &viewport);
    vkCmdSetScissor(commands, 0, 1, &area);
    for (size_t i = 0; i < map->casters.draws.size(); ++i) {
      const Draw& d = map->casters.draws[i];
      const ObjectState& object = objects[d.object];
      vkCmdBindPipeline(commands, VK_PIPELINE_BIND_POINT_GRAPHICS, map->pipelines[i]);
      Result<void, Diagnostics> bound = bind(commands, d, map->light ? map->frame : camera_frame);
      if (!bound) {
        vkCmdEndRenderPass(commands);
        return unexpected(bound.error());
      }
      VkBuffer vb = object.mesh->vertices.handle();
      VkDeviceSize offset = 0;
      vkCmdBindVertexBuffers(commands, 0, 1, &vb, &offset);
      vkCmdBindIndexBuffer(commands, object.mesh->indices.handle(), 0, VK_INDEX_TYPE_UINT32);
      vkCmdDrawIndexed(commands, object.mesh->index_count, 1, 0, 0, 0);
      triangles += object.mesh->index_count / 3;
    }
  }
  if (open) vkCmdEndRenderPass(commands);
  return triangles;
}

}  // namespace facet::runtime
