// Views of a keyword space and exact counting (Unity's ladder: full space,
// after skip_variants, after material usage).
#include <algorithm>
#include <unordered_set>

#include "facet/variants.h"
#include "view.h"

namespace facet::variants {
namespace {

bool is_skipped(const std::string& keyword, const std::vector<std::string>& skip) {
  return !keyword.empty() && std::find(skip.begin(), skip.end(), keyword) != skip.end();
}

bool in_any_group(const KeywordSpace& space, size_t set) {
  for (const KeywordCombinations& group : space.combinations) {
    if (std::find(group.sets.begin(), group.sets.end(), set) != group.sets.end()) return true;
  }
  return false;
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

AllowedStates allowed_states(const KeywordSpace& space, std::optional<Stage> stage, bool apply_skip,
                             bool drop_unreachable) {
  AllowedStates allowed;
  allowed.reserve(space.sets.size());
  for (const KeywordSet& set : space.sets) {
    std::vector<uint32_t> states;
    if (in_view(set, stage)) {
      for (uint32_t i = 0; i < set.keywords.size(); ++i) {
        if (apply_skip && is_skipped(set.keywords[i], space.skip_variants)) continue;
        if (drop_unreachable && is_skipped(set.keywords[i], space.unreachable_keywords)) continue;
        states.push_back(i);
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
    bool filtered = set.directive == KeywordDirective::shader_feature && in_view(set, stage);
    if (filtered && !in_any_group(space, s)) result.sets.push_back(s);
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

std::set<std::vector<uint32_t>> view_combinations(const KeywordCombinations& group, const AllowedStates& allowed) {
  std::set<std::vector<uint32_t>> out;
  for (const std::vector<uint32_t>& choices : group.choices) {
    std::vector<uint32_t> projected;
    projected.reserve(choices.size());
    for (size_t i = 0; i < choices.size(); ++i) {
      const std::vector<uint32_t>& states = allowed[group.sets[i]];
      if (states.size() == 1 && states[0] == kOffChoice) projected.push_back(kOffChoice);
      else if (std::binary_search(states.begin(), states.end(), choices[i])) projected.push_back(choices[i]);
      else break;
    }
    if (projected.size() == choices.size()) out.insert(std::move(projected));
  }
  return out;
}

bool in_combinations(const KeywordSpace& space, const VariantKey& key, const AllowedStates& allowed) {
  for (const KeywordCombinations& group : space.combinations) {
    std::vector<uint32_t> wanted;
    for (size_t s : group.sets) wanted.push_back(key.choice[s]);
    if (!view_combinations(group, allowed).count(wanted)) return false;
  }
  return true;
}

BigCount view_count(const KeywordSpace& space, const AllowedStates& allowed, const MaterialCombos* combos) {
  BigCount count = 1;
  size_t next_combo_set = 0;
  for (size_t s = 0; s < allowed.size(); ++s) {
    bool combined = combos && next_combo_set < combos->sets.size() && combos->sets[next_combo_set] == s;
    if (combined) {
      ++next_combo_set;
      continue;
    }
    if (in_any_group(space, s)) continue;
    count *= BigCount(allowed[s].size());
  }
  // With no material-filtered set in the view the filter changes nothing.
  if (combos && !combos->sets.empty()) count *= BigCount(combos->combos.size());
  for (const KeywordCombinations& group : space.combinations) {
    count *= BigCount(view_combinations(group, allowed).size());
  }
  return count;
}

VariantCounts count_variants(const KeywordSpace& space, const CountOptions& options) {
  VariantCounts counts;
  counts.full = view_count(space, allowed_states(space, options.stage, false), nullptr);
  AllowedStates allowed = allowed_states(space, options.stage, true);
  counts.after_skip = view_count(space, allowed, nullptr);
  counts.after_materials = counts.after_skip;
  AllowedStates reachable = allowed_states(space, options.stage, true, true);
  counts.reachable = view_count(space, reachable, nullptr);
  if (options.materials) {
    MaterialCombos combos = material_combos(space, allowed, options.stage, *options.materials);
    counts.after_materials = view_count(space, allowed, &combos);
    MaterialCombos reachable_combos = material_combos(space, reachable, options.stage, *options.materials);
    counts.reachable = view_count(space, reachable, &reachable_combos);
  }
  return counts;
}

}  // namespace facet::variants
