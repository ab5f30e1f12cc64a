// The invariants of a Package beyond its byte layout (validate_package), and
// blob deduplication.
#include <algorithm>
#include <unordered_map>
#include <string>

#include <xxhash.h>

#include "facet/package.h"
#include "codec.h"

namespace facet::package {
namespace {

std::string key_text(const variants::VariantKey& key) {
  std::string out = "[";
  for (size_t i = 0; i < key.choice.size(); ++i) {
    if (i) out += ", ";
    out += std::to_string(key.choice[i]);
  }
  return out + "]";
}

// Depth of the deepest member list; 1 for members without nested members.
uint32_t member_depth(const std::vector<BlockMember>& members) {
  uint32_t deepest = 0;
  for (const BlockMember& m : members) deepest = std::max(deepest, member_depth(m.members));
  return members.empty() ? 0 : deepest + 1;
}

std::string check_key(const variants::KeywordSpace& space, const variants::VariantKey& key) {
  if (key.choice.size() != space.sets.size()) {
    return "variant key " + key_text(key) + " has " + std::to_string(key.choice.size()) + " choices for " +
           std::to_string(space.sets.size()) + " keyword sets";
  }
  for (size_t i = 0; i < key.choice.size(); ++i) {
    if (key.choice[i] != variants::kOffChoice && key.choice[i] >= space.sets[i].keywords.size()) {
      return "variant key " + key_text(key) + " chooses keyword " + std::to_string(key.choice[i]) + " of set " +
             std::to_string(i) + ", which has " + std::to_string(space.sets[i].keywords.size());
    }
  }
  return {};
}

std::string check_stages(const PackageVariant& v, size_t blob_count) {
  for (size_t i = 0; i < v.stages.size(); ++i) {
    const PackageStage& s = v.stages[i];
    if (i > 0 && s.stage <= v.stages[i - 1].stage) {
      return "stages of variant " + key_text(v.key) + " are not in strictly increasing stage order";
    }
    if (s.blob >= blob_count) {
      return "blob index " + std::to_string(s.blob) + " out of range (" + std::to_string(blob_count) + " blobs)";
    }
    for (const UniformBlock& b : s.reflection.uniform_blocks) {
      if (member_depth(b.members) > codec::kMaxMemberDepth) {
        return "members of block '" + b.name + "' nested deeper than " + std::to_string(codec::kMaxMemberDepth) +
               " levels";
      }
    }
  }
  return {};
}

bool both_set(const ir::StateValue& v) { return !v.literal.empty() && !v.property.empty(); }
bool both_set(const std::optional<ir::StateValue>& v) { return v && both_set(*v); }

bool state_has_ambiguous_value(const ir::RenderState& s) {
  for (const auto* v : {&s.cull, &s.ztest, &s.zwrite, &s.alpha_to_mask, &s.zclip, &s.conservative, &s.offset_factor,
                        &s.offset_units}) {
    if (both_set(*v)) return true;
  }
  for (const ir::BlendState& b : s.blend) {
    if (both_set(b.src) || both_set(b.dst) || both_set(b.src_alpha) || both_set(b.dst_alpha)) return true;
  }
  for (const ir::BlendOpState& b : s.blend_op) {
    if (both_set(b.color_op) || both_set(b.alpha_op)) return true;
  }
  for (const ir::ColorMaskState& c : s.color_mask) {
    if (both_set(c.mask)) return true;
  }
  if (const auto& st = s.stencil) {
    for (const auto* v : {&st->ref, &st->read_mask, &st->write_mask, &st->comp, &st->pass, &st->fail, &st->zfail,
                          &st->comp_back, &st->pass_back, &st->fail_back, &st->zfail_back, &st->comp_front,
                          &st->pass_front, &st->fail_front, &st->zfail_front}) {
      if (both_set(*v)) return true;
    }
  }
  return false;
}

}  // namespace

namespace codec {

std::string check_variant(const variants::KeywordSpace& space, const PackageVariant& v,
                          const PackageVariant* previous, size_t blob_count) {
  if (previous && !(previous->key < v.key)) {
    return "variant key " + key_text(v.key) + " is not greater than the previous key " + key_text(previous->key);
  }
  std::string error = check_key(space, v.key);
  if (error.empty()) error = check_stages(v, blob_count);
  return error;
}

}  // namespace codec

bool validate_package(const Package& package, Diagnostics& diags) {
  bool ok = true;
  auto report = [&](const std::string& where, const std::string& what) {
    diags.add(DiagId::package_corrupt, SourceSpan{}, "invalid package: " + where + ": " + what);
    ok = false;
  };
  if (package.build.shard_index >= package.build.shard_count) {
    report("build record", "shard " + std::to_string(package.build.shard_index) + " of " +
                               std::to_string(package.build.shard_count) + " is no shard of its build");
  }
  for (const PackagePass& pass : package.passes) {
    std::string where = "pass '" + pass.name + "'";
    if (state_has_ambiguous_value(pass.state)) {
      report(where, "a render-state value has both a literal and a property");
    }
    for (size_t i = 0; i < pass.variants.size(); ++i) {
      const PackageVariant* previous = i ? &pass.variants[i - 1] : nullptr;
      std::string error = codec::check_variant(pass.keywords, pass.variants[i], previous, package.spirv_blobs.size());
      if (!error.empty()) report(where, error);
    }
  }
  return ok;
}

void deduplicate_blobs(Package& package) {
  // Hash first, compare words only on a hash match: linear in the blob bytes.
  std::unordered_multimap<uint64_t, uint32_t> by_hash;
  std::vector<std::vector<uint32_t>> blobs;
  std::vector<uint32_t> remap(package.spirv_blobs.size(), UINT32_MAX);
  auto unique_index = [&](uint32_t old_index) {
    if (remap[old_index] != UINT32_MAX) return remap[old_index];
    std::vector<uint32_t>& blob = package.spirv_blobs[old_index];
    uint64_t hash = XXH3_64bits(blob.data(), blob.size() * sizeof(uint32_t));
    auto [first, last] = by_hash.equal_range(hash);
    for (auto it = first; it != last; ++it) {
      if (blobs[it->second] == blob) return remap[old_index] = it->second;
    }
    uint32_t index = uint32_t(blobs.size());
    by_hash.emplace(hash, index);
    blobs.push_back(std::move(blob));
    return remap[old_index] = index;
  };
  for (PackagePass& pass : package.passes) {
    for (PackageVariant& v : pass.variants) {
      for (PackageStage& s : v.stages) {
        // An invalid index stays invalid for validate_package.
        s.blob = s.blob < package.spirv_blobs.size() ? unique_index(s.blob) : UINT32_MAX;
      }
    }
  }
  package.spirv_blobs = std::move(blobs);
}

}  // namespace facet::package
