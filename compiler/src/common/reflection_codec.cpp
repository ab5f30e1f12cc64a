// StageReflection in binary: every field, in declaration order. The minimum
// encoded size of each element bounds the counts the decoder accepts.
#include <string>

#include "facet/support/binary_codec.h"

namespace facet::codec {
namespace {

// name semantic location type array_size
constexpr size_t kVariableMinSize = 4 * 5;
// name type offset size dims(count) array_stride matrix_stride row_major members(count)
constexpr size_t kMemberMinSize = 4 * 4 + 4 + 4 + 4 + 1 + 4;
// name set binding size push_constant members(count)
constexpr size_t kBlockMinSize = 4 * 4 + 1 + 4;
// name kind dim arrayed set binding array_size
constexpr size_t kResourceMinSize = 4 + 1 + 4 + 1 + 4 * 3;
constexpr size_t kSpecConstantMinSize = 4 * 4;
constexpr size_t kPropertyBindingMinSize = 4 * 4;

void encode_variables(Encoder& e, const std::vector<StageVariable>& vars) {
  e.count(vars.size());
  for (const StageVariable& v : vars) {
    e.str(v.name);
    e.str(v.semantic);
    e.u32(v.location);
    e.str(v.type);
    e.u32(v.array_size);
  }
}

void encode_members(Encoder& e, const std::vector<BlockMember>& members) {
  e.count(members.size());
  for (const BlockMember& m : members) {
    e.str(m.name);
    e.str(m.type);
    e.u32(m.offset);
    e.u32(m.size);
    e.u32s(m.array_dims);
    e.u32(m.array_stride);
    e.u32(m.matrix_stride);
    e.boolean(m.row_major);
    encode_members(e, m.members);
  }
}

std::vector<StageVariable> decode_variables(Decoder& d, std::string_view what) {
  uint32_t n = d.count(kVariableMinSize, what);
  std::vector<StageVariable> out;
  out.reserve(n);
  for (uint32_t i = 0; i < n && d.ok(); ++i) {
    StageVariable v;
    v.name = d.str();
    v.semantic = d.str();
    v.location = d.u32();
    v.type = d.str();
    v.array_size = d.u32();
    out.push_back(std::move(v));
  }
  return out;
}

std::vector<BlockMember> decode_members(Decoder& d, uint32_t depth) {
  if (depth > kMaxMemberDepth) {
    d.fail("block members nested deeper than " + std::to_string(kMaxMemberDepth) + " levels");
    return {};
  }
  uint32_t n = d.count(kMemberMinSize, "block member");
  std::vector<BlockMember> out;
  out.reserve(n);
  for (uint32_t i = 0; i < n && d.ok(); ++i) {
    BlockMember m;
    m.name = d.str();
    m.type = d.str();
    m.offset = d.u32();
    m.size = d.u32();
    m.array_dims = d.u32s("array dimension");
    m.array_stride = d.u32();
    m.matrix_stride = d.u32();
    m.row_major = d.boolean("row_major flag");
    m.members = decode_members(d, depth + 1);
    out.push_back(std::move(m));
  }
  return out;
}

std::vector<UniformBlock> decode_blocks(Decoder& d) {
  uint32_t n = d.count(kBlockMinSize, "uniform block");
  std::vector<UniformBlock> out;
  out.reserve(n);
  for (uint32_t i = 0; i < n && d.ok(); ++i) {
    UniformBlock b;
    b.name = d.str();
    b.set = d.u32();
    b.binding = d.u32();
    b.size = d.u32();
    b.push_constant = d.boolean("push_constant flag");
    b.members = decode_members(d, 1);
    out.push_back(std::move(b));
  }
  return out;
}

std::vector<ResourceBinding> decode_resources(Decoder& d) {
  uint32_t n = d.count(kResourceMinSize, "resource");
  std::vector<ResourceBinding> out;
  out.reserve(n);
  for (uint32_t i = 0; i < n && d.ok(); ++i) {
    ResourceBinding r;
    r.name = d.str();
    r.kind = ResourceKind(d.enum_byte(kMaxResourceKind, "resource kind"));
    r.dim = d.str();
    r.arrayed = d.boolean("arrayed flag");
    r.set = d.u32();
    r.binding = d.u32();
    r.array_size = d.u32();
    out.push_back(std::move(r));
  }
  return out;
}

std::vector<SpecConstant> decode_spec_constants(Decoder& d) {
  uint32_t n = d.count(kSpecConstantMinSize, "specialization constant");
  std::vector<SpecConstant> out;
  out.reserve(n);
  for (uint32_t i = 0; i < n && d.ok(); ++i) {
    SpecConstant c;
    c.name = d.str();
    c.id = d.u32();
    c.type = d.str();
    c.default_value = d.str();
    out.push_back(std::move(c));
  }
  return out;
}

std::vector<PropertyBinding> decode_property_bindings(Decoder& d) {
  uint32_t n = d.count(kPropertyBindingMinSize, "property binding");
  std::vector<PropertyBinding> out;
  out.reserve(n);
  for (uint32_t i = 0; i < n && d.ok(); ++i) {
    PropertyBinding b;
    b.property = d.str();
    b.role = d.str();
    b.block = d.str();
    b.member = d.str();
    out.push_back(std::move(b));
  }
  return out;
}

// Every element is charged as if it were a fixed-size struct plus its strings.
constexpr uint64_t kElementWeight = 64;

uint64_t members_weight(const std::vector<BlockMember>& members) {
  uint64_t w = 0;
  for (const BlockMember& m : members) {
    w += kElementWeight + m.name.size() + m.type.size() + 4 * m.array_dims.size() + members_weight(m.members);
  }
  return w;
}

}  // namespace

uint64_t reflection_weight(const StageReflection& r) {
  uint64_t w = kElementWeight + r.entry_point.size();
  for (const auto* vars : {&r.inputs, &r.outputs}) {
    for (const StageVariable& v : *vars) w += kElementWeight + v.name.size() + v.semantic.size() + v.type.size();
  }
  for (const UniformBlock& b : r.uniform_blocks) w += kElementWeight + b.name.size() + members_weight(b.members);
  for (const ResourceBinding& res : r.resources) w += kElementWeight + res.name.size() + res.dim.size();
  for (const SpecConstant& c : r.spec_constants) {
    w += kElementWeight + c.name.size() + c.type.size() + c.default_value.size();
  }
  for (const PropertyBinding& b : r.property_bindings) {
    w += kElementWeight + b.property.size() + b.role.size() + b.block.size() + b.member.size();
  }
  return w;
}

void encode_reflection(Encoder& e, const StageReflection& r) {
  e.u8(uint8_t(r.stage));
  e.str(r.entry_point);
  encode_variables(e, r.inputs);
  encode_variables(e, r.outputs);
  e.count(r.uniform_blocks.size());
  for (const UniformBlock& b : r.uniform_blocks) {
    e.str(b.name);
    e.u32(b.set);
    e.u32(b.binding);
    e.u32(b.size);
    e.boolean(b.push_constant);
    encode_members(e, b.members);
  }
  e.count(r.resources.size());
  for (const ResourceBinding& res : r.resources) {
    e.str(res.name);
    e.u8(uint8_t(res.kind));
    e.str(res.dim);
    e.boolean(res.arrayed);
    e.u32(res.set);
    e.u32(res.binding);
    e.u32(res.array_size);
  }
  e.count(r.spec_constants.size());
  for (const SpecConstant& c : r.spec_constants) {
    e.str(c.name);
    e.u32(c.id);
    e.str(c.type);
    e.str(c.default_value);
  }
  e.count(r.property_bindings.size());
  for (const PropertyBinding& b : r.property_bindings) {
    e.str(b.property);
    e.str(b.role);
    e.str(b.block);
    e.str(b.member);
  }
}

StageReflection decode_reflection(Decoder& d) {
  StageReflection r;
  r.stage = Stage(d.enum_byte(kMaxStage, "reflection stage"));
  r.entry_point = d.str();
  r.inputs = decode_variables(d, "stage input");
  r.outputs = decode_variables(d, "stage output");
  r.uniform_blocks = decode_blocks(d);
  r.resources = decode_resources(d);
  r.spec_constants = decode_spec_constants(d);
  r.property_bindings = decode_property_bindings(d);
  return r;
}

}  // namespace facet::codec
