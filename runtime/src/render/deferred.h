// Unity's built-in deferred shading (SceneCamera::deferred), in three render
// passes over the frame's colour and depth images:
//   1. the G-buffer: the Deferred passes of the opaque objects (draw_list.h)
//      write RT0 (diffuse, occlusion; RGBA8), RT1 (specular, smoothness;
//      RGBA8), RT2 (world normal * 0.5 + 0.5; A2B10G10R10) and RT3, the
//      light buffer (the RGBA16F colour target: ambient, reflections and
//      emission), with the depth;
//   2. the lights: one full-screen draw a light of the stdlib's
//      Hidden/Internal-DeferredShading, reading the G-buffer as
//      _CameraGBufferTexture0..2 and the depth as _CameraDepthTexture,
//      added into the light buffer;
//   3. the forward part (renderer.cpp), which continues on the light buffer
//      and the depth: the sky, transparent objects and shaders without a
//      Deferred pass.
// Unity draws point and spot lights as volumes and skips unlit pixels with
// the stencil; a full-screen draw gives the same sums (the light's falloff is
// 0 beyond its range, the G-buffer 0 where nothing was drawn), at more fill.
#pragma once

#include <vulkan/vulkan.h>

#include <array>
#include <memory>
#include <vector>

#include "facet/runtime/image.h"
#include "render/draw_list.h"
#include "render/targets.h"
#include "render/failure.h"

namespace facet::runtime {

struct DeferredTargets {
  VkDevice device = VK_NULL_HANDLE;
  std::array<Image, 3> gbuffer;  // RT0..RT2; RT3 is the frame's colour image
  VkRenderPass gbuffer_pass = VK_NULL_HANDLE, light_pass = VK_NULL_HANDLE;
  VkFramebuffer gbuffer_framebuffer = VK_NULL_HANDLE, light_framebuffer = VK_NULL_HANDLE;
  DeferredTargets() = default;
  DeferredTargets(const DeferredTargets&) = delete;
  DeferredTargets& operator=(const DeferredTargets&) = delete;
  ~DeferredTargets();
};

inline constexpr uint32_t kGBufferTargets = 4;

// The G-buffer images and both passes' render passes and framebuffers.
// `color` (RGBA16F) ends the light pass in COLOR_ATTACHMENT_OPTIMAL; `depth`
// (D32, sampled) ends the G-buffer pass in SHADER_READ_ONLY_OPTIMAL.
Result<void, Diagnostics> make_deferred_targets(const Context& context, const Image& color, const Image& depth,
                                                uint32_t width, uint32_t height, DeferredTargets& out);

// The G-buffer textures and the depth by the names the light shader samples.
std::map<std::string, const Image*> gbuffer_textures(const DeferredTargets& targets, const Image& depth);

// The light pass's draws: one a light that reaches something (brightness
// above 0), with its light keyword, its shadow keywords and UNITY_HDR_ON.
struct DeferredLights {
  ScreenPassObject screen;  // Hidden/Internal-DeferredShading on the camera quad
  DrawListResult list;
};

Result<std::unique_ptr<DeferredLights>, Diagnostics> build_deferred_lights(const Context& context, const Scene& scene,
                                                                           ShaderLibrary& library,
                                                                           const LightSetup& lights,
                                                                           const CameraMatrices& camera);

}  // namespace facet::runtime
