// dump_keyword_space: the stable text behind `facetc --dump=variants` and
// `--list-variants`. Goldens compare it, so the format changes only on
// purpose (docs/variants.md shows it).
#include <algorithm>

#include "facet/variants.h"

namespace facet::variants {
namespace {

// The pragma spelling of a set; rebuilt from its fields for sets made by
// hand (an empty `pragma`).
std::string set_spelling(const KeywordSet& set) {
  if (!set.pragma.empty()) return set.pragma;
  std::string text(directive_name(set.directive));
  if (set.local) text += "_local";
  if (set.stages == kAllStages) return text;
  for (int s = 0; s < kStageCount; ++s) {
    if (set.applies_to(Stage(s))) text += "_" + std::string(stage_name(Stage(s)));
  }
  return text;
}

std::string padded(std::string text, size_t width, bool right_align = false) {
  if (text.size() >= width) return text;
  std::string pad(width - text.size(), ' ');
  return right_align ? pad + text : text + pad;
}

std::string joined_or_none(const std::vector<std::string>& words) {
  if (words.empty()) return "(none)";
  std::string text;
  for (const std::string& word : words) text += (text.empty() ? "" : " ") + word;
  return text;
}

void dump_sets(const KeywordSpace& space, std::string& out) {
  out += "keyword sets: " + std::to_string(space.sets.size()) + "\n";
  size_t width = 0;
  for (const KeywordSet& set : space.sets) width = std::max(width, set_spelling(set).size());
  for (size_t s = 0; s < space.sets.size(); ++s) {
    const KeywordSet& set = space.sets[s];
    std::string line = "  #" + padded(std::to_string(s), 3) + padded(set_spelling(set), width + 2);
    for (size_t i = 0; i < set.keywords.size(); ++i) {
      line += (i ? " " : "") + (set.keywords[i].empty() ? std::string("_") : set.keywords[i]);
    }
    out += line + "\n";
  }
  out += "dynamic_branch: " + joined_or_none(space.dynamic_branch_keywords) + "\n";
  out += "skip_variants: " + joined_or_none(space.skip_variants) + "\n";
  for (const KeywordCombinations& group : space.combinations) {
    std::string sets;
    for (size_t s : group.sets) sets += (sets.empty() ? "#" : " #") + std::to_string(s);
    out += "combinations: " + group.pragma + " allows " + std::to_string(group.choices.size()) +
           " combinations of sets " + sets + "\n";
  }
  if (!space.unreachable_keywords.empty()) {
    out += "unreachable: " + joined_or_none(space.unreachable_keywords) +
           " (facet's renderer never enables them; built only with --build-unreachable)\n";
  }
}

bool is_unreachable(const KeywordSpace& space, const std::vector<std::string>& keywords) {
  for (const std::string& k : keywords) {
    if (std::find(space.unreachable_keywords.begin(), space.unreachable_keywords.end(), k) !=
        space.unreachable_keywords.end()) {
      return true;
    }
  }
  return false;
}

void dump_counts(const KeywordSpace& space, const DumpOptions& options, std::string& out) {
  struct Row {
    std::string name, full, after_skip, reachable;
  };
  std::vector<Row> rows;
  VariantCounts pass = count_variants(space);
  rows.push_back({"pass", pass.full.to_string(), pass.after_skip.to_string(), pass.reachable.to_string()});
  for (int s = 0; s < kStageCount; ++s) {
    if (!(options.stages & stage_bit(Stage(s)))) continue;
    VariantCounts stage = count_variants(space, {.stage = Stage(s)});
    rows.push_back({std::string(stage_name(Stage(s))), stage.full.to_string(), stage.after_skip.to_string(),
                    stage.reachable.to_string()});
  }
  size_t full_width = 4;  // "full"
  for (const Row& row : rows) full_width = std::max(full_width, row.full.size());
  bool reachable = !space.unreachable_keywords.empty();
  out += "variant counts:\n";
  out += "  " + padded("", 10) + padded("full", full_width, true) + "  after skip_variants" +
         (reachable ? "  reachable" : "") + "\n";
  for (const Row& row : rows) {
    out += "  " + padded(row.name, 10) + padded(row.full, full_width, true) + "  " +
           (reachable ? padded(row.after_skip, 19) + "  " + row.reachable : row.after_skip) + "\n";
  }
}

void dump_variants(const KeywordSpace& space, const DumpOptions& options, std::string& out) {
  BigCount count = count_variants(space).after_skip;
  if (count > BigCount(options.max_listed)) {
    out += "variants: " + count.to_string() + " (not listed: more than " + std::to_string(options.max_listed) + ")\n";
    return;
  }
  Diagnostics unused;  // cannot fail: the count was checked above
  auto keys = enumerate(space, {.max_variants = options.max_listed}, unused);
  if (!keys) return;
  out += "variants: " + std::to_string(keys->size()) + "\n";
  size_t width = std::to_string(keys->size()).size();
  for (size_t i = 0; i < keys->size(); ++i) {
    std::vector<std::string> keywords = all_keywords(space, (*keys)[i]);
    out += "  " + padded(std::to_string(i), width, true) + "  " +
           (keywords.empty() ? std::string("(no keywords)") : joined_or_none(keywords)) +
           (is_unreachable(space, keywords) ? "  [unreachable]" : "") + "\n";
  }
}

}  // namespace

std::string dump_keyword_space(const KeywordSpace& space, const DumpOptions& options) {
  std::string out;
  dump_sets(space, out);
  if (options.counts) dump_counts(space, options, out);
  if (options.list_variants) dump_variants(space, options, out);
  return out;
}

}  // namespace facet::variants
