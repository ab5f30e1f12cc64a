// Source rewrites that let glslang's HLSL front end accept what fxc accepts.
// Each keeps the text's line structure, so #line mapping and diagnostics
// still point at the user's lines. Internal to the backend stage.
#pragma once

#include <string>
#include <string_view>

namespace facet::backend {

// Matrix swizzles ("m._14_24_34", "m._m00_m11", "m._12"), which glslang
// does not implement, become element reads: "float3(m[0][3], m[1][3],
// m[2][3])". The matrix must be a name or a member/index chain
// ("a.b[i]._11"); other text is unchanged. Comments and strings are skipped.
std::string rewrite_matrix_swizzles(std::string_view text);

}  // namespace facet::backend
