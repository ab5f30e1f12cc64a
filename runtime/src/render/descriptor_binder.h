// Descriptor sets of a frame's draws: the uniform blocks filled from the
// layers of values (object, light, material, frame), the images each
// resource binds, sets shared by draws with the same contents, and binding
// only what changed between draws.
#pragma once

#include <vulkan/vulkan.h>

#include <array>
#include <map>
#include <optional>
#include <span>
#include <string>
#include <unordered_map>
#include <vector>

#include "render/capture.h"
#include "render/descriptor_pools.h"
#include "render/draw_list.h"
#include "render/resources.h"
#include "render/screen_shadows.h"
#include "render/shadow_pass.h"
#include "render/failure.h"

namespace facet::runtime {

// Linear allocation of uniform data in host-visible buffers, reused from
// the start after reset().
class UniformArena {
 public:
  explicit UniformArena(const Context& context);
  struct Slice {
    VkBuffer buffer;
    VkDeviceSize offset;
    std::span<std::byte> bytes;
  };
  Result<Slice, Diagnostics> allocate(VkDeviceSize size);
  void reset() {
    current_ = 0;
    used_ = 0;
  }
  size_t buffers_created() const { return chunks_.size(); }

 private:
  const Context& context_;
  std::vector<Buffer> chunks_;
  size_t current_ = 0;
  VkDeviceSize used_ = 0, align_ = 256;
};

struct DescriptorBinder {
  DescriptorBinder(const Context& context, Resources& resources);

  const Context& context;
  Resources& resources;
  UniformArena arena;
  DescriptorPools pools;
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
  void push_zeros(VkCommandBuffer commands, const GpuProgram& program);

  // After the first frame every draw has its sets: the keys that found
  // shared ones are not needed again.
  void done_making_sets() { std::unordered_map<std::string, VkDescriptorSet>().swap(shared_sets); }

  // Forgets every set and uniform slice, for a frame whose draws were built
  // anew: the pools are reset and the uniform buffers written from their
  // start, so that drawing it creates nothing the frames before made room for.
  void restart();

  // At the start of each frame's recording: the frame members of every kept
  // block rewritten, and nothing known to be bound in the new command buffer.
  void refresh();

  void bind_sets(VkCommandBuffer commands, const GpuProgram& program, const Sets& sets);

  Result<const Image*, Diagnostics> image_for(const ResourceBinding& r, const ObjectState& object,
                                              const LightValues& light, bool screen_shadowed);

  // What Unity's AutoLight samples as `name` for `light`: the attenuation
  // ramp (_LightTextureB0, a point light's _LightTexture0), a spot's cone or
  // cookie, a directional light's cookie; nullopt for anything else.
  std::optional<Result<const Image*, Diagnostics>> unity_light_texture(const std::string& name,
                                                                       const LightValues& light);

  Result<const Image*, Diagnostics> cookie_image(const LightValues& light);

  // `captured`: where the descriptors' contents go when capturing the frame.
  Result<void, Diagnostics> bind(VkCommandBuffer commands, const Draw& draw, const ObjectState& object,
                                 const UniformValues& frame, CapturedDraw* captured = nullptr);

  // Set `set` of `draw`: a shared one with the same contents, or a new one.
  Result<VkDescriptorSet, Diagnostics> set_for(const GpuProgram& program, uint32_t set, const Draw& draw,
                                               const ObjectState& object, const UniformLayers& layers,
                                               const std::vector<UniformLayers>& instances, bool screen_shadowed,
                                               CapturedDraw* captured);

  // What makes two sets interchangeable: the layout, the frame layer their
  // frame members are refilled from, and every byte and handle written.
  static std::string shared_key(VkDescriptorSetLayout layout, const UniformValues* frame,
                                const std::vector<std::vector<std::byte>>& contents,
                                const std::vector<std::vector<VkDescriptorImageInfo>>& images);

  // The descriptor type and image info of resource `r` (a separate sampler
  // gets the sampler alone).
  Result<std::pair<VkDescriptorType, VkDescriptorImageInfo>, Diagnostics> image_info(const ResourceBinding& r,
                                                                                     const ObjectState& object,
                                                                                     const LightValues& light,
                                                                                     bool screen_shadowed, uint32_t set,
                                                                                     CapturedDraw* captured);
};

}  // namespace facet::runtime
