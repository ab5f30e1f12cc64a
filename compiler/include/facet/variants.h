// Keyword sets, variant spaces, exact counts, enumeration and selection,
// following Unity's rules (SPEC.md §3).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "facet/diagnostics.h"
#include "facet/ir.h"
#include "facet/result.h"
#include "facet/stage.h"

namespace facet::variants {

enum class KeywordDirective : uint8_t { multi_compile, shader_feature, dynamic_branch };

// One keyword pragma = one set of mutually exclusive keywords.
// Invariant: keywords are distinct; "" is the "no keyword" state and, when
// present, is listed where it was declared ("_" / "__" / implicit first
// entry of a single-keyword shader_feature).
struct KeywordSet {
  KeywordDirective directive = KeywordDirective::multi_compile;
  bool local = false;
  StageMask stages = kAllStages;  // narrowed by _vertex/_fragment/... suffixes
  std::vector<std::string> keywords;
  std::string pragma;             // the directive as written, e.g. "shader_feature_local_fragment"
  SourceSpan span;
};

// The keyword space of one program (one pass).
struct KeywordSpace {
  std::vector<KeywordSet> sets;                 // variant-producing sets, in declaration order
  std::vector<std::string> dynamic_branch_keywords;  // uniform bools, no variants
  std::vector<std::string> skip_variants;       // keywords never enabled
};

// A variant: for each set of the space, the index of its chosen keyword.
struct VariantKey {
  std::vector<uint32_t> choice;
  bool operator==(const VariantKey&) const = default;
  auto operator<=>(const VariantKey&) const = default;
};

// Reads every keyword pragma of `program` (shortcuts expanded per SPEC.md §3).
Result<KeywordSpace> build_keyword_space(const ir::Program& program, Diagnostics& diags);

// The non-empty keywords of `key` that apply to `stage`, in set order.
std::vector<std::string> stage_keywords(const KeywordSpace& space, const VariantKey& key, Stage stage);
// All non-empty keywords of `key`, in set order.
std::vector<std::string> all_keywords(const KeywordSpace& space, const VariantKey& key);

}  // namespace facet::variants
