// The checks an OBJ text passes before tinyobjloader reads it. tinyobjloader
// trusts its input: it resolves face indices without looking at how many
// vertices exist, reads numbers with atoi, and triangulates polygons in
// O(corners^3). So every line that tinyobjloader turns into data (v, vt, vn,
// f, and the skin weights vw, whose joint numbers it casts to int unchecked)
// is read here first, the way tinyobjloader splits it (lines end at
// \n, \r\n or \r; words are separated by spaces and tabs), and the first
// problem comes back with its line and column. Text that passes never makes
// tinyobjloader index out of bounds.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace facet::runtime {

// Limits on one OBJ file (docs/scene-format.md, "OBJ meshes").
struct ObjLimits {
  uint64_t max_file_bytes = uint64_t(1) << 30;      // 1 GiB of text
  uint32_t max_face_corners = 512;                  // corners of one polygon
  // Of the whole mesh after triangulation; each may be a vertex of its own
  // (about 400 bytes in all), so this keeps a mesh under 2 GB.
  uint64_t max_triangle_corners = uint64_t(1) << 22;
  uint64_t max_elements = 0x7fffffff;               // v, vt or vn lines: tinyobjloader counts them in an int
};

// One problem of an OBJ text; line and column count from 1 (columns in
// bytes), both 0 for a problem of the whole file (too large, no faces).
struct ObjProblem {
  size_t line = 0, column = 0;
  std::string why;
};

// The first problem of `text`, or nullopt when tinyobjloader can read it
// safely and it has at least one face.
std::optional<ObjProblem> check_obj_text(std::string_view text, const ObjLimits& limits = {});

}  // namespace facet::runtime
