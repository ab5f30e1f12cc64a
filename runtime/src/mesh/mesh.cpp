#include "facet/runtime/mesh.h"

#include <glm/glm.hpp>
#include <glm/gtc/constants.hpp>

#include <cmath>
#include <functional>

namespace facet::runtime {
namespace {

glm::vec3 vec3_of(const std::array<float, 3>& a) { return {a[0], a[1], a[2]}; }
std::array<float, 3> array_of(glm::vec3 v) { return {v.x, v.y, v.z}; }

Vertex make_vertex(glm::vec3 position, glm::vec3 normal, glm::vec2 uv) {
  Vertex v;
  v.position = array_of(position);
  v.normal = array_of(glm::normalize(normal));
  v.uv0 = {uv.x, uv.y};
  v.uv1 = v.uv0;
  glm::vec3 c = glm::normalize(normal) * 0.5f + 0.5f;
  v.color = {c.x, c.y, c.z, 1};
  return v;
}

// Adds triangle (a, b, c), swapped where needed so that its face normal
// agrees with the vertex normals; degenerate triangles (sphere poles) are dropped.
void add_triangle(MeshData& mesh, uint32_t a, uint32_t b, uint32_t c) {
  glm::vec3 pa = vec3_of(mesh.vertices[a].position), pb = vec3_of(mesh.vertices[b].position);
  glm::vec3 pc = vec3_of(mesh.vertices[c].position);
  glm::vec3 face = glm::cross(pb - pa, pc - pa);
  if (glm::dot(face, face) < 1e-14f) return;
  glm::vec3 n = vec3_of(mesh.vertices[a].normal) + vec3_of(mesh.vertices[b].normal) + vec3_of(mesh.vertices[c].normal);
  if (glm::dot(face, n) < 0) std::swap(b, c);
  mesh.indices.insert(mesh.indices.end(), {a, b, c});
}

// A (columns+1) x (rows+1) vertex grid over a parametric surface, u and v in 0..1.
void add_grid(MeshData& mesh, int columns, int rows,
              const std::function<void(float u, float v, glm::vec3& p, glm::vec3& n)>& surface) {
  uint32_t base = uint32_t(mesh.vertices.size());
  for (int j = 0; j <= rows; ++j) {
    for (int i = 0; i <= columns; ++i) {
      float u = float(i) / float(columns), v = float(j) / float(rows);
      glm::vec3 p, n;
      surface(u, v, p, n);
      mesh.vertices.push_back(make_vertex(p, n, {u, v}));
    }
  }
  auto at = [&](int i, int j) { return base + uint32_t(j * (columns + 1) + i); };
  for (int j = 0; j < rows; ++j) {
    for (int i = 0; i < columns; ++i) {
      add_triangle(mesh, at(i, j), at(i + 1, j), at(i + 1, j + 1));
      add_triangle(mesh, at(i, j), at(i + 1, j + 1), at(i, j + 1));
    }
  }
}

MeshData make_sphere() {
  MeshData mesh;
  add_grid(mesh, 48, 24, [](float u, float v, glm::vec3& p, glm::vec3& n) {
    float phi = u * glm::two_pi<float>(), theta = v * glm::pi<float>();
    n = {-std::sin(theta) * std::cos(phi), -std::cos(theta), -std::sin(theta) * std::sin(phi)};
    p = n * 0.5f;
  });
  return mesh;
}

MeshData make_torus() {
  MeshData mesh;
  add_grid(mesh, 48, 24, [](float u, float v, glm::vec3& p, glm::vec3& n) {
    float phi = u * glm::two_pi<float>(), theta = v * glm::two_pi<float>();
    glm::vec3 ring{std::cos(phi), 0, std::sin(phi)};
    n = ring * std::cos(theta) + glm::vec3(0, std::sin(theta), 0);
    p = ring * 0.35f + n * 0.15f;
  });
  return mesh;
}

MeshData make_cube() {
  MeshData mesh;
  for (int axis = 0; axis < 3; ++axis) {
    for (float side : {-1.0f, 1.0f}) {
      glm::vec3 n(0), du(0), dv(0);
      n[axis] = side;
      du[(axis + 1) % 3] = 1;
      dv[(axis + 2) % 3] = 1;
      add_grid(mesh, 1, 1, [&](float u, float v, glm::vec3& p, glm::vec3& normal) {
        p = n * 0.5f + du * (u - 0.5f) + dv * (v - 0.5f);
        normal = n;
      });
    }
  }
  return mesh;
}

MeshData make_plane() {
  MeshData mesh;
  add_grid(mesh, 10, 10, [](float u, float v, glm::vec3& p, glm::vec3& n) {
    p = {(u - 0.5f) * 10, 0, (v - 0.5f) * 10};
    n = {0, 1, 0};
  });
  return mesh;
}

MeshData make_quad() {
  MeshData mesh;
  add_grid(mesh, 1, 1, [](float u, float v, glm::vec3& p, glm::vec3& n) {
    p = {u - 0.5f, v - 0.5f, 0};
    n = {0, 0, -1};
  });
  return mesh;
}

}  // namespace

const std::vector<std::string>& builtin_mesh_names() {
  static const std::vector<std::string> names = {"cube", "plane", "quad", "sphere", "torus"};
  return names;
}

std::optional<MeshData> builtin_mesh(std::string_view name) {
  MeshData mesh;
  if (name == "cube") mesh = make_cube();
  else if (name == "sphere") mesh = make_sphere();
  else if (name == "plane") mesh = make_plane();
  else if (name == "quad") mesh = make_quad();
  else if (name == "torus") mesh = make_torus();
  else return std::nullopt;
  compute_tangents(mesh);
  return mesh;
}

void compute_tangents(MeshData& mesh) {
  std::vector<glm::vec3> tangents(mesh.vertices.size(), glm::vec3(0)), bitangents(mesh.vertices.size(), glm::vec3(0));
  for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
    const Vertex& a = mesh.vertices[mesh.indices[t]];
    const Vertex& b = mesh.vertices[mesh.indices[t + 1]];
    const Vertex& c = mesh.vertices[mesh.indices[t + 2]];
    glm::vec3 e1 = vec3_of(b.position) - vec3_of(a.position), e2 = vec3_of(c.position) - vec3_of(a.position);
    glm::vec2 d1{b.uv0[0] - a.uv0[0], b.uv0[1] - a.uv0[1]}, d2{c.uv0[0] - a.uv0[0], c.uv0[1] - a.uv0[1]};
    float det = d1.x * d2.y - d2.x * d1.y;
    if (std::abs(det) < 1e-12f) continue;
    glm::vec3 tangent = (e1 * d2.y - e2 * d1.y) / det, bitangent = (e2 * d1.x - e1 * d2.x) / det;
    for (size_t k = 0; k < 3; ++k) {
      tangents[mesh.indices[t + k]] += tangent;
      bitangents[mesh.indices[t + k]] += bitangent;
    }
  }
  for (size_t i = 0; i < mesh.vertices.size(); ++i) {
    glm::vec3 n = vec3_of(mesh.vertices[i].normal);
    glm::vec3 t = tangents[i] - n * glm::dot(n, tangents[i]);
    // (written as !(>=) so that NaN, from UV gradients that overflow, falls back too)
    if (!(glm::dot(t, t) >= 1e-12f) || !std::isfinite(glm::dot(t, t))) {  // no UV gradient: any vector orthogonal to n
      t = glm::cross(std::abs(n.y) < 0.99f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0), n);
    }
    if (!(glm::dot(t, t) >= 1e-12f) || !std::isfinite(glm::dot(t, t))) t = glm::vec3(1, 0, 0);  // a zero normal (vn 0 0 0)
    t = glm::normalize(t);
    float w = glm::dot(glm::cross(n, t), bitangents[i]) < 0 ? -1.0f : 1.0f;
    mesh.vertices[i].tangent = {t.x, t.y, t.z, w};
  }
}

Bounds mesh_bounds(const MeshData& mesh) {
  Bounds bounds;
  if (mesh.vertices.empty()) return bounds;
  glm::vec3 lo = vec3_of(mesh.vertices[0].position), hi = lo;
  for (const Vertex& v : mesh.vertices) {
    lo = glm::min(lo, vec3_of(v.position));
    hi = glm::max(hi, vec3_of(v.position));
  }
  glm::vec3 center = (lo + hi) * 0.5f;
  float radius = 0;
  for (const Vertex& v : mesh.vertices) radius = std::max(radius, glm::length(vec3_of(v.position) - center));
  bounds.center = array_of(center);
  bounds.radius = radius;
  return bounds;
}

}  // namespace facet::runtime
