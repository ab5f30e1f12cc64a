// One compiled variant of one pass on the GPU: shader modules, descriptor
// set layouts from the union of its stages' reflection (binding model sets
// 0-3), the pipeline layout, and the vertex inputs; pipelines for it are
// made per fixed-function state.
#pragma once

#include <vulkan/vulkan.h>

#include <array>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "facet/package.h"
#include "facet/result.h"
#include "facet/runtime/render_state.h"

namespace facet::runtime {

class Context;

inline constexpr uint32_t kSetCount = 4;

struct GpuProgram {
  VkDevice device = VK_NULL_HANDLE;
  std::vector<VkShaderModule> modules;
  std::vector<VkShaderStageFlagBits> stages;
  std::vector<std::string> entries;
  std::vector<std::vector<uint32_t>> spirv;  // per module, kept for frame captures
  std::array<VkDescriptorSetLayout, kSetCount> set_layouts{};
  std::array<bool, kSetCount> set_used{};
  std::array<std::vector<VkDescriptorSetLayoutBinding>, kSetCount> set_bindings;
  VkPipelineLayout layout = VK_NULL_HANDLE;
  std::vector<UniformBlock> blocks;         // every stage's blocks merged by (set, binding)
  std::vector<ResourceBinding> resources;   // likewise
  std::vector<StageVariable> vertex_inputs;
  uint32_t fragment_outputs = 0;  // bit i: the fragment stage writes SV_Target i (location i)
  uint32_t push_constant_bytes = 0;
  VkShaderStageFlags push_stages = 0;
  std::map<std::string, VkPipeline> pipelines;  // by state text

  GpuProgram() = default;
  GpuProgram(const GpuProgram&) = delete;
  GpuProgram& operator=(const GpuProgram&) = delete;
  ~GpuProgram();
};

Result<std::unique_ptr<GpuProgram>, std::string> create_program(const Context& context, const package::Package& package,
                                                               const package::PackageVariant& variant);

// The interleaved Vertex's attributes that feed the vertex stage's inputs
// (binding 0), matched by semantic.
std::vector<VkVertexInputAttributeDescription> vertex_attributes(const GpuProgram& program);

// The pipeline for this state (created on first use, then reused).
// `mirrored` flips the front face for objects with a negative scale.
// `color_targets`: the render pass's colour attachments (the deferred
// G-buffer has 4); each gets the state's blend, and a target the fragment
// stage does not write is masked off, so that it keeps what it holds.
Result<VkPipeline, std::string> get_pipeline(const Context& context, GpuProgram& program, const PipelineState& state,
                                             bool mirrored, VkRenderPass render_pass, VkPipelineCache cache,
                                             bool* created, uint32_t color_targets = 1);

}  // namespace facet::runtime
