// Passes taken from other shaders when a shader is loaded: UsePass naming
// another shader, the Fallback's ShadowCaster (in place of surface
// lowering's stand-in), a shader made only of its Fallback, and what happens
// when a name is not found or leads back to itself.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "facet/compiler.h"
#include "facet/shader_search.h"

namespace facet {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;

const char* const kForwardOnly = R"(Shader "T/ForwardOnly" {
    SubShader {
        Pass {
            Tags { "LightMode" = "ForwardBase" }
            CGPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            #include "UnityCG.cginc"
            float4 vert(float4 v : POSITION) : SV_POSITION { return UnityObjectToClipPos(v); }
            fixed4 frag() : SV_Target { return 1; }
            ENDCG
        }
    }
    FALLBACK_LINE
})";

std::string with_fallback(const std::string& line) {
  std::string text = kForwardOnly;
  text.replace(text.find("FALLBACK_LINE"), 13, line);
  return text;
}

class ShaderLinkTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("facet_link_" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  std::string write(const std::string& relative, const std::string& text) {
    fs::path path = dir_ / relative;
    fs::create_directories(path.parent_path());
    std::ofstream(path) << text;
    return path.string();
  }

  // Loads `text` as a file of the test's folder.
  std::optional<ir::Shader> load(const std::string& text, CompileOptions options = {}) {
    auto shader = compiler_.load_source((dir_ / "main.shader").string(), text, sources_, diags_, options);
    if (!shader) return std::nullopt;
    return std::move(*shader);
  }

  std::vector<SelectedPass> passes(const ir::Shader& shader) {
    auto selected = compiler_.select_passes(shader, {}, diags_);
    return selected ? std::move(*selected) : std::vector<SelectedPass>{};
  }

  const SelectedPass* caster(const std::vector<SelectedPass>& selected) {
    for (const SelectedPass& p : selected) {
      if (p.ir.tag("LightMode") == "ShadowCaster") return &p;
    }
    return nullptr;
  }

  std::string home_path(const ir::Shader& shader, const SelectedPass& pass) {
    return sources_.path(ir::program_file(shader, *pass.ir.program));
  }

  std::string messages() { return render_text(diags_, sources_); }

  fs::path dir_;
  Compiler compiler_;
  SourceMap sources_;
  Diagnostics diags_;
};

TEST_F(ShaderLinkTest, FallbackDiffuseGivesAShaderWithoutACasterLegacyVertexLitsShadowCaster) {
  auto shader = load(with_fallback("Fallback \"Diffuse\""));
  ASSERT_TRUE(shader) << messages();
  auto selected = passes(*shader);
  ASSERT_EQ(selected.size(), 2u) << messages();
  const SelectedPass* cast = caster(selected);
  ASSERT_NE(cast, nullptr);
  EXPECT_EQ(cast->ir.origin, "Fallback \"Diffuse\"");
  EXPECT_THAT(home_path(*shader, *cast), HasSubstr("Shaders/Legacy/VertexLit.shader"));
  EXPECT_FALSE(diags_.has_errors()) << messages();

  CompileOptions options;
  options.passes = {"1"};
  auto compiled = compiler_.compile(*shader, options, sources_, diags_);
  ASSERT_TRUE(compiled) << messages();
  ASSERT_EQ(compiled->package.passes.size(), 1u);
  EXPECT_EQ(compiled->package.passes[0].name, "ShadowCaster");
  EXPECT_FALSE(compiled->package.passes[0].variants.empty());
  bool depends_on_vertex_lit = false;
  for (const std::string& d : compiled->dependencies) depends_on_vertex_lit |= d.ends_with("Legacy/VertexLit.shader");
  EXPECT_TRUE(depends_on_vertex_lit);
}

TEST_F(ShaderLinkTest, AShaderWithItsOwnCasterTakesNothingFromItsFallback) {
  std::string text = with_fallback("Fallback \"Diffuse\"");
  text.insert(text.find("    }\n    Fallback"), R"(        Pass {
            Name "Mine"
            Tags { "LightMode" = "ShadowCaster" }
            CGPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            float4x4 unity_MatrixVP;
            float4 vert(float4 v : POSITION) : SV_POSITION { return mul(unity_MatrixVP, v); }
            float4 frag() : SV_Target { return 0; }
            ENDCG
        }
)");
  auto shader = load(text);
  ASSERT_TRUE(shader) << messages();
  auto selected = passes(*shader);
  ASSERT_EQ(selected.size(), 2u);
  EXPECT_EQ(caster(selected)->ir.name, "Mine");
  EXPECT_TRUE(caster(selected)->ir.origin.empty());
}

TEST_F(ShaderLinkTest, UsePassTakesAPassOfAnotherShaderWithItsIncludesAndItsState) {
  // The other shader lives under a copy of the stdlib's Shaders/, with an
  // include beside it that only its own folder holds.
  fs::path stdlib = dir_ / "stdlib";
  fs::copy(default_stdlib_dir(), stdlib, fs::copy_options::recursive);
  write("stdlib/Shaders/Lib/helper.cginc", "float4 Outline() { return float4(1, 0, 0, 1); }\n");
  write("stdlib/Shaders/Lib/Other.shader", R"(Shader "Lib/Other" {
    SubShader {
        Pass {
            Name "Outline"
            Cull Front
            CGPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            #include "helper.cginc"
            float4 vert(float4 v : POSITION) : SV_POSITION { return v; }
            float4 frag() : SV_Target { return Outline(); }
            ENDCG
        }
    }
})");
  CompileOptions options;
  options.backend.stdlib_dir = stdlib.string();
  auto shader = load(R"(Shader "T/Main" { SubShader { UsePass "Lib/Other/OUTLINE" } })", options);
  ASSERT_TRUE(shader) << messages();
  auto selected = passes(*shader);
  ASSERT_EQ(selected.size(), 1u) << messages();
  EXPECT_EQ(selected[0].ir.name, "Outline");
  EXPECT_EQ(selected[0].ir.origin, "UsePass \"Lib/Other/OUTLINE\"");
  ASSERT_TRUE(selected[0].ir.state.cull);
  EXPECT_THAT(home_path(*shader, selected[0]), HasSubstr("Lib/Other.shader"));
  auto compiled = compiler_.compile(*shader, options, sources_, diags_);
  ASSERT_TRUE(compiled) << messages();
  EXPECT_EQ(compiled->package.passes.size(), 1u);
}

TEST_F(ShaderLinkTest, AnErrorInATakenPassPointsIntoTheFileItWasWrittenIn) {
  write("Broken.shader", R"(Shader "T/Broken" {
    SubShader {
        Pass {
            Name "P"
            CGPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            float4 vert(float4 v : POSITION) : SV_POSITION { return v; }
            float4 frag() : SV_Target { return undefined_thing; }
            ENDCG
        }
    }
})");
  auto shader = load(R"(Shader "T/Main" { SubShader { UsePass "T/Broken/P" } })");
  ASSERT_TRUE(shader) << messages();
  auto compiled = compiler_.compile(*shader, {}, sources_, diags_);
  EXPECT_FALSE(compiled);
  EXPECT_THAT(messages(), HasSubstr("Broken.shader:9:"));
}

TEST_F(ShaderLinkTest, UsePassOfAMissingShaderOrPassWarnsAndSkipsThePass) {
  write("Other.shader", R"(Shader "T/Other" { SubShader { Pass { Name "A" } } })");
  auto shader = load(R"(Shader "T/Main" { SubShader { UsePass "T/Nowhere/A" UsePass "T/Other/B" } })");
  ASSERT_TRUE(shader) << messages();
  EXPECT_TRUE(passes(*shader).empty());
  std::string text = messages();
  EXPECT_THAT(text, HasSubstr("UsePass 'T/Nowhere/A' is not resolved: no shader named 'T/Nowhere' in the shader "
                              "search path; the pass is skipped"));
  EXPECT_THAT(text, HasSubstr("searched: "));
  EXPECT_THAT(text, HasSubstr("shader 'T/Other' (" + (dir_ / "Other.shader").string() + ") has no pass named 'B'"));
  EXPECT_FALSE(diags_.has_errors());
}

TEST_F(ShaderLinkTest, AFallbackNotFoundWarnsThatTheShaderCastsNoShadow) {
  auto shader = load(with_fallback("Fallback \"No/Such Shader\""));
  ASSERT_TRUE(shader) << messages();
  EXPECT_EQ(passes(*shader).size(), 1u);
  EXPECT_THAT(messages(), HasSubstr("warning: Fallback 'No/Such Shader' is not used: no shader named 'No/Such Shader' "
                                    "in the shader search path; the shader casts no shadow [-Wfallback]"));
}

TEST_F(ShaderLinkTest, AShaderWithOnlyAFallbackIsDrawnWithIt) {
  auto shader = load(R"(Shader "T/Only" { Properties { _MainTex ("Tex", 2D) = "white" {} } Fallback "Unlit/Texture" })");
  ASSERT_TRUE(shader) << messages();
  auto selected = passes(*shader);
  ASSERT_EQ(selected.size(), 1u) << messages();
  EXPECT_EQ(selected[0].ir.origin, "Fallback \"Unlit/Texture\"");
  EXPECT_THAT(messages(), HasSubstr("shader 'T/Only' has no SubShader; it is drawn with its Fallback 'Unlit/Texture'"));
  auto compiled = compiler_.compile(*shader, {}, sources_, diags_);
  ASSERT_TRUE(compiled) << messages();
  EXPECT_EQ(compiled->package.passes.size(), 1u);
}

TEST_F(ShaderLinkTest, AFallbackCycleEndsWithAWarning) {
  write("B.shader", R"(Shader "T/B" { Fallback "T/ForwardOnly" })");
  write("main.shader", with_fallback("Fallback \"T/B\""));
  auto shader = load(with_fallback("Fallback \"T/B\""));
  ASSERT_TRUE(shader) << messages();
  EXPECT_EQ(passes(*shader).size(), 1u);
  EXPECT_THAT(messages(), HasSubstr("Fallback 'T/B' is not used: '" + (dir_ / "B.shader").string() +
                                    "' has no SubShader, of its own or from its Fallback"));

  auto itself = load(with_fallback("Fallback \"T/ForwardOnly\""));
  ASSERT_TRUE(itself) << messages();
  EXPECT_THAT(messages(), HasSubstr("Fallback 'T/ForwardOnly' is not used: 'T/ForwardOnly' leads back to itself"));
}

TEST_F(ShaderLinkTest, ASurfaceShaderCastsItsCutoutFallbacksShadowAndKeepsItsStandInOtherwise) {
  const std::string surface = R"(Shader "T/Cut" {
    Properties { _MainTex ("Tex", 2D) = "white" {} _Cutoff ("Cut", Range(0, 1)) = 0.5 }
    SubShader {
        CGPROGRAM
        #pragma surface surf Lambert alphatest:_Cutoff
        sampler2D _MainTex;
        struct Input { float2 uv_MainTex; };
        void surf(Input IN, inout SurfaceOutput o) { o.Albedo = 1; o.Alpha = tex2D(_MainTex, IN.uv_MainTex).a; }
        ENDCG
    }
    Fallback "FALLBACK"
})";
  std::string cutout = surface;
  cutout.replace(cutout.find("FALLBACK"), 8, "Transparent/Cutout/VertexLit");
  auto shader = load(cutout);
  ASSERT_TRUE(shader) << messages();
  auto selected = passes(*shader);
  const SelectedPass* cast = caster(selected);
  ASSERT_NE(cast, nullptr);
  EXPECT_EQ(cast->ir.origin, "Fallback \"Transparent/Cutout/VertexLit\"");
  EXPECT_THAT(cast->ir.program->body.text, HasSubstr("_Cutoff"));

  std::string unknown = surface;
  unknown.replace(unknown.find("FALLBACK"), 8, "Company/Private");
  auto kept = load(unknown);
  ASSERT_TRUE(kept) << messages();
  auto kept_passes = passes(*kept);
  const SelectedPass* stand_in = caster(kept_passes);
  ASSERT_NE(stand_in, nullptr);
  EXPECT_TRUE(stand_in->ir.fallback_stand_in);
  EXPECT_THAT(messages(), ::testing::Not(HasSubstr("Company/Private' is not used")));
}

TEST_F(ShaderLinkTest, LegacyNamesFindTheLegacyShaders) {
  const std::string stdlib_shaders = default_stdlib_dir() + "/Shaders";
  ShaderIndex index = index_shaders({{stdlib_shaders, true}});
  for (const char* name : {"Diffuse", "VertexLit", "Specular", "Bumped Diffuse", "Bumped Specular",
                           "Transparent/Diffuse", "Transparent/VertexLit", "Transparent/Cutout/Diffuse",
                           "Transparent/Cutout/VertexLit"}) {
    auto path = find_shader(index, name);
    ASSERT_TRUE(path) << name;
    EXPECT_EQ(index.at("Legacy Shaders/" + std::string(name)), *path);
  }
  EXPECT_FALSE(find_shader(index, "Legacy Shaders/Nothing"));
}

// Every shader of the stdlib's Shaders/ folder builds the default variant of
// each pass (Standard's whole space is tens of thousands of programs)
// without an error or a warning.
TEST_F(ShaderLinkTest, EveryStdlibShaderCompilesCleanly) {
  size_t count = 0;
  CompileOptions options;
  options.keywords = std::vector<std::string>{};
  for (const auto& entry : fs::recursive_directory_iterator(default_stdlib_dir() + "/Shaders")) {
    if (entry.path().extension() != ".shader") continue;
    BuildResult built = compiler_.build_file(entry.path().string(), options);
    EXPECT_TRUE(built.ok()) << entry.path() << "\n" << built.messages();
    EXPECT_EQ(built.diagnostics.warning_count(), 0u) << entry.path() << "\n" << built.messages();
    ++count;
  }
  EXPECT_GE(count, 16u);
}

TEST_F(ShaderLinkTest, FallbackStandardGivesTheStandardShadowCaster) {
  auto shader = load(with_fallback("Fallback \"Standard\""));
  ASSERT_TRUE(shader) << messages();
  auto selected = passes(*shader);
  const SelectedPass* cast = caster(selected);
  ASSERT_NE(cast, nullptr) << messages();
  EXPECT_EQ(cast->ir.origin, "Fallback \"Standard\"");
  EXPECT_THAT(home_path(*shader, *cast), HasSubstr("Shaders/Standard.shader"));
  EXPECT_EQ(cast->ir.program->entry_points[size_t(Stage::vertex)], "vertShadowCaster");
}

}  // namespace
}  // namespace facet
