// enumerate: every variant of a view, in ascending key order. The exact count
// is checked against the cap first, so a 2^70 space fails in microseconds
// instead of exhausting memory.
#include <algorithm>

#include "facet/variants.h"
#include "view.h"

namespace facet::variants {
namespace {

// One digit of the product: a free set's allowed states, or a curated
// shortcut's surviving combinations over its sets.
struct Digit {
  std::vector<size_t> sets;
  std::vector<std::vector<uint32_t>> values;
};

std::vector<Digit> digits_of(const KeywordSpace& space, const AllowedStates& allowed) {
  std::vector<Digit> digits;
  std::vector<bool> grouped(allowed.size(), false);
  for (const KeywordCombinations& group : space.combinations) {
    Digit d{group.sets, {}};
    for (const auto& combination : view_combinations(group, allowed)) d.values.push_back(combination);
    for (size_t s : group.sets) grouped[s] = true;
    digits.push_back(std::move(d));
  }
  for (size_t s = 0; s < allowed.size(); ++s) {
    if (grouped[s]) continue;
    Digit d{{s}, {}};
    for (uint32_t choice : allowed[s]) d.values.push_back({choice});
    digits.push_back(std::move(d));
  }
  return digits;
}

// Appends every key of the product of `allowed` (curated shortcuts counting
// as one digit each), in ascending VariantKey order.
void append_product(const KeywordSpace& space, const AllowedStates& allowed, std::vector<VariantKey>& out) {
  std::vector<Digit> digits = digits_of(space, allowed);
  for (const Digit& d : digits) {
    if (d.values.empty()) return;  // a shortcut with no surviving combination: no variant
  }
  size_t first = out.size();
  std::vector<size_t> at(digits.size(), 0);
  VariantKey key;
  key.choice.resize(allowed.size());
  while (true) {
    for (size_t d = 0; d < digits.size(); ++d) {
      const std::vector<uint32_t>& value = digits[d].values[at[d]];
      for (size_t i = 0; i < value.size(); ++i) key.choice[digits[d].sets[i]] = value[i];
    }
    out.push_back(key);
    size_t d = digits.size();
    while (d > 0 && ++at[d - 1] == digits[d - 1].values.size()) at[--d] = 0;
    if (d == 0) break;
  }
  if (!space.combinations.empty()) std::sort(out.begin() + std::ptrdiff_t(first), out.end());
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
  AllowedStates allowed =
      allowed_states(space, options.stage, options.apply_skip_variants, options.drop_unreachable);
  std::optional<MaterialCombos> combos;
  if (options.materials) combos = material_combos(space, allowed, options.stage, *options.materials);
  BigCount count = view_count(space, allowed, combos ? &*combos : nullptr);
  if (count > BigCount(options.max_variants)) {
    report_too_many(space, options, count, diags);
    return failure("too many variants to enumerate: " + count.to_string());
  }
  std::vector<VariantKey> keys;
  keys.reserve(size_t(*count.to_u64()));
  if (!combos || combos->sets.empty()) {
    append_product(space, allowed, keys);
    return keys;
  }
  // Each material combination pins its shader_feature sets; the other sets
  // still take every allowed state. Combos interleave with the other sets in
  // key order, hence the sort.
  for (const std::vector<uint32_t>& combo : combos->combos) {
    AllowedStates pinned = allowed;
    for (size_t i = 0; i < combo.size(); ++i) pinned[combos->sets[i]] = {combo[i]};
    append_product(space, pinned, keys);
  }
  std::sort(keys.begin(), keys.end());
  return keys;
}

}  // namespace facet::variants
