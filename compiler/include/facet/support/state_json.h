// Render state and tags as JSON, one spelling for every output that shows
// them (the package dump, the IR dump): snake_case keys, a literal as its
// text and a property reference as {"property": name}.
#pragma once

#include <nlohmann/json.hpp>

#include <vector>

#include "facet/ir.h"

namespace facet {

// [[key, value], ...] in the order written.
nlohmann::ordered_json tags_json(const std::vector<ir::Tag>& tags);
nlohmann::ordered_json state_value_json(const ir::StateValue& value);
// Only the commands that are set; blend, blend_op and color_mask are lists
// of per-target entries, stencil an object of its set fields.
nlohmann::ordered_json render_state_json(const ir::RenderState& state);

}  // namespace facet
