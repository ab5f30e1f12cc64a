// enumerate: every variant of a view, in ascending key order. The exact count
// is checked against the cap first, so a 2^70 space fails in microseconds
// instead of exhausting memory.
#include <algorithm>

#include "facet/variants.h"
#include "variants/view.h"

namespace facet::variants {
namespace {

// Appends every key of the product of `allowed`, last set varying fastest,
// which is ascending VariantKey order.
void append_product(const AllowedStates& allowed, std::vector<VariantKey>& out) {
  std::vector<size_t> digit(allowed.size(), 0);
  VariantKey key;
  key.choice.resize(allowed.size());
  while (true) {
    for (size_t s = 0; s < allowed.size(); ++s) key.choice[s] = allowed[s][digit[s]];
    out.push_back(key);
    size_t s = allowed.size();
    while (s > 0 && ++digit[s - 1] == allowed[s - 1].size()) digit[--s] = 0;
    if (s == 0) return;
  }
}

std::string describe_view(const EnumerateOptions& options) {
  std::string view = options.stage ? std::string(stage_name(*options.stage)) + " stage" : std::string("pass");
  if (options.apply_skip_variants) view += ", after skip_variants";
  if (options.materials) view += ", after material usage";
  return view;
}

void report_too_many(const KeywordSpace& space, const EnumerateOptions& options, const BigCount& count,
                     Diagnostics& diags) {
  SourceSpan span = space.sets.empty() ? SourceSpan{} : space.sets.front().span;
  diags
      .add(DiagId::variants_too_many, span,
           "the keyword space has " + count.to_string() + " variants (" + describe_view(options) +
               "), more than the enumeration limit of " + std::to_string(options.max_variants))
      .note({}, "reduce the space with shader_feature instead of multi_compile, skip_variants, or stage "
                "suffixes, or raise the limit");
}

}  // namespace

Result<std::vector<VariantKey>> enumerate(const KeywordSpace& space, const EnumerateOptions& options,
                                          Diagnostics& diags) {
  AllowedStates allowed = allowed_states(space, options.stage, options.apply_skip_variants);
  std::optional<MaterialCombos> combos;
  if (options.materials) combos = material_combos(space, allowed, options.stage, *options.materials);
  BigCount count = view_count(allowed, combos ? &*combos : nullptr);
  if (count > BigCount(options.max_variants)) {
    report_too_many(space, options, count, diags);
    return failure("too many variants to enumerate: " + count.to_string());
  }
  std::vector<VariantKey> keys;
  keys.reserve(size_t(*count.to_u64()));
  if (!combos || combos->sets.empty()) {
    append_product(allowed, keys);
    return keys;
  }
  // Each material combination pins its shader_feature sets; the other sets
  // still take every allowed state. Combos interleave with the other sets in
  // key order, hence the sort.
  for (const std::vector<uint32_t>& combo : combos->combos) {
    AllowedStates pinned = allowed;
    for (size_t i = 0; i < combo.size(); ++i) pinned[combos->sets[i]] = {combo[i]};
    append_product(pinned, keys);
  }
  std::sort(keys.begin(), keys.end());
  return keys;
}

}  // namespace facet::variants
