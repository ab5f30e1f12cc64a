// A view of a keyword space: which states of each set survive a stage
// projection, skip_variants and the material filter. Counting and
// enumeration share it, so both always agree. Internal to the variants stage.
#pragma once

#include <optional>
#include <set>
#include <vector>

#include "facet/variants.h"

namespace facet::variants {

// Per set, the choices that remain, ascending. A set outside the stage view,
// or whose keywords are all skipped, has exactly {kOffChoice}.
using AllowedStates = std::vector<std::vector<uint32_t>>;

// `drop_unreachable` also removes the space's unreachable_keywords, as
// skip_variants removes its keywords.
AllowedStates allowed_states(const KeywordSpace& space, std::optional<Stage> stage, bool apply_skip,
                             bool drop_unreachable = false);

// The distinct combinations of one curated shortcut that survive the view:
// each listed combination with its sets' choices as the view allows them (a
// set the view left only kOffChoice projects to it), dropped when a choice is
// not allowed (a skipped keyword).
std::set<std::vector<uint32_t>> view_combinations(const KeywordCombinations& group, const AllowedStates& allowed);

// Whether `key` is one of the listed combinations of every curated shortcut.
bool in_combinations(const KeywordSpace& space, const VariantKey& key, const AllowedStates& allowed);

// The choice of a set in which nothing is enabled: its "" (no keyword) state
// when it has one the view allows, which is an exact match for "nothing
// enabled"; else its first allowed entry (Unity: the first keyword is used).
uint32_t default_choice(const KeywordSet& set, const std::vector<uint32_t>& allowed);

// True when `set` takes part in the view of `stage` (nullopt: every set).
bool in_view(const KeywordSet& set, std::optional<Stage> stage);

// The shader_feature combinations materials use, over the shader_feature
// sets in the view (`sets`, ascending). Each combo holds one choice per entry
// of `sets`: the enabled keyword (the first declared one if a material
// enables several), else default_choice(). A material enabling
// only keywords of a set that the view skipped gets no variant: its
// combination is dropped, as Unity drops skipped variants.
struct MaterialCombos {
  std::vector<size_t> sets;
  std::set<std::vector<uint32_t>> combos;
};

MaterialCombos material_combos(const KeywordSpace& space, const AllowedStates& allowed, std::optional<Stage> stage,
                               const std::vector<KeywordList>& materials);

// The number of variants of the view: the product of the allowed state
// counts, with the sets of `combos` (when given) counted together as
// combos->combos.size(), and the sets of each curated shortcut together as
// its view_combinations().
BigCount view_count(const KeywordSpace& space, const AllowedStates& allowed, const MaterialCombos* combos);

}  // namespace facet::variants
