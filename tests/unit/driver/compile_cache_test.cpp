// The driver with a compile cache: a warm build compiles nothing and gives
// the same bytes; corrupt entries are recompiled, never used.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "facet/cache.h"
#include "facet/compiler.h"

namespace facet {
namespace {

namespace fs = std::filesystem;

struct Build {
  std::vector<uint8_t> bytes;
  CompileStats stats;
};

Build build(const std::string& cache_dir, unsigned jobs = 2) {
  Compiler compiler;
  SourceMap sources;
  Diagnostics diags;
  auto shader = compiler.load(std::string(FACET_SOURCE_DIR) + "/examples/shaders/Keywords.shader", sources, diags);
  EXPECT_TRUE(shader);
  auto compiled = compiler.compile(*shader, {.jobs = jobs, .cache_dir = cache_dir}, sources, diags);
  EXPECT_TRUE(compiled) << render_text(diags, sources);
  return {package::write_package(compiled->package), compiled->stats};
}

class DriverCacheTest : public testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("facet_driver_cache_" + std::to_string(::getpid()) + "_" +
                                        testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  std::vector<fs::path> entries() const {
    std::vector<fs::path> out;
    for (const auto& e : fs::recursive_directory_iterator(dir_)) {
      if (e.is_regular_file()) out.push_back(e.path());
    }
    std::sort(out.begin(), out.end());
    return out;
  }
  fs::path dir_;
};

TEST_F(DriverCacheTest, WarmBuildCompilesNothingAndGivesTheSameBytes) {
  Build reference = build("");
  Build cold = build(dir_.string());
  EXPECT_EQ(cold.stats.cache_hits, 0u);
  EXPECT_EQ(cold.stats.compiled, cold.stats.unique_preprocessed);
  EXPECT_EQ(entries().size(), cold.stats.unique_preprocessed);
  Build warm = build(dir_.string(), 1);
  EXPECT_EQ(warm.stats.compiled, 0u);
  EXPECT_EQ(warm.stats.cache_hits, warm.stats.unique_preprocessed);
  EXPECT_EQ(reference.bytes, cold.bytes);
  EXPECT_EQ(reference.bytes, warm.bytes);
}

TEST_F(DriverCacheTest, CorruptEntriesAreRecompiledNeverUsed) {
  Build reference = build(dir_.string());
  std::vector<fs::path> files = entries();
  ASSERT_GE(files.size(), 4u);
  // A torn write (half an entry), garbage, an empty file, and a valid entry
  // of another program under this key: each is caught by a check.
  auto bytes = [](const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
  };
  std::string whole = bytes(files[0]);
  std::ofstream(files[0], std::ios::binary | std::ios::trunc) << whole.substr(0, whole.size() / 2);
  std::ofstream(files[1], std::ios::binary | std::ios::trunc) << "not a cache entry";
  std::ofstream(files[2], std::ios::binary | std::ios::trunc);
  std::string flipped = bytes(files[3]);
  flipped[flipped.size() / 2] ^= 1;
  std::ofstream(files[3], std::ios::binary | std::ios::trunc) << flipped;

  Build again = build(dir_.string());
  EXPECT_EQ(again.stats.cache_corrupt, 4u);
  EXPECT_EQ(again.stats.compiled, 4u);
  EXPECT_EQ(again.bytes, reference.bytes);
  Build healed = build(dir_.string());
  EXPECT_EQ(healed.stats.cache_corrupt, 0u);
  EXPECT_EQ(healed.stats.compiled, 0u);
}

TEST_F(DriverCacheTest, KeysChangeWithOptions) {
  (void)build(dir_.string());
  size_t first = entries().size();
  Compiler compiler;
  SourceMap sources;
  Diagnostics diags;
  auto shader = compiler.load(std::string(FACET_SOURCE_DIR) + "/examples/shaders/Keywords.shader", sources, diags);
  CompileOptions options{.cache_dir = dir_.string()};
  options.backend.opt = backend::OptLevel::none;
  auto compiled = compiler.compile(*shader, options, sources, diags);
  ASSERT_TRUE(compiled);
  EXPECT_EQ(compiled->stats.cache_hits, 0u) << "-O0 must not reuse -O entries";
  EXPECT_EQ(entries().size(), 2 * first);
}

}  // namespace
}  // namespace facet
