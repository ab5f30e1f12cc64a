// The build record (format 3): which shard of which build a package is,
// and merge_packages refusing a set of shards that is not one whole build.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "facet/package.h"

namespace facet::package {
namespace {

using ::testing::HasSubstr;

// Shard `index` of a build of `count` shards: one pass, two variants of one
// keyword set, the variant `index` of them (as --shard deals them out).
Package shard(uint32_t index, uint32_t count, uint64_t build_id = 0x1234) {
  Package p;
  p.shader_name = "S";
  p.build = {.shard_index = index, .shard_count = count, .build_id = build_id};
  p.passes = {{"P", {}, {}, {}, {}}};
  p.passes[0].keywords.sets = {{variants::KeywordDirective::multi_compile, false, kAllStages, {"", "_ON"},
                                "multi_compile", {}}};
  for (uint32_t v = 0; v < 2; ++v) {
    if (count > 1 && v % count != index) continue;
    p.passes[0].variants.push_back({{{v}}, v ? std::vector<std::string>{"_ON"} : std::vector<std::string>{},
                                    {{Stage::fragment, uint32_t(p.spirv_blobs.size()), {}}}});
    p.spirv_blobs.push_back({0x07230203, v});
  }
  return p;
}

std::string merge_error(const std::vector<Package>& shards, const std::vector<std::string>& names) {
  Diagnostics diags;
  auto merged = merge_packages(shards, diags, names);
  if (merged) return "";
  return diags.all().empty() ? "(no diagnostic)" : diags.all()[0].message;
}

TEST(PackageBuildRecordTest, ReadsBackFromTheBytes) {
  Diagnostics diags;
  auto back = read_package(write_package(shard(1, 2, 0xfeedfacecafebeefull)), diags);
  ASSERT_TRUE(back.has_value()) << diags.all()[0].message;
  EXPECT_EQ(back->build, (BuildRecord{1, 2, 0xfeedfacecafebeefull}));
  EXPECT_THAT(package_to_json(*back), HasSubstr("\"id\": \"feedfacecafebeef\""));
}

TEST(PackageBuildRecordTest, AShardIndexPastTheCountIsInvalid) {
  Package p = shard(0, 2);
  p.build.shard_index = 2;
  Diagnostics diags;
  EXPECT_FALSE(validate_package(p, diags));
  auto back = read_package(write_package(p), diags);
  EXPECT_FALSE(back.has_value());
}

TEST(PackageMergeShardsTest, AllShardsOfOneBuildMergeIntoAWholeBuild) {
  Diagnostics diags;
  auto merged = merge_packages({shard(1, 2), shard(0, 2)}, diags);
  ASSERT_TRUE(merged.has_value()) << diags.all()[0].message;
  EXPECT_EQ(merged->build, (BuildRecord{0, 1, 0x1234}));
  EXPECT_EQ(merged->passes[0].variants.size(), 2u);
  EXPECT_EQ(write_package(*merged), write_package(shard(0, 1))) << "the unsharded package, byte for byte";
}

TEST(PackageMergeShardsTest, OneShardOfTwoIsRefusedNamingTheMissingShard) {
  EXPECT_THAT(merge_error({shard(0, 2)}, {"a.facetpkg"}), HasSubstr("shard 1/2 is not given"));
}

TEST(PackageMergeShardsTest, TheSameShardTwiceIsRefusedNamingBothFiles) {
  EXPECT_THAT(merge_error({shard(0, 2), shard(0, 2), shard(1, 2)}, {"a.facetpkg", "b.facetpkg", "c.facetpkg"}),
              HasSubstr("shard 0/2 is given twice: 'a.facetpkg' and 'b.facetpkg'"));
  EXPECT_THAT(merge_error({shard(0, 1), shard(0, 1)}, {"x.facetpkg", "x.facetpkg"}),
              HasSubstr("shard 0/1 is given twice"));
}

TEST(PackageMergeShardsTest, ShardsOfDifferentBuildsAreRefused) {
  EXPECT_THAT(merge_error({shard(0, 2, 1), shard(1, 2, 2)}, {"a.facetpkg", "b.facetpkg"}),
              HasSubstr("'b.facetpkg' is not of the same build as 'a.facetpkg'"));
  EXPECT_THAT(merge_error({shard(0, 2), shard(1, 3)}, {"a.facetpkg", "b.facetpkg"}),
              HasSubstr("shard 1/3 of build 0000000000001234 vs shard 0/2"));
}

TEST(PackageMergeShardsTest, ManyMissingShardsAreListedInShort) {
  std::string error = merge_error({shard(3, 100)}, {});
  EXPECT_THAT(error, HasSubstr("the build has 100 shards, but shards 0, 1, 2, 4,"));
  EXPECT_THAT(error, HasSubstr(", .../100 are not given"));
}

}  // namespace
}  // namespace facet::package
