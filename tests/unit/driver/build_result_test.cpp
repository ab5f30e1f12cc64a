// Compiler::open_* and build*: one call from a .shader to its package, the
// result owning its messages and the source map they point into.
#include <gtest/gtest.h>

#include "facet/compiler.h"

namespace facet {
namespace {

std::string example(const char* name) { return std::string(FACET_SOURCE_DIR) + "/examples/shaders/" + name; }

TEST(BuildResultTest, BuildFileGivesThePackageWithoutThreadingSourcesOrDiagnostics) {
  Compiler compiler;
  BuildResult r = compiler.build_file(example("Keywords.shader"));
  ASSERT_TRUE(r.ok()) << r.messages();
  EXPECT_FALSE(r.compiled->package.passes.empty());
  EXPECT_FALSE(r.compiled->package.spirv_blobs.empty());
  EXPECT_FALSE(r.diagnostics.has_errors());
}

TEST(BuildResultTest, AFailedLoadKeepsItsLocatedMessageAndNoPackage) {
  Compiler compiler;
  BuildResult r = compiler.build_source("mem/Broken.shader", "Shader \"X\" {\n  SubShader { Pass { Cull Sideways } }\n}\n");
  EXPECT_FALSE(r.ok());
  EXPECT_TRUE(r.diagnostics.has_errors());
  // The message points into the text the result still holds.
  EXPECT_NE(r.messages().find("mem/Broken.shader:2:"), std::string::npos) << r.messages();
  EXPECT_NE(r.messages_json().find("\"line\""), std::string::npos);
}

TEST(BuildResultTest, ACompileErrorComesAfterTheLoadAndNamesItsLine) {
  Compiler compiler;
  const char* text = R"(Shader "X" {
  SubShader { Pass {
    CGPROGRAM
    #pragma vertex vert
    #pragma fragment frag
    float4 vert(float4 p : POSITION) : SV_POSITION { return p; }
    float4 frag() : SV_Target { return undefined_thing; }
    ENDCG
  } }
})";
  OpenedShader loaded = compiler.open_source("mem/Bad.shader", text);
  ASSERT_TRUE(loaded.ok()) << loaded.messages();
  BuildResult r = compiler.build(std::move(loaded));
  EXPECT_FALSE(r.ok());
  EXPECT_NE(r.messages().find("mem/Bad.shader:7:"), std::string::npos) << r.messages();
  EXPECT_NE(r.messages().find("undefined_thing"), std::string::npos) << r.messages();
}

TEST(BuildResultTest, OptionsReachTheBuild) {
  Compiler compiler;
  CompileOptions options;
  options.keywords = std::vector<std::string>{};  // only the variant with no keyword
  BuildResult all = compiler.build_file(example("Keywords.shader"));
  BuildResult one = compiler.build_file(example("Keywords.shader"), options);
  ASSERT_TRUE(all.ok() && one.ok()) << all.messages() << one.messages();
  EXPECT_LT(one.compiled->stats.variants, all.compiled->stats.variants);
}

}  // namespace
}  // namespace facet
