// Every example shader compiles for all of its variants to SPIR-V that passes
// spirv-val and cross-compiles to GLSL 450, ESSL 300 (vertex and fragment
// stages) and MSL (all but geometry stages).
#include <gtest/gtest.h>

#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <thread>

#include "facet/build_farm.h"
#include "facet/compiler.h"

namespace facet {
namespace {

namespace fs = std::filesystem;

std::vector<std::string> example_shaders() {
  std::vector<std::string> paths;
  for (const auto& e : fs::directory_iterator(fs::path(FACET_SOURCE_DIR) / "examples" / "shaders")) {
    if (e.path().extension() == ".shader") paths.push_back(e.path().string());
  }
  std::sort(paths.begin(), paths.end());
  return paths;
}

class DriverExamplesTest : public testing::TestWithParam<std::string> {};

TEST_P(DriverExamplesTest, EveryVariantValidatesAndCrossCompiles) {
  Compiler compiler;
  SourceMap sources;
  Diagnostics diags;
  auto shader = compiler.load(GetParam(), sources, diags);
  ASSERT_TRUE(shader) << render_text(diags, sources);
  auto compiled = compiler.compile(*shader, {}, sources, diags);
  ASSERT_TRUE(compiled) << render_text(diags, sources);
  EXPECT_EQ(diags.error_count(), 0u);
  const package::Package& pkg = compiled->package;
  ASSERT_FALSE(pkg.passes.empty());
  for (const package::PackagePass& pass : pkg.passes) {
    // Every variant after skip_variants that facet's renderer can reach is in the package.
    EXPECT_EQ(variants::count_variants(pass.keywords).reachable.to_string(), std::to_string(pass.variants.size()))
        << pass.name;
    for (const package::PackageVariant& variant : pass.variants) EXPECT_FALSE(variant.stages.empty());
  }
  const std::pair<backend::CrossTarget, const char*> targets[] = {
      {backend::CrossTarget::glsl450, "#version 450"},
      {backend::CrossTarget::essl300, "#version 300 es"},
      {backend::CrossTarget::msl, "#include <metal_stdlib>"}};
  std::vector<bool> checked(pkg.spirv_blobs.size(), false);
  for (const package::PackagePass& pass : pkg.passes) {
    for (const package::PackageVariant& variant : pass.variants) {
      for (const package::PackageStage& stage : variant.stages) {
        if (checked[stage.blob]) continue;
        checked[stage.blob] = true;
        const std::vector<uint32_t>& spirv = pkg.spirv_blobs[stage.blob];
        Diagnostics check;
        EXPECT_TRUE(backend::validate(spirv, backend::TargetEnv::vulkan1_1, check)) << render_text(check, sources);
        for (auto [target, marker] : targets) {
          // ESSL 300 has only vertex and fragment stages.
          bool vertex_or_fragment = stage.stage == Stage::vertex || stage.stage == Stage::fragment;
          if (target == backend::CrossTarget::essl300 && !vertex_or_fragment) continue;
          // Metal has no geometry stage, and SPIRV-Cross refuses a geometry
          // module that reads SV_PrimitiveID (GeometryExtrude does).
          if (target == backend::CrossTarget::msl && stage.stage == Stage::geometry) continue;
          auto text = backend::cross_compile(spirv, stage.stage, target, check);
          ASSERT_TRUE(text) << render_text(check, sources);
          EXPECT_NE(text->find(marker), std::string::npos);
        }
      }
    }
  }
  EXPECT_EQ(std::count(checked.begin(), checked.end(), true), long(pkg.spirv_blobs.size()));
}

INSTANTIATE_TEST_SUITE_P(Examples, DriverExamplesTest, testing::ValuesIn(example_shaders()),
                         [](const auto& info) { return fs::path(info.param).stem().string(); });

struct Built {
  std::vector<uint8_t> bytes;
  CompileStats stats;
};

Built build(const std::string& path, unsigned jobs) {
  Compiler compiler;
  SourceMap sources;
  Diagnostics diags;
  auto shader = compiler.load(path, sources, diags);
  EXPECT_TRUE(shader) << render_text(diags, sources);
  if (!shader) return {};
  auto compiled = compiler.compile(*shader, {.jobs = jobs}, sources, diags);
  EXPECT_TRUE(compiled) << render_text(diags, sources);
  if (!compiled) return {};
  return {package::write_package(compiled->package), compiled->stats};
}

std::string example(const char* name) { return std::string(FACET_SOURCE_DIR) + "/examples/shaders/" + name; }

TEST(DriverCompileTest, PackageBytesDoNotDependOnTheRunOrTheThreadCount) {
  Built one = build(example("Keywords.shader"), 1);
  EXPECT_EQ(one.stats.jobs, 1u);
  EXPECT_EQ(one.bytes, build(example("Keywords.shader"), 1).bytes);
  Built two = build(example("Keywords.shader"), 2);
  EXPECT_EQ(two.stats.jobs, std::min(2u, std::max(1u, std::thread::hardware_concurrency())));
  EXPECT_EQ(one.bytes, two.bytes);
  EXPECT_EQ(one.bytes, build(example("Keywords.shader"), 4).bytes);
}

// An arena of 2^31 threads crashed inside TBB: more jobs than cores is one a core.
TEST(DriverCompileTest, MoreJobsThanCoresRunOneThreadACore) {
  Built huge = build(example("Keywords.shader"), 2147483647u);
  EXPECT_EQ(huge.stats.jobs, std::max(1u, std::thread::hardware_concurrency()));
  EXPECT_EQ(huge.bytes, build(example("Keywords.shader"), 1).bytes);
}

// Dedupe ladder: programs needed -> distinct preprocessed tokens (compiled
// once each) -> distinct SPIR-V (stored once).
TEST(DriverCompileTest, ProgramsWithEqualTokensCompileOnce) {
  // ForwardBase: 8 fwdbase variants, whose VERTEXLIGHT_ON reaches only the
  // vertex stage (8 + 4 programs); ForwardAdd: 5 lights x 2.
  // Most light keywords change no token that an entry point reaches, so
  // most programs collapse before glslang ever runs (POINT_COOKIE into
  // POINT; DIRECTIONAL_COOKIE's vertex stage into POINT's, its fragment stage,
  // which samples the cookie, stays its own; ForwardBase's SHADOWS_SCREEN
  // variants pass and sample the shadow coordinate, so they stay their own).
  Built phong = build(example("PhongMultiLight.shader"), 2);
  EXPECT_EQ(phong.stats.stage_programs, 22u);
  EXPECT_EQ(phong.stats.unique_preprocessed, 10u);
  EXPECT_EQ(phong.stats.unique_spirv, 9u);

  fs::path dir = fs::temp_directory_path() / ("facet_dedupe_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  std::ofstream(dir / "unused.shader") << R"(Shader "T/Unused" {
  SubShader { Pass {
    CGPROGRAM
    #pragma vertex vert
    #pragma fragment frag
    #pragma multi_compile _ NEVER_TESTED
    #pragma multi_compile _ RED
    float4 vert(float4 v : POSITION) : SV_POSITION { return v; }
    float4 frag() : SV_Target {
    #ifdef RED
      return float4(1, 0, 0, 1);
    #else
      return 1;
    #endif
    }
    ENDCG
  } }
})";
  Built unused = build((dir / "unused.shader").string(), 2);
  fs::remove_all(dir);
  // 4 variants x 2 stages = 8 programs. NEVER_TESTED changes no token; RED
  // changes only the fragment function, which the vertex entry point does
  // not reach (stage relevance): 1 vertex + 2 fragment programs compile.
  EXPECT_EQ(unused.stats.variants, 4u);
  EXPECT_EQ(unused.stats.stage_programs, 8u);
  EXPECT_EQ(unused.stats.unique_preprocessed, 3u);
  EXPECT_EQ(unused.stats.unique_spirv, 3u);
}

}  // namespace
}  // namespace facet

namespace facet {
namespace {

// Stage relevance is sound: every stage of every variant, compiled on its
// own, gives exactly the SPIR-V the deduplicating driver stored for it, also
// at -O0, where no optimiser removes unreachable code.
class DriverStageRelevanceTest : public testing::TestWithParam<std::pair<const char*, backend::OptLevel>> {};

TEST_P(DriverStageRelevanceTest, DedupedProgramsEqualTheirOwnCompiles) {
  auto [name, opt] = GetParam();
  Compiler compiler;
  SourceMap sources;
  Diagnostics diags;
  auto shader = compiler.load(example(name), sources, diags);
  ASSERT_TRUE(shader);
  CompileOptions options;
  options.backend.opt = opt;
  auto compiled = compiler.compile(*shader, options, sources, diags);
  ASSERT_TRUE(compiled) << render_text(diags, sources);
  EXPECT_LT(compiled->stats.unique_preprocessed, compiled->stats.stage_programs) << "something was deduped";
  auto passes = compiler.select_passes(*shader, options, diags);
  ASSERT_TRUE(passes);
  const package::Package& pkg = compiled->package;
  const backend::Backend backend;
  for (size_t p = 0; p < passes->size(); ++p) {
    const SelectedPass& sel = (*passes)[p];
    for (const package::PackageVariant& variant : pkg.passes[p].variants) {
      for (const package::PackageStage& stage : variant.stages) {
        auto alone = backend.compile(*shader, *sel.ir.program, stage.stage,
                                                variants::stage_keywords(sel.keywords, variant.key, stage.stage),
                                                options.backend, sources, diags);
        ASSERT_TRUE(alone);
        EXPECT_TRUE(alone->spirv == pkg.spirv_blobs[stage.blob])
            << name << " " << stage_name(stage.stage) << " " << testing::PrintToString(variant.keywords);
      }
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Shaders, DriverStageRelevanceTest,
                         testing::Values(std::pair{"Keywords.shader", backend::OptLevel::none},
                                         std::pair{"PhongMultiLight.shader", backend::OptLevel::none},
                                         std::pair{"PhongMultiLight.shader", backend::OptLevel::performance},
                                         std::pair{"TexturedAmbient.shader", backend::OptLevel::performance}));

}  // namespace
}  // namespace facet

namespace facet {
namespace {

TEST(DriverEstimateTest, CountsTheBuildAndTimesASample) {
  Compiler compiler;
  SourceMap sources;
  Diagnostics diags;
  auto shader = compiler.load(example("Keywords.shader"), sources, diags);
  ASSERT_TRUE(shader);
  auto e = estimate_build(compiler, *shader, {.jobs = 2}, sources, diags, 8);
  ASSERT_TRUE(e) << render_text(diags, sources);
  EXPECT_EQ(e->variants, 48u);
  EXPECT_EQ(e->programs, 64u);
  EXPECT_EQ(e->unique, 50u) << "what compile() compiles";
  EXPECT_EQ(e->sampled, 8u);
  EXPECT_GT(e->seconds_per_program, 0);
  EXPECT_GT(e->estimated_seconds, e->preprocess_seconds);
  auto all = estimate_build(compiler, *shader, {.jobs = 1}, sources, diags, 1000);
  ASSERT_TRUE(all);
  EXPECT_EQ(all->sampled, 50u) << "a sample never exceeds the programs";
}

// A build carries the estimate --estimate would have given, from its own
// timings: the same counts, a sample of 16; none when the cache served all.
TEST(DriverEstimateTest, ABuildCarriesItsOwnEstimate) {
  Compiler compiler;
  SourceMap sources;
  Diagnostics diags;
  auto shader = compiler.load(example("Keywords.shader"), sources, diags);
  ASSERT_TRUE(shader);
  std::string cache = (std::filesystem::temp_directory_path() / "facet_build_estimate_cache").string();
  std::filesystem::remove_all(cache);
  auto cold = compiler.compile(*shader, {.jobs = 2, .cache_dir = cache}, sources, diags);
  ASSERT_TRUE(cold) << render_text(diags, sources);
  ASSERT_TRUE(cold->estimate);
  EXPECT_EQ(cold->estimate->variants, 48u);
  EXPECT_EQ(cold->estimate->programs, 64u);
  EXPECT_EQ(cold->estimate->unique, 50u);
  EXPECT_EQ(cold->estimate->sampled, kEstimateSample);
  EXPECT_EQ(cold->estimate->jobs, 2u);
  EXPECT_GT(cold->estimate->seconds_per_program, 0);
  EXPECT_DOUBLE_EQ(cold->estimate->preprocess_seconds, cold->stats.phases.preprocess);
  EXPECT_NEAR(cold->estimate->estimated_seconds,
              cold->estimate->preprocess_seconds + 50 * cold->estimate->seconds_per_program / 2, 1e-9);
  auto warm = compiler.compile(*shader, {.jobs = 2, .cache_dir = cache}, sources, diags);
  ASSERT_TRUE(warm);
  EXPECT_EQ(warm->stats.cache_hits, 50u);
  EXPECT_FALSE(warm->estimate) << "cache reads are no sample of a cold build";
  std::filesystem::remove_all(cache);
}

}  // namespace
}  // namespace facet
