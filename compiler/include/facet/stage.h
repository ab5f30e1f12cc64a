// Shader stages, shared by every part of facet.
#pragma once

#include <cstdint>
#include <optional>
#include <string_view>

namespace facet {

enum class Stage : uint8_t { vertex, fragment, geometry, hull, domain };
inline constexpr int kStageCount = 5;

// Bit set over Stage.
using StageMask = uint8_t;
inline constexpr StageMask stage_bit(Stage s) { return StageMask(1u << unsigned(s)); }
inline constexpr StageMask kAllStages = 0x1f;

// "vertex", "fragment", ...
std::string_view stage_name(Stage s);
// Accepts the names above and their short forms "vert", "frag", "vs", "fs", ...
std::optional<Stage> parse_stage(std::string_view name);

}  // namespace facet
