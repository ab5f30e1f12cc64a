#include "reflect.h"

#include "hlsl_rewrite.h"

#include <spirv_cross/spirv_cross.hpp>

#include <algorithm>
#include <exception>

namespace facet::backend {
namespace {

using spirv_cross::Compiler;
using spirv_cross::SPIRType;

std::string scalar_name(const SPIRType& t) {
  switch (t.basetype) {
    case SPIRType::Boolean: return "bool";
    case SPIRType::Int: return "int";
    case SPIRType::UInt: return "uint";
    case SPIRType::Int64: return "int64_t";
    case SPIRType::UInt64: return "uint64_t";
    case SPIRType::Half: return "half";
    case SPIRType::Float: return "float";
    case SPIRType::Double: return "double";
    case SPIRType::Struct: return "struct";
    default: return "unknown";
  }
}

// HLSL's "float3x4" has 3 rows; glslang gives it 3 SPIR-V columns of float4.
// A GLSL mat3x4 has 3 columns of vec4, which HLSL would call float4x3.
std::string type_name(const SPIRType& t, bool hlsl) {
  std::string base = scalar_name(t);
  if (t.basetype == SPIRType::Struct) return base;
  if (t.columns > 1) {
    uint32_t rows = hlsl ? t.columns : t.vecsize;
    uint32_t cols = hlsl ? t.vecsize : t.columns;
    return base + std::to_string(rows) + "x" + std::to_string(cols);
  }
  return t.vecsize > 1 ? base + std::to_string(t.vecsize) : base;
}

// Outermost dimension first; 0 for a runtime-sized dimension.
std::vector<uint32_t> array_dims(const Compiler& c, const SPIRType& t) {
  std::vector<uint32_t> dims;
  for (size_t k = t.array.size(); k-- > 0;) {
    uint32_t n = t.array[k];
    if (!t.array_size_literal[k]) n = c.get_constant(n).scalar();
    dims.push_back(n);
  }
  return dims;
}

std::vector<BlockMember> members_of(const Compiler& c, const SPIRType& st, bool hlsl, int depth);

BlockMember member_of(const Compiler& c, const SPIRType& st, uint32_t i, bool hlsl, int depth) {
  const SPIRType& mt = c.get_type(st.member_types[i]);
  BlockMember m;
  m.name = c.get_member_name(st.self, i);
  // A uniform the program assigns to keeps its own name (hlsl_rewrite.h).
  if (m.name.ends_with(kAssignedUniformSuffix)) m.name.resize(m.name.size() - kAssignedUniformSuffix.size());
  m.type = type_name(mt, hlsl);
  m.offset = c.type_struct_member_offset(st, i);
  m.array_dims = array_dims(c, mt);
  bool runtime_array = std::find(m.array_dims.begin(), m.array_dims.end(), 0u) != m.array_dims.end();
  m.size = runtime_array ? 0 : uint32_t(c.get_declared_struct_member_size(st, i));
  if (!mt.array.empty()) m.array_stride = c.type_struct_member_array_stride(st, i);
  if (mt.columns > 1) {
    m.matrix_stride = c.type_struct_member_matrix_stride(st, i);
    bool spirv_row_major = c.has_member_decoration(st.self, i, spv::DecorationRowMajor);
    m.row_major = hlsl ? !spirv_row_major : spirv_row_major;
  }
  if (mt.basetype == SPIRType::Struct && depth < 16) m.members = members_of(c, c.get_type(mt.self), hlsl, depth + 1);
  return m;
}

std::vector<BlockMember> members_of(const Compiler& c, const SPIRType& st, bool hlsl, int depth) {
  std::vector<BlockMember> out;
  for (uint32_t i = 0; i < st.member_types.size(); ++i) out.push_back(member_of(c, st, i, hlsl, depth));
  return out;
}

UniformBlock block_of(const Compiler& c, const spirv_cross::Resource& r, bool push_constant, bool hlsl) {
  const SPIRType& type = c.get_type(r.base_type_id);
  UniformBlock b;
  b.name = c.get_name(r.base_type_id);
  if (b.name.empty()) b.name = c.get_name(r.id);
  b.push_constant = push_constant;
  if (!push_constant) {
    b.set = c.get_decoration(r.id, spv::DecorationDescriptorSet);
    b.binding = c.get_decoration(r.id, spv::DecorationBinding);
  }
  b.size = uint32_t(c.get_declared_struct_size(type));
  b.members = members_of(c, type, hlsl, 0);
  return b;
}

std::string dim_name(spv::Dim dim) {
  switch (dim) {
    case spv::Dim1D: return "1D";
    case spv::Dim2D: return "2D";
    case spv::Dim3D: return "3D";
    case spv::DimCube: return "Cube";
    case spv::DimBuffer: return "Buffer";
    default: return "other";
  }
}

ResourceBinding resource_of(const Compiler& c, const spirv_cross::Resource& r, ResourceKind kind) {
  const SPIRType& type = c.get_type(r.type_id);
  ResourceBinding b;
  b.name = r.name.empty() ? c.get_name(r.id) : r.name;
  b.kind = kind;
  bool image = kind == ResourceKind::combined_image_sampler || kind == ResourceKind::separate_image ||
               kind == ResourceKind::storage_image;
  if (image) {
    b.dim = dim_name(type.image.dim);
    b.arrayed = type.image.arrayed;
    if (kind == ResourceKind::separate_image && type.image.dim == spv::DimBuffer) {
      b.kind = ResourceKind::uniform_texel_buffer;
    }
  }
  b.set = c.get_decoration(r.id, spv::DecorationDescriptorSet);
  b.binding = c.get_decoration(r.id, spv::DecorationBinding);
  std::vector<uint32_t> dims = array_dims(c, type);
  b.array_size = dims.empty() ? 0 : dims.front();
  return b;
}

std::vector<StageVariable> interface_of(const Compiler& c, const spirv_cross::SmallVector<spirv_cross::Resource>& list,
                                        bool hlsl) {
  std::vector<StageVariable> out;
  for (const spirv_cross::Resource& r : list) {
    const SPIRType& type = c.get_type(r.type_id);
    StageVariable v;
    v.name = c.get_name(r.id);
    v.semantic = c.get_decoration_string(r.id, spv::DecorationHlslSemanticGOOGLE);
    v.location = c.get_decoration(r.id, spv::DecorationLocation);
    v.type = type_name(type, hlsl);
    std::vector<uint32_t> dims = array_dims(c, type);
    v.array_size = dims.empty() ? 0 : dims.front();
    out.push_back(std::move(v));
  }
  std::stable_sort(out.begin(), out.end(), [](const auto& a, const auto& b) { return a.location < b.location; });
  return out;
}

std::string constant_text(const Compiler& c, spirv_cross::ConstantID id) {
  const spirv_cross::SPIRConstant& k = c.get_constant(id);
  const SPIRType& type = c.get_type(k.constant_type);
  switch (type.basetype) {
    case SPIRType::Boolean: return k.scalar() ? "true" : "false";
    case SPIRType::Int: return std::to_string(k.scalar_i32());
    case SPIRType::UInt: return std::to_string(k.scalar());
    case SPIRType::Float: return std::to_string(k.scalar_f32());
    default: return std::to_string(k.scalar());
  }
}

// GLSL vertex inputs carry no semantic; the mesh attribute of their location
// in facet's fixed vertex layout (the HLSL semantic table) stands in for it,
// so that the runtime feeds a GLSL program as it feeds an HLSL one.
std::string semantic_of_vertex_location(uint32_t location) {
  static const char* const kSemantics[] = {"POSITION", "NORMAL", "TANGENT", "COLOR"};
  if (location < 4) return kSemantics[location];
  if (location < 12) return "TEXCOORD" + std::to_string(location - 4);
  return "";
}

StageReflection reflect_with(const Compiler& c, const ReflectOptions& options) {
  StageReflection r;
  r.stage = options.stage;
  r.entry_point = options.entry_point;
  spirv_cross::ShaderResources res = c.get_shader_resources();
  r.inputs = interface_of(c, res.stage_inputs, options.hlsl);
  if (!options.hlsl && options.stage == Stage::vertex) {
    for (StageVariable& v : r.inputs) {
      if (v.semantic.empty()) v.semantic = semantic_of_vertex_location(v.location);
    }
  }
  r.outputs = interface_of(c, res.stage_outputs, options.hlsl);
  for (const auto& u : res.uniform_buffers) r.uniform_blocks.push_back(block_of(c, u, false, options.hlsl));
  std::sort(r.uniform_blocks.begin(), r.uniform_blocks.end(),
            [](const auto& a, const auto& b) { return std::tie(a.set, a.binding) < std::tie(b.set, b.binding); });
  for (const auto& p : res.push_constant_buffers) r.uniform_blocks.push_back(block_of(c, p, true, options.hlsl));
  using K = ResourceKind;
  for (const auto& x : res.sampled_images) r.resources.push_back(resource_of(c, x, K::combined_image_sampler));
  for (const auto& x : res.separate_images) r.resources.push_back(resource_of(c, x, K::separate_image));
  for (const auto& x : res.separate_samplers) r.resources.push_back(resource_of(c, x, K::separate_sampler));
  for (const auto& x : res.storage_images) r.resources.push_back(resource_of(c, x, K::storage_image));
  for (const auto& x : res.storage_buffers) r.resources.push_back(resource_of(c, x, K::storage_buffer));
  std::sort(r.resources.begin(), r.resources.end(),
            [](const auto& a, const auto& b) { return std::tie(a.set, a.binding) < std::tie(b.set, b.binding); });
  for (const spirv_cross::SpecializationConstant& s : c.get_specialization_constants()) {
    const spirv_cross::SPIRConstant& k = c.get_constant(s.id);
    r.spec_constants.push_back(
        {c.get_name(s.id), s.constant_id, type_name(c.get_type(k.constant_type), options.hlsl), constant_text(c, s.id)});
  }
  std::sort(r.spec_constants.begin(), r.spec_constants.end(), [](const auto& a, const auto& b) { return a.id < b.id; });
  return r;
}

}  // namespace

Result<StageReflection> reflect_stage(const std::vector<uint32_t>& spirv, const ReflectOptions& options,
                                      Diagnostics& diags) {
  // SPIRV-Cross throws spirv_cross::CompilerError; this is its one boundary.
  try {
    Compiler compiler(spirv);
    return reflect_with(compiler, options);
  } catch (const std::exception& e) {
    diags.add(DiagId::backend_reflection_failed, SourceSpan{}, std::string("cannot reflect SPIR-V: ") + e.what());
    return failure("reflection failed");
  }
}

void bind_properties(const std::vector<ir::Property>& properties, StageReflection& reflection) {
  auto find_member = [&](const std::string& name) -> const UniformBlock* {
    for (const UniformBlock& block : reflection.uniform_blocks) {
      for (const BlockMember& m : block.members) {
        if (m.name == name) return &block;
      }
    }
    return nullptr;
  };
  auto has_resource = [&](const std::string& name) {
    return std::any_of(reflection.resources.begin(), reflection.resources.end(),
                       [&](const ResourceBinding& r) { return r.name == name; });
  };
  auto add_member = [&](const ir::Property& p, const std::string& member, const char* role) {
    if (const UniformBlock* block = find_member(member)) {
      reflection.property_bindings.push_back({p.name, role, block->name, member});
    }
  };
  reflection.property_bindings.clear();
  for (const ir::Property& p : properties) {
    if (!p.is_texture()) {
      add_member(p, p.name, "value");
      continue;
    }
    if (has_resource(p.name)) reflection.property_bindings.push_back({p.name, "texture", "", p.name});
    if (has_resource("sampler" + p.name)) reflection.property_bindings.push_back({p.name, "sampler", "", "sampler" + p.name});
    add_member(p, p.name + "_ST", "scale_offset");
    add_member(p, p.name + "_TexelSize", "texel_size");
    add_member(p, p.name + "_HDR", "hdr_decode");
  }
}

}  // namespace facet::backend
