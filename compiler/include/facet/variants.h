// Keyword sets, variant spaces, exact counts, enumeration and selection,
// following Unity's rules (the full rule list is docs/variants.md).
//
//   Diagnostics diags;
//   auto space = variants::build_keyword_space(program, diags);
//   if (!space) return;                        // errors are in diags
//   auto counts = variants::count_variants(*space, {.stage = Stage::fragment});
//   auto keys = variants::enumerate(*space, {.stage = Stage::fragment}, diags);
//   auto pick = variants::select_variant(*space, material_kw, global_kw, {}, diags);
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "facet/bigcount.h"
#include "facet/diagnostics.h"
#include "facet/ir.h"
#include "facet/result.h"
#include "facet/stage.h"

namespace facet::variants {

enum class KeywordDirective : uint8_t { multi_compile, shader_feature, dynamic_branch };

// One keyword pragma = one set of mutually exclusive keywords.
// Invariant: keywords are distinct; "" is the "no keyword" state and, when
// present, is listed where it was declared ("_" / "__" / implicit first
// entry of a single-keyword shader_feature). A set holds at least one
// non-empty keyword; a keyword two sets of a space declare puts both sets
// in one KeywordCombinations entry (docs/variants.md §1, rules 8 and 9).
struct KeywordSet {
  KeywordDirective directive = KeywordDirective::multi_compile;
  bool local = false;
  StageMask stages = kAllStages;  // narrowed by _vertex/_fragment/... suffixes
  std::vector<std::string> keywords;
  std::string pragma;             // the directive as written, e.g. "shader_feature_local_fragment"
                                  // or the shortcut, e.g. "multi_compile_fwdbase"
  SourceSpan span;

  bool applies_to(Stage s) const { return (stages & stage_bit(s)) != 0; }
};

// `#pragma keyword_rule requires|excludes|implies KEYWORD OTHER...`: a
// constraint between keywords that removes variants (docs/stripping.md).
//   requires A B C : A only together with B and C
//   excludes A B C : A never together with B or C
//   implies  A B   : as requires, and selecting A at draw time enables B
enum class RuleKind : uint8_t { requires_all, excludes, implies };

struct KeywordRule {
  RuleKind kind = RuleKind::requires_all;
  std::string keyword;
  std::vector<std::string> others;
  SourceSpan span;
};

// Unity's shortcuts are curated lists, not products: multi_compile_fwdbase
// has 83 of the 512 combinations of its nine keywords. Its keywords are sets
// of the space like any others, and this lists the combinations of those sets
// that exist; every other combination of them is not a variant.
struct KeywordCombinations {
  std::vector<size_t> sets;                       // ascending indices into KeywordSpace::sets
  std::vector<std::vector<uint32_t>> choices;     // per combination, the choice of each of `sets`
  std::string pragma;                             // the shortcut, e.g. "multi_compile_fwdbase"
  SourceSpan span;
};

// The keyword space of one program (one pass).
struct KeywordSpace {
  std::vector<KeywordSet> sets;                 // variant-producing sets, in declaration order
  std::vector<std::string> dynamic_branch_keywords;  // uniform bools, no variants
  std::vector<std::string> skip_variants;       // keywords never enabled
  std::vector<KeywordRule> rules;               // keyword_rule pragmas, in order
  std::vector<KeywordCombinations> combinations;  // curated shortcuts; sets in no entry combine freely
  // Keywords of Unity's shortcuts that facet's renderer never enables
  // (lightmaps, shadowmask, vertex lights, ...): counted as Unity counts
  // them, reported as unreachable, and not built by default.
  std::vector<std::string> unreachable_keywords;
};

// VariantKey::choice value meaning "this set contributes no keyword": every
// keyword of the set is in skip_variants (the set keeps only its off state),
// or the key is a stage projection and the set does not apply to the stage.
inline constexpr uint32_t kOffChoice = UINT32_MAX;

// A variant: for each set of the space, the index of its chosen keyword (or
// kOffChoice). Keys order lexicographically, first set most significant,
// which is also the order enumerate() produces.
struct VariantKey {
  std::vector<uint32_t> choice;
  bool operator==(const VariantKey&) const = default;
  auto operator<=>(const VariantKey&) const = default;
};

// The keywords one material enables (Toggle/KeywordEnum-derived included).
using KeywordList = std::vector<std::string>;

// ---- building -------------------------------------------------------------

// Reads every keyword pragma of `program` (shortcuts expanded as docs/variants.md §2 lists them)
// and its skip_variants. Reports every bad pragma before failing; warnings
// (duplicates, unknown shortcut modifiers, unused skip_variants) survive a
// success.
Result<KeywordSpace> build_keyword_space(const ir::Program& program, Diagnostics& diags);

// The names build_keyword_space expands, e.g. "multi_compile_fwdbase", in
// the order docs/variants.md lists them.
std::vector<std::string> known_shortcuts();

// ---- keys -----------------------------------------------------------------

// The non-empty keywords of `key` that apply to `stage`, in set order.
std::vector<std::string> stage_keywords(const KeywordSpace& space, const VariantKey& key, Stage stage);
// All non-empty keywords of `key`, in set order.
std::vector<std::string> all_keywords(const KeywordSpace& space, const VariantKey& key);
// `key` with every set that does not apply to `stage` set to kOffChoice, so
// that variants differing only in other stages' keywords project equally.
VariantKey project(const KeywordSpace& space, const VariantKey& key, Stage stage);

// ---- counting -------------------------------------------------------------

// Unity's counting ladder for one pass or one stage of it; each rung is at
// most the one before. Exact at any size.
struct VariantCounts {
  BigCount full;             // product of the set sizes (the listed combinations of curated shortcuts)
  BigCount after_skip;       // skip_variants applied
  BigCount after_materials;  // shader_feature sets restricted to the combinations
                             // materials use; equals after_skip without materials
  BigCount reachable;        // after_materials without unreachable_keywords: what facet builds
};

struct CountOptions {
  // nullopt: the whole pass (every set); a stage: only the sets applying to
  // it, i.e. the number of distinct programs that stage needs.
  std::optional<Stage> stage;
  // nullopt: no material filter. An empty list means "no material uses the
  // shader", which leaves 0 variants when the view has shader_feature sets.
  std::optional<std::vector<KeywordList>> materials;
};

VariantCounts count_variants(const KeywordSpace& space, const CountOptions& options = {});

// ---- enumeration ----------------------------------------------------------

struct EnumerateOptions {
  std::optional<Stage> stage;        // per-stage view: distinct projections (see project())
  bool apply_skip_variants = true;
  std::optional<std::vector<KeywordList>> materials;  // as CountOptions::materials
  bool drop_unreachable = false;     // leave out variants with KeywordSpace::unreachable_keywords
  uint64_t max_variants = 65536;     // more than this is an error, never a huge allocation
};

// Every variant of the view, distinct, in ascending VariantKey order (the
// first set varies slowest, the last fastest). Fails with a diagnostic
// giving the exact count when it exceeds options.max_variants.
Result<std::vector<VariantKey>> enumerate(const KeywordSpace& space, const EnumerateOptions& options,
                                          Diagnostics& diags);

// ---- the variants of a build ----------------------------------------------

// One pass's variants as the variant stage hands them on to the compile: the
// pass's keyword space and the keys chosen from it (full keys of `space`, in
// ascending order), after strip rules and filters.
struct VariantSet {
  KeywordSpace space;
  std::vector<VariantKey> keys;
  uint64_t stripped = 0;  // enumerated variants that stripping removed

  std::vector<std::string> keywords(const VariantKey& key) const;  // all_keywords(space, key)
};

// ---- selection at draw time -----------------------------------------------

struct SelectOptions {
  // Unity 2022.2+ strictShaderVariantMatching: no exact match is an error.
  bool strict = false;
  // The variants that exist (e.g. a package's); full keys, not projections.
  // nullptr: every variant of the space after skip_variants.
  const std::vector<VariantKey>* available = nullptr;
};

struct Selection {
  VariantKey key;
  bool exact = false;  // false: Unity's closest match was used
  // Enabled keywords that no set or dynamic_branch of the space declares;
  // they are ignored.
  std::vector<std::string> unknown_keywords;
  // Global keywords naming a local keyword; ignored, as in Unity, because a
  // local keyword is only set per material.
  std::vector<std::string> ignored_global_keywords;
  // Enabled dynamic_branch keywords: the uniform bools to set to true.
  std::vector<std::string> dynamic_branches_on;
};

// Picks the variant for a draw from material keywords ∪ global keywords.
// The requested key takes, per set, the enabled keyword; when none is, the
// set's "_" state if it has one (that is an exact match), else its first
// entry; entries removed by skip_variants are passed over. Exact match when
// that key exists; otherwise Unity's closest match: the variant sharing the
// most enabled keywords, ties to the first declared entries (the smallest
// key); in strict mode an error naming the keyword combination that has no
// variant.
Result<Selection> select_variant(const KeywordSpace& space, const KeywordList& material_keywords,
                                 const KeywordList& global_keywords, const SelectOptions& options,
                                 Diagnostics& diags);

// ---- stripping -----------------------------------------------------------------

// A declarative strip filter, like Unity's IPreprocessShaders without code
// (docs/stripping.md). Rules apply to every pass, or to the one `pass` names
// (a name, case-insensitive, or a 0-based index).
//   deny       : drop variants that enable all of `keywords`
//   allow      : exempt variants that enable all of `keywords` from deny rules
//   always_on  : the feature is always on: drop variants without each keyword
//   always_off : the feature is never used: drop variants with any keyword
enum class StripKind : uint8_t { deny, allow, always_on, always_off };

struct StripRule {
  StripKind kind = StripKind::deny;
  std::vector<std::string> keywords;
  std::string pass;  // "" : every pass
};

struct StripFilter {
  std::vector<StripRule> rules;
  bool empty() const { return rules.empty(); }
};

// Why the variant with these enabled keywords is stripped, or nullopt when it
// stays: the first keyword_rule of the space it breaks, else the filter's
// verdict for this pass (`pass_name`, `pass_index`).
std::optional<std::string> strip_reason(const KeywordSpace& space, const std::vector<std::string>& keywords,
                                        const StripFilter& filter, const std::string& pass_name, size_t pass_index);

// Keywords that `implies` rules add to an enabled list, to a fixed point.
KeywordList apply_implications(const KeywordSpace& space, KeywordList keywords);

// "requires", "excludes", "implies".
std::string_view rule_kind_name(RuleKind kind);

// ---- keywords implied by material property values ---------------------------

// A property value a material sets (a float: toggles and enums are floats).
struct PropertyValue {
  std::string name;
  float value = 0;
};

// The keywords a material's property values enable, as Unity's material
// inspector sets them, in property order:
//   [Toggle(KW)]      KW when the value is not 0; [Toggle] alone: NAME_ON
//   [ToggleOff(KW)]   KW when the value is 0;     [ToggleOff] alone: NAME_OFF
//   [KeywordEnum(A, B C, ...)]  NAME_A, NAME_B_C, ... for the entry the value
//                     selects (truncated and clamped to the entries)
// where NAME is the property name upper-cased and entries are upper-cased
// with spaces as '_'. Properties absent from `values` use their defaults;
// attribute names compare case-insensitively.
KeywordList keywords_from_properties(const std::vector<ir::Property>& properties,
                                     const std::vector<PropertyValue>& values = {});

// ---- text -----------------------------------------------------------------

struct DumpOptions {
  StageMask stages = kAllStages;  // stages to print a count line for
  bool counts = true;             // the counting ladder, pass and stages
  bool list_variants = false;     // one line per variant of the pass
  uint64_t max_listed = 4096;     // larger spaces print their count instead
};

// Stable text for `facetc --dump=variants` / `--list-variants`; the format
// is documented in docs/variants.md.
std::string dump_keyword_space(const KeywordSpace& space, const DumpOptions& options = {});

// "multi_compile", "shader_feature", "dynamic_branch".
std::string_view directive_name(KeywordDirective directive);

}  // namespace facet::variants
