#include "bare_renderer.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cstring>
#include <map>
#include <tuple>

#include "facet/runtime/buffer.h"
#include "facet/runtime/image.h"
#include "facet/runtime/vulkan_context.h"

namespace facet::bench {

using runtime::CapturedDraw;
using runtime::CapturedProgram;
using runtime::FrameCapture;

struct BareProgram {
  std::vector<VkShaderModule> modules;
  std::array<VkDescriptorSetLayout, 4> layouts{};
  VkPipelineLayout layout = VK_NULL_HANDLE;
};

struct BareDraw {
  VkPipeline pipeline = VK_NULL_HANDLE;
  std::array<VkDescriptorSet, 4> sets{};
};

struct BareState {
  runtime::Context& context;
  const FrameCapture& capture;
  VkDevice device = VK_NULL_HANDLE;
  VkRenderPass render_pass = VK_NULL_HANDLE;
  runtime::Image color, depth;
  VkFramebuffer framebuffer = VK_NULL_HANDLE;
  std::array<VkSampler, 2> samplers{};  // trilinear repeat, point clamp
  std::vector<runtime::Buffer> vertex_buffers, index_buffers;
  std::vector<runtime::Image> images;
  runtime::Buffer uniforms, readback;
  VkDescriptorPool pool = VK_NULL_HANDLE;
  std::vector<BareProgram> programs;
  std::vector<BareDraw> draws;
  std::map<std::tuple<size_t, std::string, bool>, VkPipeline> pipelines;  // by program, state and winding
  VkCommandPool command_pool = VK_NULL_HANDLE;
  VkCommandBuffer commands = VK_NULL_HANDLE;
  VkFence fence = VK_NULL_HANDLE;
  VkQueryPool queries = VK_NULL_HANDLE;

  BareState(runtime::Context& c, const FrameCapture& f) : context(c), capture(f), device(c.device()) {}
  ~BareState() {
    vkDeviceWaitIdle(device);
    if (queries) vkDestroyQueryPool(device, queries, nullptr);
    if (fence) vkDestroyFence(device, fence, nullptr);
    if (command_pool) vkDestroyCommandPool(device, command_pool, nullptr);
    for (auto& [key, pipeline] : pipelines) vkDestroyPipeline(device, pipeline, nullptr);
    if (pool) vkDestroyDescriptorPool(device, pool, nullptr);
    for (BareProgram& p : programs) {
      if (p.layout) vkDestroyPipelineLayout(device, p.layout, nullptr);
      for (VkDescriptorSetLayout l : p.layouts) {
        if (l) vkDestroyDescriptorSetLayout(device, l, nullptr);
      }
      for (VkShaderModule m : p.modules) vkDestroyShaderModule(device, m, nullptr);
    }
    for (VkSampler s : samplers) {
      if (s) vkDestroySampler(device, s, nullptr);
    }
    if (framebuffer) vkDestroyFramebuffer(device, framebuffer, nullptr);
    if (render_pass) vkDestroyRenderPass(device, render_pass, nullptr);
  }
};

namespace {

using Clock = std::chrono::steady_clock;

std::string failed(const char* what, VkResult r) { return fmt::format("bare renderer: {} ({})", what, runtime::vk_result_name(r)); }

template <typename T>
Result<T, std::string> made(runtime::VkResultOf<T> r) {
  if (!r) return unexpected(runtime::describe(r.error()));
  return std::move(*r);
}

Result<void, std::string> make_targets(BareState& s) {
  const FrameCapture& c = s.capture;
  auto color = made(runtime::create_image(s.context, {.width = c.width, .height = c.height, .format = c.color_format,
                                                      .usage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT |
                                                               VK_IMAGE_USAGE_TRANSFER_SRC_BIT}));
  auto depth = made(runtime::create_image(s.context, {.width = c.width, .height = c.height, .format = c.depth_format,
                                                      .usage = VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT}));
  if (!color) return unexpected(color.error());
  if (!depth) return unexpected(depth.error());
  s.color = std::move(*color);
  s.depth = std::move(*depth);
  std::array<VkAttachmentDescription, 2> a{};
  for (VkAttachmentDescription& d : a) {
    d.samples = VK_SAMPLE_COUNT_1_BIT;
    d.loadOp = d.stencilLoadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
    d.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
    d.stencilStoreOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
    d.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
  }
  a[0].format = c.color_format;
  a[0].finalLayout = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;
  a[1].format = c.depth_format;
  a[1].storeOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
  a[1].finalLayout = VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL;
  VkAttachmentReference color_ref{0, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL};
  VkAttachmentReference depth_ref{1, VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL};
  VkSubpassDescription subpass{0, VK_PIPELINE_BIND_POINT_GRAPHICS, 0, nullptr, 1, &color_ref, nullptr, &depth_ref};
  VkSubpassDependency to_copy{0, VK_SUBPASS_EXTERNAL,
                              VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT | VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT,
                              VK_PIPELINE_STAGE_TRANSFER_BIT,
                              VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT | VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT,
                              VK_ACCESS_TRANSFER_READ_BIT};
  VkRenderPassCreateInfo pass{VK_STRUCTURE_TYPE_RENDER_PASS_CREATE_INFO};
  pass.attachmentCount = 2;
  pass.pAttachments = a.data();
  pass.subpassCount = 1;
  pass.pSubpasses = &subpass;
  pass.dependencyCount = 1;
  pass.pDependencies = &to_copy;
  if (VkResult r = vkCreateRenderPass(s.device, &pass, nullptr, &s.render_pass); r) return unexpected(failed("render pass", r));
  VkImageView views[2] = {s.color.view(), s.depth.view()};
  VkFramebufferCreateInfo fb{VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO};
  fb.renderPass = s.render_pass;
  fb.attachmentCount = 2;
  fb.pAttachments = views;
  fb.width = c.width;
  fb.height = c.height;
  fb.layers = 1;
  if (VkResult r = vkCreateFramebuffer(s.device, &fb, nullptr, &s.framebuffer); r) return unexpected(failed("framebuffer", r));
  return {};
}

Result<void, std::string> make_samplers(BareState& s) {
  for (size_t i = 0; i < 2; ++i) {
    bool point = i == 1;
    VkSamplerCreateInfo info{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
    info.magFilter = info.minFilter = point ? VK_FILTER_NEAREST : VK_FILTER_LINEAR;
    info.mipmapMode = point ? VK_SAMPLER_MIPMAP_MODE_NEAREST : VK_SAMPLER_MIPMAP_MODE_LINEAR;
    info.addressModeU = info.addressModeV = info.addressModeW =
        point ? VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE : VK_SAMPLER_ADDRESS_MODE_REPEAT;
    info.maxLod = point ? 0 : VK_LOD_CLAMP_NONE;
    if (VkResult r = vkCreateSampler(s.device, &info, nullptr, &s.samplers[i]); r) return unexpected(failed("sampler", r));
  }
  return {};
}

Result<void, std::string> upload_data(BareState& s) {
  for (const runtime::CapturedMesh& m : s.capture.meshes) {
    auto v = made(runtime::create_buffer(s.context, m.vertices.size(), VK_BUFFER_USAGE_VERTEX_BUFFER_BIT));
    auto i = made(runtime::create_buffer(s.context, m.indices.size() * 4, VK_BUFFER_USAGE_INDEX_BUFFER_BIT));
    if (!v) return unexpected(v.error());
    if (!i) return unexpected(i.error());
    std::memcpy(v->data(), m.vertices.data(), m.vertices.size());
    std::memcpy(i->data(), m.indices.data(), m.indices.size() * 4);
    s.vertex_buffers.push_back(std::move(*v));
    s.index_buffers.push_back(std::move(*i));
  }
  for (const runtime::CapturedImage& c : s.capture.images) {
    auto image = made(runtime::create_image(s.context, c.desc));
    if (!image) return unexpected(image.error());
    std::vector<std::span<const std::byte>> mips(c.mips.begin(), c.mips.end());
    if (auto up = runtime::upload_image(s.context, *image, mips); !up) return unexpected(runtime::describe(up.error()));
    s.images.push_back(std::move(*image));
  }
  return {};
}

Result<void, std::string> make_program(BareState& s, const CapturedProgram& c) {
  BareProgram p;
  for (const runtime::CapturedStage& stage : c.stages) {
    VkShaderModuleCreateInfo info{VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
    info.codeSize = stage.spirv.size() * 4;
    info.pCode = stage.spirv.data();
    VkShaderModule m = VK_NULL_HANDLE;
    if (VkResult r = vkCreateShaderModule(s.device, &info, nullptr, &m); r) return unexpected(failed("shader module", r));
    p.modules.push_back(m);
  }
  for (size_t set = 0; set < 4; ++set) {
    VkDescriptorSetLayoutCreateInfo info{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
    info.bindingCount = uint32_t(c.sets[set].size());
    info.pBindings = c.sets[set].data();
    if (VkResult r = vkCreateDescriptorSetLayout(s.device, &info, nullptr, &p.layouts[set]); r) {
      return unexpected(failed("descriptor set layout", r));
    }
  }
  VkPushConstantRange range{c.push_stages, 0, c.push_constant_bytes};
  VkPipelineLayoutCreateInfo info{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
  info.setLayoutCount = 4;
  info.pSetLayouts = p.layouts.data();
  info.pushConstantRangeCount = c.push_constant_bytes ? 1 : 0;
  info.pPushConstantRanges = &range;
  if (VkResult r = vkCreatePipelineLayout(s.device, &info, nullptr, &p.layout); r) return unexpected(failed("pipeline layout", r));
  s.programs.push_back(std::move(p));
  return {};
}

Result<VkPipeline, std::string> make_pipeline(BareState& s, const CapturedDraw& d) {
  const CapturedProgram& c = s.capture.programs[d.program];
  const BareProgram& p = s.programs[d.program];
  const runtime::PipelineState& st = d.state;
  std::vector<VkPipelineShaderStageCreateInfo> stages;
  for (size_t i = 0; i < c.stages.size(); ++i) {
    stages.push_back({VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO, nullptr, 0, c.stages[i].stage, p.modules[i],
                      c.stages[i].entry.c_str(), nullptr});
  }
  VkVertexInputBindingDescription binding{0, s.capture.vertex_stride, VK_VERTEX_INPUT_RATE_VERTEX};
  VkPipelineVertexInputStateCreateInfo vertex{VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO, nullptr, 0, 1,
                                              &binding, uint32_t(c.attributes.size()), c.attributes.data()};
  VkPipelineInputAssemblyStateCreateInfo assembly{VK_STRUCTURE_TYPE_PIPELINE_INPUT_ASSEMBLY_STATE_CREATE_INFO, nullptr, 0,
                                                  VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST, VK_FALSE};
  VkPipelineViewportStateCreateInfo viewport{VK_STRUCTURE_TYPE_PIPELINE_VIEWPORT_STATE_CREATE_INFO, nullptr, 0, 1, nullptr,
                                             1, nullptr};
  bool bias = st.offset_factor != 0 || st.offset_units != 0;
  VkPipelineRasterizationStateCreateInfo raster{
      VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_STATE_CREATE_INFO, nullptr, 0, VK_FALSE, VK_FALSE, VK_POLYGON_MODE_FILL,
      st.cull, d.mirrored ? VK_FRONT_FACE_COUNTER_CLOCKWISE : VK_FRONT_FACE_CLOCKWISE, bias, st.offset_units, 0,
      st.offset_factor, 1};
  VkPipelineMultisampleStateCreateInfo multisample{VK_STRUCTURE_TYPE_PIPELINE_MULTISAMPLE_STATE_CREATE_INFO};
  multisample.rasterizationSamples = VK_SAMPLE_COUNT_1_BIT;
  multisample.alphaToCoverageEnable = st.alpha_to_mask;
  VkPipelineDepthStencilStateCreateInfo depth{VK_STRUCTURE_TYPE_PIPELINE_DEPTH_STENCIL_STATE_CREATE_INFO};
  depth.depthTestEnable = st.depth_test;
  depth.depthWriteEnable = st.zwrite;
  depth.depthCompareOp = st.ztest;
  depth.stencilTestEnable = st.stencil;
  depth.front = st.front;
  depth.back = st.back;
  VkPipelineColorBlendAttachmentState blend{st.blend, st.src, st.dst, st.op, st.src_alpha, st.dst_alpha, st.op_alpha,
                                            st.color_mask};
  VkPipelineColorBlendStateCreateInfo color{VK_STRUCTURE_TYPE_PIPELINE_COLOR_BLEND_STATE_CREATE_INFO};
  color.attachmentCount = 1;
  color.pAttachments = &blend;
  VkDynamicState dynamic_states[] = {VK_DYNAMIC_STATE_VIEWPORT, VK_DYNAMIC_STATE_SCISSOR};
  VkPipelineDynamicStateCreateInfo dynamic{VK_STRUCTURE_TYPE_PIPELINE_DYNAMIC_STATE_CREATE_INFO, nullptr, 0, 2,
                                           dynamic_states};
  VkGraphicsPipelineCreateInfo info{VK_STRUCTURE_TYPE_GRAPHICS_PIPELINE_CREATE_INFO};
  info.stageCount = uint32_t(stages.size());
  info.pStages = stages.data();
  info.pVertexInputState = &vertex;
  info.pInputAssemblyState = &assembly;
  info.pViewportState = &viewport;
  info.pRasterizationState = &raster;
  info.pMultisampleState = &multisample;
  info.pDepthStencilState = &depth;
  info.pColorBlendState = &color;
  info.pDynamicState = &dynamic;
  info.layout = p.layout;
  info.renderPass = s.render_pass;
  VkPipeline pipeline = VK_NULL_HANDLE;
  if (VkResult r = vkCreateGraphicsPipelines(s.device, VK_NULL_HANDLE, 1, &info, nullptr, &pipeline); r) {
    return unexpected(failed("graphics pipeline", r));
  }
  return pipeline;
}

// All uniform bytes of all draws in one buffer, each at an aligned offset,
// written once: the baseline never rebuilds a uniform.
Result<std::vector<VkDeviceSize>, std::string> fill_uniforms(BareState& s) {
  VkPhysicalDeviceProperties props{};
  vkGetPhysicalDeviceProperties(s.context.physical_device(), &props);
  VkDeviceSize align = std::max<VkDeviceSize>(16, props.limits.minUniformBufferOffsetAlignment);
  std::vector<VkDeviceSize> offsets;
  VkDeviceSize total = 0;
  for (const CapturedDraw& d : s.capture.draws) {
    for (const runtime::CapturedDescriptor& desc : d.descriptors) {
      if (desc.type != VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER) continue;
      offsets.push_back(total);
      total += (std::max<VkDeviceSize>(desc.uniform_bytes.size(), 16) + align - 1) / align * align;
    }
  }
  auto buffer = made(runtime::create_buffer(s.context, std::max<VkDeviceSize>(total, 16), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT));
  if (!buffer) return unexpected(buffer.error());
  s.uniforms = std::move(*buffer);
  size_t k = 0;
  for (const CapturedDraw& d : s.capture.draws) {
    for (const runtime::CapturedDescriptor& desc : d.descriptors) {
      if (desc.type != VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER) continue;
      std::memcpy(static_cast<std::byte*>(s.uniforms.data()) + offsets[k++], desc.uniform_bytes.data(),
                  desc.uniform_bytes.size());
    }
  }
  return offsets;
}

Result<void, std::string> make_pool(BareState& s) {
  std::array<VkDescriptorPoolSize, 4> sizes{{{VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 0},
                                             {VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 0},
                                             {VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE, 0},
                                             {VK_DESCRIPTOR_TYPE_SAMPLER, 0}}};
  uint32_t sets = 0;
  for (const CapturedDraw& d : s.capture.draws) {
    sets += 4;
    for (const runtime::CapturedDescriptor& desc : d.descriptors) {
      for (VkDescriptorPoolSize& size : sizes) {
        if (size.type == desc.type) size.descriptorCount += desc.count;
      }
    }
  }
  for (VkDescriptorPoolSize& size : sizes) size.descriptorCount = std::max(1u, size.descriptorCount);
  VkDescriptorPoolCreateInfo info{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
  info.maxSets = std::max(1u, sets);
  info.poolSizeCount = uint32_t(sizes.size());
  info.pPoolSizes = sizes.data();
  if (VkResult r = vkCreateDescriptorPool(s.device, &info, nullptr, &s.pool); r) return unexpected(failed("descriptor pool", r));
  return {};
}

Result<void, std::string> make_draws(BareState& s) {
  auto offsets = fill_uniforms(s);
  if (!offsets) return unexpected(offsets.error());
  FACET_TRY(make_pool(s));
  size_t k = 0;
  for (const CapturedDraw& d : s.capture.draws) {
    BareDraw draw;
    VkPipeline& pipeline = s.pipelines[{d.program, runtime::describe(d.state), d.mirrored}];
    if (!pipeline) {
      auto made_pipeline = make_pipeline(s, d);
      if (!made_pipeline) return unexpected(made_pipeline.error());
      pipeline = *made_pipeline;
    }
    draw.pipeline = pipeline;
    s.draws.push_back(draw);
    BareDraw& bd = s.draws.back();
    const BareProgram& p = s.programs[d.program];
    for (size_t set = 0; set < 4; ++set) {
      if (s.capture.programs[d.program].sets[set].empty()) continue;
      VkDescriptorSetAllocateInfo allocate{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO, nullptr, s.pool, 1, &p.layouts[set]};
      if (VkResult r = vkAllocateDescriptorSets(s.device, &allocate, &bd.sets[set]); r) {
        return unexpected(failed("descriptor set", r));
      }
    }
    std::vector<VkDescriptorBufferInfo> buffers;
    std::vector<std::vector<VkDescriptorImageInfo>> images;
    buffers.reserve(d.descriptors.size());
    images.reserve(d.descriptors.size());
    std::vector<VkWriteDescriptorSet> writes;
    for (const runtime::CapturedDescriptor& desc : d.descriptors) {
      VkWriteDescriptorSet w{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET, nullptr, bd.sets[desc.set], desc.binding, 0,
                             desc.count, desc.type};
      if (desc.type == VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER) {
        buffers.push_back({s.uniforms.handle(), (*offsets)[k++], std::max<VkDeviceSize>(desc.uniform_bytes.size(), 16)});
        w.pBufferInfo = &buffers.back();
      } else {
        VkDescriptorImageInfo info{s.samplers[desc.sampler == runtime::CapturedSampler::point_clamp ? 1 : 0],
                                   desc.image >= 0 ? s.images[size_t(desc.image)].view() : VK_NULL_HANDLE,
                                   VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
        images.emplace_back(desc.count, info);
        w.pImageInfo = images.back().data();
      }
      writes.push_back(w);
    }
    vkUpdateDescriptorSets(s.device, uint32_t(writes.size()), writes.data(), 0, nullptr);
  }
  return {};
}

Result<void, std::string> make_submission(BareState& s) {
  VkCommandPoolCreateInfo pool{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO, nullptr,
                               VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT, s.context.queue_family()};
  if (VkResult r = vkCreateCommandPool(s.device, &pool, nullptr, &s.command_pool); r) return unexpected(failed("command pool", r));
  VkCommandBufferAllocateInfo allocate{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO, nullptr, s.command_pool,
                                       VK_COMMAND_BUFFER_LEVEL_PRIMARY, 1};
  if (VkResult r = vkAllocateCommandBuffers(s.device, &allocate, &s.commands); r) return unexpected(failed("command buffer", r));
  VkFenceCreateInfo fence{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
  if (VkResult r = vkCreateFence(s.device, &fence, nullptr, &s.fence); r) return unexpected(failed("fence", r));
  if (s.context.device_info().timestamp_valid_bits) {
    VkQueryPoolCreateInfo q{VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO, nullptr, 0, VK_QUERY_TYPE_TIMESTAMP, 2};
    if (VkResult r = vkCreateQueryPool(s.device, &q, nullptr, &s.queries); r) return unexpected(failed("query pool", r));
  }
  auto readback = made(runtime::create_buffer(s.context, VkDeviceSize(s.capture.width) * s.capture.height * 8,
                                              VK_BUFFER_USAGE_TRANSFER_DST_BIT));
  if (!readback) return unexpected(readback.error());
  s.readback = std::move(*readback);
  return {};
}

void record(BareState& s) {
  VkCommandBuffer cb = s.commands;
  const FrameCapture& c = s.capture;
  VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO, nullptr,
                                 VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT};
  vkBeginCommandBuffer(cb, &begin);
  if (s.queries) {
    vkCmdResetQueryPool(cb, s.queries, 0, 2);
    vkCmdWriteTimestamp(cb, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, s.queries, 0);
  }
  VkClearValue clears[2]{};
  std::memcpy(clears[0].color.float32, c.clear_color.data(), 16);
  clears[1].depthStencil = {1.0f, 0};
  VkRect2D area{{0, 0}, {c.width, c.height}};
  VkRenderPassBeginInfo pass{VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO, nullptr, s.render_pass, s.framebuffer, area, 2, clears};
  vkCmdBeginRenderPass(cb, &pass, VK_SUBPASS_CONTENTS_INLINE);
  VkViewport viewport{0, 0, float(c.width), float(c.height), 0, 1};
  vkCmdSetViewport(cb, 0, 1, &viewport);
  vkCmdSetScissor(cb, 0, 1, &area);
  std::vector<std::byte> zeros(256);
  for (size_t i = 0; i < c.draws.size(); ++i) {
    const CapturedDraw& d = c.draws[i];
    const BareProgram& p = s.programs[d.program];
    const CapturedProgram& cp = c.programs[d.program];
    vkCmdBindPipeline(cb, VK_PIPELINE_BIND_POINT_GRAPHICS, s.draws[i].pipeline);
    for (uint32_t set = 0; set < 4; ++set) {
      if (s.draws[i].sets[set]) {
        vkCmdBindDescriptorSets(cb, VK_PIPELINE_BIND_POINT_GRAPHICS, p.layout, set, 1, &s.draws[i].sets[set], 0, nullptr);
      }
    }
    if (cp.push_constant_bytes) {
      if (zeros.size() < cp.push_constant_bytes) zeros.resize(cp.push_constant_bytes);
      vkCmdPushConstants(cb, p.layout, cp.push_stages, 0, cp.push_constant_bytes, zeros.data());
    }
    VkBuffer vb = s.vertex_buffers[d.mesh].handle();
    VkDeviceSize offset = 0;
    vkCmdBindVertexBuffers(cb, 0, 1, &vb, &offset);
    vkCmdBindIndexBuffer(cb, s.index_buffers[d.mesh].handle(), 0, VK_INDEX_TYPE_UINT32);
    vkCmdDrawIndexed(cb, uint32_t(c.meshes[d.mesh].indices.size()), d.instances, 0, 0, 0);
  }
  vkCmdEndRenderPass(cb);
  if (s.queries) vkCmdWriteTimestamp(cb, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, s.queries, 1);
  VkBufferImageCopy region{};
  region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
  region.imageExtent = {c.width, c.height, 1};
  vkCmdCopyImageToBuffer(cb, s.color.handle(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, s.readback.handle(), 1, &region);
  VkMemoryBarrier host{VK_STRUCTURE_TYPE_MEMORY_BARRIER, nullptr, VK_ACCESS_TRANSFER_WRITE_BIT, VK_ACCESS_HOST_READ_BIT};
  vkCmdPipelineBarrier(cb, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 1, &host, 0, nullptr, 0, nullptr);
  vkEndCommandBuffer(cb);
}

}  // namespace

BareRenderer::BareRenderer(runtime::Context& context, const FrameCapture& capture)
    : state_(std::make_unique<BareState>(context, capture)) {}

BareRenderer::~BareRenderer() = default;

Result<void, std::string> BareRenderer::prepare() {
  BareState& s = *state_;
  FACET_TRY(make_targets(s));
  FACET_TRY(make_samplers(s));
  FACET_TRY(upload_data(s));
  for (const CapturedProgram& p : s.capture.programs) FACET_TRY(make_program(s, p));
  FACET_TRY(make_draws(s));
  return make_submission(s);
}

Result<BareFrame, std::string> BareRenderer::render_frame() {
  BareState& s = *state_;
  Clock::time_point start = Clock::now();
  vkResetCommandBuffer(s.commands, 0);
  record(s);
  VkSubmitInfo submit{VK_STRUCTURE_TYPE_SUBMIT_INFO};
  submit.commandBufferCount = 1;
  submit.pCommandBuffers = &s.commands;
  if (VkResult r = vkQueueSubmit(s.context.queue(), 1, &submit, s.fence); r) return unexpected(failed("submit", r));
  const double cpu_ms = std::chrono::duration<double, std::milli>(Clock::now() - start).count();
  if (VkResult r = vkWaitForFences(s.device, 1, &s.fence, VK_TRUE, UINT64_MAX); r) return unexpected(failed("wait", r));
  vkResetFences(s.device, 1, &s.fence);
  BareFrame frame;
  frame.cpu_ms = cpu_ms;
  frame.host_ms = std::chrono::duration<double, std::milli>(Clock::now() - start).count();
  uint64_t stamps[2] = {0, 0};
  if (s.queries && vkGetQueryPoolResults(s.device, s.queries, 0, 2, sizeof(stamps), stamps, sizeof(uint64_t),
                                         VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT) == VK_SUCCESS) {
    frame.gpu_ms = double(stamps[1] - stamps[0]) * s.context.device_info().timestamp_period_ns / 1e6;
  }
  return frame;
}

std::vector<uint16_t> BareRenderer::pixels() const {
  const BareState& s = *state_;
  std::vector<uint16_t> out(size_t(s.capture.width) * s.capture.height * 4);
  std::memcpy(out.data(), s.readback.data(), out.size() * 2);
  return out;
}

}  // namespace facet::bench
