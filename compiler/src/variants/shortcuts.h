// Unity's built-in keyword shortcuts (multi_compile_fwdbase, ...) as facet
// defines them (SPEC.md §3): fixed cartesian products of plain sets, with
// modifiers that remove keywords. Internal to the variants stage.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace facet::variants {

// One shortcut's sets; "" is the off state.
using ShortcutSets = std::vector<std::vector<std::string>>;

// The sets `name` (e.g. "multi_compile_fog") expands to; nullopt when it is
// not a known shortcut.
std::optional<ShortcutSets> expand_shortcut(std::string_view name);

// Keywords that `modifier` (e.g. "noshadow") removes; nullopt when it is not
// a known modifier. Known modifiers that remove nothing return an empty list
// (facet has no lightmaps, so the lightmap modifiers have nothing to remove).
std::optional<std::vector<std::string>> modifier_removals(std::string_view modifier);

// Known modifier names, for "unknown modifier" messages.
std::vector<std::string> known_modifiers();

}  // namespace facet::variants
