// Views of a keyword space and exact counting (Unity's ladder: full space,
// after skip_variants, after material usage).
#include <algorithm>
#include <unordered_set>

#include "facet/variants.h"
#include "variants/view.h"

namespace facet::variants {
namespace {

bool is_skipped(const std::string& keyword, const std::vector<std::string>& skip) {
  return !keyword.empty() && std::find(skip.begin(), skip.end(), keyword) != skip.end();
}

// The choice a material makes in one set; nullopt when it enables keywords
// of the set but the view removed all of them.
std::optional<uint32_t> material_state(const KeywordSet& set, const std::vector<uint32_t>& allowed,
                                       const std::unordered_set<std::string>& enabled) {
  bool any_enabled = false;
  for (uint32_t i = 0; i < set.keywords.size(); ++i) {
    if (set.keywords[i].empty() || !enabled.count(set.keywords[i])) continue;
    any_enabled = true;
    if (std::binary_search(allowed.begin(), allowed.end(), i)) return i;
  }
  if (any_enabled) return std::nullopt;
  return default_choice(set, allowed);
}

}  // namespace

uint32_t default_choice(const KeywordSet& set, const std::vector<uint32_t>& allowed) {
  for (uint32_t choice : allowed) {
    if (choice != kOffChoice && set.keywords[choice].empty()) return choice;
  }
  return allowed.front();
}

bool in_view(const KeywordSet& set, std::optional<Stage> stage) { return !stage || set.applies_to(*stage); }

AllowedStates allowed_states(const KeywordSpace& space, std::optional<Stage> stage, bool apply_skip) {
  AllowedStates allowed;
  allowed.reserve(space.sets.size());
  for (const KeywordSet& set : space.sets) {
    std::vector<uint32_t> states;
    if (in_view(set, stage)) {
      for (uint32_t i = 0; i < set.keywords.size(); ++i) {
        if (!apply_skip || !is_skipped(set.keywords[i], space.skip_variants)) states.push_back(i);
      }
    }
    // Out of the view, or every keyword skipped: the set keeps one state,
    // "no keyword", so that skipping never empties the whole space.
    if (states.empty()) states.push_back(kOffChoice);
    allowed.push_back(std::move(states));
  }
  return allowed;
}

MaterialCombos material_combos(const KeywordSpace& space, const AllowedStates& allowed, std::optional<Stage> stage,
                               const std::vector<KeywordList>& materials) {
  MaterialCombos result;
  for (size_t s = 0; s < space.sets.size(); ++s) {
    const KeywordSet& set = space.sets[s];
    if (set.directive == KeywordDirective::shader_feature && in_view(set, stage)) result.sets.push_back(s);
  }
  for (const KeywordList& material : materials) {
    std::unordered_set<std::string> enabled(material.begin(), material.end());
    std::vector<uint32_t> combo;
    for (size_t s : result.sets) {
      std::optional<uint32_t> state = material_state(space.sets[s], allowed[s], enabled);
      if (!state) break;
      combo.push_back(*state);
    }
    if (combo.size() == result.sets.size()) result.combos.insert(std::move(combo));
  }
  return result;
}

BigCount view_count(const AllowedStates& allowed, const MaterialCombos* combos) {
  BigCount count = 1;
  size_t next_combo_set = 0;
  for (size_t s = 0; s < allowed.size(); ++s) {
    bool combined = combos && next_combo_set < combos->sets.size() && combos->sets[next_combo_set] == s;
    if (combined) {
      ++next_combo_set;
      continue;
    }
    count *= BigCount(allowed[s].size());
  }
  // With no material-filtered set in the view the filter changes nothing.
  if (combos && !combos->sets.empty()) count *= BigCount(combos->combos.size());
  return count;
}

VariantCounts count_variants(const KeywordSpace& space, const CountOptions& options) {
  VariantCounts counts;
  counts.full = view_count(allowed_states(space, options.stage, false), nullptr);
  AllowedStates allowed = allowed_states(space, options.stage, true);
  counts.after_skip = view_count(allowed, nullptr);
  counts.after_materials = counts.after_skip;
  if (options.materials) {
    MaterialCombos combos = material_combos(space, allowed, options.stage, *options.materials);
    counts.after_materials = view_count(allowed, &combos);
  }
  return counts;
}

}  // namespace facet::variants
