// What one frame of render_scene drew, as plain data: the meshes' bytes,
// each program's SPIR-V, vertex attributes and descriptor layouts, each
// draw's fixed-function state and the exact bytes of its uniform blocks, and
// the texels of every texture it bound. Another program can issue the same
// draws from it without facet (bench/frame_overhead does, to measure what
// facet's per-frame work costs against a bare Vulkan loop).
//
//   runtime::FrameCapture capture;
//   auto frame = runtime::render_scene(*context, *scene, {.shader_compiler = runtime::make_shader_compiler(), .capture = &capture});
#pragma once

#include <vulkan/vulkan.h>

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "facet/runtime/image.h"
#include "facet/runtime/render_state.h"

namespace facet::runtime {

struct CapturedMesh {
  std::vector<std::byte> vertices;  // interleaved, FrameCapture::vertex_stride bytes each
  std::vector<uint32_t> indices;
};

struct CapturedImage {
  ImageDesc desc;                            // usage: sampled + transfer dst
  std::vector<std::vector<std::byte>> mips;  // tightly packed, layers consecutive in each
};

struct CapturedStage {
  VkShaderStageFlagBits stage = VK_SHADER_STAGE_VERTEX_BIT;
  std::string entry;
  std::vector<uint32_t> spirv;
};

struct CapturedProgram {
  std::vector<CapturedStage> stages;
  std::vector<VkVertexInputAttributeDescription> attributes;  // all from binding 0
  std::array<std::vector<VkDescriptorSetLayoutBinding>, 4> sets;
  uint32_t push_constant_bytes = 0;  // facet pushes zeros
  VkShaderStageFlags push_stages = 0;
};

enum class CapturedSampler { trilinear_repeat, point_clamp };

struct CapturedDescriptor {
  uint32_t set = 0, binding = 0;
  VkDescriptorType type = VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER;
  uint32_t count = 1;                      // array elements, all the same image
  std::vector<std::byte> uniform_bytes;    // a uniform buffer's contents
  int image = -1;                          // into FrameCapture::images (not for plain samplers)
  CapturedSampler sampler = CapturedSampler::trilinear_repeat;
};

struct CapturedDraw {
  size_t program = 0;  // into FrameCapture::programs
  size_t mesh = 0;     // into FrameCapture::meshes
  PipelineState state;
  bool mirrored = false;  // front face counter-clockwise
  uint32_t instances = 1;  // GPU instancing: the mesh drawn this many times
  std::vector<CapturedDescriptor> descriptors;
};

struct FrameCapture {
  uint32_t width = 0, height = 0;
  VkFormat color_format = VK_FORMAT_R16G16B16A16_SFLOAT;
  VkFormat depth_format = VK_FORMAT_D32_SFLOAT;
  std::array<float, 4> clear_color{};  // linear, as the render pass clears
  uint32_t vertex_stride = 0;
  std::vector<CapturedMesh> meshes;
  std::vector<CapturedImage> images;
  std::vector<CapturedProgram> programs;
  std::vector<CapturedDraw> draws;  // in submission order
};

}  // namespace facet::runtime
