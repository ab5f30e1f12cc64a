// Unity's built-in keyword shortcuts (multi_compile_fwdbase, ...): their
// keyword sets, Unity's listed combinations of them where the shortcut is a
// curated list rather than a product, and the modifiers that remove
// keywords. Internal to the variants stage.
#pragma once

#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "facet/stage.h"

namespace facet::variants {

// One set of a shortcut; "" is the off state.
struct ShortcutSet {
  std::vector<std::string> keywords;
  StageMask stages = kAllStages;
};

struct Shortcut {
  std::vector<ShortcutSet> sets;
  // Unity's combinations, each the keywords it enables; empty when every
  // combination of the sets exists.
  std::vector<std::vector<std::string>> combinations;
  // Keywords facet's renderer never enables (lightmaps, the shadowmask,
  // vertex lights): counted, reported unreachable, not built by default.
  std::vector<std::string> unreachable;
};

// What `name` (e.g. "multi_compile_fog") expands to; nullopt when it is not
// a known shortcut.
std::optional<Shortcut> expand_shortcut(std::string_view name);

// Keywords that `modifier` (e.g. "noshadow") removes; nullopt when it is not
// a known modifier. "nolppv" removes nothing: light probe proxy volumes are
// not a keyword.
std::optional<std::vector<std::string>> modifier_removals(std::string_view modifier);

// Known modifier names, for "unknown modifier" messages.
std::vector<std::string> known_modifiers();

}  // namespace facet::variants
