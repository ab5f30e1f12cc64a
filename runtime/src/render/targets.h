// Small pieces the renderer's extra render passes share: a one-subpass
// render pass over given attachments, its framebuffer, and the full-screen
// quad that keeps the camera's matrices (the deferred light pass and the
// screen-space shadow pass rebuild positions from the camera depth with it).
#pragma once

#include <vulkan/vulkan.h>

#include <memory>
#include <string>
#include <vector>

#include "render/draw_list.h"
#include "render/failure.h"

namespace facet::runtime {

// An attachment stored at the end; cleared unless `load`.
VkAttachmentDescription attachment(VkFormat format, bool load, VkImageLayout initial, VkImageLayout final);

// One subpass over `attachments` (colour first; the depth, if any, last),
// ordered after what came before it and before what reads it (fragment
// shaders, attachments, transfers).
Result<VkRenderPass, Diagnostics> make_single_pass(VkDevice device,
                                                   const std::vector<VkAttachmentDescription>& attachments,
                                                   bool has_depth, const char* what);

Result<VkFramebuffer, Diagnostics> make_framebuffer(VkDevice device, VkRenderPass pass,
                                                    const std::vector<VkImageView>& views, uint32_t width,
                                                    uint32_t height);

// The built-in quad over the whole screen, drawn with the camera's own
// view-projection: its object matrix (camera_quad_uniforms) takes it back
// through the camera, and each corner's normal is the view ray through it
// in Unity's camera space (+Z forward, z = 1), which Unity's deferred
// shaders read when _LightAsQuad is 1 (set here too).
Result<GpuMesh, Diagnostics> camera_quad_mesh(const Context& context, const CameraMatrices& camera);
UniformValues camera_quad_uniforms(const CameraMatrices& camera);

// The object of one of the renderer's own full-screen passes: the stdlib's
// Shaders/<file> on the camera quad. `source` names it in messages.
struct ScreenPassObject {
  SceneObject source;
  std::unique_ptr<GpuMesh> quad;
  std::vector<ObjectState> objects;  // one, shared by all of the pass's draws
};

// `what` says what needs the shader, for the errors ("the deferred light
// pass"); `json_path` is the scene key that asked for the pass.
Result<void, Diagnostics> make_screen_pass_object(const Context& context, const Scene& scene, ShaderLibrary& library,
                                                  const CameraMatrices& camera, const std::string& file,
                                                  const std::string& what, const std::string& json_path,
                                                  ScreenPassObject& out);

}  // namespace facet::runtime
