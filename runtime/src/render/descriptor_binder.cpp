#include "render/descriptor_binder.h"

#include <fmt/format.h>

#include <algorithm>

#include "facet/runtime/vulkan_context.h"
#include "render/instancing.h"

namespace facet::runtime {
namespace {

}  // namespace

UniformArena::UniformArena(const Context& context) : context_(context) {
  VkPhysicalDeviceProperties p{};
  vkGetPhysicalDeviceProperties(context.physical_device(), &p);
  align_ = std::max<VkDeviceSize>(16, p.limits.minUniformBufferOffsetAlignment);
}

Result<UniformArena::Slice, Diagnostics> UniformArena::allocate(VkDeviceSize size) {
  size = std::max<VkDeviceSize>(size, 16);
  while (current_ < chunks_.size() && used_ + size > chunks_[current_].size()) {
    ++current_;
    used_ = 0;
  }
  if (current_ == chunks_.size()) {
    VkResultOf<Buffer> b = create_buffer(context_, std::max<VkDeviceSize>(size, 1 << 18), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT);
    if (!b) return unexpected(render_error(describe(b.error()), DiagId::vulkan_failed));
    chunks_.push_back(std::move(*b));
    used_ = 0;
  }
  Buffer& chunk = chunks_[current_];
  Slice s{chunk.handle(), used_, {static_cast<std::byte*>(chunk.data()) + used_, size_t(size)}};
  used_ = (used_ + size + align_ - 1) / align_ * align_;
  return s;
}

DescriptorBinder::DescriptorBinder(const Context& context, Resources& resources)
    : context(context), resources(resources), arena(context), pools(context.device()) {}

void DescriptorBinder::restart() {
  pools.reset();
  arena.reset();
  retained.clear();
  kept_blocks.clear();
  shared_sets.clear();
  bound_layout = VK_NULL_HANDLE;
}

void DescriptorBinder::push_zeros(VkCommandBuffer commands, const GpuProgram& program) {
  if (!program.push_constant_bytes) return;
  if (zeros.size() < program.push_constant_bytes) zeros.resize(program.push_constant_bytes);
  vkCmdPushConstants(commands, program.layout, program.push_stages, 0, program.push_constant_bytes, zeros.data());
}

void DescriptorBinder::refresh() {
  for (const KeptBlock& k : kept_blocks) refill_members(k.bytes, *k.block, k.frame_members);
  bound_layout = VK_NULL_HANDLE;
}

void DescriptorBinder::bind_sets(VkCommandBuffer commands, const GpuProgram& program, const Sets& sets) {
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

Result<const Image*, Diagnostics> DescriptorBinder::image_for(const ResourceBinding& r, const ObjectState& object,
                                                              const LightValues& light, bool screen_shadowed) {
  if (auto it = overrides.find(r.name); it != overrides.end()) return it->second;
  // In any set: Unity's own AutoLight.cginc declares it outside facet's light set.
  if (r.name == "_ShadowMapTexture" && screen_shadowed && screen_shadows) {
    if (const Image* mask = screen_shadows->mask_of(&light)) return mask;
  }
  if (r.set == 1 && r.name == "_LightTexture0" && light.cookie) return cookie_image(light);
  // Declared outside facet's light set: Unity's own AutoLight.cginc, whose
  // falloffs are textures (Resources::light_falloff, spot_cone).
  if (r.set != 1 && (r.name == "_LightTexture0" || r.name == "_LightTextureB0")) {
    if (std::optional<Result<const Image*, Diagnostics>> t = unity_light_texture(r.name, light)) return *t;
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
      if (!t) return unexpected(render_error(t.error(), DiagId::texture_invalid));
      return &(*t)->image;
    }
  }
  Result<const Image*, std::string> f = resources.fallback(r.dim.empty() ? "2D" : r.dim, r.arrayed);
  if (!f) return unexpected(render_error(fmt::format("resource '{}': {}", r.name, f.error()), DiagId::texture_invalid));
  return *f;
}

std::optional<Result<const Image*, Diagnostics>> DescriptorBinder::unity_light_texture(const std::string& name,
                                                                                       const LightValues& light) {
  auto made = [&](Result<const Image*, std::string> image) -> Result<const Image*, Diagnostics> {
    if (!image) {
      return unexpected(render_error(fmt::format("resource '{}': {}", name, image.error()), DiagId::texture_invalid));
    }
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

Result<const Image*, Diagnostics> DescriptorBinder::cookie_image(const LightValues& light) {
  Result<const LoadedTexture*, std::string> t = resources.texture(*light.cookie);
  if (!t) {
    return unexpected(render_error(fmt::format("{}.cookie: {}", light.json_path, t.error()), DiagId::texture_invalid));
  }
  return &(*t)->image;
}

Result<void, Diagnostics> DescriptorBinder::bind(VkCommandBuffer commands, const Draw& draw, const ObjectState& object,
                                                 const UniformValues& frame, CapturedDraw* captured) {
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
    Result<VkDescriptorSet, Diagnostics> ds =
        set_for(program, set, draw, object, layers, instances, screen_shadowed, captured);
    if (!ds) return unexpected(ds.error());
    sets[set] = *ds;
  }
  retained[&draw] = sets;
  bind_sets(commands, program, sets);
  return {};
}

Result<VkDescriptorSet, Diagnostics> DescriptorBinder::set_for(const GpuProgram& program, uint32_t set,
                                                               const Draw& draw, const ObjectState& object,
                                                               const UniformLayers& layers,
                                                               const std::vector<UniformLayers>& instances,
                                                               bool screen_shadowed, CapturedDraw* captured) {
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
    Result<std::pair<VkDescriptorType, VkDescriptorImageInfo>, Diagnostics> image =
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
  if (!allocated) return unexpected(render_error(allocated.error()));
  VkDescriptorSet ds = *allocated;
  std::vector<VkDescriptorBufferInfo> buffers;
  std::vector<VkWriteDescriptorSet> writes;
  buffers.reserve(blocks.size());
  for (size_t b = 0; b < blocks.size(); ++b) {
    const UniformBlock& block = *blocks[b];
    Result<UniformArena::Slice, Diagnostics> slice = arena.allocate(block.size);
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

std::string DescriptorBinder::shared_key(VkDescriptorSetLayout layout, const UniformValues* frame,
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

Result<std::pair<VkDescriptorType, VkDescriptorImageInfo>, Diagnostics> DescriptorBinder::image_info(
    const ResourceBinding& r, const ObjectState& object, const LightValues& light, bool screen_shadowed, uint32_t set,
    CapturedDraw* captured) {
  VkDescriptorImageInfo info{};
  Result<VkSampler, std::string> sampler = resources.sampler();
  if (!sampler) return unexpected(render_error(sampler.error()));
  info.sampler = *sampler;
  VkDescriptorType type = VK_DESCRIPTOR_TYPE_SAMPLER;
  CapturedDescriptor described{set, r.binding, type, std::max(1u, r.array_size)};
  if (r.kind != ResourceKind::separate_sampler) {
    Result<const Image*, Diagnostics> image = image_for(r, object, light, screen_shadowed);
    if (!image) return unexpected(image.error());
    if (captured) {
      Result<int, std::string> index = capture->image(*image);
      if (!index) {
        return unexpected(
            render_error(fmt::format("resource '{}': {}", r.name, index.error()), DiagId::texture_invalid));
      }
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
      if (!clamp) return unexpected(render_error(clamp.error()));
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

}  // namespace facet::runtime
