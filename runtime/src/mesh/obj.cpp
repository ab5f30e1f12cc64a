// OBJ meshes through tinyobjloader: every shape of the file in one mesh,
// one vertex per face corner (no welding: OBJ indexes attributes apart).
// The text is checked first (mesh/obj_check.h), so that a hostile file gets
// a located error instead of an out-of-bounds read inside tinyobjloader.
#define TINYOBJLOADER_IMPLEMENTATION
#include <tiny_obj_loader.h>

#include <fmt/format.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <glm/glm.hpp>
#include <new>
#include <sstream>

#include "facet/runtime/mesh.h"
#include "mesh/obj_check.h"

namespace facet::runtime {
namespace {

// The whole file, refused before reading when it is over the size limit.
std::optional<std::string> read_text(const std::string& path, uint64_t max_bytes, std::string& error) {
  std::error_code ec;
  uint64_t size = std::filesystem::file_size(path, ec);
  if (ec) {
    error = fmt::format("{}: cannot read the OBJ file ({})", path, ec.message());
    return std::nullopt;
  }
  if (size > max_bytes) {
    error = fmt::format("{}: the file has {} bytes, more than the {} an OBJ mesh may have", path, size, max_bytes);
    return std::nullopt;
  }
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  if (!in && !in.eof()) {
    error = fmt::format("{}: cannot read the OBJ file", path);
    return std::nullopt;
  }
  return std::move(text).str();
}

// One attribute of a corner, or nullopt when its index is outside the data
// (never after check_obj_text; kept so that a disagreement with
// tinyobjloader is an error, not a wild read).
template <size_t N>
std::optional<std::array<float, N>> attribute(const std::vector<tinyobj::real_t>& data, int index) {
  if (index < 0 || size_t(index) >= data.size() / N) return std::nullopt;
  std::array<float, N> out;
  for (size_t k = 0; k < N; ++k) out[k] = data[N * size_t(index) + k];
  return out;
}

glm::vec3 vec3_of(const std::array<float, 3>& a) { return {a[0], a[1], a[2]}; }

// Flat normals from the faces; a degenerate or overflowing face gets +Y.
void flat_normals(MeshData& mesh) {
  for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
    glm::vec3 a = vec3_of(mesh.vertices[t].position), b = vec3_of(mesh.vertices[t + 1].position);
    glm::vec3 c = vec3_of(mesh.vertices[t + 2].position);
    glm::vec3 n = glm::cross(b - a, c - a);
    float length2 = glm::dot(n, n);
    n = length2 > 0 && std::isfinite(length2) ? glm::normalize(n) : glm::vec3(0, 1, 0);
    for (size_t k = 0; k < 3; ++k) mesh.vertices[t + k].normal = {n.x, n.y, n.z};
  }
}

std::optional<MeshData> to_mesh(const tinyobj::ObjReader& reader, const std::string& path, std::string& error) {
  const tinyobj::attrib_t& attrib = reader.GetAttrib();
  MeshData mesh;
  bool has_normals = true;
  for (const tinyobj::shape_t& shape : reader.GetShapes()) {
    for (const tinyobj::index_t& index : shape.mesh.indices) {
      Vertex v;
      std::optional<std::array<float, 3>> position = attribute<3>(attrib.vertices, index.vertex_index);
      if (!position) {
        error = fmt::format("{}: face index {} is outside the file's vertices", path, index.vertex_index + 1);
        return std::nullopt;
      }
      v.position = *position;
      if (auto normal = attribute<3>(attrib.normals, index.normal_index)) {
        v.normal = *normal;
      } else {
        has_normals = false;
      }
      if (auto uv = attribute<2>(attrib.texcoords, index.texcoord_index)) {
        v.uv0 = *uv;
        v.uv1 = v.uv0;
      }
      mesh.indices.push_back(uint32_t(mesh.vertices.size()));
      mesh.vertices.push_back(v);
    }
  }
  if (!has_normals) flat_normals(mesh);
  return mesh;
}

// Coordinates that each fit a float may still sum past one in the bounds
// (their centre and radius), which the camera and shadow fitting use.
bool bounds_are_finite(const MeshData& mesh) {
  Bounds bounds = mesh_bounds(mesh);
  return std::isfinite(bounds.radius) && std::isfinite(bounds.center[0]) && std::isfinite(bounds.center[1]) &&
         std::isfinite(bounds.center[2]);
}

std::optional<MeshData> parse_obj(const std::string& text, const std::string& path, std::string& error) {
  tinyobj::ObjReader reader;
  tinyobj::ObjReaderConfig config;
  config.triangulate = true;
  if (!reader.ParseFromString(text, "", config)) {
    error = path + ": " + (reader.Error().empty() ? "cannot read the OBJ file" : reader.Error());
    while (!error.empty() && error.back() == '\n') error.pop_back();
    return std::nullopt;
  }
  std::optional<MeshData> mesh = to_mesh(reader, path, error);
  if (!mesh) return std::nullopt;
  if (mesh->indices.empty()) {
    error = path + ": the OBJ file has no faces (an empty mesh)";
    return std::nullopt;
  }
  if (!bounds_are_finite(*mesh)) {
    error = path + ": the mesh is too large (its bounding sphere does not fit a float)";
    return std::nullopt;
  }
  compute_tangents(*mesh);
  return mesh;
}

std::optional<MeshData> read_obj(const std::string& path, std::string& error) {
  ObjLimits limits;
  std::optional<std::string> text = read_text(path, limits.max_file_bytes, error);
  if (!text) return std::nullopt;
  if (std::optional<ObjProblem> problem = check_obj_text(*text, limits)) {
    error = problem->line ? fmt::format("{}:{}:{}: {}", path, problem->line, problem->column, problem->why)
                          : fmt::format("{}: {}", path, problem->why);
    return std::nullopt;
  }
  // The limits keep a checked mesh to a few GiB; a machine with less memory
  // gets an error here rather than an abort.
  try {
    return parse_obj(*text, path, error);
  } catch (const std::bad_alloc&) {
    error = path + ": not enough memory to read the OBJ mesh";
    return std::nullopt;
  }
}

}  // namespace

std::optional<MeshData> load_obj(const std::string& path, Diagnostics& diags) {
  std::string why;
  std::optional<MeshData> mesh = read_obj(path, why);
  if (!mesh) diags.add(DiagId::mesh_invalid, SourceSpan{}, std::move(why));
  return mesh;
}

}  // namespace facet::runtime
