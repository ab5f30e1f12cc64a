// The driver with a compile cache: a warm build compiles nothing and gives
// the same bytes; corrupt entries are recompiled, never used.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "facet/cache.h"
#include "facet/compiler.h"
#include "unit/test_http_server.h"

namespace facet {
namespace {

namespace fs = std::filesystem;

struct Build {
  std::vector<uint8_t> bytes;
  CompileStats stats;
};

Build build(const std::string& cache_dir, unsigned jobs = 2,
            const std::string& path = std::string(FACET_SOURCE_DIR) + "/examples/shaders/Keywords.shader") {
  Compiler compiler;
  SourceMap sources;
  Diagnostics diags;
  auto shader = compiler.load(path, sources, diags);
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

  // Compiled programs (not the include manifests stored beside them).
  std::vector<fs::path> entries() const {
    std::vector<fs::path> out;
    for (const auto& e : fs::recursive_directory_iterator(dir_)) {
      if (!e.is_regular_file()) continue;
      std::ifstream in(e.path(), std::ios::binary);
      char magic[10] = {};
      in.read(magic, sizeof magic);
      if (std::string_view(magic, sizeof magic) == "FACETCACHE") out.push_back(e.path());
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
  EXPECT_EQ(cold.stats.preprocess_skipped, 0u);
  Build warm = build(dir_.string(), 1);
  EXPECT_EQ(warm.stats.preprocess_skipped, warm.stats.stage_programs) << "include manifests are current";
  EXPECT_EQ(warm.stats.compiled, 0u);
  EXPECT_EQ(warm.stats.cache_hits, warm.stats.unique_preprocessed);
  EXPECT_TRUE(reference.bytes == cold.bytes);
  EXPECT_TRUE(reference.bytes == warm.bytes);
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

  Build again = build(dir_.string());  // manifests current: straight to the entries
  EXPECT_EQ(again.stats.cache_corrupt, 4u);
  EXPECT_EQ(again.stats.compiled, 4u);
  EXPECT_TRUE(again.bytes == reference.bytes);
  Build healed = build(dir_.string());
  EXPECT_EQ(healed.stats.cache_corrupt, 0u);
  EXPECT_EQ(healed.stats.compiled, 0u);
}

// Direct mode: a changed include invalidates the manifests that list it; a
// change that leaves the tokens alone still hits the compiled entries.
TEST_F(DriverCacheTest, ChangedIncludesAreNoticedWithoutPreprocessingTheRest) {
  fs::path src = dir_ / "src";
  fs::create_directories(src);
  std::ofstream(src / "Tint.cginc") << "float4 tint(float4 c) { return c * 0.5; }\n";
  std::ofstream(src / "T.shader") << R"(Shader "T/Tint" { SubShader { Pass {
    CGPROGRAM
    #pragma vertex vert
    #pragma fragment frag
    #pragma multi_compile _ A
    #include "Tint.cginc"
    float4 vert(float4 v : POSITION) : SV_POSITION { return v; }
    float4 frag() : SV_Target { return tint(float4(1, 1, 1, 1)); }
    ENDCG
  } } })";
  std::string cache = (dir_ / "cache").string(), shader = (src / "T.shader").string();
  Build cold = build(cache, 2, shader);
  Build warm = build(cache, 2, shader);
  EXPECT_EQ(warm.stats.preprocess_skipped, 4u);
  EXPECT_TRUE(warm.bytes == cold.bytes);

  std::ofstream(src / "Tint.cginc") << "// a comment changes no token\nfloat4 tint(float4 c) { return c * 0.5; }\n";
  Build comment = build(cache, 2, shader);
  EXPECT_EQ(comment.stats.preprocess_skipped, 0u) << "every manifest lists Tint.cginc";
  EXPECT_EQ(comment.stats.compiled, 0u) << "the tokens are the same";

  std::ofstream(src / "Tint.cginc") << "float4 tint(float4 c) { return c * 0.25; }\n";
  Build changed = build(cache, 2, shader);
  EXPECT_EQ(changed.stats.preprocess_skipped, 0u);
  EXPECT_EQ(changed.stats.compiled, 1u) << "only the fragment program calls tint()";
  EXPECT_FALSE(changed.bytes == cold.bytes);
  Build again = build(cache, 2, shader);
  EXPECT_EQ(again.stats.preprocess_skipped, 4u);
  EXPECT_TRUE(again.bytes == changed.bytes);
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


namespace facet {
namespace {

Build build_remote(const std::string& cache_dir, const std::string& url) {
  Compiler compiler;
  SourceMap sources;
  Diagnostics diags;
  auto shader = compiler.load(std::string(FACET_SOURCE_DIR) + "/examples/shaders/Keywords.shader", sources, diags);
  auto compiled = compiler.compile(*shader, {.jobs = 2, .cache_dir = cache_dir, .cache_url = url}, sources, diags);
  EXPECT_TRUE(compiled) << render_text(diags, sources);
  return {package::write_package(compiled->package), compiled->stats};
}

// Two builders share a cache server; the second compiles nothing.
TEST_F(DriverCacheTest, SharedServerServesAnotherBuilder) {
  test_http::TestHttpServer server(cache::sha256_hex);
  Build reference = build("");
  Build first = build_remote((dir_ / "a").string(), server.url());
  EXPECT_EQ(first.stats.cache_hits, 0u);
  EXPECT_GT(server.puts(), 0);
  Build second = build_remote((dir_ / "b").string(), server.url());  // another machine: empty local folder
  EXPECT_EQ(second.stats.compiled, 0u);
  EXPECT_EQ(second.stats.cache_remote_hits, second.stats.cache_hits);
  EXPECT_EQ(second.stats.preprocess_skipped, second.stats.stage_programs) << "manifests come from the server too";
  Build third = build_remote((dir_ / "b").string(), server.url());  // remote hits were copied into b
  EXPECT_EQ(third.stats.cache_remote_hits, 0u);
  EXPECT_EQ(third.stats.compiled, 0u);
  Build remote_only = build_remote("", server.url());
  EXPECT_EQ(remote_only.stats.compiled, 0u);
  EXPECT_TRUE(first.bytes == reference.bytes);
  EXPECT_TRUE(second.bytes == reference.bytes);
  EXPECT_TRUE(third.bytes == reference.bytes);
  EXPECT_TRUE(remote_only.bytes == reference.bytes);
}

}  // namespace
}  // namespace facet
