// Every example shader compiles for all of its variants to SPIR-V that passes
// spirv-val and cross-compiles to GLSL 450, ESSL 300 and MSL.
#include <gtest/gtest.h>

#include <filesystem>

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
    // All variants after skip_variants are in the package.
    EXPECT_EQ(variants::count_variants(pass.keywords).after_skip.to_string(), std::to_string(pass.variants.size()))
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
          if (target == backend::CrossTarget::essl300 && stage.stage == Stage::geometry) continue;
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

TEST(DriverCompileTest, PackageBytesDoNotDependOnTheRun) {
  auto build = [] {
    Compiler compiler;
    SourceMap sources;
    Diagnostics diags;
    auto shader = compiler.load(std::string(FACET_SOURCE_DIR) + "/examples/shaders/PhongMultiLight.shader", sources,
                                diags);
    auto compiled = compiler.compile(*shader, {}, sources, diags);
    return package::write_package(compiled->package);
  };
  EXPECT_EQ(build(), build());
}

}  // namespace
}  // namespace facet
