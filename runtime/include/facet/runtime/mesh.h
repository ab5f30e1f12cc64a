// Meshes on the CPU: built-in shapes with Unity's sizes and orientation,
// OBJ files through tinyobjloader, and tangents from UVs. World space is
// left-handed and Y-up as in Unity, and triangles are wound so that
// cross(b - a, c - a) points out of the surface (clockwise seen from the
// front, Unity's front faces).
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "facet/diagnostics.h"

namespace facet::runtime {

// One interleaved vertex. `zero` feeds stage inputs whose semantic has no
// data here (TEXCOORD2..7, BLENDWEIGHTS, ...): they read 0.
struct Vertex {
  std::array<float, 3> position{};
  std::array<float, 3> normal{};
  std::array<float, 4> tangent{1, 0, 0, 1};  // xyz, w = handedness of the bitangent
  std::array<float, 2> uv0{};
  std::array<float, 2> uv1{};
  std::array<float, 4> color{1, 1, 1, 1};
  std::array<float, 4> zero{};
};

struct MeshData {
  std::vector<Vertex> vertices;
  std::vector<uint32_t> indices;  // triangle list
};

struct Bounds {
  std::array<float, 3> center{};
  float radius = 0;  // of a sphere around every vertex
};

// Unity's primitives: "cube" (1 unit), "sphere" (radius 0.5), "plane"
// (10 x 10 in XZ, facing +Y), "quad" (1 x 1 in XY, facing -Z) and a "torus"
// (radii 0.35 and 0.15 in XZ). Colours are the normal mapped to 0..1, so
// that vertex-colour shaders have something to show; uv1 = uv0.
std::optional<MeshData> builtin_mesh(std::string_view name);
const std::vector<std::string>& builtin_mesh_names();

// An OBJ file (triangulated; normals computed when absent, UVs 0 when
// absent). An error (mesh_invalid) names the file, and the line and column
// of a bad line.
std::optional<MeshData> load_obj(const std::string& path, Diagnostics& diags);

// Per-vertex tangents from positions, normals and uv0 (Lengyel's method),
// orthogonalised against the normal, w = +-1.
void compute_tangents(MeshData& mesh);

Bounds mesh_bounds(const MeshData& mesh);

}  // namespace facet::runtime
