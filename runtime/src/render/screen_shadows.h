// Unity's screen-space shadows for directional lights: before the camera's
// passes, one full-screen draw a shadowed directional light of the stdlib's
// Hidden/Internal-ScreenSpaceShadows looks the light's map (the cascade a
// pixel falls in) up at every pixel of the camera depth texture and writes
// the light's visibility into a screen-sized R8 mask. Every draw whose
// variant has SHADOWS_SCREEN (ForwardBase and ForwardAdd receivers, the
// deferred light pass) samples that mask as _ShadowMapTexture at its screen
// position instead of the map. As in Unity the mask holds what the camera
// depth texture holds, the opaque objects (queue <= 2500); transparent
// objects get no SHADOWS_SCREEN (draw_list.cpp).
#pragma once

#include <vulkan/vulkan.h>

#include <memory>
#include <vector>

#include "facet/runtime/image.h"
#include "render/draw_list.h"
#include "render/targets.h"
#include "render/failure.h"

namespace facet::runtime {

struct ScreenShadows {
  VkDevice device = VK_NULL_HANDLE;
  VkRenderPass render_pass = VK_NULL_HANDLE;
  ScreenPassObject screen;           // Hidden/Internal-ScreenSpaceShadows on the camera quad
  DrawListResult list;               // one draw a mask, its light the mask's
  std::vector<Image> masks;          // parallel to list.draws
  std::vector<VkFramebuffer> framebuffers;
  std::vector<VkPipeline> pipelines;
  ScreenShadows() = default;
  ScreenShadows(const ScreenShadows&) = delete;
  ScreenShadows& operator=(const ScreenShadows&) = delete;
  ~ScreenShadows();
  // The mask of `light` (a scene light or a draw's copy of one), or null.
  const Image* mask_of(const LightValues* light) const;
  bool owns(const Image* image) const;
};

// Whether the draw's variant reads a screen-space mask (its SHADOWS_SCREEN).
bool reads_screen_shadows(const Draw& draw);

// The directional lights some draw of `receivers` reads a mask of.
std::vector<const LightValues*> screen_shadowed_lights(const std::vector<const std::vector<Draw>*>& receivers);

// A mask and its draw for each of `lights` (their shadow maps and the camera
// depth texture are made before it), with the pipelines.
Result<void, Diagnostics> prepare_screen_shadows(const Context& context, const Scene& scene, ShaderLibrary& library,
                                                 const CameraMatrices& camera,
                                                 const std::vector<const LightValues*>& lights, uint32_t width,
                                                 uint32_t height, VkPipelineCache cache, ScreenShadows& out,
                                                 uint64_t& pipelines_created);

}  // namespace facet::runtime
