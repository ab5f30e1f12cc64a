// facetc with a cache folder whose files were swapped, rewritten or replaced
// by things that are not entries: every build succeeds, warns about the
// entry it did not use, and writes the package a build without cache writes.
#include <sys/stat.h>

#include <map>

#include "facet/cache.h"
#include "facetc_test_util.h"

namespace facet::tools::testing {
namespace {

using ::testing::HasSubstr;
using ::testing::Not;

class FacetcCacheCorruptionTest : public FacetcTest {
 protected:
  void SetUp() override {
    FacetcTest::SetUp();
    ASSERT_EQ(facetc({example("Unlit.shader"), "--no-cache", "-o", "ref.facetpkg"}).exit_code, 0);
    FacetcRun cold = build("cold.facetpkg");
    ASSERT_EQ(cold.exit_code, 0) << cold.err;
    for (const auto& e : fs::recursive_directory_iterator(dir_ / "cache")) {
      if (!e.is_regular_file()) continue;
      std::string bytes = read_all(e.path());
      (bytes.starts_with("FACETMANIFEST") ? manifests_ : entries_).push_back(e.path());
    }
    std::sort(entries_.begin(), entries_.end());
    std::sort(manifests_.begin(), manifests_.end());
    ASSERT_EQ(entries_.size(), 2u) << "Unlit: a vertex and a fragment program";
    ASSERT_EQ(manifests_.size(), 2u);
  }

  FacetcRun build(const std::string& output) const {
    return facetc({example("Unlit.shader"), "--cache-dir", "cache", "--stats", "-o", output});
  }

  // A build with the cache as the test left it: it succeeds, says what it
  // refused, and writes the reference package; then a second build finds
  // the cache repaired.
  void expect_refused_and_repaired(const std::string& expected) {
    FacetcRun warm = build("warm.facetpkg");
    ASSERT_EQ(warm.exit_code, 0) << warm.err;
    EXPECT_THAT(warm.err, HasSubstr(expected));
    EXPECT_THAT(warm.err, HasSubstr("warning: "));
    EXPECT_TRUE(read_all(dir_ / "warm.facetpkg") == read_all(dir_ / "ref.facetpkg")) << "a wrong package";
    FacetcRun again = build("again.facetpkg");
    ASSERT_EQ(again.exit_code, 0) << again.err;
    EXPECT_THAT(again.err, Not(HasSubstr("corrupt"))) << "the build replaced what it refused";
    EXPECT_THAT(again.err, HasSubstr("local hits 2 / remote hits 0 / compiled 0"));
    EXPECT_TRUE(read_all(dir_ / "again.facetpkg") == read_all(dir_ / "ref.facetpkg"));
  }

  static std::string key_of(const fs::path& file) { return file.filename().string(); }

  std::vector<fs::path> entries_, manifests_;
};

TEST_F(FacetcCacheCorruptionTest, SwappedEntriesAreNotUsed) {
  std::string a = read_all(entries_[0]), b = read_all(entries_[1]);
  write_all(entries_[0], b);
  write_all(entries_[1], a);
  expect_refused_and_repaired("it was stored under another key (" + key_of(entries_[1]) + ")");
}

TEST_F(FacetcCacheCorruptionTest, ManifestRewrittenToNameAnotherEntryIsNotBelieved) {
  // A manifest that is well formed, bound to its key, with a valid check,
  // but naming the other program's entry.
  auto first = cache::decode_manifest(read_all(manifests_[0]), key_of(manifests_[0]));
  auto second = cache::decode_manifest(read_all(manifests_[1]), key_of(manifests_[1]));
  ASSERT_TRUE(first && second);
  ASSERT_NE(first->entry_key, second->entry_key);
  first->entry_key = second->entry_key;
  write_all(manifests_[0], cache::encode_manifest(key_of(manifests_[0]), *first));
  expect_refused_and_repaired("it holds another program");
}

TEST_F(FacetcCacheCorruptionTest, EntryThatIsAFifoIsRefusedWithoutBlocking) {
  fs::remove(entries_[0]);
  ASSERT_EQ(::mkfifo(entries_[0].c_str(), 0600), 0);
  expect_refused_and_repaired("'" + entries_[0].string().substr(dir_.string().size() + 1) +
                              "': a FIFO, not a regular file");
}

TEST_F(FacetcCacheCorruptionTest, ManifestThatIsAFifoIsRefusedWithoutBlocking) {
  fs::remove(manifests_[0]);
  ASSERT_EQ(::mkfifo(manifests_[0].c_str(), 0600), 0);
  expect_refused_and_repaired("corrupt include manifest");
}

TEST_F(FacetcCacheCorruptionTest, EntryThatIsADirectoryIsRefused) {
  fs::remove(entries_[0]);
  fs::create_directory(entries_[0]);
  FacetcRun warm = build("warm.facetpkg");
  ASSERT_EQ(warm.exit_code, 0) << warm.err;
  EXPECT_THAT(warm.err, HasSubstr("a directory, not a regular file"));
  EXPECT_TRUE(read_all(dir_ / "warm.facetpkg") == read_all(dir_ / "ref.facetpkg"));
}

TEST_F(FacetcCacheCorruptionTest, OversizedEntryIsRefusedUnread) {
  fs::resize_file(entries_[0], cache::kMaxEntryBytes + 1);  // sparse: costs no disk
  expect_refused_and_repaired("67108865 bytes, over the limit of 67108864 bytes");
}

TEST_F(FacetcCacheCorruptionTest, SymlinkToALargeSparseFileIsRefusedUnread) {
  fs::path big = dir_ / "big";
  std::ofstream(big).close();
  fs::resize_file(big, 6ull << 30);
  fs::remove(entries_[1]);
  fs::create_symlink(big, entries_[1]);
  expect_refused_and_repaired("6442450944 bytes, over the limit");
}

TEST_F(FacetcCacheCorruptionTest, ManifestNamingDevZeroIsStaleNotACrash) {
  auto m = cache::decode_manifest(read_all(manifests_[0]), key_of(manifests_[0]));
  ASSERT_TRUE(m);
  m->files.emplace_back("/dev/zero", 0);
  write_all(manifests_[0], cache::encode_manifest(key_of(manifests_[0]), *m));
  expect_refused_and_repaired("it lists '/dev/zero': a device, not a regular file");
}

}  // namespace
}  // namespace facet::tools::testing
