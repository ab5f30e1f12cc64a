// OBJ meshes through tinyobjloader: every shape of the file in one mesh,
// one vertex per face corner (no welding: OBJ indexes attributes apart).
#define TINYOBJLOADER_IMPLEMENTATION
#include <tiny_obj_loader.h>

#include <glm/glm.hpp>

#include "facet/runtime/mesh.h"

namespace facet::runtime {
namespace {

glm::vec3 position_of(const tinyobj::attrib_t& attrib, int index) {
  return {attrib.vertices[3 * index], attrib.vertices[3 * index + 1], attrib.vertices[3 * index + 2]};
}

}  // namespace

std::optional<MeshData> load_obj(const std::string& path, MeshError& error) {
  tinyobj::ObjReader reader;
  tinyobj::ObjReaderConfig config;
  config.triangulate = true;
  if (!reader.ParseFromFile(path, config)) {
    error.message = path + ": " + (reader.Error().empty() ? "cannot read the OBJ file" : reader.Error());
    while (!error.message.empty() && error.message.back() == '\n') error.message.pop_back();
    return std::nullopt;
  }
  const tinyobj::attrib_t& attrib = reader.GetAttrib();
  MeshData mesh;
  bool has_normals = true;
  for (const tinyobj::shape_t& shape : reader.GetShapes()) {
    for (const tinyobj::index_t& index : shape.mesh.indices) {
      Vertex v;
      glm::vec3 p = position_of(attrib, index.vertex_index);
      v.position = {p.x, p.y, p.z};
      if (index.normal_index >= 0) {
        v.normal = {attrib.normals[3 * index.normal_index], attrib.normals[3 * index.normal_index + 1],
                    attrib.normals[3 * index.normal_index + 2]};
      } else {
        has_normals = false;
      }
      if (index.texcoord_index >= 0) {
        v.uv0 = {attrib.texcoords[2 * index.texcoord_index], attrib.texcoords[2 * index.texcoord_index + 1]};
        v.uv1 = v.uv0;
      }
      mesh.indices.push_back(uint32_t(mesh.vertices.size()));
      mesh.vertices.push_back(v);
    }
  }
  if (mesh.indices.empty()) {
    error.message = path + ": the OBJ file has no faces";
    return std::nullopt;
  }
  if (!has_normals) {  // flat normals from the faces
    for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
      glm::vec3 a(mesh.vertices[t].position[0], mesh.vertices[t].position[1], mesh.vertices[t].position[2]);
      glm::vec3 b(mesh.vertices[t + 1].position[0], mesh.vertices[t + 1].position[1], mesh.vertices[t + 1].position[2]);
      glm::vec3 c(mesh.vertices[t + 2].position[0], mesh.vertices[t + 2].position[1], mesh.vertices[t + 2].position[2]);
      glm::vec3 n = glm::cross(b - a, c - a);
      n = glm::dot(n, n) > 0 ? glm::normalize(n) : glm::vec3(0, 1, 0);
      for (size_t k = 0; k < 3; ++k) mesh.vertices[t + k].normal = {n.x, n.y, n.z};
    }
  }
  compute_tangents(mesh);
  return mesh;
}

}  // namespace facet::runtime
