// The compile cache's entry format and local backend: round trips, and every
// truncated, altered or swapped entry is rejected, never served; what is not
// a regular file, or is too large, is refused without blocking or reading it.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <chrono>
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
  EXPECT_EQ(a.token_hash, b.token_hash);
}

const std::string kKey = "0123456789abcdef0123456789abcdef";
const std::string kOtherKey = "fedcba9876543210fedcba9876543210";

CacheEntry sample_entry() {
  CacheEntry e;
  e.spirv = {0x07230203, 0x00010300, 0x00080001, 42, 0, 7, 8, 9};
  e.reflection.stage = Stage::fragment;
  e.reflection.entry_point = "frag";
  e.reflection.uniform_blocks.push_back(
      {.name = "$Globals", .set = 2, .binding = 0, .size = 16, .members = {{.name = "_Color", .type = "float4"}}});
  e.included_files = {"/stdlib/UnityCG.cginc", "/work/My File.cginc"};
  e.token_hash = 0x1234567890abcdefull;
  return e;
}

TEST(CacheEntryTest, RoundTrips) {
  CacheEntry e = sample_entry();
  auto back = decode_entry(encode_entry(kKey, e), kKey);
  ASSERT_TRUE(back);
  expect_same(*back, e);
  EXPECT_EQ(encode_entry(kKey, e), encode_entry(kKey, e));
}

TEST(CacheEntryTest, AnEntryIsBoundToItsKey) {
  auto moved = decode_entry(encode_entry(kKey, sample_entry()), kOtherKey);
  ASSERT_FALSE(moved) << "an entry stored under one key must not decode under another";
  EXPECT_NE(moved.error().reason.find("stored under another key (" + kKey + ")"), std::string::npos)
      << moved.error().reason;
}

TEST(CacheManifestTest, RoundTripsAndIsBoundToItsKey) {
  IncludeManifest m{.entry_key = kOtherKey, .token_hash = 42, .files = {{"/a/b.cginc", 7}, {"/c d.hlsl", 9}}};
  auto back = decode_manifest(encode_manifest(kKey, m), kKey);
  ASSERT_TRUE(back);
  EXPECT_EQ(back->entry_key, m.entry_key);
  EXPECT_EQ(back->token_hash, m.token_hash);
  EXPECT_EQ(back->files, m.files);
  auto moved = decode_manifest(encode_manifest(kKey, m), kOtherKey);
  ASSERT_FALSE(moved);
  EXPECT_NE(moved.error().reason.find("stored under another key"), std::string::npos) << moved.error().reason;
  std::string bytes = encode_manifest(kKey, m);
  for (size_t n = 0; n < bytes.size(); ++n) EXPECT_FALSE(decode_manifest(bytes.substr(0, n), kKey)) << n;
}

TEST(CacheEntryTest, EveryTruncationIsRejected) {
  std::string bytes = encode_entry(kKey, sample_entry());
  for (size_t n = 0; n < bytes.size(); ++n) EXPECT_FALSE(decode_entry(bytes.substr(0, n), kKey)) << n;
  EXPECT_FALSE(decode_entry(bytes + "x", kKey));
}

TEST(CacheEntryTest, EveryByteFlipIsRejected) {
  std::string bytes = encode_entry(kKey, sample_entry());
  for (size_t i = 0; i < bytes.size(); ++i) {
    std::string bad = bytes;
    bad[i] = char(bad[i] ^ 0x5a);
    EXPECT_FALSE(decode_entry(bad, kKey)) << i;
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
  EXPECT_FALSE(miss.corrupt());
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
  std::string bytes = encode_entry(key, sample_entry());
  std::ofstream(cache.path_of(key), std::ios::binary | std::ios::trunc) << bytes.substr(0, bytes.size() / 2);
  LoadResult torn = cache.load(key);
  EXPECT_FALSE(torn.entry);
  EXPECT_TRUE(torn.corrupt());
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

TEST_F(LocalCacheTest, SwappedEntriesAreCorruptNotServed) {
  LocalCache cache(dir_.string());
  CacheEntry a = sample_entry(), b = sample_entry();
  b.spirv.push_back(99);
  ASSERT_TRUE(cache.store(kKey, a));
  ASSERT_TRUE(cache.store(kOtherKey, b));
  fs::path swap = dir_ / "swap";
  fs::rename(cache.path_of(kKey), swap);
  fs::rename(cache.path_of(kOtherKey), cache.path_of(kKey));
  fs::rename(swap, cache.path_of(kOtherKey));
  for (const std::string& key : {kKey, kOtherKey}) {
    LoadResult swapped = cache.load(key);
    EXPECT_FALSE(swapped.entry) << key;
    EXPECT_NE(swapped.problem.find("stored under another key"), std::string::npos) << swapped.problem;
  }
}

// Each load must come back at once with the entry refused: a FIFO would
// block a plain open, a directory once aborted with bad_alloc, and a
// symlink to a huge file was read whole.
TEST_F(LocalCacheTest, WhatIsNotASmallRegularFileIsRefusedUnread) {
  LocalCache cache(dir_.string());
  fs::create_directories(fs::path(cache.path_of(kKey)).parent_path());
  auto refused = [&](const std::string& what) {
    auto started = std::chrono::steady_clock::now();
    LoadResult r = cache.load(kKey);
    EXPECT_LT(std::chrono::steady_clock::now() - started, std::chrono::seconds(5)) << what;
    EXPECT_FALSE(r.entry) << what;
    fs::remove_all(cache.path_of(kKey));
    return r.problem;
  };
  ASSERT_EQ(::mkfifo(cache.path_of(kKey).c_str(), 0600), 0);
  EXPECT_NE(refused("fifo").find("a FIFO, not a regular file"), std::string::npos);
  fs::create_directory(cache.path_of(kKey));
  EXPECT_NE(refused("directory").find("a directory, not a regular file"), std::string::npos);
  fs::path big = dir_ / "big";
  std::ofstream(big).close();
  fs::resize_file(big, 6ull << 30);  // sparse: no disk
  fs::create_symlink(big, cache.path_of(kKey));
  EXPECT_NE(refused("symlink to 6 GiB").find("over the limit of 67108864 bytes"), std::string::npos);
  std::ofstream(cache.path_of(kKey)).close();
  fs::resize_file(cache.path_of(kKey), kMaxEntryBytes + 1);
  EXPECT_NE(refused("oversized").find("over the limit"), std::string::npos);
  fs::create_symlink("/dev/zero", cache.path_of(kKey));
  EXPECT_NE(refused("/dev/zero").find("a device, not a regular file"), std::string::npos);
  ASSERT_TRUE(cache.store(kKey, sample_entry())) << "a store replaces what was refused";
  EXPECT_TRUE(cache.load(kKey).entry);
}

TEST_F(LocalCacheTest, HashFileRefusesDevicesFifosAndHugeFiles) {
  fs::create_directories(dir_);
  EXPECT_FALSE(hash_file("/dev/zero").hash);
  EXPECT_NE(hash_file("/dev/zero").problem.find("a device"), std::string::npos);
  ASSERT_EQ(::mkfifo((dir_ / "fifo").c_str(), 0600), 0);
  EXPECT_NE(hash_file((dir_ / "fifo").string()).problem.find("a FIFO"), std::string::npos);
  std::ofstream(dir_ / "big").close();
  fs::resize_file(dir_ / "big", 6ull << 30);
  EXPECT_NE(hash_file((dir_ / "big").string()).problem.find("over the limit"), std::string::npos);
  FileHash missing = hash_file((dir_ / "missing").string());
  EXPECT_FALSE(missing.hash);
  EXPECT_EQ(missing.problem, "") << "a missing file only makes a manifest stale";
  std::ofstream(dir_ / "small") << "abc";
  EXPECT_TRUE(hash_file((dir_ / "small").string()).hash);
}

TEST_F(LocalCacheTest, StoresCheckTheTokenHashAManifestExpects) {
  CacheStores stores{.local = LocalCache(dir_.string())};
  stores.store_entry(kKey, sample_entry());
  EntryLookup hit = stores.load_entry(kKey, sample_entry().token_hash);
  ASSERT_TRUE(hit.entry);
  EXPECT_TRUE(hit.problems.empty());
  EntryLookup other = stores.load_entry(kKey, 1);
  EXPECT_FALSE(other.entry);
  EXPECT_TRUE(other.other_program);
  ASSERT_EQ(other.problems.size(), 1u);
  EXPECT_NE(other.problems[0].find("corrupt cache entry '" + LocalCache(dir_.string()).path_of(kKey) + "'"),
            std::string::npos)
      << other.problems[0];
}

TEST(CacheBuildIdTest, NamesTheVersion) { EXPECT_EQ(build_id().rfind("facet-", 0), 0u); }

}  // namespace
}  // namespace facet::cache
