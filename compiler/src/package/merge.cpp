// merge_packages: shards of one build back into one package.
#include <fmt/format.h>

#include <map>

#include "facet/package.h"

namespace facet::package {
namespace {

// Everything but the variants and the SPIR-V, which is what shards share.
std::string frame_of(const Package& p) {
  Package frame = p;
  frame.spirv_blobs.clear();
  for (PackagePass& pass : frame.passes) pass.variants.clear();
  return package_to_json(frame);
}

bool same_stages(const PackageVariant& a, const Package& pa, const PackageVariant& b, const Package& pb) {
  if (a.stages.size() != b.stages.size() || a.keywords != b.keywords) return false;
  for (size_t i = 0; i < a.stages.size(); ++i) {
    if (a.stages[i].stage != b.stages[i].stage ||
        pa.spirv_blobs[a.stages[i].blob] != pb.spirv_blobs[b.stages[i].blob]) {
      return false;
    }
  }
  return true;
}

}  // namespace

Result<Package> merge_packages(const std::vector<Package>& shards, Diagnostics& diags) {
  if (shards.empty()) {
    diags.add(DiagId::package_merge_mismatch, {}, "nothing to merge");
    return failure("no shards");
  }
  const std::string frame = frame_of(shards[0]);
  for (size_t i = 1; i < shards.size(); ++i) {
    if (frame_of(shards[i]) != frame) {
      diags.add(DiagId::package_merge_mismatch, {},
                fmt::format("shard {} is not of the same build as shard 0: shader '{}' vs '{}', or its passes, "
                            "properties or keyword spaces differ",
                            i, shards[i].shader_name, shards[0].shader_name));
      return failure("mismatched shards");
    }
  }
  Package out = shards[0];
  out.spirv_blobs.clear();
  for (size_t p = 0; p < out.passes.size(); ++p) {
    std::map<variants::VariantKey, std::pair<const PackageVariant*, const Package*>> by_key;
    for (const Package& shard : shards) {
      for (const PackageVariant& v : shard.passes[p].variants) {
        auto [it, inserted] = by_key.emplace(v.key, std::make_pair(&v, &shard));
        if (!inserted && !same_stages(*it->second.first, *it->second.second, v, shard)) {
          diags.add(DiagId::package_merge_mismatch, {},
                    fmt::format("pass {} has the variant {{{}}} in two shards with different SPIR-V", p,
                                fmt::join(v.keywords, " ")));
          return failure("conflicting variants");
        }
      }
    }
    out.passes[p].variants.clear();
    for (const auto& [key, found] : by_key) {
      PackageVariant v = *found.first;
      for (PackageStage& s : v.stages) {  // blobs appended, then stored once below
        out.spirv_blobs.push_back(found.second->spirv_blobs[s.blob]);
        s.blob = uint32_t(out.spirv_blobs.size() - 1);
      }
      out.passes[p].variants.push_back(std::move(v));
    }
  }
  deduplicate_blobs(out);
  if (!validate_package(out, diags)) return failure("invalid merge");
  return out;
}

}  // namespace facet::package
