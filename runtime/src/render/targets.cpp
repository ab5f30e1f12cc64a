#include "render/targets.h"

#include <fmt/format.h>

#include <glm/gtc/matrix_transform.hpp>

#include "facet/runtime/vulkan_context.h"

namespace facet::runtime {
namespace {

// The built-in quad (-0.5..0.5) to 0..1, then to the whole of clip space,
// halfway into the depth range: at depth 0 (the near plane) the round trip
// through the camera's inverse could land it a rounding error in front of
// the near plane, where it is clipped away.
glm::mat4 quad_to_clip() {
  return glm::translate(glm::mat4(1), glm::vec3(-1, -1, 0.5f)) * glm::scale(glm::mat4(1), glm::vec3(2, 2, 1)) *
         glm::translate(glm::mat4(1), glm::vec3(0.5f, 0.5f, 0));
}

glm::mat4 inverse_view_projection(const CameraMatrices& camera) {
  return glm::inverse(camera.projection * camera.view);
}

}  // namespace

VkAttachmentDescription attachment(VkFormat format, bool load, VkImageLayout initial, VkImageLayout final) {
  VkAttachmentDescription a{};
  a.format = format;
  a.samples = VK_SAMPLE_COUNT_1_BIT;
  a.loadOp = load ? VK_ATTACHMENT_LOAD_OP_LOAD : VK_ATTACHMENT_LOAD_OP_CLEAR;
  a.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
  a.stencilLoadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
  a.stencilStoreOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
  a.initialLayout = initial;
  a.finalLayout = final;
  return a;
}

Result<VkRenderPass, Diagnostics> make_single_pass(VkDevice device,
                                                   const std::vector<VkAttachmentDescription>& attachments,
                                                   bool has_depth, const char* what) {
  std::vector<VkAttachmentReference> colors;
  for (uint32_t i = 0; i + (has_depth ? 1 : 0) < attachments.size(); ++i) {
    colors.push_back({i, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL});
  }
  VkAttachmentReference depth{uint32_t(attachments.size() - 1), VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL};
  VkSubpassDescription subpass{};
  subpass.pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
  subpass.colorAttachmentCount = uint32_t(colors.size());
  subpass.pColorAttachments = colors.data();
  subpass.pDepthStencilAttachment = has_depth ? &depth : nullptr;
  constexpr VkPipelineStageFlags kWrites =
      VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT | VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT;
  constexpr VkPipelineStageFlags kUses =
      VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT | VK_PIPELINE_STAGE_EARLY_FRAGMENT_TESTS_BIT | kWrites;
  constexpr VkAccessFlags kWriteAccess =
      VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT | VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT;
  constexpr VkAccessFlags kUseAccess = VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_COLOR_ATTACHMENT_READ_BIT |
                                       VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_READ_BIT | kWriteAccess;
  VkSubpassDependency deps[2]{};
  // Outside the subpass the transfer stage too: the readback and GrabPass copies.
  constexpr VkPipelineStageFlags kOutside = kUses | VK_PIPELINE_STAGE_TRANSFER_BIT;
  deps[0] = {VK_SUBPASS_EXTERNAL, 0, kOutside, kUses,
             kWriteAccess | VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_TRANSFER_READ_BIT, kUseAccess, 0};
  deps[1] = {0, VK_SUBPASS_EXTERNAL, kWrites, kOutside, kWriteAccess, kUseAccess | VK_ACCESS_TRANSFER_READ_BIT, 0};
  VkRenderPassCreateInfo info{VK_STRUCTURE_TYPE_RENDER_PASS_CREATE_INFO};
  info.attachmentCount = uint32_t(attachments.size());
  info.pAttachments = attachments.data();
  info.subpassCount = 1;
  info.pSubpasses = &subpass;
  info.dependencyCount = 2;
  info.pDependencies = deps;
  VkRenderPass pass = VK_NULL_HANDLE;
  if (VkResult r = vkCreateRenderPass(device, &info, nullptr, &pass); r != VK_SUCCESS) {
    return unexpected(render_error(fmt::format("cannot create the {} render pass: {}", what, vk_result_name(r)),
                                   DiagId::vulkan_failed));
  }
  return pass;
}

Result<VkFramebuffer, Diagnostics> make_framebuffer(VkDevice device, VkRenderPass pass,
                                                    const std::vector<VkImageView>& views, uint32_t width,
                                                    uint32_t height) {
  VkFramebufferCreateInfo fb{VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO};
  fb.renderPass = pass;
  fb.attachmentCount = uint32_t(views.size());
  fb.pAttachments = views.data();
  fb.width = width;
  fb.height = height;
  fb.layers = 1;
  VkFramebuffer framebuffer = VK_NULL_HANDLE;
  if (VkResult r = vkCreateFramebuffer(device, &fb, nullptr, &framebuffer); r != VK_SUCCESS) {
    return unexpected(render_error("cannot create a framebuffer: " + vk_result_name(r), DiagId::vulkan_failed));
  }
  return framebuffer;
}

Result<GpuMesh, Diagnostics> camera_quad_mesh(const Context& context, const CameraMatrices& camera) {
  MeshData quad = *builtin_mesh("quad");
  const glm::mat4 to_world = inverse_view_projection(camera) * quad_to_clip();
  for (Vertex& v : quad.vertices) {
    // Two points on the pixel's view ray: where the quad's corner lands, and deeper.
    glm::vec4 clip = quad_to_clip() * glm::vec4(v.position[0], v.position[1], 0, 1);
    glm::vec4 a = to_world * glm::vec4(v.position[0], v.position[1], 0, 1);
    glm::vec4 b = inverse_view_projection(camera) * glm::vec4(clip.x, clip.y, 0.9f, 1);
    glm::vec3 ray = glm::vec3(camera.world_to_camera * glm::vec4(glm::vec3(b) / b.w - glm::vec3(a) / a.w, 0));
    if (ray.z < 0) ray = -ray;
    ray /= ray.z;
    v.normal = {ray.x, ray.y, ray.z};
  }
  return upload_mesh(context, quad);
}

UniformValues camera_quad_uniforms(const CameraMatrices& camera) {
  UniformValues values = draw_uniforms(inverse_view_projection(camera) * quad_to_clip());
  values.set_vector("_LightAsQuad", 1);
  return values;
}

Result<void, Diagnostics> make_screen_pass_object(const Context& context, const Scene& scene, ShaderLibrary& library,
                                                  const CameraMatrices& camera, const std::string& file,
                                                  const std::string& what, const std::string& json_path,
                                                  ScreenPassObject& out) {
  SceneObject& source = out.source;
  source.name = what;
  source.json_path = json_path;
  source.mesh = "quad";
  source.material.json_path = json_path;
  Result<ShaderAsset*, Diagnostics> shader = library.load_built_in(file);
  if (!shader) {
    return unexpected(scene_error(library.report_sources(), scene, json_path, DiagId::shader_unavailable,
                                  fmt::format("the shader of {}, the stdlib's {}, does not load", what, file),
                                  shader.error()));
  }
  source.material.shader = (*shader)->path;
  if ((*shader)->passes.empty()) {
    return unexpected(render_error(
        fmt::format("{}: {}: the shader of {}, {}, has no pass", scene.path, json_path, what, source.material.shader)));
  }
  Result<GpuMesh, Diagnostics> quad = camera_quad_mesh(context, camera);
  if (!quad) return unexpected(quad.error());
  out.quad = std::make_unique<GpuMesh>(std::move(*quad));
  ObjectState s;
  s.scene = &source;
  s.shader = *shader;
  Diagnostics material_diags;
  Result<Material> material =
      make_material(s.shader->shader, source.material, scene.path, library.report_sources(), material_diags);
  if (!material) return unexpected(material_diags);
  s.material = std::move(*material);
  s.mesh = out.quad.get();
  s.draw = camera_quad_uniforms(camera);
  out.objects.push_back(std::move(s));
  return {};
}

}  // namespace facet::runtime
