// examples/uber/StandardUber.shader, our Standard-style uber shader over
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

std::string uber_path() { return std::string(FACET_SOURCE_DIR) + "/examples/uber/StandardUber.shader"; }

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
  ASSERT_EQ(pkg.passes.size(), 4u);
  // fwdbase 4 x fog 4 x instancing 2; fwdadd_fullshadows 40 x fog 4;
  // shadowcaster 2 x instancing 2; meta 1.
  EXPECT_EQ(pkg.passes[0].variants.size(), 32u);
  EXPECT_EQ(pkg.passes[1].variants.size(), 160u);
  EXPECT_EQ(pkg.passes[2].variants.size(), 4u);
  EXPECT_EQ(pkg.passes[3].variants.size(), 1u);
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
// four passes with a fixed seed.
TEST(StdlibStandardUberTest, SeededSampleOf64KeywordSetsCompilesToValidSpirv) {
  Loaded l;
  load(l);
  CompileOptions options;
  auto passes = l.compiler.select_passes(*l.shader, options, l.diags);
  ASSERT_TRUE(passes) << render_text(l.diags, l.sources);
  ASSERT_EQ(passes->size(), 4u);

  std::vector<uint64_t> sizes;
  uint64_t total = 0;
  for (const SelectedPass& p : *passes) {
    uint64_t n = 1;
    for (const variants::KeywordSet& set : p.keywords.sets) n *= set.keywords.size();
    sizes.push_back(n);
    total += n;
  }
  EXPECT_GT(total, 50000u) << "the uber shader's full space";

  std::mt19937_64 rng(20240601);
  std::set<std::pair<size_t, std::vector<std::string>>> chosen;
  while (chosen.size() < 64) {
    uint64_t r = std::uniform_int_distribution<uint64_t>(0, total - 1)(rng);
    size_t pass = 0;
    while (r >= sizes[pass]) r -= sizes[pass++];
    const variants::KeywordSpace& space = (*passes)[pass].keywords;
    variants::VariantKey key;
    for (const variants::KeywordSet& set : space.sets) {
      key.choice.push_back(static_cast<uint32_t>(r % set.keywords.size()));
      r /= set.keywords.size();
    }
    chosen.insert({(*passes)[pass].pass, variants::all_keywords(space, key)});
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
