// StageReflection <-> JSON (nlohmann::json). The package stores reflection
// in this form and `facetc --dump` prints it, so the shape is stable:
//
//   {"stage": "fragment", "entry_point": "frag",
//    "inputs":  [{"name", "semantic", "location", "type", "array_size"}],
//    "outputs": [...],
//    "uniform_blocks": [{"name", "set", "binding", "size", "push_constant",
//                        "members": [{"name", "type", "offset", "size",
//                                     "array_dims", "array_stride",
//                                     "matrix_stride", "row_major",
//                                     "members"}]}],
//    "resources": [{"name", "kind", "dim", "arrayed", "set", "binding", "array_size"}],
//    "spec_constants": [{"name", "id", "type", "default_value"}],
//    "property_bindings": [{"property", "role", "block", "member"}]}
//
// Through nlohmann::json, keys are in alphabetical order (its object order);
// through reflection_to_ordered_json (the package dump), in the order above.
// Either way the same reflection gives the same bytes, and arrays keep the
// order of StageReflection (which is itself sorted, see reflection.h).
// kind: "combined_image_sampler" "separate_image" "separate_sampler"
//       "storage_image" "storage_buffer" "uniform_texel_buffer".
#pragma once

#include <nlohmann/json.hpp>

#include <string>
#include <string_view>

#include "facet/reflection.h"
#include "facet/result.h"

namespace facet {

// nlohmann's ADL hooks: `nlohmann::json j = reflection;`. from_json throws
// nlohmann::json::exception on malformed input (nlohmann's convention); use
// reflection_from_json() where exceptions must not escape.
void to_json(nlohmann::json& j, const StageReflection& reflection);
void from_json(const nlohmann::json& j, StageReflection& reflection);

// The same object with its keys in the order above.
nlohmann::ordered_json reflection_to_ordered_json(const StageReflection& reflection);

// Non-throwing reading: Failure::reason says what is wrong.
Result<StageReflection> reflection_from_json(const nlohmann::json& j);

// Serialised text (indent < 0: one line), and the same parse of text.
std::string reflection_to_json_text(const StageReflection& reflection, int indent = 2);
Result<StageReflection> reflection_from_json_text(const std::string& text);

std::string_view resource_kind_name(ResourceKind kind);

}  // namespace facet
