// Source rewrites that let glslang's HLSL front end accept what fxc accepts.
// Each keeps the text's line structure, so #line mapping and diagnostics
// still point at the user's lines. Internal to the backend stage.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace facet::backend {

// Matrix swizzles ("m._14_24_34", "m._m00_m11", "m._12"), which glslang
// does not implement, become element reads: "float3(m[0][3], m[1][3],
// m[2][3])". The matrix must be a name or a member/index chain
// ("a.b[i]._11"); other text is unchanged. Comments and strings are skipped.
std::string rewrite_matrix_swizzles(std::string_view text);

// fxc lets a program assign to a global uniform (it writes a per-invocation
// copy); glslang refuses. A top-level declaration line "[uniform] TYPE A,
// B = INIT, ...;" declaring one of `names` is split into one declaration per
// name on the same line, and each assigned NAME becomes "TYPE
// NAME_facet_uniform [= INIT]; static TYPE NAME = NAME_facet_uniform;", so
// the program writes its copy and the uniform keeps its place (reflection
// drops the suffix again).
std::string rewrite_assigned_uniforms(std::string_view text, const std::vector<std::string>& names);

// fxc takes `v.x` of a one-component vector (float1, half1, ...) as an
// l-value (Unity's UNITY_TRANSFER_FOG writes `o.fogCoord.x` of a float1);
// glslang makes float1 a scalar and refuses to assign through its swizzle.
// In a whole program (after preprocessing), `.x` or `.r` after a name that
// is declared only as a scalar or a one-component vector is blanked out (two
// spaces: columns stay): the same value, an l-value glslang takes. A name
// also declared with any other type somewhere, or that follows a ',', '}' or
// '>' anywhere (a later declarator of a list, an argument, a struct
// instance, a template type: its type is not known here), keeps its
// swizzles.
std::string drop_scalar_swizzles(std::string_view text);

// The suffix rewrite_assigned_uniforms gives a uniform's declaration.
inline constexpr std::string_view kAssignedUniformSuffix = "_facet_uniform";

}  // namespace facet::backend
