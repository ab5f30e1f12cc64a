#include "mesh/gltf_geometry.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <map>

#include "mesh/tinygltf.h"

namespace facet::runtime {
namespace {

// Thrown inside this file only, caught by gltf_parts: the checks nest
// deeply and an exception keeps each of them one line.
struct Bad {
  std::string why;
};

[[noreturn]] void fail(const std::string& where, const std::string& what) { throw Bad{where + ": " + what}; }

const char* type_name(int type) {
  switch (type) {
    case TINYGLTF_TYPE_SCALAR: return "SCALAR";
    case TINYGLTF_TYPE_VEC2: return "VEC2";
    case TINYGLTF_TYPE_VEC3: return "VEC3";
    case TINYGLTF_TYPE_VEC4: return "VEC4";
    default: return "a matrix or unknown type";
  }
}

int components_of(int type) {
  switch (type) {
    case TINYGLTF_TYPE_SCALAR: return 1;
    case TINYGLTF_TYPE_VEC2: return 2;
    case TINYGLTF_TYPE_VEC3: return 3;
    case TINYGLTF_TYPE_VEC4: return 4;
    default: return 0;
  }
}

int component_bytes(int component_type) {
  switch (component_type) {
    case TINYGLTF_COMPONENT_TYPE_BYTE:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return 1;
    case TINYGLTF_COMPONENT_TYPE_SHORT:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return 2;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
    case TINYGLTF_COMPONENT_TYPE_FLOAT: return 4;
    default: return 0;
  }
}

// What one attribute may be: its element types and component types
// (normalized integers where glTF allows them).
struct Shape {
  std::vector<int> types;
  bool integers = false;  // unsigned byte/short, normalized (UVs, colours)
  bool indices = false;   // unsigned byte/short/int, not normalized
};

// An accessor checked against its buffer view and buffer: every element it
// declares lies inside the data.
struct View {
  const unsigned char* data = nullptr;
  size_t stride = 0, count = 0;
  int components = 0, component_type = 0;
  std::string where;  // "accessors[3]", for messages about its values

  double component(size_t element, int k) const {
    const unsigned char* p = data + element * stride + size_t(k) * size_t(component_bytes(component_type));
    switch (component_type) {
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return double(*p);
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
        uint16_t v;
        std::memcpy(&v, p, 2);
        return double(v);
      }
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: {
        uint32_t v;
        std::memcpy(&v, p, 4);
        return double(v);
      }
      default: {
        float v;
        std::memcpy(&v, p, 4);
        return double(v);
      }
    }
  }

  // Component k of `element` as a float: normalized integers scaled to
  // 0..1, floats checked to be finite.
  float number(size_t element, int k) const {
    double v = component(element, k);
    if (component_type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE) return float(v / 255.0);
    if (component_type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT) return float(v / 65535.0);
    if (!std::isfinite(v)) fail(where, fmt::format("element {} holds a value that is not a finite number", element));
    return float(v);
  }
};

bool allowed_component(const Shape& shape, int component_type, bool normalized) {
  if (shape.indices) {
    return !normalized && (component_type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE ||
                           component_type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT ||
                           component_type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT);
  }
  if (component_type == TINYGLTF_COMPONENT_TYPE_FLOAT) return true;
  return shape.integers && normalized &&
         (component_type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE ||
          component_type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT);
}

std::string allowed_list(const Shape& shape) {
  std::string types;
  for (int t : shape.types) types += std::string(types.empty() ? "" : " or ") + type_name(t);
  if (shape.indices) return "SCALAR of unsigned byte, short or int";
  return types + (shape.integers ? " of float or normalized unsigned byte or short" : " of float");
}

struct Context {
  const tinygltf::Model& model;
  const GltfLimits& limits;
  uint64_t vertices = 0, corners = 0;  // of the whole model so far
};

// The buffer view of accessor `a`, checked against its buffer.
const tinygltf::BufferView& buffer_view(const Context& c, const tinygltf::Accessor& a, const std::string& at) {
  if (a.sparse.isSparse) fail(at, "sparse accessors are not supported");
  if (a.bufferView < 0) fail(at, "the accessor has no buffer view (zero-filled accessors are not supported)");
  if (size_t(a.bufferView) >= c.model.bufferViews.size()) {
    fail(at + ".bufferView",
         fmt::format("buffer view {} does not exist (the file has {})", a.bufferView, c.model.bufferViews.size()));
  }
  const tinygltf::BufferView& bv = c.model.bufferViews[size_t(a.bufferView)];
  std::string bv_at = fmt::format("bufferViews[{}]", a.bufferView);
  if (bv.buffer < 0 || size_t(bv.buffer) >= c.model.buffers.size()) {
    fail(bv_at + ".buffer",
         fmt::format("buffer {} does not exist (the file has {})", bv.buffer, c.model.buffers.size()));
  }
  size_t size = c.model.buffers[size_t(bv.buffer)].data.size();
  if (bv.byteOffset > size || bv.byteLength > size - bv.byteOffset) {
    fail(bv_at, fmt::format("bytes {} to {} lie past the end of buffer {}, which has {} bytes", bv.byteOffset,
                            double(bv.byteOffset) + double(bv.byteLength), bv.buffer, size));
  }
  if (bv.byteStride != 0 && (bv.byteStride < 4 || bv.byteStride > 252 || bv.byteStride % 4 != 0)) {
    fail(bv_at + ".byteStride",
         fmt::format("{} is not a stride glTF allows (a multiple of 4 from 4 to 252)", bv.byteStride));
  }
  return bv;
}

View checked_view(const Context& c, int index, const Shape& shape) {
  const tinygltf::Accessor& a = c.model.accessors[size_t(index)];
  std::string at = fmt::format("accessors[{}]", index);
  bool type_ok = std::find(shape.types.begin(), shape.types.end(), a.type) != shape.types.end();
  if (!type_ok || !allowed_component(shape, a.componentType, a.normalized)) {
    fail(at, fmt::format("the accessor is {} of component type {}{}; expected {}", type_name(a.type), a.componentType,
                         a.normalized ? " (normalized)" : "", allowed_list(shape)));
  }
  if (a.count == 0) fail(at, "the accessor has no elements");
  if (a.count > c.limits.max_triangle_corners) {
    fail(at, fmt::format("{} elements, more than the {} a glTF accessor may have here", a.count,
                         c.limits.max_triangle_corners));
  }
  const tinygltf::BufferView& bv = buffer_view(c, a, at);
  size_t element = size_t(components_of(a.type)) * size_t(component_bytes(a.componentType));
  size_t stride = bv.byteStride ? bv.byteStride : element;
  if (stride < element)
    fail(at, fmt::format("its elements of {} bytes do not fit the buffer view's stride of {}", element, stride));
  // count <= 2^26 and stride <= 252: the sum cannot overflow.
  uint64_t end = uint64_t(stride) * (a.count - 1) + element;
  if (a.byteOffset > bv.byteLength || end > bv.byteLength - a.byteOffset) {
    fail(at, fmt::format("its {} elements end at byte {} of buffer view {}, which has {} bytes", a.count,
                         double(a.byteOffset) + double(end), a.bufferView, bv.byteLength));
  }
  View v;
  v.data = c.model.buffers[size_t(bv.buffer)].data.data() + bv.byteOffset + a.byteOffset;
  v.stride = stride;
  v.count = a.count;
  v.components = components_of(a.type);
  v.component_type = a.componentType;
  v.where = at;
  return v;
}

// Accessor `index` for a use (`use` names it: "meshes[0].primitives[0].attributes.POSITION"),
// which prefixes every message.
View view(const Context& c, int index, const std::string& use, const Shape& shape) {
  if (index < 0 || size_t(index) >= c.model.accessors.size()) {
    fail(use, fmt::format("accessor {} does not exist (the file has {})", index, c.model.accessors.size()));
  }
  try {
    return checked_view(c, index, shape);
  } catch (const Bad& bad) {
    throw Bad{use + ": " + bad.why};
  }
}

std::optional<View> attribute(const Context& c, const tinygltf::Primitive& p, const char* name,
                              const std::string& where, const Shape& shape, size_t count) {
  auto it = p.attributes.find(name);
  if (it == p.attributes.end()) return std::nullopt;
  std::string use = where + ".attributes." + name;
  View v = view(c, it->second, use, shape);
  if (v.count != count) {
    fail(use, fmt::format("{} has {} elements, POSITION has {} (every attribute needs one per vertex)", v.where,
                          v.count, count));
  }
  return v;
}

// Where a primitive's vertices go: the node's world matrix, followed by
// glTF's right-handed space to facet's left-handed one (x negated).
struct Placement {
  glm::dmat4 world{1.0};
  glm::dmat3 linear{1.0}, normals{1.0};  // facet-space linear part and its inverse transpose
  double det = 1;                        // of the glTF-space linear part
};

Placement placement(const glm::dmat4& world) {
  Placement p;
  glm::dmat4 mirror(1.0);
  mirror[0][0] = -1;
  p.world = mirror * world;
  p.det = glm::determinant(glm::dmat3(world));
  p.linear = glm::dmat3(p.world);
  p.normals = glm::transpose(glm::inverse(p.linear));
  return p;
}

std::array<float, 3> normalized(glm::dvec3 v, std::array<float, 3> fallback) {
  double length2 = glm::dot(v, v);
  if (!(length2 > 0) || !std::isfinite(length2)) return fallback;
  v /= std::sqrt(length2);
  return {float(v.x), float(v.y), float(v.z)};
}

Vertex vertex(const Placement& at, size_t i, const View& position, const std::optional<View>& normal,
              const std::optional<View>& tangent, const std::optional<View>& uv0, const std::optional<View>& uv1,
              const std::optional<View>& color) {
  Vertex v;
  glm::dvec4 p = at.world * glm::dvec4(position.number(i, 0), position.number(i, 1), position.number(i, 2), 1.0);
  v.position = {float(p.x), float(p.y), float(p.z)};
  if (normal) {
    glm::dvec3 n(normal->number(i, 0), normal->number(i, 1), normal->number(i, 2));
    v.normal = normalized(at.normals * n, {0, 1, 0});
  }
  if (tangent) {
    glm::dvec3 t(tangent->number(i, 0), tangent->number(i, 1), tangent->number(i, 2));
    std::array<float, 3> xyz = normalized(at.linear * t, {1, 0, 0});
    // The mirror flips the bitangent's side, and so does a mirroring node.
    float w = tangent->number(i, 3) < 0 ? -1.0f : 1.0f;
    v.tangent = {xyz[0], xyz[1], xyz[2], at.det > 0 ? -w : w};
  }
  if (uv0) v.uv0 = {uv0->number(i, 0), 1 - uv0->number(i, 1)};
  v.uv1 = uv1 ? std::array<float, 2>{uv1->number(i, 0), 1 - uv1->number(i, 1)} : v.uv0;
  if (color)
    v.color = {color->number(i, 0), color->number(i, 1), color->number(i, 2),
               color->components == 4 ? color->number(i, 3) : 1.0f};
  return v;
}

// A strip's or fan's corners as a triangle list, in glTF's order (the
// winding of each triangle as the spec defines it).
std::vector<uint32_t> triangle_list(const std::vector<uint32_t>& in, int mode) {
  std::vector<uint32_t> out;
  for (size_t i = 0; i + 2 < in.size(); ++i) {
    if (mode == TINYGLTF_MODE_TRIANGLE_STRIP) {
      out.insert(out.end(), {in[i], in[i + 1 + i % 2], in[i + 2 - i % 2]});
    } else {
      out.insert(out.end(), {in[i + 1], in[i + 2], in[0]});
    }
  }
  return out;
}

// The primitive's triangle corners: its indices, checked against the
// vertex count, or 0..count-1; strips and fans become lists.
std::vector<uint32_t> corners(Context& c, const tinygltf::Primitive& p, const std::string& where, size_t vertices) {
  std::vector<uint32_t> out;
  if (p.indices < 0) {
    for (size_t i = 0; i < vertices; ++i) out.push_back(uint32_t(i));
  } else {
    View v = view(c, p.indices, where + ".indices", Shape{{TINYGLTF_TYPE_SCALAR}, false, true});
    out.reserve(v.count);
    for (size_t i = 0; i < v.count; ++i) {
      double index = v.component(i, 0);
      if (index >= double(vertices)) {
        fail(where + ".indices", fmt::format("index {} (element {} of {}) is past the {} vertices of the primitive",
                                             index, i, v.where, vertices));
      }
      out.push_back(uint32_t(index));
    }
  }
  bool list = p.mode == TINYGLTF_MODE_TRIANGLES || p.mode == -1;
  if (list && out.size() % 3 != 0) {
    fail(where, fmt::format("{} corners are not whole triangles (a multiple of 3)", out.size()));
  }
  if (!list) {
    if (out.size() < 3) fail(where, fmt::format("a triangle strip or fan of {} corners has no triangle", out.size()));
    // Checked before the list is built: a strip of n corners is 3(n - 2) of them.
    if (3 * out.size() > c.limits.max_triangle_corners) {
      fail(where, fmt::format("the model has more than {} triangle corners (the limit of one glTF mesh)",
                              c.limits.max_triangle_corners));
    }
    out = triangle_list(out, p.mode);
  }
  c.corners += out.size();
  if (c.corners > c.limits.max_triangle_corners) {
    fail(where, fmt::format("the model has more than {} triangle corners (the limit of one glTF mesh)",
                            c.limits.max_triangle_corners));
  }
  return out;
}

// Flat normals for a primitive without NORMAL: one vertex per corner, the
// face normal of facet's winding.
void flat_normals(MeshData& mesh) {
  MeshData flat;
  for (uint32_t index : mesh.indices) flat.vertices.push_back(mesh.vertices[index]);
  for (size_t t = 0; t + 2 < flat.vertices.size(); t += 3) {
    auto p = [&](size_t k) {
      const auto& a = flat.vertices[t + k].position;
      return glm::dvec3(a[0], a[1], a[2]);
    };
    std::array<float, 3> n = normalized(glm::cross(p(1) - p(0), p(2) - p(0)), {0, 1, 0});
    for (size_t k = 0; k < 3; ++k) {
      flat.vertices[t + k].normal = n;
      flat.indices.push_back(uint32_t(t + k));
    }
  }
  mesh = std::move(flat);
}

MeshData primitive_mesh(Context& c, const tinygltf::Primitive& p, const std::string& where, const Placement& at) {
  if (p.mode != TINYGLTF_MODE_TRIANGLES && p.mode != TINYGLTF_MODE_TRIANGLE_STRIP &&
      p.mode != TINYGLTF_MODE_TRIANGLE_FAN && p.mode != -1) {
    fail(where + ".mode",
         fmt::format("primitive mode {} is not supported (only triangles: lists, strips and fans, modes 4 to 6)",
                     p.mode));
  }
  auto it = p.attributes.find("POSITION");
  if (it == p.attributes.end()) fail(where + ".attributes", "the primitive has no POSITION");
  View position = view(c, it->second, where + ".attributes.POSITION", Shape{{TINYGLTF_TYPE_VEC3}});
  size_t n = position.count;
  c.vertices += n;
  if (c.vertices > c.limits.max_vertices) {
    fail(where, fmt::format("the model has more than {} vertices (the limit of one glTF mesh)", c.limits.max_vertices));
  }
  Shape vec3{{TINYGLTF_TYPE_VEC3}}, vec4{{TINYGLTF_TYPE_VEC4}}, uv{{TINYGLTF_TYPE_VEC2}, true};
  Shape rgba{{TINYGLTF_TYPE_VEC3, TINYGLTF_TYPE_VEC4}, true};
  std::optional<View> normal = attribute(c, p, "NORMAL", where, vec3, n);
  std::optional<View> tangent = attribute(c, p, "TANGENT", where, vec4, n);
  std::optional<View> uv0 = attribute(c, p, "TEXCOORD_0", where, uv, n);
  std::optional<View> uv1 = attribute(c, p, "TEXCOORD_1", where, uv, n);
  std::optional<View> color = attribute(c, p, "COLOR_0", where, rgba, n);
  MeshData mesh;
  mesh.vertices.reserve(n);
  for (size_t i = 0; i < n; ++i) mesh.vertices.push_back(vertex(at, i, position, normal, tangent, uv0, uv1, color));
  mesh.indices = corners(c, p, where, n);
  // glTF's front faces wind counter-clockwise, facet's clockwise: the mirror
  // rewinds every triangle, unless the node mirrors too.
  if (at.det > 0) {
    for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3) std::swap(mesh.indices[t + 1], mesh.indices[t + 2]);
  }
  if (!normal) flat_normals(mesh);
  if (!tangent) compute_tangents(mesh);
  return mesh;
}

void append(MeshData& to, const MeshData& from) {
  uint32_t base = uint32_t(to.vertices.size());
  to.vertices.insert(to.vertices.end(), from.vertices.begin(), from.vertices.end());
  for (uint32_t i : from.indices) to.indices.push_back(base + i);
}

struct Builder {
  Context context;
  std::vector<GltfPart> parts;
  std::map<int, size_t> part_of;  // material -> index in parts

  void add_mesh(int mesh_index, const std::string& use, const glm::dmat4& world) {
    const tinygltf::Model& m = context.model;
    if (mesh_index < 0 || size_t(mesh_index) >= m.meshes.size()) {
      fail(use, fmt::format("mesh {} does not exist (the file has {})", mesh_index, m.meshes.size()));
    }
    Placement at = placement(world);
    // A node scaled to nothing (glTF's way to hide one) has no triangles to draw.
    if (!(std::abs(at.det) > 0) || !std::isfinite(at.det)) return;
    const tinygltf::Mesh& mesh = m.meshes[size_t(mesh_index)];
    for (size_t i = 0; i < mesh.primitives.size(); ++i) {
      const tinygltf::Primitive& p = mesh.primitives[i];
      std::string where = fmt::format("meshes[{}].primitives[{}]", mesh_index, i);
      if (p.material < -1 || (p.material >= 0 && size_t(p.material) >= m.materials.size())) {
        fail(where + ".material",
             fmt::format("material {} does not exist (the file has {})", p.material, m.materials.size()));
      }
      MeshData data = primitive_mesh(context, p, where, at);
      auto [slot, added] = part_of.emplace(p.material, parts.size());
      if (added) parts.push_back({p.material, {}});
      append(parts[slot->second].mesh, data);
    }
  }

  static glm::dmat4 local_matrix(const tinygltf::Node& node, const std::string& at) {
    auto check = [&](const std::vector<double>& v, size_t n, const char* key) {
      if (!v.empty() && v.size() != n) fail(at + "." + key, fmt::format("expected {} numbers, got {}", n, v.size()));
      for (double x : v)
        if (!std::isfinite(x)) fail(at + "." + key, "a number is not finite");
    };
    check(node.matrix, 16, "matrix");
    check(node.translation, 3, "translation");
    check(node.rotation, 4, "rotation");
    check(node.scale, 3, "scale");
    if (!node.matrix.empty()) return glm::make_mat4(node.matrix.data());
    glm::dmat4 t(1.0), r(1.0), s(1.0);
    if (!node.translation.empty()) t[3] = glm::dvec4(node.translation[0], node.translation[1], node.translation[2], 1);
    if (!node.rotation.empty()) {
      glm::dquat q(node.rotation[3], node.rotation[0], node.rotation[1], node.rotation[2]);
      double length = glm::length(q);
      if (!(length > 0)) fail(at + ".rotation", "the quaternion has length 0");
      r = glm::mat4_cast(q / length);
    }
    if (!node.scale.empty()) s = glm::scale(glm::dmat4(1.0), glm::dvec3(node.scale[0], node.scale[1], node.scale[2]));
    return t * r * s;
  }

  // Depth first, with its own stack: a hostile hierarchy cannot overflow
  // the call stack, and a node reached twice (a cycle, or two parents) is an error.
  void add_scene(const std::vector<int>& roots, const std::string& at) {
    const tinygltf::Model& m = context.model;
    std::vector<bool> reached(m.nodes.size(), false);
    struct Item {
      int node;
      glm::dmat4 parent;
      uint32_t depth;
      std::string use;
    };
    std::vector<Item> stack;
    for (size_t i = roots.size(); i-- > 0;)
      stack.push_back({roots[i], glm::dmat4(1.0), 1, fmt::format("{}.nodes[{}]", at, i)});
    while (!stack.empty()) {
      Item item = std::move(stack.back());
      stack.pop_back();
      if (item.node < 0 || size_t(item.node) >= m.nodes.size()) {
        fail(item.use, fmt::format("node {} does not exist (the file has {})", item.node, m.nodes.size()));
      }
      std::string node_at = fmt::format("nodes[{}]", item.node);
      if (reached[size_t(item.node)]) {
        fail(item.use,
             fmt::format("{} is reached twice (glTF nodes form a tree: one parent each, no cycles)", node_at));
      }
      reached[size_t(item.node)] = true;
      if (item.depth > context.limits.max_node_depth) {
        fail(node_at, fmt::format("the node hierarchy is deeper than {} levels", context.limits.max_node_depth));
      }
      const tinygltf::Node& node = m.nodes[size_t(item.node)];
      glm::dmat4 world = item.parent * local_matrix(node, node_at);
      if (node.mesh >= 0) add_mesh(node.mesh, node_at + ".mesh", world);
      for (size_t i = node.children.size(); i-- > 0;) {
        stack.push_back({node.children[i], world, item.depth + 1, fmt::format("{}.children[{}]", node_at, i)});
      }
    }
  }
};

}  // namespace

std::optional<std::vector<GltfPart>> gltf_parts(const tinygltf::Model& model, const GltfLimits& limits,
                                                std::string& why) {
  Builder b{Context{model, limits}, {}, {}};
  try {
    if (model.scenes.empty()) {
      for (size_t i = 0; i < model.meshes.size(); ++i)
        b.add_mesh(int(i), fmt::format("meshes[{}]", i), glm::dmat4(1.0));
    } else {
      int scene = model.defaultScene < 0 ? 0 : model.defaultScene;
      if (size_t(scene) >= model.scenes.size()) {
        fail("scene", fmt::format("scene {} does not exist (the file has {})", scene, model.scenes.size()));
      }
      b.add_scene(model.scenes[size_t(scene)].nodes, fmt::format("scenes[{}]", scene));
    }
  } catch (const Bad& bad) {
    why = bad.why;
    return std::nullopt;
  }
  if (b.parts.empty()) {
    why = "the default scene has no triangles (no node with a mesh)";
    return std::nullopt;
  }
  return std::move(b.parts);
}

}  // namespace facet::runtime
