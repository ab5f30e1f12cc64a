// merge_packages: shards of one build back into one package.
#include <fmt/format.h>

#include <map>

#include "facet/package.h"

namespace facet::package {
namespace {

// Everything but the variants, the SPIR-V and the shard index, which is
// what shards share.
std::string frame_of(const Package& p) {
  Package frame = p;
  frame.build.shard_index = 0;
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

std::string name_of(const std::vector<std::string>& names, size_t i) {
  return i < names.size() ? fmt::format("'{}'", names[i]) : fmt::format("package #{}", i);
}

std::string shard_text(const BuildRecord& b) { return fmt::format("shard {}/{}", b.shard_index, b.shard_count); }

// Exactly shards 0..N-1 of one build, each once; else an error naming the
// foreign, repeated or missing shard. A merge of less would write a package
// that silently lacks variants.
bool shards_make_one_build(const std::vector<Package>& shards, const std::vector<std::string>& names,
                           Diagnostics& diags) {
  const BuildRecord& first = shards[0].build;
  auto fail = [&](std::string message) {
    diags.add(DiagId::package_merge_mismatch, {}, std::move(message));
    return false;
  };
  std::map<uint32_t, size_t> given;  // shard index -> the package that is it
  for (size_t i = 0; i < shards.size(); ++i) {
    const BuildRecord& b = shards[i].build;
    if (b.shard_count != first.shard_count || b.build_id != first.build_id) {
      return fail(fmt::format("{} is not of the same build as {}: {} of build {:016x} vs {} of build {:016x} "
                              "(another shader, shader text or options)",
                              name_of(names, i), name_of(names, 0), shard_text(b), b.build_id, shard_text(first),
                              first.build_id));
    }
    auto [it, inserted] = given.emplace(b.shard_index, i);
    if (!inserted) {
      return fail(fmt::format("{} is given twice: {} and {}", shard_text(b), name_of(names, it->second),
                              name_of(names, i)));
    }
  }
  std::vector<std::string> missing;
  for (uint32_t s = 0; s < first.shard_count && missing.size() < 16; ++s) {
    if (!given.count(s)) missing.push_back(std::to_string(s));
  }
  if (!missing.empty()) {
    size_t absent = first.shard_count - given.size();
    return fail(fmt::format("the build has {} shards, but shard{} {}{}/{} {} not given; merging fewer would "
                            "write a package without their variants",
                            first.shard_count, absent == 1 ? "" : "s", fmt::join(missing, ", "),
                            absent > missing.size() ? ", ..." : "", first.shard_count, absent == 1 ? "is" : "are"));
  }
  return true;
}

}  // namespace

Result<Package> merge_packages(const std::vector<Package>& shards, Diagnostics& diags,
                               const std::vector<std::string>& names) {
  if (shards.empty()) {
    diags.add(DiagId::package_merge_mismatch, {}, "nothing to merge");
    return failure("no shards");
  }
  if (!shards_make_one_build(shards, names, diags)) return failure("incomplete or mixed shards");
  const std::string frame = frame_of(shards[0]);
  for (size_t i = 1; i < shards.size(); ++i) {
    if (frame_of(shards[i]) != frame) {
      diags.add(DiagId::package_merge_mismatch, {},
                fmt::format("{} is not of the same build as {}: shader '{}' vs '{}', or its passes, "
                            "properties or keyword spaces differ",
                            name_of(names, i), name_of(names, 0), shards[i].shader_name, shards[0].shader_name));
      return failure("mismatched shards");
    }
  }
  Package out = shards[0];
  out.build.shard_index = 0;  // the whole build, as its unsharded package records it
  out.build.shard_count = 1;
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
