// glTF 2.0 meshes (.gltf with its buffers, or one .glb) through tinygltf,
// in facet's space: every triangle primitive of the default scene, placed by
// its node's transform, with positions, normals, tangents, two UV sets and
// vertex colours, plus the PBR inputs of its materials. glTF is right-handed
// with UV (0, 0) at the image's top-left; facet is left-handed as in Unity
// with UV (0, 0) at the bottom-left, so X is negated, triangles are rewound,
// tangent handedness flips, and v becomes 1 - v (docs/scene-format.md,
// "glTF meshes").
//
// Nothing of the file is trusted: the GLB container, every accessor, buffer
// view, index, node reference and image URI is checked against what exists
// before it is read, and the first problem comes back as a diagnostic (mesh_invalid) that
// names the file and the glTF path of the bad value.
//
//   Diagnostics diags;
//   auto model = runtime::load_gltf("helmet.gltf", diags, {.materials = true});
//   if (!model) { fputs(render_text(diags, {}).c_str(), stderr); return 1; }
//   runtime::MeshData all = runtime::merge_gltf_parts(*model);
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "facet/runtime/mesh.h"

namespace facet::runtime {

// Limits on one glTF file (docs/scene-format.md, "glTF meshes").
struct GltfLimits {
  uint64_t max_file_bytes = uint64_t(1) << 30;  // the .gltf/.glb and each external buffer
  // Of the whole model, after node instancing: a vertex takes about 400
  // bytes across the loader's, the renderer's and the driver's copies, and
  // a primitive without normals gets a vertex a corner, so these keep a
  // model under 2 GB.
  uint64_t max_vertices = uint64_t(1) << 21;
  uint64_t max_triangle_corners = uint64_t(1) << 22;
  uint32_t max_node_depth = 64;  // of the node hierarchy
};

struct GltfOptions {
  // Read the materials too, and check that the image files their textures
  // name exist (next to the glTF file, as relative URIs). Off: materials are
  // left empty and images are not looked at.
  bool materials = false;
  GltfLimits limits;
};

// A texture of a material: an image file (a resolved path) and the UV set it reads.
struct GltfTexture {
  std::string path;
  int texcoord = 0;
};

// One glTF material's metallic-roughness inputs; factors are as in the file
// (colours linear).
struct GltfMaterial {
  std::string name;
  std::array<float, 4> base_color{1, 1, 1, 1};
  float metallic = 1, roughness = 1;
  std::array<float, 3> emissive{0, 0, 0};
  float normal_scale = 1;
  std::optional<GltfTexture> base_color_texture, metallic_roughness_texture, normal_texture, emissive_texture;
};

// The triangles of one material (-1: primitives without a material).
struct GltfPart {
  int material = -1;
  MeshData mesh;
};

struct GltfModel {
  std::vector<GltfPart> parts;            // one per material used, in order of first use; never empty
  std::vector<GltfMaterial> materials;    // all of the file's (when GltfOptions::materials)
  std::vector<std::string> buffer_files;  // the .bin files read beside it (for depfiles)
};

// True for a path ending in .gltf or .glb (any case).
bool is_gltf_path(const std::string& path);

// Reads a .gltf or .glb file; errors name the file ("<path>: meshes[0]...").
std::optional<GltfModel> load_gltf(const std::string& path, Diagnostics& diags, const GltfOptions& options = {});

// The parts as one mesh: all of them, or those of `material` only.
MeshData merge_gltf_parts(const GltfModel& model, std::optional<int> material = std::nullopt);

}  // namespace facet::runtime
