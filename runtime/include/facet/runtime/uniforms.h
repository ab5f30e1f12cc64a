// Uniform values by name and the writer that lays them into a block by its
// reflection (offsets, array and matrix strides, row_major), so that no
// layout is written by hand on the C++ side.
#pragma once

#include <array>
#include <cstddef>
#include <span>
#include <string>
#include <unordered_map>
#include <vector>

#include "facet/reflection.h"

namespace facet::runtime {

// A value is a list of elements; a non-matrix element is 4 floats (a
// scalar or a short vector in the first components), a matrix element 16
// floats in glm's column-major order. Arrays put their elements back to back.
class UniformValues {
 public:
  void set_vector(const std::string& name, float x, float y = 0, float z = 0, float w = 0);
  void set_vector(const std::string& name, const std::array<float, 4>& v) { set_vector(name, v[0], v[1], v[2], v[3]); }
  void set_matrix(const std::string& name, const float* column_major16);
  void set_elements(const std::string& name, std::vector<float> floats) { values_[name] = std::move(floats); }
  const std::vector<float>* find(const std::string& name) const;
  // Sets every value of `other`, keeping this table's entries: pointers from
  // find() stay valid (a renderer updates its frame values this way).
  void assign(const UniformValues& other);

 private:
  std::unordered_map<std::string, std::vector<float>> values_;
};

// Looks a name up in each table in order; the first that has it wins.
using UniformLayers = std::vector<const UniformValues*>;

// The block's bytes: every member found in `layers` written at its offset,
// everything else 0. Names are matched whole ("unity_ObjectToWorld");
// struct members are left 0. Returns the members that nothing filled.
std::vector<std::string> fill_block(std::span<std::byte> out, const UniformBlock& block, const UniformLayers& layers);

// A member of a block (index into block.members) and its value in a layer.
struct MemberSource {
  size_t member = 0;
  const std::vector<float>* value = nullptr;
};

// The members whose value comes from layers[layer] (the first layer that
// has them), and rewriting just those: a renderer refills the per-frame
// members of a kept block this way, with no lookup by name. The pointers
// stay valid while that layer lives and is only updated through assign().
std::vector<MemberSource> members_from_layer(const UniformBlock& block, const UniformLayers& layers, size_t layer);
void refill_members(std::span<std::byte> out, const UniformBlock& block, const std::vector<MemberSource>& members);

// One member's bytes from one value (exposed for tests).
void write_member(std::span<std::byte> out, const BlockMember& member, const std::vector<float>& value);

}  // namespace facet::runtime
