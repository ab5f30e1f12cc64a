// The GPU side of shadows (shadows.h): a depth render pass, one D32
// map per light whose receivers' variants sample it, the casters'
// pipelines, and recording every map before the camera's pass. The camera
// depth texture of objects that sample _CameraDepthTexture is made the same
// way, as Unity makes it: the opaque objects' ShadowCaster passes seen from
// the camera.
#pragma once

#include <vulkan/vulkan.h>

#include <array>
#include <functional>
#include <memory>
#include <vector>

#include "facet/runtime/image.h"
#include "render/draw_list.h"
#include "render/shadows.h"
#include "render/failure.h"

namespace facet::runtime {

// A point light's distance cube (R32F, six layers, sampled as a cube) and
// the depth buffer its faces share, with a 2D view of each face to render to.
struct CubeTarget {
  VkDevice device = VK_NULL_HANDLE;
  Image color, depth;
  std::array<VkImageView, 6> faces{};
  CubeTarget() = default;
  CubeTarget(const CubeTarget&) = delete;
  CubeTarget& operator=(const CubeTarget&) = delete;
  ~CubeTarget();
};

// One depth map, or one face of a point light's cube (`cube` set, `face`
// 0..5; the draws and frame values are that face's, the images the cube's).
struct ShadowMap {
  ShadowView view;
  const LightValues* light = nullptr;  // null for the camera depth texture
  uint32_t width = 0, height = 0;
  DrawListResult casters;
  UniformValues frame;  // the frame uniforms with the light as the camera (unused for the camera depth texture)
  Image depth;
  Image unused_color;  // R8, never written (see make_depth_pass)
  VkFramebuffer framebuffer = VK_NULL_HANDLE;
  std::vector<VkPipeline> pipelines;  // per caster draw
  std::shared_ptr<CubeTarget> cube;
  int face = 0;
  // A cascade: its square of the atlas, and whether it is drawn in the
  // render pass of the entry before it (the atlas's first cascade owns the
  // target); its casters see `caster_light`, the light with this cascade's
  // bias.
  VkRect2D area{};
  bool continues = false;
  std::unique_ptr<LightValues> caster_light;
};

struct ShadowPasses {
  VkDevice device = VK_NULL_HANDLE;
  VkRenderPass render_pass = VK_NULL_HANDLE;
  VkRenderPass cube_pass = VK_NULL_HANDLE;  // a cube face: R32F distance and depth
  std::vector<std::unique_ptr<ShadowMap>> maps;  // the lights' maps (six a cube), then the camera depth texture
  ShadowPasses() = default;
  ShadowPasses(const ShadowPasses&) = delete;
  ShadowPasses& operator=(const ShadowPasses&) = delete;
  ~ShadowPasses();
  // The map (or cube) that `light`'s receivers sample, or null.
  const Image* map_of(const LightValues* light) const;
  const ShadowMap* camera_depth() const;
  bool is_cube(const Image* image) const;
  // The lights' maps and cubes, a cube counted once.
  size_t light_maps() const;
};

// Makes a map for each view whose light some drawn variant samples it with
// (samples_shadow_map), with the caster draws and their pipelines.
Result<void, Diagnostics> prepare_shadow_maps(const Context& context, const Scene& scene,
                                              std::vector<ObjectState>& objects, const LightSetup& lights,
                                              const std::vector<ShadowView>& views,
                                              const std::vector<const std::vector<Draw>*>& receivers,
                                              ShaderLibrary& library, VkPipelineCache cache, ShadowPasses& out,
                                              uint64_t& pipelines_created);

// Adds the camera depth texture: the ShadowCaster passes of the opaque
// objects (queue <= 2500) from the camera, at the frame's size.
Result<void, Diagnostics> prepare_camera_depth(const Context& context, const Scene& scene,
                                               std::vector<ObjectState>& objects, const LightValues& no_light,
                                               const CameraMatrices& camera, uint32_t width, uint32_t height,
                                               ShaderLibrary& library, VkPipelineCache cache, ShadowPasses& out,
                                               uint64_t& pipelines_created);

using BindDraw = std::function<Result<void, Diagnostics>(VkCommandBuffer, const Draw&, const UniformValues& frame)>;

// Records every map's pass; the camera depth texture's draws see
// `camera_frame`, the frame's own values. Returns the triangles drawn.
Result<uint64_t, Diagnostics> record_shadow_maps(VkCommandBuffer commands, const ShadowPasses& passes,
                                                 const std::vector<ObjectState>& objects, const BindDraw& bind,
                                                 const UniformValues& camera_frame);

}  // namespace facet::runtime
