#include "facet/runtime/uniforms.h"

#include <cstdint>
#include <cstring>
#include <string_view>

namespace facet::runtime {
namespace {

struct Shape {
  enum Base { floating, signed_int, unsigned_int } base = floating;
  uint32_t rows = 1, columns = 1;  // "float4" is 1 x 4, "float4x3" 4 x 3
  bool matrix = false;
  bool known = false;
};

// "float", "half3", "int2", "uint", "bool", "float4x4", "min16float2" ...
Shape shape_of(std::string_view type) {
  Shape s;
  auto strip = [&](std::string_view prefix) {
    if (type.substr(0, prefix.size()) != prefix) return false;
    type.remove_prefix(prefix.size());
    return true;
  };
  if (strip("min16float") || strip("float") || strip("half") || strip("double") || strip("fixed")) s.base = Shape::floating;
  else if (strip("min16int") || strip("int")) s.base = Shape::signed_int;
  else if (strip("min16uint") || strip("uint") || strip("bool")) s.base = Shape::unsigned_int;
  else return s;
  s.known = true;
  if (type.empty()) return s;
  if (type.size() == 1 && type[0] >= '1' && type[0] <= '4') {
    s.columns = uint32_t(type[0] - '0');
    return s;
  }
  if (type.size() == 3 && type[1] == 'x' && type[0] >= '1' && type[0] <= '4' && type[2] >= '1' && type[2] <= '4') {
    s.rows = uint32_t(type[0] - '0');
    s.columns = uint32_t(type[2] - '0');
    s.matrix = true;
    return s;
  }
  s.known = false;
  return s;
}

void put(std::span<std::byte> out, size_t offset, Shape::Base base, float value) {
  if (offset + 4 > out.size()) return;  // a reflection inconsistency must not write past the block
  uint32_t bits = 0;
  if (base == Shape::floating) {
    std::memcpy(&bits, &value, 4);
  } else if (base == Shape::signed_int) {
    int32_t i = int32_t(value);
    std::memcpy(&bits, &i, 4);
  } else {
    bits = value > 0 ? uint32_t(value) : 0u;
  }
  std::memcpy(out.data() + offset, &bits, 4);
}

}  // namespace

void UniformValues::set_vector(const std::string& name, float x, float y, float z, float w) {
  values_[name] = {x, y, z, w};
}

void UniformValues::set_matrix(const std::string& name, const float* m) { values_[name].assign(m, m + 16); }

void UniformValues::assign(const UniformValues& other) {
  for (const auto& [name, value] : other.values_) values_[name] = value;
}

const std::vector<float>* UniformValues::find(const std::string& name) const {
  auto it = values_.find(name);
  return it == values_.end() ? nullptr : &it->second;
}

void write_member(std::span<std::byte> out, const BlockMember& member, const std::vector<float>& value) {
  Shape s = shape_of(member.type);
  if (!s.known) return;
  uint32_t elements = 1;
  for (uint32_t d : member.array_dims) elements *= d;
  const uint32_t source_stride = s.matrix ? 16 : 4;
  for (uint32_t e = 0; e < elements; ++e) {
    size_t base = member.offset + size_t(e) * member.array_stride;
    size_t src = size_t(e) * source_stride;
    if (src + (s.matrix ? 16 : 1) > value.size()) break;
    if (!s.matrix) {
      for (uint32_t c = 0; c < s.columns && src + c < value.size(); ++c) put(out, base + 4 * c, s.base, value[src + c]);
      continue;
    }
    // Element (r, c) of the R x C matrix is glm's [c][r] = value[src + 4c + r].
    for (uint32_t r = 0; r < s.rows; ++r) {
      for (uint32_t c = 0; c < s.columns; ++c) {
        size_t at = member.row_major ? base + size_t(r) * member.matrix_stride + 4 * c
                                     : base + size_t(c) * member.matrix_stride + 4 * r;
        put(out, at, s.base, value[src + 4 * c + r]);
      }
    }
  }
}

std::vector<std::string> fill_block(std::span<std::byte> out, const UniformBlock& block, const UniformLayers& layers) {
  std::memset(out.data(), 0, out.size());
  std::vector<std::string> missing;
  for (const BlockMember& member : block.members) {
    const std::vector<float>* value = nullptr;
    for (const UniformValues* layer : layers) {
      if (layer && (value = layer->find(member.name))) break;
    }
    if (value) write_member(out, member, *value);
    else missing.push_back(member.name);
  }
  return missing;
}

std::vector<MemberSource> members_from_layer(const UniformBlock& block, const UniformLayers& layers, size_t layer) {
  std::vector<MemberSource> out;
  for (size_t m = 0; m < block.members.size(); ++m) {
    for (size_t l = 0; l < layers.size(); ++l) {
      const std::vector<float>* value = layers[l] ? layers[l]->find(block.members[m].name) : nullptr;
      if (!value) continue;
      if (l == layer) out.push_back({m, value});
      break;
    }
  }
  return out;
}

void refill_members(std::span<std::byte> out, const UniformBlock& block, const std::vector<MemberSource>& members) {
  for (const MemberSource& m : members) write_member(out, block.members[m.member], *m.value);
}

}  // namespace facet::runtime
