// stdlib/Shaders/Standard.shader, facet's Standard: an uber shader over
// the UnityStandardCore* includes, compiles to valid SPIR-V for the variants
// of representative materials and for a seeded random sample of its full
// keyword space (the whole space is tens of thousands of programs: a
// benchmark's job, not a unit test's).
#include <gtest/gtest.h>

#include <random>
#include <set>

#include "stdlib_compile.h"

namespace facet {
namespace {

std::string uber_path() { return std::string(FACET_SOURCE_DIR) + "/stdlib/Shaders/Standard.shader"; }

struct Loaded {
  Compiler compiler;
  SourceMap sources;
  Diagnostics diags;
  std::optional<ir::Shader> shader;
};

void load(Loaded& l) {
  auto shader = l.compiler.load(uber_path(), l.sources, l.diags);
  ASSERT_TRUE(shader) << render_text(l.diags, l.sources);
  l.shader = std::move(*shader);
}

struct Material {
  const char* name;
  variants::KeywordList keywords;
};

class StdlibStandardUberMaterialTest : public testing::TestWithParam<Material> {};

// Per material: every engine (multi_compile) variant of every pass.
TEST_P(StdlibStandardUberMaterialTest, EveryEngineVariantOfTheMaterialCompilesToValidSpirv) {
  Loaded l;
  load(l);
  CompileOptions options;
  options.materials = std::vector<variants::KeywordList>{GetParam().keywords};
  auto compiled = l.compiler.compile(*l.shader, options, l.sources, l.diags);
  ASSERT_TRUE(compiled) << render_text(l.diags, l.sources);
  EXPECT_EQ(l.diags.error_count(), 0u) << render_text(l.diags, l.sources);
  const package::Package& pkg = compiled->package;
  ASSERT_EQ(pkg.passes.size(), 5u);
  // fwdbase 8 (vertex lights or not) x fog 4 x instancing 2; fwdadd_fullshadows 13 x fog 4 (Unity's
  // 47 without the shadowmask keywords);
  // shadowcaster 2 x instancing 2; prepassfinal 4 (LIGHTPROBE_SH, UNITY_HDR_ON: no lightmaps or
  // shadowmask) x instancing 2; meta 1.
  EXPECT_EQ(pkg.passes[0].variants.size(), 64u);
  EXPECT_EQ(pkg.passes[1].variants.size(), 52u);
  EXPECT_EQ(pkg.passes[2].variants.size(), 4u);
  EXPECT_EQ(pkg.passes[3].variants.size(), 8u);
  EXPECT_EQ(pkg.passes[4].variants.size(), 1u);
  for (const package::PackagePass& pass : pkg.passes)
    for (const package::PackageVariant& variant : pass.variants) EXPECT_EQ(variant.stages.size(), 2u) << pass.name;
  EXPECT_GT(stdlib_test::expect_valid_spirv(pkg), 8u);
}

INSTANTIATE_TEST_SUITE_P(
    Materials, StdlibStandardUberMaterialTest,
    testing::Values(Material{"OpaqueMetallic", {"_METALLICGLOSSMAP"}},
                    Material{"NormalMappedEmissive", {"_NORMALMAP", "_EMISSION"}},
                    Material{"Cutout", {"_ALPHATEST_ON", "_SMOOTHNESS_TEXTURE_ALBEDO_CHANNEL_A"}},
                    Material{"TransparentFade", {"_ALPHABLEND_ON", "_SPECULARHIGHLIGHTS_OFF", "_GLOSSYREFLECTIONS_OFF"}},
                    Material{"Premultiplied", {"_ALPHAPREMULTIPLY_ON", "_NORMALMAP", "_METALLICGLOSSMAP"}},
                    Material{"DetailParallax", {"_DETAIL_MULX2", "_PARALLAXMAP", "_NORMALMAP"}}),
    [](const auto& info) { return std::string(info.param.name); });

// 64 (pass, keyword set) pairs drawn uniformly from the whole space of all
// five passes (ForwardBase, ForwardAdd, ShadowCaster, Deferred, Meta) with a
// fixed seed.
TEST(StdlibStandardUberTest, SeededSampleOf64KeywordSetsCompilesToValidSpirv) {
  Loaded l;
  load(l);
  CompileOptions options;
  auto passes = l.compiler.select_passes(*l.shader, options, l.diags);
  ASSERT_TRUE(passes) << render_text(l.diags, l.sources);
  ASSERT_EQ(passes->size(), 5u);

  // The variants facet builds of each pass (Unity's listed shortcut
  // combinations, without the keywords facet's renderer never enables).
  std::vector<std::vector<variants::VariantKey>> keys;
  uint64_t total = 0;
  for (const SelectedPass& p : *passes) {
    auto all = variants::enumerate(p.keywords, {.drop_unreachable = true, .max_variants = 1u << 20}, l.diags);
    ASSERT_TRUE(all) << render_text(l.diags, l.sources);
    total += all->size();
    keys.push_back(std::move(*all));
  }
  EXPECT_GT(total, 40000u) << "the variants facet builds of the uber shader";

  std::mt19937_64 rng(20240601);
  std::set<std::pair<size_t, std::vector<std::string>>> chosen;
  while (chosen.size() < 64) {
    uint64_t r = std::uniform_int_distribution<uint64_t>(0, total - 1)(rng);
    size_t pass = 0;
    while (r >= keys[pass].size()) r -= keys[pass++].size();
    const variants::KeywordSpace& space = (*passes)[pass].keywords;
    chosen.insert({(*passes)[pass].pass, variants::all_keywords(space, keys[pass][size_t(r)])});
  }
  options.variant_filter = [&](const VariantInfo& v) { return chosen.count({v.pass_index, v.keywords}) > 0; };
  auto compiled = l.compiler.compile(*l.shader, options, l.sources, l.diags);
  ASSERT_TRUE(compiled) << render_text(l.diags, l.sources);
  EXPECT_EQ(l.diags.error_count(), 0u) << render_text(l.diags, l.sources);
  EXPECT_EQ(compiled->stats.variants, 64u);
  stdlib_test::expect_valid_spirv(compiled->package);
}

}  // namespace
}  // namespace facet
