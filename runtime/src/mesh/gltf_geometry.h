// The geometry half of the glTF loader: a parsed tinygltf model's default
// scene as facet meshes. tinygltf checks the JSON's shape and that buffers
// have their declared sizes, but not that an accessor stays inside its
// buffer view, that a buffer view stays inside its buffer, that indices
// stay below the vertex count, or that nodes form a tree; each of those is
// checked here before any byte is read.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "facet/runtime/gltf.h"

namespace tinygltf {
class Model;
}

namespace facet::runtime {

// The triangles of the model's default scene (scene 0 when none is named;
// every mesh once, untransformed, when the file has no scenes), grouped by
// material, in facet's space. `why` gets the first problem, with the glTF
// path of the value ("meshes[0].primitives[1].indices: ...").
std::optional<std::vector<GltfPart>> gltf_parts(const tinygltf::Model& model, const GltfLimits& limits,
                                                std::string& why);

}  // namespace facet::runtime
