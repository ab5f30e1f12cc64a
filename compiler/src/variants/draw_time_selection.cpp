// select_variant: which variant a draw uses, from material ∪ global keywords
// (docs/variants.md §6). Exact match, else Unity's closest match, else (strict) an
// error naming the keyword combination that has no variant.
#include <algorithm>
#include <unordered_map>
#include <unordered_set>

#include "facet/variants.h"
#include "view.h"

namespace facet::variants {
namespace {

void push_unique(std::vector<std::string>& list, const std::string& item) {
  if (std::find(list.begin(), list.end(), item) == list.end()) list.push_back(item);
}

// Sorts the caller's keywords into those that count for matching and those
// that are reported and ignored.
class EnabledKeywords {
 public:
  EnabledKeywords(const KeywordSpace& space, Selection& report) : space_(space), report_(report) {
    for (size_t s = 0; s < space.sets.size(); ++s) {
      const auto& keywords = space.sets[s].keywords;
      for (uint32_t i = 0; i < keywords.size(); ++i) {
        if (!keywords[i].empty()) set_of_.emplace(keywords[i], s);
      }
    }
  }

  void add(const KeywordList& material, const KeywordList& global) {
    std::unordered_set<std::string> from_material(material.begin(), material.end());
    for (const std::string& keyword : material) add_one(keyword, false);
    for (const std::string& keyword : global) add_one(keyword, !from_material.count(keyword));
  }

  bool contains(const std::string& keyword) const { return enabled_.count(keyword) != 0; }

 private:
  void add_one(const std::string& keyword, bool global_only) {
    if (keyword.empty()) return;
    auto it = set_of_.find(keyword);
    if (it != set_of_.end()) {
      // Local keywords cannot be switched on globally (Unity's rule).
      if (global_only && space_.sets[it->second].local) {
        return push_unique(report_.ignored_global_keywords, keyword);
      }
      enabled_.insert(keyword);
      return;
    }
    const auto& dynamic = space_.dynamic_branch_keywords;
    if (std::find(dynamic.begin(), dynamic.end(), keyword) != dynamic.end()) {
      return push_unique(report_.dynamic_branches_on, keyword);
    }
    push_unique(report_.unknown_keywords, keyword);
  }

  const KeywordSpace& space_;
  Selection& report_;
  std::unordered_map<std::string, size_t> set_of_;  // declared keyword -> its set
  std::unordered_set<std::string> enabled_;
};

bool enabled_at(const KeywordSet& set, uint32_t choice, const EnabledKeywords& enabled) {
  return choice != kOffChoice && enabled.contains(set.keywords[choice]);
}

// The key the enabled keywords ask for: per set the enabled entry, or the
// set's default choice when none is. A set with several enabled entries is a
// conflict that no variant satisfies; its index is returned.
std::optional<size_t> requested_key(const KeywordSpace& space, const AllowedStates& allowed,
                                    const EnabledKeywords& enabled, VariantKey& key) {
  std::optional<size_t> conflict;
  key.choice.assign(space.sets.size(), 0);
  for (size_t s = 0; s < space.sets.size(); ++s) {
    std::vector<uint32_t> hits;
    for (uint32_t i = 0; i < space.sets[s].keywords.size(); ++i) {
      if (enabled_at(space.sets[s], i, enabled)) hits.push_back(i);
    }
    key.choice[s] = hits.empty() ? default_choice(space.sets[s], allowed[s]) : hits.front();
    if (hits.size() > 1 && !conflict) conflict = s;
  }
  return conflict;
}

bool is_available(const KeywordSpace& space, const VariantKey& key, const AllowedStates& allowed,
                  const SelectOptions& options) {
  if (options.available) {
    const auto& list = *options.available;
    return std::find(list.begin(), list.end(), key) != list.end();
  }
  for (size_t s = 0; s < allowed.size(); ++s) {
    if (!std::binary_search(allowed[s].begin(), allowed[s].end(), key.choice[s])) return false;
  }
  return in_combinations(space, key, allowed);
}

// Closest match over the whole space after skip_variants, the same answer
// closest_in_list would give over every variant: the score is a sum over
// sets, so the smallest best key takes, per set, the first allowed entry
// that is enabled, else the first allowed entry.
VariantKey closest_in_space(const KeywordSpace& space, const AllowedStates& allowed, const EnabledKeywords& enabled) {
  VariantKey key;
  for (size_t s = 0; s < space.sets.size(); ++s) {
    auto hit = std::find_if(allowed[s].begin(), allowed[s].end(),
                            [&](uint32_t choice) { return enabled_at(space.sets[s], choice, enabled); });
    key.choice.push_back(hit != allowed[s].end() ? *hit : allowed[s].front());
  }
  // A curated shortcut's sets take its best listed combination together:
  // the most enabled keywords, ties to the smallest (combinations are sorted).
  for (const KeywordCombinations& group : space.combinations) {
    std::set<std::vector<uint32_t>> combinations = view_combinations(group, allowed);
    const std::vector<uint32_t>* best = nullptr;
    size_t best_score = 0;
    for (const std::vector<uint32_t>& combination : combinations) {
      size_t score = 0;
      for (size_t i = 0; i < combination.size(); ++i) {
        score += enabled_at(space.sets[group.sets[i]], combination[i], enabled) ? 1 : 0;
      }
      if (!best || score > best_score) {
        best = &combination;
        best_score = score;
      }
    }
    if (!best) continue;
    for (size_t i = 0; i < best->size(); ++i) key.choice[group.sets[i]] = (*best)[i];
  }
  return key;
}

size_t shared_keywords(const KeywordSpace& space, const VariantKey& key, const EnabledKeywords& enabled) {
  if (key.choice.size() != space.sets.size()) FACET_ICE("available variant does not match its keyword space");
  size_t score = 0;
  for (size_t s = 0; s < space.sets.size(); ++s) score += enabled_at(space.sets[s], key.choice[s], enabled) ? 1 : 0;
  return score;
}

// Closest match over an explicit list: most shared keywords, ties to the
// smallest key, independent of the list's order.
const VariantKey* closest_in_list(const KeywordSpace& space, const std::vector<VariantKey>& list,
                                  const EnabledKeywords& enabled) {
  const VariantKey* best = nullptr;
  size_t best_score = 0;
  for (const VariantKey& key : list) {
    size_t score = shared_keywords(space, key, enabled);
    if (!best || score > best_score || (score == best_score && key < *best)) {
      best = &key;
      best_score = score;
    }
  }
  return best;
}

std::string quoted_keywords(const std::vector<std::string>& keywords) {
  std::string text;
  for (const std::string& keyword : keywords) text += (text.empty() ? "" : " ") + keyword;
  return "'" + text + "'";
}

void report_no_exact_match(const KeywordSpace& space, const VariantKey& requested, std::optional<size_t> conflict,
                           const EnabledKeywords& enabled, Diagnostics& diags) {
  std::vector<std::string> wanted;
  for (size_t s = 0; s < space.sets.size(); ++s) {
    const KeywordSet& set = space.sets[s];
    for (uint32_t i = 0; i < set.keywords.size(); ++i) {
      bool chosen = requested.choice[s] == i || (conflict == s && enabled_at(set, i, enabled));
      if (chosen && !set.keywords[i].empty()) wanted.push_back(set.keywords[i]);
    }
  }
  Diagnostic& d = diags.add(DiagId::variants_no_exact_match, SourceSpan{},
                            "strict variant matching: no variant has exactly the keywords " +
                                (wanted.empty() ? std::string("'' (no keywords)") : quoted_keywords(wanted)));
  if (conflict) {
    d.note(space.sets[*conflict].span, "more than one keyword of this set is enabled; a variant has at most one");
  }
  for (const std::string& keyword : wanted) {
    const auto& skip = space.skip_variants;
    if (std::find(skip.begin(), skip.end(), keyword) != skip.end()) {
      d.note({}, "'" + keyword + "' is listed in skip_variants");
    }
  }
}

}  // namespace

Result<Selection> select_variant(const KeywordSpace& space, const KeywordList& material_keywords,
                                 const KeywordList& global_keywords, const SelectOptions& options,
                                 Diagnostics& diags) {
  Selection selection;
  EnabledKeywords enabled(space, selection);
  // keyword_rule implies: enabling A enables what it implies.
  enabled.add(apply_implications(space, material_keywords), apply_implications(space, global_keywords));
  AllowedStates allowed = allowed_states(space, std::nullopt, true);
  std::optional<size_t> conflict = requested_key(space, allowed, enabled, selection.key);
  selection.exact = !conflict && is_available(space, selection.key, allowed, options);
  if (selection.exact) return selection;
  if (options.strict) {
    report_no_exact_match(space, selection.key, conflict, enabled, diags);
    return failure("no variant matches the enabled keywords exactly");
  }
  if (!options.available) {
    selection.key = closest_in_space(space, allowed, enabled);
    return selection;
  }
  const VariantKey* best = closest_in_list(space, *options.available, enabled);
  if (!best) {
    diags.add(DiagId::variants_no_exact_match, SourceSpan{}, "the pass has no variants to select from");
    return failure("no variants");
  }
  selection.key = *best;
  return selection;
}

}  // namespace facet::variants
