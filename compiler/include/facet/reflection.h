// Reflection of one compiled stage: what an engine needs to bind it without
// hand-written layouts. Plain data; JSON through facet/reflection_json.h.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "facet/stage.h"

namespace facet {

// A stage input or output ("in float3 normal : NORMAL" -> location 1).
struct StageVariable {
  std::string name;      // as SPIR-V names it (may be glslang's mangled name)
  std::string semantic;  // HLSL semantic upper-cased ("TEXCOORD0"); "" for GLSL
  uint32_t location = 0;
  std::string type;      // "float4", "float3x3", "int2", ...
  uint32_t array_size = 0;  // 0: not an array

  bool operator==(const StageVariable&) const = default;
};

// A member of a uniform block; nested structs have members of their own.
// Offsets, strides and sizes are read from SPIR-V decorations.
struct BlockMember {
  std::string name;
  std::string type;            // "float4", "float4x4", "struct", ...
  uint32_t offset = 0;
  uint32_t size = 0;           // whole member, arrays included
  std::vector<uint32_t> array_dims;  // outermost first; empty if not an array
  uint32_t array_stride = 0;
  uint32_t matrix_stride = 0;
  bool row_major = false;
  std::vector<BlockMember> members;

  bool operator==(const BlockMember&) const = default;
};

struct UniformBlock {
  std::string name;       // block type or instance name ("$Globals" for loose uniforms)
  uint32_t set = 0, binding = 0;
  uint32_t size = 0;      // declared size in bytes
  bool push_constant = false;
  std::vector<BlockMember> members;

  bool operator==(const UniformBlock&) const = default;
};

enum class ResourceKind : uint8_t {
  combined_image_sampler, separate_image, separate_sampler, storage_image, storage_buffer, uniform_texel_buffer
};

struct ResourceBinding {
  std::string name;
  ResourceKind kind = ResourceKind::combined_image_sampler;
  std::string dim;         // "1D", "2D", "3D", "Cube", "Buffer"; "" for samplers and buffers
  bool arrayed = false;    // 2DArray, CubeArray
  uint32_t set = 0, binding = 0;
  uint32_t array_size = 0; // 0: not an array

  bool operator==(const ResourceBinding&) const = default;
};

struct SpecConstant {
  std::string name;
  uint32_t id = 0;
  std::string type;
  std::string default_value;  // printed as text

  bool operator==(const SpecConstant&) const = default;
};

// Which material property feeds which uniform or texture: "_Color" ->
// block "$Globals" member "_Color"; "_MainTex" -> texture "_MainTex";
// "_MainTex_ST" is fed by "_MainTex" with role "scale_offset".
struct PropertyBinding {
  std::string property;
  std::string role;    // "value", "texture", "scale_offset", "texel_size", "hdr_decode"
  std::string block;   // empty for textures
  std::string member;  // uniform member or resource name

  bool operator==(const PropertyBinding&) const = default;
};

struct StageReflection {
  Stage stage = Stage::vertex;
  std::string entry_point;
  std::vector<StageVariable> inputs, outputs;    // sorted by location
  std::vector<UniformBlock> uniform_blocks;      // sorted by (set, binding), push constants last
  std::vector<ResourceBinding> resources;        // sorted by (set, binding)
  std::vector<SpecConstant> spec_constants;      // sorted by id
  std::vector<PropertyBinding> property_bindings;

  bool operator==(const StageReflection&) const = default;
};

}  // namespace facet
