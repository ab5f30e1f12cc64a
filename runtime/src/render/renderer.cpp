// render_scene: load what the scene names, build the draw list, record one
// command buffer (render pass into RGBA16F + depth, a readback copy,
// timestamps around the pass), submit, then tone map on the host.
#include "facet/runtime/renderer.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cstring>
#include <functional>
#include <map>
#include <unordered_map>
#include <optional>
#include <glm/gtc/packing.hpp>

#include "facet/runtime/gltf.h"
#include "facet/runtime/vulkan_context.h"
#include "render/background.h"
#include "render/capture.h"
#include "render/deferred.h"
#include "render/descriptor_pools.h"
#include "render/draw_list.h"
#include "render/environment_lighting.h"
#include "render/probes.h"
#include "render/grab.h"
#include "render/instancing.h"
#include "render/post.h"
#include "render/resources.h"
#include "render/screen_shadows.h"
#include "render/shadow_pass.h"

namespace facet::runtime {
namespace {

using Clock = std::chrono::steady_clock;
double ms_since(Clock::time_point t) { return std::chrono::duration<double, std::milli>(Clock::now() - t).count(); }

RenderError error(std::string message) { return RenderError{std::move(message)}; }

double median(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  return values[values.size() / 2];
}

// Vulkan objects of one frame, destroyed in reverse order.
struct FrameObjects {
  VkDevice device = VK_NULL_HANDLE;
  VkRenderPass render_pass = VK_NULL_HANDLE;
  // With GrabPasses: the parts before the first grab and between grabs
  // (the last part is render_pass with its colour loaded).
  VkRenderPass first_part = VK_NULL_HANDLE, middle_part = VK_NULL_HANDLE, last_part = VK_NULL_HANDLE;
  VkFramebuffer framebuffer = VK_NULL_HANDLE;
  VkPipelineCache cache = VK_NULL_HANDLE;
  ~FrameObjects() {
    if (!device) return;
    vkDeviceWaitIdle(device);
    if (framebuffer) vkDestroyFramebuffer(device, framebuffer, nullptr);
    for (VkRenderPass p : {render_pass, first_part, middle_part, last_part}) {
      if (p) vkDestroyRenderPass(device, p, nullptr);
    }
    if (cache) vkDestroyPipelineCache(device, cache, nullptr);
  }
};

// Linear allocation of uniform data in host-visible buffers.
class UniformArena {
 public:
  UniformArena(const Context& context) : context_(context) {
    VkPhysicalDeviceProperties p{};
    vkGetPhysicalDeviceProperties(context.physical_device(), &p);
    align_ = std::max<VkDeviceSize>(16, p.limits.minUniformBufferOffsetAlignment);
  }
  struct Slice {
    VkBuffer buffer;
    VkDeviceSize offset;
    std::span<std::byte> bytes;
  };
  Result<Slice, RenderError> allocate(VkDeviceSize size) {
    size = std::max<VkDeviceSize>(size, 16);
    while (current_ < chunks_.size() && used_ + size > chunks_[current_].size()) {
      ++current_;
      used_ = 0;
    }
    if (current_ == chunks_.size()) {
      VkResultOf<Buffer> b = create_buffer(context_, std::max<VkDeviceSize>(size, 1 << 18), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT);
      if (!b) return unexpected(error(describe(b.error())));
      chunks_.push_back(std::move(*b));
      used_ = 0;
    }
    Buffer& chunk = chunks_[current_];
    Slice s{chunk.handle(), used_, {static_cast<std::byte*>(chunk.data()) + used_, size_t(size)}};
    used_ = (used_ + size + align_ - 1) / align_ * align_;
    return s;
  }

 private:
  const Context& context_;
  std::vector<Buffer> chunks_;
  size_t current_ = 0;
  VkDeviceSize used_ = 0, align_ = 256;
};

// D32 with stencil where the device has it (and, for a depth the frame
// samples, can sample it), else D32 without stencil.
VkFormat depth_format(const Context& context, bool sampled) {
  VkFormatProperties p{};
  vkGetPhysicalDeviceFormatProperties(context.physical_device(), VK_FORMAT_D32_SFLOAT_S8_UINT, &p);
  VkFormatFeatureFlags needs = VK_FORMAT_FEATURE_DEPTH_STENCIL_ATTACHMENT_BIT |
                               (sampled ? VK_FORMAT_FEATURE_SAMPLED_IMAGE_BIT : 0);
  return (p.optimalTilingFeatures & needs) == needs ? VK_FORMAT_D32_SFLOAT_S8_UINT : VK_FORMAT_D32_SFLOAT;
}

// How a render pass of the scene begins and ends. A frame with GrabPasses
// is drawn in parts split at each grab (grab.h): every part but the first
// loads what the one before left, every part but the last leaves the colour
// ready to be copied and keeps the depth.
struct PassEnds {
  bool load = false;     // continue the previous part (else clear)
  bool to_grab = false;  // a grab follows: colour to TRANSFER_SRC_OPTIMAL, depth stored
  // The last part: the colour (and with `depth_sampled` the depth) ends in
  // SHADER_READ_ONLY_OPTIMAL for the image-effect chain instead of being read back.
  bool sampled = false;
  bool depth_sampled = false;
};

Result<VkRenderPass, RenderError> make_render_pass(VkDevice device, VkFormat depth, const PassEnds& ends) {
  VkAttachmentDescription attachments[2]{};
  attachments[0].format = VK_FORMAT_R16G16B16A16_SFLOAT;
  attachments[0].samples = VK_SAMPLE_COUNT_1_BIT;
  attachments[0].loadOp = ends.load ? VK_ATTACHMENT_LOAD_OP_LOAD : VK_ATTACHMENT_LOAD_OP_CLEAR;
  attachments[0].storeOp = VK_ATTACHMENT_STORE_OP_STORE;
  attachments[0].stencilLoadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
  attachments[0].stencilStoreOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
  attachments[0].initialLayout = ends.load ? VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL : VK_IMAGE_LAYOUT_UNDEFINED;
  attachments[0].finalLayout = ends.sampled && !ends.to_grab ? VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL
                                                             : VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;
  attachments[1] = attachments[0];
  attachments[1].format = depth;
  bool keep_depth = ends.to_grab || ends.depth_sampled;
  attachments[1].storeOp = keep_depth ? VK_ATTACHMENT_STORE_OP_STORE : VK_ATTACHMENT_STORE_OP_DONT_CARE;
  attachments[1].stencilLoadOp = ends.load ? VK_ATTACHMENT_LOAD_OP_LOAD : VK_ATTACHMENT_LOAD_OP_CLEAR;
  attachments[1].stencilStoreOp = ends.to_grab ? VK_ATTACHMENT_STORE_OP_STORE : VK_ATTACHMENT_STORE_OP_DONT_CARE;
  attachments[1].initialLayout = ends.load ? VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL : VK_IMAGE_LAYOUT_UNDEFINED;
  attachments[1].finalLayout = ends.depth_sampled && !ends.to_grab ? VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL
                                                                   : VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL;
  VkAttachmentReference color{0, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL};
  VkAttachmentReference depth_ref{1, VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL};
  VkSubpassDescription subpass{};
  subpass.pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
  subpass.colorAttachmentCount = 1;
  subpass.pColorAttachments = &color;
  subpass.pDepthStencilAttachment = &depth_ref;
  VkSubpassDependency after{};
  after.srcSubpass = 0;
  after.dstSubpass = VK_SUBPASS_EXTERNAL;
  after.srcStageMask = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT | VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT;
  after.dstStageMask = VK_PIPELINE_STAGE_TRANSFER_BIT | VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT;
  after.srcAccessMask = VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT | VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT;
  after.dstAccessMask = VK_ACCESS_TRANSFER_READ_BIT | VK_ACCESS_SHADER_READ_BIT;
  VkRenderPassCreateInfo info{VK_STRUCTURE_TYPE_RENDER_PASS_CREATE_INFO};
  info.attachmentCount = 2;
  info.pAttachments = attachments;
  info.subpassCount = 1;
  info.pSubpasses = &subpass;
  info.dependencyCount = 1;
  info.pDependencies = &after;
  VkRenderPass pass = VK_NULL_HANDLE;
  if (VkResult r = vkCreateRenderPass(device, &info, nullptr, &pass); r != VK_SUCCESS) {
    return unexpected(error("cannot create the render pass: " + vk_result_name(r)));
  }
  return pass;
}

// One command buffer and fence, reused by every frame.
struct Submitter {
  const Context* context = nullptr;
  VkCommandPool pool = VK_NULL_HANDLE;
  VkCommandBuffer commands = VK_NULL_HANDLE;
  VkFence fence = VK_NULL_HANDLE;
  Submitter() = default;
  Submitter(Submitter&& o) noexcept { *this = std::move(o); }
  Submitter& operator=(Submitter&& o) noexcept {
    std::swap(context, o.context);
    std::swap(pool, o.pool);
    std::swap(commands, o.commands);
    std::swap(fence, o.fence);
    return *this;
  }
  ~Submitter() {
    if (!context) return;
    if (fence) vkDestroyFence(context->device(), fence, nullptr);
    if (pool) vkDestroyCommandPool(context->device(), pool, nullptr);
  }
  // `submitted`: set when vkQueueSubmit returns, before the wait.
  VkResultOf<void> submit(const std::function<void(VkCommandBuffer)>& record, Clock::time_point* submitted = nullptr) {
    VkDevice device = context->device();
    vkResetCommandBuffer(commands, 0);
    VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
    begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    vkBeginCommandBuffer(commands, &begin);
    record(commands);
    VkResult r = vkEndCommandBuffer(commands);
    VkSubmitInfo submit{VK_STRUCTURE_TYPE_SUBMIT_INFO};
    submit.commandBufferCount = 1;
    submit.pCommandBuffers = &commands;
    if (r == VK_SUCCESS) r = vkQueueSubmit(context->queue(), 1, &submit, fence);
    if (submitted) *submitted = Clock::now();
    if (r == VK_SUCCESS) r = vkWaitForFences(device, 1, &fence, VK_TRUE, UINT64_MAX);
    if (r == VK_SUCCESS) r = vkResetFences(device, 1, &fence);
    if (r != VK_SUCCESS) return vk_failure(VkErrorCode::submit_failed, "recording, submitting or waiting failed", r);
    return {};
  }
};

Result<Submitter, RenderError> make_submitter(const Context& context) {
  Submitter s;
  s.context = &context;
  VkCommandPoolCreateInfo pool{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
  pool.flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
  pool.queueFamilyIndex = context.queue_family();
  if (VkResult r = vkCreateCommandPool(context.device(), &pool, nullptr, &s.pool); r != VK_SUCCESS) {
    return unexpected(error("cannot create a command pool: " + vk_result_name(r)));
  }
  VkCommandBufferAllocateInfo allocate{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
  allocate.commandPool = s.pool;
  allocate.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
  allocate.commandBufferCount = 1;
  if (VkResult r = vkAllocateCommandBuffers(context.device(), &allocate, &s.commands); r != VK_SUCCESS) {
    return unexpected(error("cannot allocate a command buffer: " + vk_result_name(r)));
  }
  VkFenceCreateInfo fence{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
  if (VkResult r = vkCreateFence(context.device(), &fence, nullptr, &s.fence); r != VK_SUCCESS) {
    return unexpected(error("cannot create a fence: " + vk_result_name(r)));
  }
  return s;
}

// The image-effect chain's two ping-pong images, its colour-only render pass
// and a framebuffer per image.
struct PostTargets {
  VkDevice device = VK_NULL_HANDLE;
  VkRenderPass render_pass = VK_NULL_HANDLE;
  std::array<Image, 2> images;
  std::array<VkFramebuffer, 2> framebuffers{};
  VkSampler point_sampler = VK_NULL_HANDLE;  // the camera depth texture's, as Unity's: point, clamp
  ~PostTargets() {
    if (!device) return;
    vkDeviceWaitIdle(device);
    if (point_sampler) vkDestroySampler(device, point_sampler, nullptr);
    for (VkFramebuffer f : framebuffers)
      if (f) vkDestroyFramebuffer(device, f, nullptr);
    if (render_pass) vkDestroyRenderPass(device, render_pass, nullptr);
  }
};

Result<void, RenderError> make_post_targets(const Context& context, PostTargets& t, int width, int height) {
  t.device = context.device();
  VkAttachmentDescription a{};
  a.format = VK_FORMAT_R16G16B16A16_SFLOAT;
  a.samples = VK_SAMPLE_COUNT_1_BIT;
  a.loadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;  // every step covers every pixel
  a.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
  a.stencilLoadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
  a.stencilStoreOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
  a.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
  a.finalLayout = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
  VkAttachmentReference color{0, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL};
  VkSubpassDescription subpass{};
  subpass.pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
  subpass.colorAttachmentCount = 1;
  subpass.pColorAttachments = &color;
  // Before: the image was the source of the step before last (write after read).
  // After: the next step samples it, or the readback copies it.
  VkSubpassDependency deps[2]{};
  deps[0].srcSubpass = VK_SUBPASS_EXTERNAL;
  deps[0].dstSubpass = 0;
  deps[0].srcStageMask = VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT;
  deps[0].dstStageMask = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT;
  deps[0].srcAccessMask = VK_ACCESS_SHADER_READ_BIT;
  deps[0].dstAccessMask = VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT;
  deps[1].srcSubpass = 0;
  deps[1].dstSubpass = VK_SUBPASS_EXTERNAL;
  deps[1].srcStageMask = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT;
  deps[1].dstStageMask = VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT | VK_PIPELINE_STAGE_TRANSFER_BIT;
  deps[1].srcAccessMask = VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT;
  deps[1].dstAccessMask = VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_TRANSFER_READ_BIT;
  VkRenderPassCreateInfo info{VK_STRUCTURE_TYPE_RENDER_PASS_CREATE_INFO};
  info.attachmentCount = 1;
  info.pAttachments = &a;
  info.subpassCount = 1;
  info.pSubpasses = &subpass;
  info.dependencyCount = 2;
  info.pDependencies = deps;
  if (VkResult r = vkCreateRenderPass(t.device, &info, nullptr, &t.render_pass); r != VK_SUCCESS) {
    return unexpected(error("cannot create the image-effect render pass: " + vk_result_name(r)));
  }
  VkSamplerCreateInfo sampler{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
  sampler.magFilter = sampler.minFilter = VK_FILTER_NEAREST;
  sampler.mipmapMode = VK_SAMPLER_MIPMAP_MODE_NEAREST;
  sampler.addressModeU = sampler.addressModeV = sampler.addressModeW = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
  if (vkCreateSampler(t.device, &sampler, nullptr, &t.point_sampler) != VK_SUCCESS) {
    return unexpected(error("cannot create the depth texture's sampler"));
  }
  for (size_t i = 0; i < 2; ++i) {
    VkResultOf<Image> image = create_image(context, {.width = uint32_t(width), .height = uint32_t(height),
                                                     .format = VK_FORMAT_R16G16B16A16_SFLOAT,
                                                     .usage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT |
                                                              VK_IMAGE_USAGE_TRANSFER_SRC_BIT});
    if (!image) return unexpected(error(describe(image.error())));
    t.images[i] = std::move(*image);
    VkImageView view = t.images[i].view();
    VkFramebufferCreateInfo fb{VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO};
    fb.renderPass = t.render_pass;
    fb.attachmentCount = 1;
    fb.pAttachments = &view;
    fb.width = uint32_t(width);
    fb.height = uint32_t(height);
    fb.layers = 1;
    if (vkCreateFramebuffer(t.device, &fb, nullptr, &t.framebuffers[i]) != VK_SUCCESS) {
      return unexpected(error("cannot create an image-effect framebuffer"));
    }
  }
  return {};
}

struct Loader {
  const Context& context;
  const Scene& scene;
  ShaderLibrary& library;
  Resources& resources;
  std::map<std::string, std::unique_ptr<GpuMesh>> meshes;

  Result<GpuMesh*, RenderError> mesh(const SceneObject& object) {
    std::string key = object.gltf_material ? fmt::format("{}#{}", object.mesh, *object.gltf_material) : object.mesh;
    if (auto it = meshes.find(key); it != meshes.end()) return it->second.get();
    std::optional<MeshData> data;
    MeshError mesh_error;
    if (object.builtin_mesh) {
      data = builtin_mesh(object.mesh);
    } else if (is_gltf_path(object.mesh)) {
      if (std::optional<GltfModel> model = load_gltf(object.mesh, mesh_error)) {
        data = merge_gltf_parts(*model, object.gltf_material);
      }
    } else {
      data = load_obj(object.mesh, mesh_error);
    }
    if (!data) return unexpected(error(fmt::format("{}: {}.mesh: {}", scene.path, object.json_path, mesh_error.message)));
    Result<GpuMesh, RenderError> gpu = upload_mesh(context, *data);
    if (!gpu) return unexpected(gpu.error());
    auto& slot = meshes[key];
    slot = std::make_unique<GpuMesh>(std::move(*gpu));
    return slot.get();
  }

  Result<void, RenderError> texel_sizes(Material& material, const SceneObject& object) {
    for (const auto& [name, ref] : material.textures) {
      Result<const LoadedTexture*, std::string> t = resources.texture(ref);
      if (!t) return unexpected(error(fmt::format("{}: {}.material.properties.{}: {}", scene.path, object.json_path, name, t.error())));
      float w = float((*t)->width), h = float((*t)->height);
      material.uniforms.set_vector(name + "_TexelSize", 1 / w, 1 / h, w, h);
    }
    return {};
  }

  Result<ObjectState, RenderError> object(size_t index, const CameraMatrices& camera) {
    const SceneObject& o = scene.objects[index];
    ObjectState s;
    s.index = index;
    s.scene = &o;
    Result<ShaderAsset*, std::string> shader = library.load(o.material.shader);
    if (!shader) {
      return unexpected(error(fmt::format("{}: {}.material.shader: the shader does not compile:\n{}", scene.path,
                                          o.json_path, shader.error())));
    }
    s.shader = *shader;
    Result<Material, MaterialError> material = make_material(s.shader->shader, o.material, scene.path);
    if (!material) return unexpected(error(material.error().message));
    s.material = std::move(*material);
    FACET_TRY(texel_sizes(s.material, o));
    s.queue = o.material.queue.value_or(s.shader->queue);
    Result<GpuMesh*, RenderError> m = mesh(o);
    if (!m) return unexpected(m.error());
    s.mesh = *m;
    s.model = transform_matrix(o.transform);
    s.model_values = true;
    s.mirrored = glm::determinant(glm::mat3(s.model)) < 0;
    const Bounds& b = s.mesh->bounds;
    s.center = glm::vec3(s.model * glm::vec4(b.center[0], b.center[1], b.center[2], 1));
    float scale = std::max({std::abs(o.transform.scale[0]), std::abs(o.transform.scale[1]), std::abs(o.transform.scale[2])});
    s.radius = b.radius * scale;
    s.distance = glm::length(s.center - camera.position);
    return s;
  }
};

struct Recorder {
  const Context& context;
  Resources& resources;
  UniformArena& arena;
  DescriptorPools& pools;
  std::map<std::string, const Image*> overrides;  // by resource name: the chain's _MainTex and depth
  VkSampler point_sampler = VK_NULL_HANDLE;        // for overridden depth images (not linearly filterable)
  CaptureBuilder* capture = nullptr;
  const ShadowPasses* shadows = nullptr;  // _ShadowMapTexture of the draw's light
  const ScreenShadows* screen_shadows = nullptr;  // the mask SHADOWS_SCREEN draws read as _ShadowMapTexture
  // What the first frame allocated and wrote for each draw. Later frames
  // bind the same sets and rewrite in place (the previous frame has
  // finished), once a frame (refresh()), the members that come from the frame
  // layer, which is recomputed every frame; the object's, light's and
  // material's values stay as written.
  struct KeptBlock {
    const UniformBlock* block;
    std::span<std::byte> bytes;
    std::vector<MemberSource> frame_members;
  };
  using Sets = std::array<VkDescriptorSet, kSetCount>;
  static constexpr size_t kFrameLayer = 4;  // in the layers of bind()
  static constexpr uint32_t kPerDrawSet = 3;  // the object's set: never shared
  std::unordered_map<const Draw*, Sets> retained;
  const std::vector<ObjectState>* instance_owners = nullptr;  // what Draw::instances index
  std::vector<KeptBlock> kept_blocks;  // those with frame members
  // The frame, light and material sets are shared by every draw whose set
  // has the same layout, frame layer and contents (its blocks' bytes, its
  // images, views and samplers): written once, bound by each, refilled once.
  // Needed only while the first frame makes the sets (done_making_sets()).
  std::unordered_map<std::string, VkDescriptorSet> shared_sets;
  // What is bound, so that a draw rebinds only the sets that differ.
  VkPipelineLayout bound_layout = VK_NULL_HANDLE;
  Sets bound_sets{};

  std::vector<std::byte> zeros;
  void push_zeros(VkCommandBuffer commands, const GpuProgram& program) {
    if (!program.push_constant_bytes) return;
    if (zeros.size() < program.push_constant_bytes) zeros.resize(program.push_constant_bytes);
    vkCmdPushConstants(commands, program.layout, program.push_stages, 0, program.push_constant_bytes, zeros.data());
  }

  // After the first frame every draw has its sets: the keys that found
  // shared ones are not needed again.
  void done_making_sets() { std::unordered_map<std::string, VkDescriptorSet>().swap(shared_sets); }

  // At the start of each frame's recording: the frame members of every kept
  // block rewritten, and nothing known to be bound in the new command buffer.
  void refresh() {
    for (const KeptBlock& k : kept_blocks) refill_members(k.bytes, *k.block, k.frame_members);
    bound_layout = VK_NULL_HANDLE;
  }

  void bind_sets(VkCommandBuffer commands, const GpuProgram& program, const Sets& sets) {
    const bool same_layout = bound_layout == program.layout;
    for (uint32_t set = 0; set < kSetCount; ++set) {
      if (same_layout && bound_sets[set] == sets[set]) continue;
      bound_sets[set] = sets[set];
      if (sets[set]) {
        vkCmdBindDescriptorSets(commands, VK_PIPELINE_BIND_POINT_GRAPHICS, program.layout, set, 1, &sets[set], 0, nullptr);
      }
    }
    bound_layout = program.layout;
    push_zeros(commands, program);
  }

  Result<const Image*, RenderError> image_for(const ResourceBinding& r, const ObjectState& object, const LightValues& light,
                                              bool screen_shadowed) {
    if (auto it = overrides.find(r.name); it != overrides.end()) return it->second;
    // In any set: Unity's own AutoLight.cginc declares it outside facet's light set.
    if (r.name == "_ShadowMapTexture" && screen_shadowed && screen_shadows) {
      if (const Image* mask = screen_shadows->mask_of(&light)) return mask;
    }
    if (r.set == 1 && r.name == "_LightTexture0" && light.cookie) return cookie_image(light);
    // Declared outside facet's light set: Unity's own AutoLight.cginc, whose
    // falloffs are textures (Resources::light_falloff, spot_cone).
    if (r.set != 1 && (r.name == "_LightTexture0" || r.name == "_LightTextureB0")) {
      if (std::optional<Result<const Image*, RenderError>> t = unity_light_texture(r.name, light)) return *t;
    }
    if (r.set == 1 && r.name == "_ShadowMapTexture" && shadows) {
      if (const Image* map = shadows->map_of(&light)) return map;
    }
    if (r.name == "_CameraDepthTexture" && shadows && shadows->camera_depth()) return &shadows->camera_depth()->depth;
    if ((r.name == "unity_SpecCube0" || r.name == "unity_SpecCube1") && object.probes[r.name.back() == '1']) {
      return object.probes[r.name.back() == '1'];
    }
    if (r.set == 2 && r.dim == "2D" && !r.arrayed) {
      auto it = object.material.textures.find(r.name);
      if (it != object.material.textures.end()) {
        Result<const LoadedTexture*, std::string> t = resources.texture(it->second);
        if (!t) return unexpected(error(t.error()));
        return &(*t)->image;
      }
    }
    Result<const Image*, std::string> f = resources.fallback(r.dim.empty() ? "2D" : r.dim, r.arrayed);
    if (!f) return unexpected(error(fmt::format("resource '{}': {}", r.name, f.error())));
    return *f;
  }

  // What Unity's AutoLight samples as `name` for `light`: the attenuation
  // ramp (_LightTextureB0, a point light's _LightTexture0), a spot's cone or
  // cookie, a directional light's cookie; nullopt for anything else.
  std::optional<Result<const Image*, RenderError>> unity_light_texture(const std::string& name,
                                                                       const LightValues& light) {
    auto made = [&](Result<const Image*, std::string> image) -> Result<const Image*, RenderError> {
      if (!image) return unexpected(error(fmt::format("resource '{}': {}", name, image.error())));
      return *image;
    };
    if (name == "_LightTextureB0" || light.keyword == "POINT") return made(resources.light_falloff());
    if (light.cookie) return cookie_image(light);
    if (light.keyword == "SPOT") {
      const std::vector<float>* spot = light.values.find("_FacetSpotParams");
      if (!spot || spot->size() < 2) return std::nullopt;
      const float cos_outer = (*spot)[0], cos_inner = cos_outer + 1.0f / (*spot)[1];
      return made(resources.spot_cone(cos_outer, cos_inner));
    }
    return std::nullopt;
  }

  Result<const Image*, RenderError> cookie_image(const LightValues& light) {
    Result<const LoadedTexture*, std::string> t = resources.texture(*light.cookie);
    if (!t) return unexpected(error(fmt::format("{}.cookie: {}", light.json_path, t.error())));
    return &(*t)->image;
  }

  // `captured`: where the descriptors' contents go when capturing the frame.
  Result<void, RenderError> bind(VkCommandBuffer commands, const Draw& draw, const ObjectState& object,
                                 const UniformValues& frame, CapturedDraw* captured = nullptr) {
    GpuProgram& program = *draw.variant->program;
    if (auto it = retained.find(&draw); it != retained.end()) {
      bind_sets(commands, program, it->second);
      return {};
    }
    // The object's, light's, material's and frame's values, first found first.
    std::vector<UniformValues> model_values(std::max<size_t>(1, draw.instances.size()));
    auto layers_of = [&](const ObjectState& o, UniformValues& model) -> UniformLayers {
      if (o.model_values) model = draw_uniforms(o.model);
      return {&o.draw, o.model_values ? &model : nullptr, &draw.light->values, &o.material.uniforms, &frame};
    };
    UniformLayers layers = layers_of(object, model_values[0]);
    // An instanced draw's objects, each with its own layers (the draw's object alone when not merged).
    std::vector<UniformLayers> instances;
    for (size_t i = 0; i < draw.instances.size(); ++i) {
      instances.push_back(i == 0 ? layers : layers_of((*instance_owners)[draw.instances[i]], model_values[i]));
    }
    if (instances.empty()) instances.push_back(layers);
    const bool screen_shadowed = reads_screen_shadows(draw);
    Sets sets{};
    for (uint32_t set = 0; set < kSetCount; ++set) {
      if (!program.set_used[set]) continue;
      Result<VkDescriptorSet, RenderError> ds =
          set_for(program, set, draw, object, layers, instances, screen_shadowed, captured);
      if (!ds) return unexpected(ds.error());
      sets[set] = *ds;
    }
    retained[&draw] = sets;
    bind_sets(commands, program, sets);
    return {};
  }

  // Set `set` of `draw`: a shared one with the same contents, or a new one.
  Result<VkDescriptorSet, RenderError> set_for(const GpuProgram& program, uint32_t set, const Draw& draw,
                                               const ObjectState& object, const UniformLayers& layers,
                                               const std::vector<UniformLayers>& instances, bool screen_shadowed,
                                               CapturedDraw* captured) {
    std::vector<const UniformBlock*> blocks;
    std::vector<std::vector<std::byte>> contents;
    for (const UniformBlock& block : program.blocks) {
      if (block.set != set) continue;
      blocks.push_back(&block);
      contents.emplace_back(block.size);
      if (is_instanced_block(block)) {
        fill_instanced_block(contents.back(), block, instances);
      } else {
        fill_block(contents.back(), block, layers);
      }
      if (captured) {
        captured->descriptors.push_back({set, block.binding, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 1, contents.back()});
      }
    }
    std::vector<const ResourceBinding*> bound;
    std::vector<VkDescriptorType> types;
    std::vector<std::vector<VkDescriptorImageInfo>> images;
    for (const ResourceBinding& r : program.resources) {
      if (r.set != set) continue;
      Result<std::pair<VkDescriptorType, VkDescriptorImageInfo>, RenderError> image =
          image_info(r, object, *draw.light, screen_shadowed, set, captured);
      if (!image) return unexpected(image.error());
      bound.push_back(&r);
      types.push_back(image->first);
      images.emplace_back(std::max(1u, r.array_size), image->second);
    }
    std::string key;
    if (set != kPerDrawSet) {
      key = shared_key(program.set_layouts[set], layers[kFrameLayer], contents, images);
      if (auto it = shared_sets.find(key); it != shared_sets.end()) return it->second;
    }
    Result<VkDescriptorSet, std::string> allocated = pools.allocate(program.set_layouts[set], program.set_bindings[set]);
    if (!allocated) return unexpected(error(allocated.error()));
    VkDescriptorSet ds = *allocated;
    std::vector<VkDescriptorBufferInfo> buffers;
    std::vector<VkWriteDescriptorSet> writes;
    buffers.reserve(blocks.size());
    for (size_t b = 0; b < blocks.size(); ++b) {
      const UniformBlock& block = *blocks[b];
      Result<UniformArena::Slice, RenderError> slice = arena.allocate(block.size);
      if (!slice) return unexpected(slice.error());
      std::span<std::byte> bytes = slice->bytes.subspan(0, block.size);
      std::copy(contents[b].begin(), contents[b].end(), bytes.begin());
      std::vector<MemberSource> frame_members = members_from_layer(block, layers, kFrameLayer);
      if (!frame_members.empty()) kept_blocks.push_back({&block, bytes, std::move(frame_members)});
      buffers.push_back({slice->buffer, slice->offset, std::max<VkDeviceSize>(block.size, 16)});
      VkWriteDescriptorSet w{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
      w.dstSet = ds;
      w.dstBinding = block.binding;
      w.descriptorCount = 1;
      w.descriptorType = VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER;
      w.pBufferInfo = &buffers.back();
      writes.push_back(w);
    }
    for (size_t i = 0; i < bound.size(); ++i) {
      VkWriteDescriptorSet w{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
      w.dstSet = ds;
      w.dstBinding = bound[i]->binding;
      w.descriptorCount = uint32_t(images[i].size());
      w.descriptorType = types[i];
      w.pImageInfo = images[i].data();
      writes.push_back(w);
    }
    vkUpdateDescriptorSets(context.device(), uint32_t(writes.size()), writes.data(), 0, nullptr);
    if (!key.empty()) shared_sets.emplace(std::move(key), ds);
    return ds;
  }

  // What makes two sets interchangeable: the layout, the frame layer their
  // frame members are refilled from, and every byte and handle written.
  static std::string shared_key(VkDescriptorSetLayout layout, const UniformValues* frame,
                                const std::vector<std::vector<std::byte>>& contents,
                                const std::vector<std::vector<VkDescriptorImageInfo>>& images) {
    std::string key;
    auto put = [&](const void* data, size_t size) { key.append(static_cast<const char*>(data), size); };
    put(&layout, sizeof layout);
    put(&frame, sizeof frame);
    for (const std::vector<std::byte>& c : contents) {
      const uint64_t size = c.size();
      put(&size, sizeof size);
      put(c.data(), c.size());
    }
    for (const std::vector<VkDescriptorImageInfo>& i : images) {
      put(&i.front().sampler, sizeof(VkSampler));
      put(&i.front().imageView, sizeof(VkImageView));
    }
    return key;
  }

  // The descriptor type and image info of resource `r` (a separate sampler
  // gets the sampler alone).
  Result<std::pair<VkDescriptorType, VkDescriptorImageInfo>, RenderError> image_info(
      const ResourceBinding& r, const ObjectState& object, const LightValues& light, bool screen_shadowed, uint32_t set,
      CapturedDraw* captured) {
    VkDescriptorImageInfo info{};
    Result<VkSampler, std::string> sampler = resources.sampler();
    if (!sampler) return unexpected(error(sampler.error()));
    info.sampler = *sampler;
    VkDescriptorType type = VK_DESCRIPTOR_TYPE_SAMPLER;
    CapturedDescriptor described{set, r.binding, type, std::max(1u, r.array_size)};
    if (r.kind != ResourceKind::separate_sampler) {
      Result<const Image*, RenderError> image = image_for(r, object, light, screen_shadowed);
      if (!image) return unexpected(image.error());
      if (captured) {
        Result<int, std::string> index = capture->image(*image);
        if (!index) return unexpected(error(fmt::format("resource '{}': {}", r.name, index.error())));
        described.image = *index;
      }
      // Depth is not linearly filterable; a shadow cube's distances must not
      // be blended; a screen-space shadow mask is read texel for texel.
      bool unfiltered = is_depth_format((*image)->desc().format) || (shadows && shadows->is_cube(*image)) ||
                        (screen_shadows && screen_shadows->owns(*image));
      if (unfiltered && point_sampler) {
        info.sampler = point_sampler;
      }
      if (resources.clamped(*image)) {
        Result<VkSampler, std::string> clamp = resources.clamp_sampler();
        if (!clamp) return unexpected(error(clamp.error()));
        info.sampler = *clamp;
      }
      info.imageView = (*image)->sample_view();
      info.imageLayout = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
      type = r.kind == ResourceKind::combined_image_sampler ? VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER
                                                            : VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE;
    }
    if (captured) {
      described.type = type;
      described.sampler = info.sampler == point_sampler && point_sampler ? CapturedSampler::point_clamp
                                                                         : CapturedSampler::trilinear_repeat;
      captured->descriptors.push_back(std::move(described));
    }
    return std::pair{type, info};
  }
};

glm::vec3 tonemap(glm::vec3 c, Tonemap mode) {
  c = glm::max(c, glm::vec3(0));
  if (mode == Tonemap::reinhard) return c / (1.0f + c);
  if (mode == Tonemap::aces) {  // Narkowicz's fit of the ACES filmic curve
    return glm::clamp((c * (2.51f * c + 0.03f)) / (c * (2.43f * c + 0.59f) + 0.14f), 0.0f, 1.0f);
  }
  return glm::min(c, glm::vec3(1));
}

void finish_image(RenderedFrame& frame, const std::byte* halves, const Scene& scene) {
  size_t n = size_t(frame.width) * frame.height;
  frame.hdr.resize(n * 4);
  frame.ldr.resize(n * 4);
  float exposure = scene.camera.exposure;
  for (size_t i = 0; i < n * 4; ++i) {
    uint16_t h;
    std::memcpy(&h, halves + 2 * i, 2);
    frame.hdr[i] = glm::unpackHalf1x16(h) * (i % 4 == 3 ? 1.0f : exposure);
  }
  for (size_t p = 0; p < n; ++p) {
    glm::vec3 c = tonemap({frame.hdr[4 * p], frame.hdr[4 * p + 1], frame.hdr[4 * p + 2]}, scene.tonemap);
    for (int k = 0; k < 3; ++k) frame.ldr[4 * p + k] = uint8_t(std::lround(linear_to_srgb(c[k]) * 255.0));
    frame.ldr[4 * p + 3] = 255;
  }
}

}  // namespace

Result<RenderedFrame, RenderError> render_scene(Context& context, const Scene& scene, const RenderOptions& options) {
  Clock::time_point start = Clock::now();
  RenderedFrame frame;
  frame.width = options.width ? options.width : scene.width;
  frame.height = options.height ? options.height : scene.height;
  if (options.frames < 1) return unexpected(error("frames must be at least 1"));
  if (options.capture && !scene.post.empty()) {
    return unexpected(error(scene.path + ": a frame capture does not cover image effects"));
  }
  // Probes first: each renders the scene (through this function) before
  // this render takes the shader library.
  std::vector<CubeMips> probe_cubes;
  if (!scene.reflection_probes.empty()) {
    Result<std::vector<CubeMips>, RenderError> cubes = render_probes(context, scene, options);
    if (!cubes) return unexpected(cubes.error());
    probe_cubes = std::move(*cubes);
  }
  std::optional<ShaderLibrary> own_library;
  ShaderLibrary* kept = nullptr;
  uint64_t reloaded = 0;
  if (options.shaders) {
    ShaderStore& store = *options.shaders;
    if (store.context && store.context != &context) {
      return unexpected(error("the ShaderStore holds GPU programs of another Context: give each Context its own"));
    }
    store.context = &context;
    if (!store.library) store.library = std::make_unique<ShaderLibrary>(options.shader_compiler);
    kept = store.library.get();
    kept->set_compiler(options.shader_compiler);
    reloaded = kept->forget_changed();
  }
  ShaderLibrary& library = kept ? *kept : own_library.emplace(options.shader_compiler);
  library.begin_render();
  library.set_strict_variants(options.strict_variants);
  Resources resources(context);
  resources.keep_pixels(options.capture != nullptr);
  Loader loader{context, scene, library, resources, {}};
  CameraMatrices camera = camera_matrices(scene.camera, frame.width, frame.height);
  Result<EnvironmentLighting, std::string> environment = environment_lighting(scene);
  if (!environment) return unexpected(error(environment.error()));
  if (Result<const Image*, std::string> cube = resources.environment_cube(environment->cube); !cube) {
    return unexpected(error("cannot create the environment cube: " + cube.error()));
  }
  UniformValues frame_values = frame_uniforms(scene, camera, frame.width, frame.height, environment->ambient);
  std::vector<const Image*> probe_images;
  for (const CubeMips& cube : probe_cubes) {
    Result<const Image*, std::string> image = resources.add_probe(cube);
    if (!image) return unexpected(error("cannot create a reflection probe's cube: " + image.error()));
    probe_images.push_back(*image);
  }
  std::vector<ObjectState> objects;
  for (size_t i = 0; i < scene.objects.size(); ++i) {
    Result<ObjectState, RenderError> o = loader.object(i, camera);
    if (!o) return unexpected(o.error());
    if (!probe_images.empty()) {
      ProbeChoice choice = choose_probes(scene, o->center);
      add_probe_values(o->draw, scene, choice);
      for (int slot : {0, 1}) {
        int probe = slot == 0 ? choice.probe0 : choice.probe1;
        o->probes[size_t(slot)] = probe >= 0 ? probe_images[size_t(probe)] : nullptr;
      }
    }
    objects.push_back(std::move(*o));
  }
  LightSetup lights = setup_lights(scene, camera.view, environment->ambient);
  std::vector<ShadowView> shadow_views;
  for (size_t i = 0; i < scene.lights.size(); ++i) {
    if (std::optional<ShadowView> v = shadow_view(scene, i, objects, camera, float(frame.width) / float(frame.height))) {
      add_shadow_values(lights.lights[i], scene.lights[i], *v, scene.shadow_resolution);
      shadow_views.push_back(*v);
    }
  }
  if (Result<void, std::string> cookies = resources.load_cookies(scene); !cookies) return unexpected(error(cookies.error()));
  Result<DrawListResult, RenderError> list = build_draws(context, scene, objects, lights, library);
  if (!list) return unexpected(list.error());
  frame.stats.instanced_away = merge_instanced_draws(list->draws, objects);
  std::unique_ptr<GpuMesh> quad;
  if (!scene.post.empty() || scene.camera.clear_sky) {
    Result<GpuMesh, RenderError> q = upload_mesh(context, *builtin_mesh("quad"));
    if (!q) return unexpected(q.error());
    quad = std::make_unique<GpuMesh>(std::move(*q));
  }
  SceneObject sky_source;
  if (scene.camera.clear_sky) {
    FACET_TRY(add_sky_background(context, scene, library, quad.get(), &lights.none, sky_source, objects, *list));
  }
  std::unique_ptr<PostChain> post;
  if (!scene.post.empty()) {
    auto chain = build_post_chain(context, scene, library, resources, quad.get(), &lights.none, frame.width, frame.height);
    if (!chain) return unexpected(chain.error());
    post = std::move(*chain);
  }
  // The deferred path's light pass; without an object drawn deferred the
  // frame is a forward one.
  std::unique_ptr<DeferredLights> deferred;
  if (scene.camera.deferred && !list->gbuffer.empty()) {
    auto built = build_deferred_lights(context, scene, library, lights, camera);
    if (!built) return unexpected(built.error());
    deferred = std::move(*built);
  }
  // Unity draws the sky behind the opaque objects at the far plane; the
  // deferred ones are in the depth before the sky, so it is tested there
  // (its draw is given depth 1 by its viewport, see below).
  for (Draw& d : list->draws) {
    if (!deferred || !objects[d.object].background) continue;
    d.state.depth_test = true;
    d.state.ztest = VK_COMPARE_OP_LESS_OR_EQUAL;
    d.state.zwrite = false;
    d.record.state = describe(d.state) + " (at the far plane: behind the deferred objects)";
  }
  // The camera depth texture is the depth buffer itself, kept when an image
  // effect samples it (as the deferred light pass samples it), through its
  // depth-only view (Image::sample_view).
  bool depth_sampled = post && std::any_of(post->list.draws.begin(), post->list.draws.end(),
                                           [](const Draw& d) { return samples(d, "_CameraDepthTexture"); });
  const bool depth_readable = depth_sampled || deferred;

  FrameObjects fo;
  fo.device = context.device();
  VkFormat depth = depth_format(context, depth_readable);
  VkResultOf<Image> color = create_image(context, {.width = uint32_t(frame.width), .height = uint32_t(frame.height),
                                                   .format = VK_FORMAT_R16G16B16A16_SFLOAT,
                                                   .usage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT |
                                                            (post ? VkImageUsageFlags(VK_IMAGE_USAGE_SAMPLED_BIT) : 0u)});
  if (!color) return unexpected(error(describe(color.error())));
  VkResultOf<Image> depth_image = create_image(context, {.width = uint32_t(frame.width), .height = uint32_t(frame.height),
                                                         .format = depth,
                                                         .usage = VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT |
                                                                  (depth_readable ? VkImageUsageFlags(VK_IMAGE_USAGE_SAMPLED_BIT) : 0u)});
  if (!depth_image) return unexpected(error(describe(depth_image.error())));
  PostTargets targets;
  if (post) FACET_TRY(make_post_targets(context, targets, frame.width, frame.height));
  // After the deferred passes the forward part continues on their colour and depth.
  const PassEnds last_part{.load = deferred != nullptr, .sampled = post != nullptr, .depth_sampled = depth_sampled};
  DeferredTargets gbuffer;
  if (deferred) {
    FACET_TRY(make_deferred_targets(context, *color, *depth_image, uint32_t(frame.width), uint32_t(frame.height), gbuffer));
  }
  Result<VkRenderPass, RenderError> pass = make_render_pass(context.device(), depth, last_part);
  if (!pass) return unexpected(pass.error());
  fo.render_pass = *pass;
  VkImageView views[2] = {color->view(), depth_image->view()};
  VkFramebufferCreateInfo fb{VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO};
  fb.renderPass = fo.render_pass;
  fb.attachmentCount = 2;
  fb.pAttachments = views;
  fb.width = uint32_t(frame.width);
  fb.height = uint32_t(frame.height);
  fb.layers = 1;
  if (vkCreateFramebuffer(context.device(), &fb, nullptr, &fo.framebuffer) != VK_SUCCESS) {
    return unexpected(error("cannot create the framebuffer"));
  }
  VkPipelineCacheCreateInfo cache_info{VK_STRUCTURE_TYPE_PIPELINE_CACHE_CREATE_INFO};
  if (VkResult r = vkCreatePipelineCache(context.device(), &cache_info, nullptr, &fo.cache); r != VK_SUCCESS) {
    fo.cache = VK_NULL_HANDLE;  // undefined after a failure; the frame's objects destroy what is not null
    return unexpected(error(fmt::format("cannot create the pipeline cache (VkResult {})", int(r))));
  }
  // The pipelines of `draws` in `render_pass`, one a draw.
  auto pipelines_for = [&](const std::vector<Draw>& draws, const std::vector<ObjectState>& owners,
                           VkRenderPass render_pass, uint32_t color_targets) -> Result<std::vector<VkPipeline>, RenderError> {
    std::vector<VkPipeline> out;
    for (const Draw& d : draws) {
      bool created = false;
      Result<VkPipeline, std::string> p = get_pipeline(context, *d.variant->program, d.state, owners[d.object].mirrored,
                                                       render_pass, fo.cache, &created, color_targets);
      if (!p) return unexpected(error(fmt::format("{}: {}: {}", scene.path, d.record.object, p.error())));
      out.push_back(*p);
      frame.stats.pipelines += created;
    }
    return out;
  };
  Result<std::vector<VkPipeline>, RenderError> made = pipelines_for(list->draws, objects, fo.render_pass, 1);
  if (!made) return unexpected(made.error());
  const std::vector<VkPipeline> pipelines = std::move(*made);
  std::vector<VkPipeline> gbuffer_pipelines, light_pipelines;
  if (deferred) {
    made = pipelines_for(list->gbuffer, objects, gbuffer.gbuffer_pass, kGBufferTargets);
    if (!made) return unexpected(made.error());
    gbuffer_pipelines = std::move(*made);
    made = pipelines_for(deferred->list.draws, deferred->screen.objects, gbuffer.light_pass, 1);
    if (!made) return unexpected(made.error());
    light_pipelines = std::move(*made);
  }
  Result<GrabPlan, RenderError> grab_plan =
      plan_grabs(context, scene, list->draws, uint32_t(frame.width), uint32_t(frame.height));
  if (!grab_plan) return unexpected(grab_plan.error());
  GrabPlan& grabs = *grab_plan;
  if (!grabs.points.empty()) {
    if (options.capture) return unexpected(error(scene.path + ": a frame capture does not cover GrabPass"));
    PassEnds first{.load = deferred != nullptr, .to_grab = true}, middle{.load = true, .to_grab = true}, last = last_part;
    last.load = true;
    for (auto [ends, out] : {std::pair{first, &fo.first_part}, {middle, &fo.middle_part}, {last, &fo.last_part}}) {
      Result<VkRenderPass, RenderError> part = make_render_pass(context.device(), depth, ends);
      if (!part) return unexpected(part.error());
      *out = *part;
    }
  }
  ShadowPasses shadows;
  // The maps some drawn variant samples: forward receivers', and the deferred light pass's.
  std::vector<const std::vector<Draw>*> receivers = {&list->draws};
  if (deferred) receivers.push_back(&deferred->list.draws);
  FACET_TRY(prepare_shadow_maps(context, scene, objects, lights, shadow_views, receivers, library, fo.cache, shadows,
                                frame.stats.pipelines));
  // The directional lights whose receivers read a screen-space mask.
  std::vector<Draw> no_draws;
  const std::vector<const LightValues*> screen_lights = screen_shadowed_lights(
      {&list->draws, deferred ? &deferred->list.draws : &no_draws});
  // Objects that sample _CameraDepthTexture get Unity's depth texture: the
  // opaque objects' ShadowCaster passes from the camera, before the scene;
  // the screen-space shadow pass reads it too.
  if (!screen_lights.empty() ||
      std::any_of(list->draws.begin(), list->draws.end(), [](const Draw& d) { return samples(d, "_CameraDepthTexture"); })) {
    FACET_TRY(prepare_camera_depth(context, scene, objects, lights.none, camera, uint32_t(frame.width),
                                   uint32_t(frame.height), library, fo.cache, shadows, frame.stats.pipelines));
  }
  ScreenShadows screen_shadows;
  FACET_TRY(prepare_screen_shadows(context, scene, library, camera, screen_lights, uint32_t(frame.width),
                                   uint32_t(frame.height), fo.cache, screen_shadows, frame.stats.pipelines));
  if (options.capture && !shadows.maps.empty()) {
    return unexpected(error(scene.path + ": a frame capture does not cover shadow maps or the camera depth texture"));
  }
  std::vector<VkPipeline> post_pipelines;
  if (post) {
    made = pipelines_for(post->list.draws, post->steps, targets.render_pass, 1);
    if (!made) return unexpected(made.error());
    post_pipelines = std::move(*made);
  }
  DescriptorPools pools(context.device());
  UniformArena arena(context);
  Recorder recorder{context, resources, arena, pools};
  recorder.instance_owners = &objects;
  recorder.shadows = &shadows;
  recorder.screen_shadows = &screen_shadows;
  if (!shadows.maps.empty() || deferred) {
    Result<VkSampler, std::string> sampler = resources.point_sampler();
    if (!sampler) return unexpected(error(sampler.error()));
    recorder.point_sampler = *sampler;
  }
  std::optional<CaptureBuilder> capture;
  if (options.capture) {
    *options.capture = FrameCapture{};
    options.capture->width = uint32_t(frame.width);
    options.capture->height = uint32_t(frame.height);
    options.capture->depth_format = depth;
    options.capture->vertex_stride = sizeof(Vertex);
    capture.emplace(*options.capture, resources);
  }
  VkDeviceSize bytes = VkDeviceSize(frame.width) * frame.height * 8;
  VkResultOf<Buffer> readback = create_buffer(context, bytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT);
  if (!readback) return unexpected(error(describe(readback.error())));
  std::optional<RenderError> failed;
  VkQueryPool queries = context.timestamp_pool();
  // What every frame does: the frame uniforms and every draw's uniform bytes
  // (descriptor sets are written by the first frame and kept), recording,
  // submission and the wait.
  Result<Submitter, RenderError> submitter_made = make_submitter(context);
  if (!submitter_made) return unexpected(submitter_made.error());
  Submitter& submitter = *submitter_made;
  auto record = [&](VkCommandBuffer commands, bool capturing) {
    recorder.refresh();
    if (queries) {
      vkCmdResetQueryPool(commands, queries, 0, 2);
      vkCmdWriteTimestamp(commands, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, queries, 0);
    }
    glm::vec3 clear = linear_color({scene.camera.clear_color[0], scene.camera.clear_color[1], scene.camera.clear_color[2]});
    if (capturing) options.capture->clear_color = {clear.r, clear.g, clear.b, scene.camera.clear_color[3]};
    Result<uint64_t, RenderError> shadow_triangles = record_shadow_maps(
        commands, shadows, objects,
        [&](VkCommandBuffer c, const Draw& d, const UniformValues& light_frame) {
          return recorder.bind(c, d, objects[d.object], light_frame);
        },
        frame_values);
    if (!shadow_triangles) {
      failed = shadow_triangles.error();
      return;
    }
    frame.stats.triangles += *shadow_triangles;
    VkViewport viewport{0, 0, float(frame.width), float(frame.height), 0, 1};
    VkRect2D scissor{{0, 0}, {uint32_t(frame.width), uint32_t(frame.height)}};
    // Binds `mesh` (unless it is bound already) and draws all of it, `instances` times.
    const GpuMesh* bound_mesh = nullptr;
    auto draw_mesh = [&](const GpuMesh& mesh, uint32_t instances = 1) {
      if (bound_mesh != &mesh) {
        VkBuffer vb = mesh.vertices.handle();
        VkDeviceSize offset = 0;
        vkCmdBindVertexBuffers(commands, 0, 1, &vb, &offset);
        vkCmdBindIndexBuffer(commands, mesh.indices.handle(), 0, VK_INDEX_TYPE_UINT32);
        bound_mesh = &mesh;
      }
      vkCmdDrawIndexed(commands, mesh.index_count, instances, 0, 0, 0);
      frame.stats.triangles += uint64_t(mesh.index_count / 3) * instances;
    };
    // Draws `draws` [first, last) with `pipelines` in a render pass already begun.
    auto draw_all = [&](const std::vector<Draw>& draws, const std::vector<VkPipeline>& draw_pipelines,
                        const std::vector<ObjectState>& owners, size_t first = 0, size_t last = SIZE_MAX) {
      vkCmdSetViewport(commands, 0, 1, &viewport);
      vkCmdSetScissor(commands, 0, 1, &scissor);
      for (size_t i = first; i < std::min(last, draws.size()) && !failed; ++i) {
        const Draw& d = draws[i];
        const ObjectState& object = owners[d.object];
        vkCmdBindPipeline(commands, VK_PIPELINE_BIND_POINT_GRAPHICS, draw_pipelines[i]);
        if (Result<void, RenderError> bound = recorder.bind(commands, d, object, frame_values); !bound) {
          failed = bound.error();
          break;
        }
        draw_mesh(*object.mesh);
      }
    };
    for (size_t i = 0; i < screen_shadows.list.draws.size() && !failed; ++i) {
      VkRenderPassBeginInfo mask{VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO};
      mask.renderPass = screen_shadows.render_pass;
      mask.framebuffer = screen_shadows.framebuffers[i];
      mask.renderArea = {{0, 0}, {uint32_t(frame.width), uint32_t(frame.height)}};
      VkClearValue lit{};
      lit.color = {{1, 1, 1, 1}};
      mask.clearValueCount = 1;
      mask.pClearValues = &lit;
      vkCmdBeginRenderPass(commands, &mask, VK_SUBPASS_CONTENTS_INLINE);
      recorder.overrides.clear();
      draw_all(screen_shadows.list.draws, screen_shadows.pipelines, screen_shadows.screen.objects, i, i + 1);
      vkCmdEndRenderPass(commands);
    }
    if (deferred) {
      glm::vec3 clear_rgb = linear_color({scene.camera.clear_color[0], scene.camera.clear_color[1], scene.camera.clear_color[2]});
      std::array<VkClearValue, kGBufferTargets + 1> gclears{};
      gclears[3].color = {{clear_rgb.r, clear_rgb.g, clear_rgb.b, scene.camera.clear_color[3]}};
      gclears[4].depthStencil = {1.0f, 0};
      VkRenderPassBeginInfo g{VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO};
      g.renderPass = gbuffer.gbuffer_pass;
      g.framebuffer = gbuffer.gbuffer_framebuffer;
      g.renderArea = {{0, 0}, {uint32_t(frame.width), uint32_t(frame.height)}};
      g.clearValueCount = uint32_t(gclears.size());
      g.pClearValues = gclears.data();
      vkCmdBeginRenderPass(commands, &g, VK_SUBPASS_CONTENTS_INLINE);
      recorder.overrides.clear();
      draw_all(list->gbuffer, gbuffer_pipelines, objects);
      vkCmdEndRenderPass(commands);
      VkRenderPassBeginInfo l = g;
      l.renderPass = gbuffer.light_pass;
      l.framebuffer = gbuffer.light_framebuffer;
      l.clearValueCount = 0;
      l.pClearValues = nullptr;
      vkCmdBeginRenderPass(commands, &l, VK_SUBPASS_CONTENTS_INLINE);
      recorder.overrides = gbuffer_textures(gbuffer, *depth_image);
      draw_all(deferred->list.draws, light_pipelines, deferred->screen.objects);
      vkCmdEndRenderPass(commands);
      transition(commands, *depth_image, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
                 VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL);
    }
    VkClearValue clears[2]{};
    clears[0].color = {{clear.r, clear.g, clear.b, scene.camera.clear_color[3]}};
    clears[1].depthStencil = {1.0f, 0};
    VkRenderPassBeginInfo begin{VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO};
    begin.renderPass = grabs.points.empty() ? fo.render_pass : fo.first_part;
    begin.framebuffer = fo.framebuffer;
    begin.renderArea = {{0, 0}, {uint32_t(frame.width), uint32_t(frame.height)}};
    begin.clearValueCount = 2;
    begin.pClearValues = clears;
    vkCmdBeginRenderPass(commands, &begin, VK_SUBPASS_CONTENTS_INLINE);
    vkCmdSetViewport(commands, 0, 1, &viewport);
    vkCmdSetScissor(commands, 0, 1, &scissor);
    recorder.overrides.clear();
    for (auto& [name, image] : grabs.images) recorder.overrides[name] = &image;
    std::map<std::string, bool> grabbed;
    size_t next_grab = 0;
    for (size_t i = 0; i < list->draws.size() && !failed; ++i) {
      const Draw& d = list->draws[i];
      const ObjectState& object = objects[d.object];
      if (next_grab < grabs.points.size() && grabs.points[next_grab].draw == i) {
        vkCmdEndRenderPass(commands);
        record_grab(commands, *color, grabs.points[next_grab], grabs, grabbed);
        frame.stats.grabs += grabs.points[next_grab].names.size();
        ++next_grab;
        VkRenderPassBeginInfo part = begin;
        part.renderPass = next_grab < grabs.points.size() ? fo.middle_part : fo.last_part;
        part.clearValueCount = 0;
        part.pClearValues = nullptr;
        vkCmdBeginRenderPass(commands, &part, VK_SUBPASS_CONTENTS_INLINE);
        vkCmdSetViewport(commands, 0, 1, &viewport);
        vkCmdSetScissor(commands, 0, 1, &scissor);
      }
      if (deferred && object.background) {
        VkViewport far_plane = viewport;
        far_plane.minDepth = far_plane.maxDepth = 1;
        vkCmdSetViewport(commands, 0, 1, &far_plane);
      }
      vkCmdBindPipeline(commands, VK_PIPELINE_BIND_POINT_GRAPHICS, pipelines[i]);
      std::optional<CapturedDraw> captured;
      if (capturing) {
        captured = CapturedDraw{capture->program(*d.variant->program), capture->mesh(*object.mesh), d.state, object.mirrored};
        recorder.capture = &*capture;
      }
      if (Result<void, RenderError> bound = recorder.bind(commands, d, object, frame_values, captured ? &*captured : nullptr);
          !bound) {
        failed = bound.error();
        break;
      }
      const uint32_t instances = uint32_t(std::max<size_t>(1, d.instances.size()));
      if (captured) {
        captured->instances = instances;
        options.capture->draws.push_back(std::move(*captured));
      }
      draw_mesh(*object.mesh, instances);
      if (deferred && object.background) vkCmdSetViewport(commands, 0, 1, &viewport);
    }
    vkCmdEndRenderPass(commands);
    const Image* result = &*color;
    for (size_t i = 0; post && i < post->list.draws.size() && !failed; ++i) {
      VkRenderPassBeginInfo step{VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO};
      step.renderPass = targets.render_pass;
      step.framebuffer = targets.framebuffers[i % 2];
      step.renderArea = begin.renderArea;
      vkCmdBeginRenderPass(commands, &step, VK_SUBPASS_CONTENTS_INLINE);
      vkCmdSetViewport(commands, 0, 1, &viewport);
      vkCmdSetScissor(commands, 0, 1, &scissor);
      recorder.overrides = {{"_MainTex", result}};
      if (depth_sampled) recorder.overrides["_CameraDepthTexture"] = &*depth_image;
      recorder.point_sampler = targets.point_sampler;
      vkCmdBindPipeline(commands, VK_PIPELINE_BIND_POINT_GRAPHICS, post_pipelines[i]);
      if (Result<void, RenderError> bound = recorder.bind(commands, post->list.draws[i], post->steps[i], frame_values);
          !bound) {
        failed = bound.error();
      } else {
        draw_mesh(*quad);
      }
      vkCmdEndRenderPass(commands);
      result = &targets.images[i % 2];
    }
    if (post) transition(commands, *result, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL);
    if (queries) vkCmdWriteTimestamp(commands, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, queries, 1);
    VkBufferImageCopy region{};
    region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    region.imageExtent = {uint32_t(frame.width), uint32_t(frame.height), 1};
    vkCmdCopyImageToBuffer(commands, result->handle(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, readback->handle(), 1, &region);
    VkMemoryBarrier host{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
    host.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
    host.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
    vkCmdPipelineBarrier(commands, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 1, &host, 0, nullptr, 0,
                         nullptr);
  };
  for (int f = 0; f < options.frames; ++f) {
    Clock::time_point frame_start = Clock::now();
    frame.stats.triangles = 0;
    frame.stats.grabs = 0;
    // In place: the kept blocks point at these values.
    if (f > 0) frame_values.assign(per_frame_uniforms(scene, camera, frame.width, frame.height));
    Clock::time_point submit_returned = frame_start;
    VkResultOf<void> submitted =
        submitter.submit([&](VkCommandBuffer c) { record(c, f == 0 && capture); }, &submit_returned);
    frame.stats.frame_ms.push_back(ms_since(frame_start));
    frame.stats.frame_cpu_ms.push_back(std::chrono::duration<double, std::milli>(submit_returned - frame_start).count());
    if (failed) return unexpected(*failed);
    if (!submitted) return unexpected(error(describe(submitted.error())));
    uint64_t stamps[2] = {0, 0};
    if (queries && vkGetQueryPoolResults(context.device(), queries, 0, 2, sizeof(stamps), stamps, sizeof(uint64_t),
                                         VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT) == VK_SUCCESS) {
      frame.stats.frame_gpu_ms.push_back(double(stamps[1] - stamps[0]) * context.device_info().timestamp_period_ns / 1e6);
    }
    if (f == 0) recorder.done_making_sets();
    if (options.after_frame) options.after_frame(f);
  }
  if (!frame.stats.frame_gpu_ms.empty()) frame.stats.gpu_ms = median(frame.stats.frame_gpu_ms);
  finish_image(frame, static_cast<const std::byte*>(readback->data()), scene);
  for (const auto& map : shadows.maps) {
    for (Draw& d : map->casters.draws) frame.draws.push_back(std::move(d.record));
    (map->light ? frame.stats.shadow_draws : frame.stats.depth_texture_draws) += map->casters.draws.size();
  }
  frame.stats.shadow_maps = shadows.light_maps();
  for (Draw& d : screen_shadows.list.draws) frame.draws.push_back(std::move(d.record));
  frame.compiled.insert(frame.compiled.end(), screen_shadows.list.compiled.begin(), screen_shadows.list.compiled.end());
  frame.stats.variants_compiled += screen_shadows.list.variants_compiled;
  frame.stats.screen_shadow_masks = screen_shadows.list.draws.size();
  for (Draw& d : list->gbuffer) frame.draws.push_back(std::move(d.record));
  if (deferred) {
    for (Draw& d : deferred->list.draws) frame.draws.push_back(std::move(d.record));
    frame.compiled.insert(frame.compiled.end(), deferred->list.compiled.begin(), deferred->list.compiled.end());
    frame.stats.variants_compiled += deferred->list.variants_compiled;
    frame.stats.deferred_lights = deferred->list.draws.size();
  }
  frame.stats.gbuffer_draws = list->gbuffer.size();
  for (Draw& d : list->draws) {
    frame.stats.additive_draws += d.record.additive;
    frame.stats.instanced_draws += d.instances.size() > 1;
    frame.draws.push_back(std::move(d.record));
    for (DrawRecord& r : d.instance_records) frame.draws.push_back(std::move(r));
  }
  frame.stats.draws = list->draws.size() + frame.stats.shadow_draws + frame.stats.depth_texture_draws +
                      frame.stats.gbuffer_draws + frame.stats.deferred_lights + frame.stats.screen_shadow_masks;
  frame.compiled.insert(frame.compiled.end(), list->compiled.begin(), list->compiled.end());
  frame.stats.variants_compiled += list->variants_compiled;
  if (post) {
    for (Draw& d : post->list.draws) frame.draws.push_back(std::move(d.record));
    frame.stats.draws += post->list.draws.size();
    frame.compiled.insert(frame.compiled.end(), post->list.compiled.begin(), post->list.compiled.end());
    frame.stats.variants_compiled += post->list.variants_compiled;
  }
  for (const auto& map : shadows.maps) {  // compiled last: after the draws that sample them
    frame.compiled.insert(frame.compiled.end(), map->casters.compiled.begin(), map->casters.compiled.end());
    frame.stats.variants_compiled += map->casters.variants_compiled;
  }
  for (DrawRecord& r : list->skipped) frame.draws.push_back(std::move(r));
  for (const auto& map : shadows.maps) {
    for (DrawRecord& r : map->casters.skipped) frame.draws.push_back(std::move(r));
  }
  frame.stats.shaders_loaded = library.loaded();
  frame.stats.shaders_reloaded = reloaded;
  frame.shader_files = library.files_read();
  frame.variant_misses = library.misses();
  frame.stats.textures_loaded = resources.textures_loaded();
  frame.stats.compile_ms = library.seconds() * 1000;
  frame.stats.total_ms = ms_since(start);
  return frame;
}

}  // namespace facet::runtime
