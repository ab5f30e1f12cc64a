// build_keyword_space: the keyword pragmas of one program, read with Unity's
// rules (docs/variants.md). Every bad pragma is reported before
// the build fails, so one run shows all of them.
#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <map>
#include <set>
#include <string_view>
#include <utility>

#include "facet/support/suggest.h"
#include "facet/variants.h"
#include "shortcuts.h"

namespace facet::variants {
namespace {

constexpr std::array<std::pair<std::string_view, KeywordDirective>, 3> kBases = {{
    {"multi_compile", KeywordDirective::multi_compile},
    {"shader_feature", KeywordDirective::shader_feature},
    {"dynamic_branch", KeywordDirective::dynamic_branch},
}};

constexpr std::array<std::pair<std::string_view, Stage>, 5> kStageSuffixes = {{
    {"_vertex", Stage::vertex},
    {"_fragment", Stage::fragment},
    {"_geometry", Stage::geometry},
    {"_hull", Stage::hull},
    {"_domain", Stage::domain},
}};

struct DirectiveForm {
  KeywordDirective directive = KeywordDirective::multi_compile;
  bool local = false;
  StageMask stages = kAllStages;
};

// The base a pragma name belongs to: the name is the base itself or the base
// followed by '_'. Other pragmas (vertex, target, ...) are not ours.
std::optional<std::pair<std::string_view, KeywordDirective>> keyword_family(std::string_view name) {
  for (const auto& base : kBases) {
    if (name == base.first) return base;
    if (name.size() > base.first.size() && name.starts_with(base.first) && name[base.first.size()] == '_') {
      return base;
    }
  }
  return std::nullopt;
}

// base[_local][_stage] -> the form; nullopt for anything else (shortcuts, typos).
std::optional<DirectiveForm> parse_directive(std::string_view name) {
  auto family = keyword_family(name);
  if (!family) return std::nullopt;
  DirectiveForm form;
  form.directive = family->second;
  std::string_view rest = name.substr(family->first.size());
  if (rest.starts_with("_local")) {
    form.local = true;
    rest.remove_prefix(6);
  }
  if (rest.empty()) return form;
  for (const auto& [suffix, stage] : kStageSuffixes) {
    if (rest == suffix) {
      form.stages = stage_bit(stage);
      return form;
    }
  }
  return std::nullopt;
}

// Every spelling parse_directive accepts, for "did you mean" suggestions.
std::vector<std::string> all_directive_spellings() {
  std::vector<std::string> names;
  for (const auto& base : kBases) {
    for (std::string_view local : {"", "_local"}) {
      std::string stem = std::string(base.first) + std::string(local);
      names.push_back(stem);
      for (const auto& suffix : kStageSuffixes) names.push_back(stem + std::string(suffix.first));
    }
  }
  return names;
}

// The closest candidate within two edits, for a "did you mean" note.
std::optional<std::string> suggest(std::string_view name, const std::vector<std::string>& candidates) {
  std::optional<std::string> best;
  size_t best_distance = 3;
  for (const std::string& candidate : candidates) {
    size_t distance = facet::edit_distance(name, candidate);
    if (distance < best_distance) {
      best = candidate;
      best_distance = distance;
    }
  }
  return best;
}

bool is_all_underscores(std::string_view s) {
  return !s.empty() && std::all_of(s.begin(), s.end(), [](char c) { return c == '_'; });
}

// Keywords become #defines, so they must be identifiers.
bool is_identifier(std::string_view s) {
  auto alpha = [](char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_'; };
  auto digit = [](char c) { return c >= '0' && c <= '9'; };
  if (s.empty() || !alpha(s[0])) return false;
  return std::all_of(s.begin(), s.end(), [&](char c) { return alpha(c) || digit(c); });
}

// The pragma's arguments up to a trailing "//" comment, which a parser that
// keeps comments in pragma lines would otherwise hand us as keywords.
std::vector<std::string_view> pragma_args(const ir::Pragma& pragma) {
  std::vector<std::string_view> args;
  for (const std::string& arg : pragma.args) {
    if (std::string_view(arg).starts_with("//")) break;
    args.push_back(arg);
  }
  return args;
}

std::string join(const std::vector<std::string>& items, std::string_view separator) {
  std::string text;
  for (const std::string& item : items) {
    if (!text.empty()) text += separator;
    text += item;
  }
  return text;
}

// The most combinations sets sharing keywords are combined into.
constexpr size_t kMaxCombinedChoices = size_t(1) << 20;

class SpaceBuilder {
 public:
  explicit SpaceBuilder(Diagnostics& diags) : diags_(diags) {}

  void add(const ir::Pragma& pragma);
  KeywordSpace finish();

 private:
  struct Declaration {
    SourceSpan span;
    bool dynamic = false;
    StageMask stages = kAllStages;
    size_t set = SIZE_MAX;  // index of the set that declared it
  };

  void add_keyword_pragma(const ir::Pragma& pragma, const DirectiveForm& form);
  void add_shortcut(const ir::Pragma& pragma);
  void add_combinations(const ir::Pragma& pragma, const std::vector<size_t>& sets,
                        const std::vector<std::vector<std::string>>& combinations);
  void add_skip_variants(const ir::Pragma& pragma);
  void add_keyword_rule(const ir::Pragma& pragma);
  void report_unknown_directive(const ir::Pragma& pragma);
  std::optional<std::vector<std::string>> read_keywords(const ir::Pragma& pragma);
  bool claim(const std::string& keyword, SourceSpan span, bool dynamic, StageMask stages = kAllStages);
  void tie_shared_keywords(size_t set, const std::vector<std::pair<std::string, size_t>>& shared);
  void combine_overlapping_sets(size_t set, const std::vector<size_t>& earlier);
  void combine_pending_overlaps();
  void add_set(KeywordSet set);

  Diagnostics& diags_;
  KeywordSpace space_;
  std::map<std::string, Declaration> declared_;  // keyword -> its first pragma
  std::map<std::string, SourceSpan> skip_spans_;  // skip_variants keyword -> its pragma
  std::vector<std::pair<std::string, size_t>> shared_;  // of the set being added: keyword, earlier set
  std::vector<size_t> overlapping_;  // of the set being added: earlier sets sharing a keyword
  // Sets added with overlaps, combined once their pragma's own combinations exist.
  std::vector<std::pair<size_t, std::vector<size_t>>> pending_overlaps_;
};

void SpaceBuilder::add(const ir::Pragma& pragma) {
  if (pragma.name == "skip_variants") return add_skip_variants(pragma);
  if (pragma.name == "keyword_rule") return add_keyword_rule(pragma);
  if (!keyword_family(pragma.name)) return;  // not a keyword pragma
  if (auto form = parse_directive(pragma.name)) return add_keyword_pragma(pragma, *form);
  // Not base[_local][_stage]: a shortcut, or a typo of one or of a suffix.
  if (pragma.name.starts_with("multi_compile_")) return add_shortcut(pragma);
  report_unknown_directive(pragma);
}

// Validates names, maps all-underscore names to "" and drops repeats with a
// warning. nullopt (after an error) when the pragma cannot form a set.
std::optional<std::vector<std::string>> SpaceBuilder::read_keywords(const ir::Pragma& pragma) {
  std::vector<std::string> keywords;
  bool ok = true;
  for (std::string_view arg : pragma_args(pragma)) {
    std::string keyword = is_all_underscores(arg) ? std::string() : std::string(arg);
    if (!keyword.empty() && !is_identifier(keyword)) {
      diags_.add(DiagId::pragma_bad_keyword_set, pragma.span,
                 "invalid keyword name '" + keyword + "' in '#pragma " + pragma.name +
                     "'; a keyword is an identifier of letters, digits and '_'");
      ok = false;
      continue;
    }
    if (std::find(keywords.begin(), keywords.end(), keyword) != keywords.end()) {
      std::string what =
          keyword.empty() ? "more than one '_' (no keyword) entry" : "duplicate keyword '" + keyword + "'";
      diags_.add(DiagId::pragma_duplicate_keyword, pragma.span,
                 what + " in '#pragma " + pragma.name + "'; the repeat is ignored");
      continue;
    }
    keywords.push_back(std::move(keyword));
  }
  if (!ok) return std::nullopt;
  if (keywords.empty()) {
    diags_.add(DiagId::pragma_bad_keyword_set, pragma.span, "'#pragma " + pragma.name + "' declares no keywords");
    return std::nullopt;
  }
  return keywords;
}

void SpaceBuilder::add_keyword_pragma(const ir::Pragma& pragma, const DirectiveForm& form) {
  auto keywords = read_keywords(pragma);
  if (!keywords) return;
  bool only_off = std::all_of(keywords->begin(), keywords->end(), [](const std::string& k) { return k.empty(); });
  if (only_off) {
    diags_.add(DiagId::pragma_empty_keyword_set, pragma.span,
               "'#pragma " + pragma.name + "' lists only '_' (no keyword) and adds no variants");
    return;
  }
  if (form.directive == KeywordDirective::dynamic_branch) {
    for (const std::string& keyword : *keywords) {
      if (!keyword.empty() && claim(keyword, pragma.span, true)) space_.dynamic_branch_keywords.push_back(keyword);
    }
    return;
  }
  // "shader_feature A" means "shader_feature _ A"; a lone multi_compile
  // keyword stays always on.
  if (form.directive == KeywordDirective::shader_feature && keywords->size() == 1) {
    keywords->insert(keywords->begin(), std::string());
  }
  add_set(KeywordSet{form.directive, form.local, form.stages, std::move(*keywords), pragma.name, pragma.span});
  combine_pending_overlaps();
}

void SpaceBuilder::add_shortcut(const ir::Pragma& pragma) {
  auto shortcut = expand_shortcut(pragma.name);
  if (!shortcut) {
    Diagnostic& d = diags_.add(DiagId::pragma_unknown_shortcut, pragma.span,
                               "unknown keyword shortcut '" + pragma.name + "' adds no keywords; the known shortcuts are " +
                                   join(known_shortcuts(), ", "));
    std::vector<std::string> candidates = known_shortcuts();
    for (std::string& spelling : all_directive_spellings()) candidates.push_back(std::move(spelling));
    if (auto guess = suggest(pragma.name, candidates)) d.note({}, "did you mean '" + *guess + "'?");
    return;
  }
  std::vector<std::string> removed;
  for (std::string_view arg : pragma_args(pragma)) {
    if (auto removes = modifier_removals(arg)) {
      removed.insert(removed.end(), removes->begin(), removes->end());
      continue;
    }
    diags_.add(DiagId::pragma_unknown_shortcut_modifier, pragma.span,
               "unknown modifier '" + std::string(arg) + "' for '" + pragma.name +
                   "' is ignored; known modifiers are " + join(known_modifiers(), ", "));
  }
  auto is_removed = [&](const std::string& k) { return std::find(removed.begin(), removed.end(), k) != removed.end(); };
  bool curated = !shortcut->combinations.empty();
  if (curated) {
    // Unity's rule: a modifier removes the combinations that hold its
    // keywords; keywords left in no combination leave their sets.
    std::erase_if(shortcut->combinations,
                  [&](const std::vector<std::string>& c) { return std::any_of(c.begin(), c.end(), is_removed); });
    std::set<std::string> used;
    for (const auto& combination : shortcut->combinations) used.insert(combination.begin(), combination.end());
    for (ShortcutSet& set : shortcut->sets) {
      std::erase_if(set.keywords, [&](const std::string& k) { return !k.empty() && !used.count(k); });
    }
  } else {
    for (ShortcutSet& set : shortcut->sets) std::erase_if(set.keywords, is_removed);
  }
  std::vector<size_t> added;
  for (ShortcutSet& set : shortcut->sets) {
    // A set that a modifier emptied (or left with only "_") adds no variants.
    bool any = std::any_of(set.keywords.begin(), set.keywords.end(), [](const std::string& k) { return !k.empty(); });
    if (!any) continue;
    size_t before = space_.sets.size();
    add_set(KeywordSet{KeywordDirective::multi_compile, false, set.stages, std::move(set.keywords), pragma.name,
                       pragma.span});
    if (space_.sets.size() > before) added.push_back(before);
  }
  for (size_t s : added) {
    for (const std::string& k : space_.sets[s].keywords) {
      bool unreachable = std::find(shortcut->unreachable.begin(), shortcut->unreachable.end(), k) !=
                         shortcut->unreachable.end();
      if (unreachable) space_.unreachable_keywords.push_back(k);
    }
  }
  if (curated) add_combinations(pragma, added, shortcut->combinations);
  combine_pending_overlaps();
}

// The listed combinations of a curated shortcut over the sets it added, as
// choices; a shortcut whose combinations cover every product adds nothing.
void SpaceBuilder::add_combinations(const ir::Pragma& pragma, const std::vector<size_t>& sets,
                                    const std::vector<std::vector<std::string>>& combinations) {
  if (sets.empty()) return;
  KeywordCombinations group{sets, {}, pragma.name, pragma.span};
  std::set<std::vector<uint32_t>> choices;
  for (const std::vector<std::string>& combination : combinations) {
    std::vector<uint32_t> row;
    for (size_t s : sets) {
      const std::vector<std::string>& keywords = space_.sets[s].keywords;
      auto hit = std::find_if(keywords.begin(), keywords.end(), [&](const std::string& k) {
        return !k.empty() && std::find(combination.begin(), combination.end(), k) != combination.end();
      });
      if (hit == keywords.end()) hit = std::find(keywords.begin(), keywords.end(), std::string());
      if (hit == keywords.end()) break;  // the set has no off state and the combination none of its keywords
      row.push_back(uint32_t(hit - keywords.begin()));
    }
    if (row.size() == sets.size()) choices.insert(std::move(row));
  }
  uint64_t product = 1;
  for (size_t s : sets) product *= space_.sets[s].keywords.size();
  if (choices.size() == product) return;
  group.choices.assign(choices.begin(), choices.end());
  space_.combinations.push_back(std::move(group));
}

void SpaceBuilder::add_skip_variants(const ir::Pragma& pragma) {
  auto keywords = read_keywords(pragma);
  if (!keywords) return;
  for (const std::string& keyword : *keywords) {
    if (keyword.empty() || skip_spans_.count(keyword)) continue;  // "_" names no keyword
    skip_spans_.emplace(keyword, pragma.span);
    space_.skip_variants.push_back(keyword);
  }
}

void SpaceBuilder::add_keyword_rule(const ir::Pragma& pragma) {
  std::vector<std::string> args;
  for (std::string_view a : pragma_args(pragma)) args.emplace_back(a);
  static const std::map<std::string, RuleKind> kinds = {
      {"requires", RuleKind::requires_all}, {"excludes", RuleKind::excludes}, {"implies", RuleKind::implies}};
  auto kind = args.empty() ? kinds.end() : kinds.find(args[0]);
  if (kind == kinds.end() || args.size() < 3) {
    diags_.add(DiagId::pragma_bad_keyword_rule, pragma.span,
               "'#pragma keyword_rule' takes 'requires', 'excludes' or 'implies', a keyword and the keywords it "
               "constrains");
    return;
  }
  for (size_t i = 1; i < args.size(); ++i) {
    if (!is_identifier(args[i]) || is_all_underscores(args[i])) {
      diags_.add(DiagId::pragma_bad_keyword_rule, pragma.span, "invalid keyword name '" + args[i] + "' in a keyword_rule");
      return;
    }
  }
  space_.rules.push_back({kind->second, args[1], {args.begin() + 2, args.end()}, pragma.span});
}

void SpaceBuilder::report_unknown_directive(const ir::Pragma& pragma) {
  Diagnostic& d = diags_.add(DiagId::pragma_unknown_keyword_directive, pragma.span,
                             "unknown keyword pragma '" + pragma.name +
                                 "'; the forms are multi_compile, shader_feature and dynamic_branch, "
                                 "each with an optional '_local' and one of the stage suffixes "
                                 "'_vertex', '_fragment', '_geometry', '_hull', '_domain'");
  if (auto guess = suggest(pragma.name, all_directive_spellings())) d.note({}, "did you mean '" + *guess + "'?");
}

// Records the first declaration of `keyword`; a second one is an error with
// a note at the first, and the caller drops the keyword.
bool SpaceBuilder::claim(const std::string& keyword, SourceSpan span, bool dynamic, StageMask stages) {
  auto [it, inserted] = declared_.emplace(keyword, Declaration{span, dynamic, stages, space_.sets.size()});
  if (inserted) return true;
  // Sets of different stages may share a keyword (Unity's SpeedTree:
  // `multi_compile_vertex __ LOD_FADE_PERCENTAGE LOD_FADE_CROSSFADE` and
  // `multi_compile_fragment __ LOD_FADE_CROSSFADE`): no stage sees it twice,
  // and add_set ties the two sets so the keyword is on in both or neither.
  const Declaration& d = it->second;
  bool disjoint = !dynamic && !d.dynamic && (d.stages & stages) == 0 && d.set < space_.sets.size();
  bool tied_already = std::any_of(space_.combinations.begin(), space_.combinations.end(), [&](const auto& g) {
    return std::find(g.sets.begin(), g.sets.end(), d.set) != g.sets.end();
  });
  if (disjoint && !tied_already) {
    shared_.emplace_back(keyword, d.set);
    return true;
  }
  // Sets of one stage may share a keyword too (`multi_compile _ VERTEXLIGHT_ON`
  // beside `multi_compile_fwdbase`), and so may a set and a shortcut's set of
  // another stage: as in Unity, a variant enables the union
  // of its sets' choices, and choices with the same union are one variant
  // (combine_overlapping_sets).
  bool overlapping = !dynamic && !d.dynamic && d.set < space_.sets.size();
  if (overlapping) {
    if (std::find(overlapping_.begin(), overlapping_.end(), d.set) == overlapping_.end()) overlapping_.push_back(d.set);
    return true;
  }
  SourceSpan first = it->second.span;
  diags_.add(DiagId::pragma_keyword_in_two_sets, span,
             "keyword '" + keyword + "' is already declared by another keyword pragma; a keyword belongs to one set")
      .note(first, "'" + keyword + "' was first declared here");
  return false;
}

// The same keywords as `set`, ignoring order: a repeat of an earlier pragma.
const KeywordSet* find_same_set(const std::vector<KeywordSet>& sets, const KeywordSet& set) {
  auto sorted = [](std::vector<std::string> keywords) {
    std::sort(keywords.begin(), keywords.end());
    return keywords;
  };
  std::vector<std::string> wanted = sorted(set.keywords);
  for (const KeywordSet& other : sets) {
    if (other.stages == set.stages && other.directive == set.directive && sorted(other.keywords) == wanted) {
      return &other;
    }
  }
  return nullptr;
}

void SpaceBuilder::add_set(KeywordSet set) {
  // Unity compiles a keyword set declared twice (a surface shader's own
  // '#pragma multi_compile_fog' next to the one its lowering adds) once.
  if (const KeywordSet* same = find_same_set(space_.sets, set)) {
    diags_.add(DiagId::pragma_repeated_keyword_set, set.span,
               "'#pragma " + set.pragma + "' repeats the keyword set of an earlier pragma; it adds no variants")
        .note(same->span, "the same keywords are declared here");
    return;
  }
  shared_.clear();
  overlapping_.clear();
  std::erase_if(set.keywords,
                [&](const std::string& k) { return !k.empty() && !claim(k, set.span, false, set.stages); });
  bool any = std::any_of(set.keywords.begin(), set.keywords.end(), [](const std::string& k) { return !k.empty(); });
  if (!any) return;
  space_.sets.push_back(std::move(set));
  if (!shared_.empty()) tie_shared_keywords(space_.sets.size() - 1, shared_);
  if (!overlapping_.empty()) pending_overlaps_.emplace_back(space_.sets.size() - 1, overlapping_);
}

void SpaceBuilder::combine_pending_overlaps() {
  for (const auto& [set, earlier] : pending_overlaps_) combine_overlapping_sets(set, earlier);
  pending_overlaps_.clear();
}

// The new set `set` shares keywords with earlier sets of its stages. It
// joins them (and every set of a combination group holding one of them) in
// one group whose choices are the distinct unions of keywords: of the
// choices giving one union, the one enabling the most sets is kept, so that
// a shared keyword is on in every set declaring it, in every stage.
void SpaceBuilder::combine_overlapping_sets(size_t set, const std::vector<size_t>& earlier) {
  std::set<size_t> members(earlier.begin(), earlier.end());
  members.insert(set);
  std::vector<size_t> groups;  // indices into space_.combinations
  for (bool grew = true; grew;) {
    grew = false;
    for (size_t g = 0; g < space_.combinations.size(); ++g) {
      const KeywordCombinations& group = space_.combinations[g];
      bool touches = std::any_of(group.sets.begin(), group.sets.end(), [&](size_t s) { return members.count(s); });
      if (!touches || std::find(groups.begin(), groups.end(), g) != groups.end()) continue;
      groups.push_back(g);
      members.insert(group.sets.begin(), group.sets.end());
      grew = true;
    }
  }
  const std::vector<size_t> sets(members.begin(), members.end());
  auto position = [&](size_t s) { return size_t(std::find(sets.begin(), sets.end(), s) - sets.begin()); };
  // Every choice of the members: each group's listed combinations times the free sets.
  std::vector<std::vector<uint32_t>> rows{std::vector<uint32_t>(sets.size(), 0)};
  bool too_many = false;
  auto expand = [&](auto&& each_choice) {
    std::vector<std::vector<uint32_t>> next;
    for (const std::vector<uint32_t>& row : rows) {
      each_choice(row, next);
      too_many = too_many || next.size() > kMaxCombinedChoices;
      if (too_many) return;
    }
    rows = std::move(next);
  };
  std::set<size_t> grouped;
  for (size_t g : groups) {
    const KeywordCombinations& group = space_.combinations[g];
    grouped.insert(group.sets.begin(), group.sets.end());
    expand([&](const std::vector<uint32_t>& row, std::vector<std::vector<uint32_t>>& next) {
      for (const std::vector<uint32_t>& choice : group.choices) {
        std::vector<uint32_t> r = row;
        for (size_t i = 0; i < choice.size(); ++i) r[position(group.sets[i])] = choice[i];
        next.push_back(std::move(r));
      }
    });
  }
  for (size_t s : sets) {
    if (grouped.count(s)) continue;
    expand([&](const std::vector<uint32_t>& row, std::vector<std::vector<uint32_t>>& next) {
      for (uint32_t i = 0; i < space_.sets[s].keywords.size(); ++i) {
        std::vector<uint32_t> r = row;
        r[position(s)] = i;
        next.push_back(std::move(r));
      }
    });
  }
  const KeywordSet& added = space_.sets[set];
  if (too_many) {
    diags_.add(DiagId::pragma_keyword_in_two_sets, added.span,
               fmt::format("'#pragma {}' shares keywords with earlier sets; together they have more than {} "
                           "combinations, too many to combine",
                           added.pragma, kMaxCombinedChoices));
    return;
  }
  std::map<std::set<std::string>, std::pair<size_t, std::vector<uint32_t>>> by_union;  // union -> (sets on, choice)
  for (const std::vector<uint32_t>& row : rows) {
    std::set<std::string> keywords;
    size_t on = 0;
    for (size_t i = 0; i < sets.size(); ++i) {
      const std::string& k = space_.sets[sets[i]].keywords[row[i]];
      if (!k.empty()) keywords.insert(k), ++on;
    }
    auto [it, inserted] = by_union.try_emplace(std::move(keywords), on, row);
    if (!inserted && on > it->second.first) it->second = {on, row};
  }
  KeywordCombinations combined{sets, {}, added.pragma, added.span};
  for (auto& [keywords, best] : by_union) combined.choices.push_back(std::move(best.second));
  std::sort(combined.choices.begin(), combined.choices.end());
  std::sort(groups.rbegin(), groups.rend());
  for (size_t g : groups) space_.combinations.erase(space_.combinations.begin() + long(g));
  space_.combinations.push_back(std::move(combined));
}

// The combinations of the new set `set` and the earlier set holding the same
// keywords in which each shared keyword is on in both or in neither.
void SpaceBuilder::tie_shared_keywords(size_t set, const std::vector<std::pair<std::string, size_t>>& shared) {
  size_t earlier = shared.front().second;
  const KeywordSet& a = space_.sets[earlier];
  const KeywordSet& b = space_.sets[set];
  KeywordCombinations group{{earlier, set}, {}, b.pragma, b.span};
  for (uint32_t i = 0; i < a.keywords.size(); ++i) {
    for (uint32_t j = 0; j < b.keywords.size(); ++j) {
      bool agree = std::all_of(shared.begin(), shared.end(), [&](const auto& s) {
        return s.second != earlier || (a.keywords[i] == s.first) == (b.keywords[j] == s.first);
      });
      if (agree) group.choices.push_back({i, j});
    }
  }
  space_.combinations.push_back(std::move(group));
}

KeywordSpace SpaceBuilder::finish() {
  // Rules may name keywords declared after them; a rule naming none is a typo.
  for (const KeywordRule& rule : space_.rules) {
    std::vector<std::string> named = rule.others;
    named.push_back(rule.keyword);
    for (const std::string& k : named) {
      auto it = declared_.find(k);
      if (it == declared_.end() || it->second.dynamic) {
        diags_.add(DiagId::pragma_bad_keyword_rule, rule.span,
                   "keyword_rule names '" + k + "', which no keyword pragma of this program declares");
      }
    }
  }
  // Checked at the end: skip_variants may come before the declaration.
  for (const std::string& keyword : space_.skip_variants) {
    auto it = declared_.find(keyword);
    SourceSpan span = skip_spans_.at(keyword);
    if (it == declared_.end()) {
      diags_.add(DiagId::pragma_unused_skip_variant, span,
                 "skip_variants keyword '" + keyword + "' is not declared by any keyword pragma of this program");
    } else if (it->second.dynamic) {
      diags_.add(DiagId::pragma_unused_skip_variant, span,
                 "skip_variants keyword '" + keyword + "' is a dynamic_branch keyword, which has no variants to skip")
          .note(it->second.span, "'" + keyword + "' is declared here");
    }
  }
  return std::move(space_);
}

}  // namespace

Result<KeywordSpace> build_keyword_space(const ir::Program& program, Diagnostics& diags) {
  size_t errors_before = diags.error_count();
  SpaceBuilder builder(diags);
  for (const ir::Pragma& pragma : program.pragmas) builder.add(pragma);
  KeywordSpace space = builder.finish();
  if (diags.error_count() > errors_before) return failure("invalid keyword pragmas");
  return space;
}

std::string_view directive_name(KeywordDirective directive) {
  switch (directive) {
    case KeywordDirective::multi_compile: return "multi_compile";
    case KeywordDirective::shader_feature: return "shader_feature";
    case KeywordDirective::dynamic_branch: return "dynamic_branch";
  }
  return "?";
}

}  // namespace facet::variants
