// Reading keywords out of variant keys.
#include <algorithm>

#include "facet/variants.h"

namespace facet::variants {
namespace {

// The keyword `key` chooses in set `s`; "" for the off state. A key that
// does not fit its space is a bug in the caller, not a user error.
const std::string& chosen_keyword(const KeywordSpace& space, const VariantKey& key, size_t s) {
  static const std::string kNone;
  uint32_t choice = key.choice[s];
  if (choice == kOffChoice) return kNone;
  if (choice >= space.sets[s].keywords.size()) FACET_ICE("variant key choice out of range");
  return space.sets[s].keywords[choice];
}

void check_key(const KeywordSpace& space, const VariantKey& key) {
  if (key.choice.size() != space.sets.size()) FACET_ICE("variant key does not match its keyword space");
}

}  // namespace

std::vector<std::string> stage_keywords(const KeywordSpace& space, const VariantKey& key, Stage stage) {
  check_key(space, key);
  std::vector<std::string> keywords;
  for (size_t s = 0; s < space.sets.size(); ++s) {
    if (!space.sets[s].applies_to(stage)) continue;
    const std::string& keyword = chosen_keyword(space, key, s);
    // Sets sharing a keyword both choose it: it is listed once.
    bool listed = std::find(keywords.begin(), keywords.end(), keyword) != keywords.end();
    if (!keyword.empty() && !listed) keywords.push_back(keyword);
  }
  return keywords;
}

std::vector<std::string> all_keywords(const KeywordSpace& space, const VariantKey& key) {
  check_key(space, key);
  std::vector<std::string> keywords;
  for (size_t s = 0; s < space.sets.size(); ++s) {
    const std::string& keyword = chosen_keyword(space, key, s);
    // A keyword that sets share is listed once.
    bool listed = std::find(keywords.begin(), keywords.end(), keyword) != keywords.end();
    if (!keyword.empty() && !listed) keywords.push_back(keyword);
  }
  return keywords;
}

VariantKey project(const KeywordSpace& space, const VariantKey& key, Stage stage) {
  check_key(space, key);
  VariantKey projected = key;
  for (size_t s = 0; s < space.sets.size(); ++s) {
    if (!space.sets[s].applies_to(stage)) projected.choice[s] = kOffChoice;
  }
  return projected;
}

std::vector<std::string> VariantSet::keywords(const VariantKey& key) const { return all_keywords(space, key); }

}  // namespace facet::variants
