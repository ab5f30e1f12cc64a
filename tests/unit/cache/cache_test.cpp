// The compile cache's entry format and local backend: round trips, and every
// truncated or altered entry is rejected, never served.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "facet/cache.h"
#include "facet/reflection_json.h"

namespace facet::cache {
namespace {

namespace fs = std::filesystem;

void expect_same(const CacheEntry& a, const CacheEntry& b) {
  EXPECT_EQ(a.spirv, b.spirv);
  EXPECT_EQ(reflection_to_json_text(a.reflection), reflection_to_json_text(b.reflection));
  EXPECT_EQ(a.included_files, b.included_files);
}

CacheEntry sample_entry() {
  CacheEntry e;
  e.spirv = {0x07230203, 0x00010300, 0x00080001, 42, 0, 7, 8, 9};
  e.reflection.stage = Stage::fragment;
  e.reflection.entry_point = "frag";
  e.reflection.uniform_blocks.push_back(
      {.name = "$Globals", .set = 2, .binding = 0, .size = 16, .members = {{.name = "_Color", .type = "float4"}}});
  e.included_files = {"/stdlib/UnityCG.cginc", "/work/My File.cginc"};
  return e;
}

TEST(CacheEntryTest, RoundTrips) {
  CacheEntry e = sample_entry();
  auto back = decode_entry(encode_entry(e));
  ASSERT_TRUE(back);
  expect_same(*back, e);
  EXPECT_EQ(encode_entry(e), encode_entry(e));
}

TEST(CacheEntryTest, EveryTruncationIsRejected) {
  std::string bytes = encode_entry(sample_entry());
  for (size_t n = 0; n < bytes.size(); ++n) EXPECT_FALSE(decode_entry(bytes.substr(0, n))) << n;
  EXPECT_FALSE(decode_entry(bytes + "x"));
}

TEST(CacheEntryTest, EveryByteFlipIsRejected) {
  std::string bytes = encode_entry(sample_entry());
  for (size_t i = 0; i < bytes.size(); ++i) {
    std::string bad = bytes;
    bad[i] = char(bad[i] ^ 0x5a);
    EXPECT_FALSE(decode_entry(bad)) << i;
  }
}

class LocalCacheTest : public testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("facet_cache_test_" + std::to_string(::getpid()) + "_" +
                                        testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
};

TEST_F(LocalCacheTest, MissThenStoreThenHit) {
  LocalCache cache(dir_.string());
  const std::string key = "0123456789abcdef0123456789abcdef";
  LoadResult miss = cache.load(key);
  EXPECT_FALSE(miss.entry);
  EXPECT_FALSE(miss.corrupt);
  ASSERT_TRUE(cache.store(key, sample_entry()));
  LoadResult hit = cache.load(key);
  ASSERT_TRUE(hit.entry);
  expect_same(*hit.entry, sample_entry());
  EXPECT_EQ(cache.path_of(key), (dir_ / "01" / key).string());
  for (const auto& e : fs::recursive_directory_iterator(dir_)) {
    EXPECT_EQ(e.path().string().find(".tmp"), std::string::npos) << "no temporary left: " << e.path();
  }
}

TEST_F(LocalCacheTest, CorruptEntryIsAMissAndIsReplaced) {
  LocalCache cache(dir_.string());
  const std::string key = "fedcba9876543210fedcba9876543210";
  ASSERT_TRUE(cache.store(key, sample_entry()));
  std::string bytes = encode_entry(sample_entry());
  std::ofstream(cache.path_of(key), std::ios::binary | std::ios::trunc) << bytes.substr(0, bytes.size() / 2);
  LoadResult torn = cache.load(key);
  EXPECT_FALSE(torn.entry);
  EXPECT_TRUE(torn.corrupt);
  ASSERT_TRUE(cache.store(key, sample_entry()));
  EXPECT_TRUE(cache.load(key).entry);
}

TEST_F(LocalCacheTest, KeysThatAreNotHexAreRefused) {
  LocalCache cache(dir_.string());
  for (const std::string key : {"../../etc/passwd", "ABCDEF0123456789", "short", ""}) {
    EXPECT_FALSE(cache.store(key, sample_entry())) << key;
    EXPECT_FALSE(cache.load(key).entry) << key;
  }
  EXPECT_FALSE(fs::exists(dir_));
}

TEST_F(LocalCacheTest, UnwritableFolderFailsQuietly) {
  std::ofstream(dir_.string()) << "a file, not a folder";
  LocalCache cache((dir_ / "sub").string());
  EXPECT_FALSE(cache.store("0123456789abcdef0123456789abcdef", sample_entry()));
  fs::remove(dir_);
}

TEST(CacheBuildIdTest, NamesTheVersion) { EXPECT_EQ(build_id().rfind("facet-", 0), 0u); }

}  // namespace
}  // namespace facet::cache
