#include "render/program.h"

#include <fmt/format.h>

#include <algorithm>
#include <cstddef>

#include "facet/runtime/image.h"
#include "facet/runtime/mesh.h"
#include "facet/runtime/vulkan_context.h"

namespace facet::runtime {
namespace {

VkShaderStageFlagBits stage_bit_of(Stage stage) {
  switch (stage) {
    case Stage::vertex: return VK_SHADER_STAGE_VERTEX_BIT;
    case Stage::fragment: return VK_SHADER_STAGE_FRAGMENT_BIT;
    case Stage::geometry: return VK_SHADER_STAGE_GEOMETRY_BIT;
    case Stage::hull: return VK_SHADER_STAGE_TESSELLATION_CONTROL_BIT;
    case Stage::domain: return VK_SHADER_STAGE_TESSELLATION_EVALUATION_BIT;
  }
  return VK_SHADER_STAGE_VERTEX_BIT;
}

Result<VkDescriptorType, std::string> descriptor_type(const ResourceBinding& r) {
  switch (r.kind) {
    case ResourceKind::combined_image_sampler: return VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
    case ResourceKind::separate_image: return VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE;
    case ResourceKind::separate_sampler: return VK_DESCRIPTOR_TYPE_SAMPLER;
    default: return unexpected(fmt::format("resource '{}': storage and texel-buffer resources are not supported", r.name));
  }
}

void merge_members(std::vector<BlockMember>& into, const std::vector<BlockMember>& from) {
  for (const BlockMember& m : from) {
    auto same = [&](const BlockMember& x) { return x.name == m.name; };
    if (std::find_if(into.begin(), into.end(), same) == into.end()) into.push_back(m);
  }
}

struct LayoutBinding {
  VkDescriptorSetLayoutBinding binding{};
};

// The attribute of the interleaved Vertex that feeds a stage input.
struct Attribute {
  uint32_t offset = 0;
  VkFormat format = VK_FORMAT_R32G32B32A32_SFLOAT;
};

Attribute attribute_for(const StageVariable& input) {
  const std::string& s = input.semantic;
  bool is_int = input.type.rfind("int", 0) == 0 || input.type.rfind("min16int", 0) == 0;
  bool is_uint = input.type.rfind("uint", 0) == 0 || input.type.rfind("bool", 0) == 0;
  if (is_int) return {offsetof(Vertex, zero), VK_FORMAT_R32G32B32A32_SINT};
  if (is_uint) return {offsetof(Vertex, zero), VK_FORMAT_R32G32B32A32_UINT};
  if (s == "POSITION" || s == "SV_POSITION" || s == "POSITION0") return {offsetof(Vertex, position), VK_FORMAT_R32G32B32_SFLOAT};
  if (s == "NORMAL" || s == "NORMAL0") return {offsetof(Vertex, normal), VK_FORMAT_R32G32B32_SFLOAT};
  if (s == "TANGENT" || s == "TANGENT0") return {offsetof(Vertex, tangent), VK_FORMAT_R32G32B32A32_SFLOAT};
  if (s == "COLOR" || s == "COLOR0") return {offsetof(Vertex, color), VK_FORMAT_R32G32B32A32_SFLOAT};
  if (s == "TEXCOORD0" || s == "TEXCOORD") return {offsetof(Vertex, uv0), VK_FORMAT_R32G32_SFLOAT};
  if (s == "TEXCOORD1") return {offsetof(Vertex, uv1), VK_FORMAT_R32G32_SFLOAT};
  return {offsetof(Vertex, zero), VK_FORMAT_R32G32B32A32_SFLOAT};
}

constexpr uint32_t kMaxBinding = 1024;
constexpr uint32_t kMaxDescriptorArray = 4096;

Result<void, std::string> build_layouts(GpuProgram& p) {
  std::array<std::vector<VkDescriptorSetLayoutBinding>, kSetCount> sets;
  auto add = [&](uint32_t set, uint32_t binding, VkDescriptorType type, uint32_t count,
                 const std::string& name) -> Result<void, std::string> {
    if (set >= kSetCount) return unexpected(fmt::format("'{}' is in descriptor set {} (at most 3)", name, set));
    // facetc numbers bindings from 0 and arrays are a shader's own; a
    // package whose reflection says otherwise was edited, and a driver sizes
    // its tables by them (binding 2^31 made lavapipe allocate 240 GB).
    if (binding >= kMaxBinding || count > kMaxDescriptorArray) {
      return unexpected(
          fmt::format("'{}' has binding {} and {} descriptors (at most {} and {}): the package's "
                      "reflection is not facetc's",
                      name, binding, count, kMaxBinding - 1, kMaxDescriptorArray));
    }
    VkDescriptorSetLayoutBinding b{};
    b.binding = binding;
    b.descriptorType = type;
    b.descriptorCount = std::max(1u, count);
    b.stageFlags = VK_SHADER_STAGE_ALL_GRAPHICS;
    sets[set].push_back(b);
    p.set_used[set] = true;
    return {};
  };
  for (const UniformBlock& b : p.blocks) FACET_TRY(add(b.set, b.binding, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 1, b.name));
  for (const ResourceBinding& r : p.resources) {
    Result<VkDescriptorType, std::string> type = descriptor_type(r);
    if (!type) return unexpected(type.error());
    FACET_TRY(add(r.set, r.binding, *type, r.array_size, r.name));
  }
  p.set_bindings = sets;
  for (uint32_t s = 0; s < kSetCount; ++s) {
    VkDescriptorSetLayoutCreateInfo info{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
    info.bindingCount = uint32_t(sets[s].size());
    info.pBindings = sets[s].data();
    if (vkCreateDescriptorSetLayout(p.device, &info, nullptr, &p.set_layouts[s]) != VK_SUCCESS) {
      return unexpected(std::string("cannot create a descriptor set layout"));
    }
  }
  VkPushConstantRange range{p.push_stages, 0, p.push_constant_bytes};
  VkPipelineLayoutCreateInfo info{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
  info.setLayoutCount = kSetCount;
  info.pSetLayouts = p.set_layouts.data();
  info.pushConstantRangeCount = p.push_constant_bytes ? 1 : 0;
  info.pPushConstantRanges = &range;
  if (vkCreatePipelineLayout(p.device, &info, nullptr, &p.layout) != VK_SUCCESS) {
    return unexpected(std::string("cannot create a pipeline layout"));
  }
  return {};
}

}  // namespace

GpuProgram::~GpuProgram() {
  if (!device) return;
  for (auto& [key, pipeline] : pipelines) vkDestroyPipeline(device, pipeline, nullptr);
  if (layout) vkDestroyPipelineLayout(device, layout, nullptr);
  for (VkDescriptorSetLayout l : set_layouts) {
    if (l) vkDestroyDescriptorSetLayout(device, l, nullptr);
  }
  for (VkShaderModule m : modules) vkDestroyShaderModule(device, m, nullptr);
}

Result<std::unique_ptr<GpuProgram>, std::string> create_program(const Context& context, const package::Package& package,
                                                               const package::PackageVariant& variant) {
  auto p = std::make_unique<GpuProgram>();
  p->device = context.device();
  for (const package::PackageStage& stage : variant.stages) {
    const std::vector<uint32_t>& words = package.spirv_blobs.at(stage.blob);
    VkShaderModuleCreateInfo info{VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
    info.codeSize = words.size() * 4;
    info.pCode = words.data();
    VkShaderModule module = VK_NULL_HANDLE;
    if (vkCreateShaderModule(p->device, &info, nullptr, &module) != VK_SUCCESS) {
      return unexpected(std::string("cannot create a shader module"));
    }
    p->modules.push_back(module);
    p->spirv.push_back(words);
    p->stages.push_back(stage_bit_of(stage.stage));
    p->entries.push_back(stage.reflection.entry_point);
    const StageReflection& r = stage.reflection;
    if (stage.stage == Stage::vertex) p->vertex_inputs = r.inputs;
    if (stage.stage == Stage::fragment) {
      for (const StageVariable& out : r.outputs) {
        for (uint32_t l = 0; l < std::max(1u, out.array_size); ++l) {
          if (out.location + l < 32) p->fragment_outputs |= 1u << (out.location + l);
        }
      }
    }
    for (const UniformBlock& b : r.uniform_blocks) {
      if (b.push_constant) {
        p->push_constant_bytes = std::max(p->push_constant_bytes, b.size);
        p->push_stages |= stage_bit_of(stage.stage);
        continue;
      }
      auto same = [&](const UniformBlock& x) { return x.set == b.set && x.binding == b.binding; };
      auto it = std::find_if(p->blocks.begin(), p->blocks.end(), same);
      if (it == p->blocks.end()) {
        p->blocks.push_back(b);
      } else {
        it->size = std::max(it->size, b.size);
        merge_members(it->members, b.members);
      }
    }
    for (const ResourceBinding& res : r.resources) {
      auto same = [&](const ResourceBinding& x) { return x.set == res.set && x.binding == res.binding; };
      if (std::find_if(p->resources.begin(), p->resources.end(), same) == p->resources.end()) p->resources.push_back(res);
    }
  }
  if (std::find(p->stages.begin(), p->stages.end(), VK_SHADER_STAGE_VERTEX_BIT) == p->stages.end() ||
      std::find(p->stages.begin(), p->stages.end(), VK_SHADER_STAGE_FRAGMENT_BIT) == p->stages.end()) {
    return unexpected(std::string("the pass has no vertex or no fragment stage"));
  }
  FACET_TRY(build_layouts(*p));
  return p;
}

std::vector<VkVertexInputAttributeDescription> vertex_attributes(const GpuProgram& program) {
  std::vector<VkVertexInputAttributeDescription> attributes;
  for (const StageVariable& input : program.vertex_inputs) {
    if (input.semantic.rfind("SV_", 0) == 0 && input.semantic != "SV_POSITION") continue;
    Attribute a = attribute_for(input);
    uint32_t locations = std::max(1u, input.array_size);
    for (uint32_t l = 0; l < locations; ++l) attributes.push_back({input.location + l, 0, a.format, a.offset});
  }
  return attributes;
}

namespace {

bool has_stage(const GpuProgram& program, VkShaderStageFlagBits stage) {
  return std::find(program.stages.begin(), program.stages.end(), stage) != program.stages.end();
}

// What the pass needs of the device beyond the core: a clear error rather
// than a pipeline the driver may crash on.
Result<void, std::string> check_features(const Context& context, const GpuProgram& program, const PipelineState& state) {
  const VkPhysicalDeviceFeatures& on = context.enabled_features();
  auto lacks = [&](const char* what, const char* feature) {
    return unexpected(fmt::format("{} needs the Vulkan feature {}, which {} does not have", what, feature,
                                  context.device_info().name));
  };
  if (has_stage(program, VK_SHADER_STAGE_GEOMETRY_BIT) && !on.geometryShader) {
    return lacks("the pass's geometry stage", "geometryShader");
  }
  if (has_stage(program, VK_SHADER_STAGE_TESSELLATION_CONTROL_BIT) && !on.tessellationShader) {
    return lacks("the pass's hull and domain stages", "tessellationShader");
  }
  if (state.depth_clamp && !on.depthClamp) return lacks("'ZClip False'", "depthClamp");
  return {};
}

}  // namespace

Result<VkPipeline, std::string> get_pipeline(const Context& context, GpuProgram& program, const PipelineState& state,
                                             bool mirrored, VkRenderPass render_pass, VkPipelineCache cache,
                                             bool* created, uint32_t color_targets) {
  std::string key = describe(state) + (mirrored ? " mirrored" : "");
  if (color_targets != 1) key += fmt::format(" targets {}", color_targets);
  if (state.stencil) {
    key += fmt::format(" {} {} {} {} {} {}", int(state.front.compareOp), int(state.front.passOp), state.front.reference,
                       int(state.back.compareOp), int(state.back.passOp), state.back.reference);
  }
  key += fmt::format(" {} {} {} {} {}", int(state.src_alpha), int(state.dst_alpha), int(state.op), int(state.op_alpha),
                     state.alpha_to_mask);
  if (auto it = program.pipelines.find(key); it != program.pipelines.end()) {
    if (created) *created = false;
    return it->second;
  }
  FACET_TRY(check_features(context, program, state));
  std::vector<VkPipelineShaderStageCreateInfo> stages;
  for (size_t i = 0; i < program.modules.size(); ++i) {
    VkPipelineShaderStageCreateInfo s{VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO};
    s.stage = program.stages[i];
    s.module = program.modules[i];
    s.pName = program.entries[i].c_str();
    stages.push_back(s);
  }
  VkVertexInputBindingDescription binding{0, sizeof(Vertex), VK_VERTEX_INPUT_RATE_VERTEX};
  std::vector<VkVertexInputAttributeDescription> attributes = vertex_attributes(program);
  VkPipelineVertexInputStateCreateInfo vertex{VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO};
  vertex.vertexBindingDescriptionCount = 1;
  vertex.pVertexBindingDescriptions = &binding;
  vertex.vertexAttributeDescriptionCount = uint32_t(attributes.size());
  vertex.pVertexAttributeDescriptions = attributes.data();
  VkPipelineInputAssemblyStateCreateInfo assembly{VK_STRUCTURE_TYPE_PIPELINE_INPUT_ASSEMBLY_STATE_CREATE_INFO};
  const bool tessellated = has_stage(program, VK_SHADER_STAGE_TESSELLATION_CONTROL_BIT);
  // The hull stage takes the mesh's triangles as 3-point patches.
  assembly.topology = tessellated ? VK_PRIMITIVE_TOPOLOGY_PATCH_LIST : VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST;
  VkPipelineTessellationStateCreateInfo tessellation{VK_STRUCTURE_TYPE_PIPELINE_TESSELLATION_STATE_CREATE_INFO};
  tessellation.patchControlPoints = 3;
  VkPipelineViewportStateCreateInfo viewport{VK_STRUCTURE_TYPE_PIPELINE_VIEWPORT_STATE_CREATE_INFO};
  viewport.viewportCount = 1;
  viewport.scissorCount = 1;
  VkPipelineRasterizationStateCreateInfo raster{VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_STATE_CREATE_INFO};
  raster.polygonMode = VK_POLYGON_MODE_FILL;
  raster.cullMode = state.cull;
  // Unity's front faces are clockwise on screen; the projection flips y so
  // that row 0 is the top, which keeps that winding in framebuffer space.
  raster.frontFace = mirrored ? VK_FRONT_FACE_COUNTER_CLOCKWISE : VK_FRONT_FACE_CLOCKWISE;
  raster.depthClampEnable = state.depth_clamp;  // ZClip False (check_features: the device has depthClamp)
  raster.depthBiasEnable = state.offset_factor != 0 || state.offset_units != 0;
  raster.depthBiasSlopeFactor = state.offset_factor;
  raster.depthBiasConstantFactor = state.offset_units;
  raster.lineWidth = 1;
  VkPipelineMultisampleStateCreateInfo multisample{VK_STRUCTURE_TYPE_PIPELINE_MULTISAMPLE_STATE_CREATE_INFO};
  multisample.rasterizationSamples = VK_SAMPLE_COUNT_1_BIT;
  multisample.alphaToCoverageEnable = state.alpha_to_mask;
  VkPipelineDepthStencilStateCreateInfo depth{VK_STRUCTURE_TYPE_PIPELINE_DEPTH_STENCIL_STATE_CREATE_INFO};
  depth.depthTestEnable = state.depth_test;
  depth.depthWriteEnable = state.zwrite;
  depth.depthCompareOp = state.ztest;
  depth.stencilTestEnable = state.stencil;
  depth.front = state.front;
  depth.back = state.back;
  VkPipelineColorBlendAttachmentState blend{};
  blend.blendEnable = state.blend;
  blend.srcColorBlendFactor = state.src;
  blend.dstColorBlendFactor = state.dst;
  blend.colorBlendOp = state.op;
  blend.srcAlphaBlendFactor = state.src_alpha;
  blend.dstAlphaBlendFactor = state.dst_alpha;
  blend.alphaBlendOp = state.op_alpha;
  blend.colorWriteMask = state.color_mask;
  std::vector<VkPipelineColorBlendAttachmentState> blends(color_targets, blend);
  const bool independent = context.enabled_features().independentBlend;
  for (uint32_t i = 0; i < color_targets && color_targets > 1 && independent; ++i) {
    if (!(program.fragment_outputs & (1u << i))) blends[i].colorWriteMask = 0;
  }
  VkPipelineColorBlendStateCreateInfo color{VK_STRUCTURE_TYPE_PIPELINE_COLOR_BLEND_STATE_CREATE_INFO};
  color.attachmentCount = color_targets;
  color.pAttachments = blends.data();
  VkDynamicState dynamic_states[] = {VK_DYNAMIC_STATE_VIEWPORT, VK_DYNAMIC_STATE_SCISSOR};
  VkPipelineDynamicStateCreateInfo dynamic{VK_STRUCTURE_TYPE_PIPELINE_DYNAMIC_STATE_CREATE_INFO};
  dynamic.dynamicStateCount = 2;
  dynamic.pDynamicStates = dynamic_states;
  VkGraphicsPipelineCreateInfo info{VK_STRUCTURE_TYPE_GRAPHICS_PIPELINE_CREATE_INFO};
  info.stageCount = uint32_t(stages.size());
  info.pStages = stages.data();
  info.pVertexInputState = &vertex;
  info.pInputAssemblyState = &assembly;
  info.pTessellationState = tessellated ? &tessellation : nullptr;
  info.pViewportState = &viewport;
  info.pRasterizationState = &raster;
  info.pMultisampleState = &multisample;
  info.pDepthStencilState = &depth;
  info.pColorBlendState = &color;
  info.pDynamicState = &dynamic;
  info.layout = program.layout;
  info.renderPass = render_pass;
  VkPipeline pipeline = VK_NULL_HANDLE;
  if (VkResult r = vkCreateGraphicsPipelines(context.device(), cache, 1, &info, nullptr, &pipeline); r != VK_SUCCESS) {
    return unexpected(fmt::format("cannot create a graphics pipeline ({})", vk_result_name(r)));
  }
  program.pipelines[key] = pipeline;
  if (created) *created = true;
  return pipeline;
}

}  // namespace facet::runtime
