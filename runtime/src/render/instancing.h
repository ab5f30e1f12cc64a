// GPU instancing as Unity does it for a material with instancing enabled:
// consecutive draws of one pass variant (built with INSTANCING_ON) become
// one instanced draw, each object's per-instance values (its matrices, the
// UNITY_INSTANCING_BUFFER properties) an element of the arrays of the
// variant's UnityInstancing_* blocks (stdlib/UnityInstancing.cginc).
#pragma once

#include <span>
#include <vector>

#include "facet/runtime/uniforms.h"
#include "render/draw_list.h"

namespace facet::runtime {

// The most objects one instanced draw holds: the stdlib's
// UNITY_INSTANCED_ARRAY_SIZE.
inline constexpr size_t kMaxInstances = 128;

// A UnityInstancing_* block: arrays of one struct per instance.
bool is_instanced_block(const UniformBlock& block);

// Merges each run of consecutive draws that can be one instanced draw: their
// variant has INSTANCING_ON, and they share the pass variant, light, mesh,
// fixed-function state, winding and every material value outside the
// per-instance arrays, and use no reflection probe. The run's first draw
// keeps its place, lists the run's objects in Draw::instances and the
// others' records in Draw::instance_records; at most kMaxInstances a draw.
// Returns the number of draws merged away.
size_t merge_instanced_draws(std::vector<Draw>& draws, const std::vector<ObjectState>& objects);

// An instanced block's bytes: element i of each struct array filled by
// member name from instances[i] (a member "<name>Array", as Unity names the
// built-ins there, from <name>), everything else 0.
void fill_instanced_block(std::span<std::byte> out, const UniformBlock& block,
                          const std::vector<UniformLayers>& instances);

}  // namespace facet::runtime
