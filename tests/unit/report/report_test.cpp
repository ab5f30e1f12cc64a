// The variant report's numbers for the example shaders, its findings, the
// material rung and the three renderings.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "facet/report.h"

namespace facet::report {
namespace {

namespace fs = std::filesystem;

std::string example(const std::string& name) { return std::string(FACET_SOURCE_DIR) + "/examples/shaders/" + name; }

ShaderReport report_of(const std::string& path, ReportOptions options = {}) {
  Compiler compiler;
  SourceMap sources;
  Diagnostics diags;
  auto shader = compiler.load(path, sources, diags);
  EXPECT_TRUE(shader) << render_text(diags, sources);
  if (!shader) return {};
  auto passes = compiler.select_passes(*shader, {}, diags);
  auto compiled = compiler.compile(*shader, {.jobs = 2}, sources, diags);
  EXPECT_TRUE(compiled) << render_text(diags, sources);
  if (!compiled) return {};
  return build_report(*shader, *passes, *compiled, sources, options);
}

const Ladder& ladder(const PassReport& p, const std::string& scope) {
  for (const Ladder& l : p.ladders) {
    if (l.scope == scope) return l;
  }
  static const Ladder none;
  ADD_FAILURE() << "no ladder " << scope;
  return none;
}

bool has_finding(const PassReport& p, FindingKind kind, const std::string& keyword, const std::string& stage = "") {
  return std::any_of(p.findings.begin(), p.findings.end(), [&](const Finding& f) {
    return f.kind == kind && f.keyword == keyword && f.stage == stage;
  });
}

// Keywords.shader: fog {4} x debug {2} x _EMISSION {2} x overlay {3, fragment only}.
TEST(ReportLadderTest, KeywordsShaderHasTheFullLadder) {
  ShaderReport r = report_of(example("Keywords.shader"));
  ASSERT_EQ(r.passes.size(), 1u);
  const PassReport& p = r.passes[0];
  EXPECT_EQ(ladder(p, "pass").full, BigCount(48));
  EXPECT_EQ(ladder(p, "pass").after_skip, BigCount(48));
  EXPECT_EQ(ladder(p, "pass").programs, 64u);
  EXPECT_EQ(ladder(p, "pass").after_strip, 48u);
  EXPECT_EQ(ladder(p, "vertex").after_strip, 16u);
  const Ladder& vs = ladder(p, "vertex");
  EXPECT_EQ(vs.full, BigCount(16));  // the overlay set is fragment-only
  EXPECT_EQ(vs.programs, 16u);
  EXPECT_EQ(vs.unique_tokens, 2u);  // only fog reaches the vertex function: on or off
  EXPECT_EQ(vs.unique_spirv, 2u);
  const Ladder& fs_ = ladder(p, "fragment");
  EXPECT_EQ(fs_.full, BigCount(48));
  EXPECT_EQ(fs_.programs, 48u);
  EXPECT_EQ(fs_.unique_tokens, 48u);
  EXPECT_EQ(fs_.unique_spirv, 40u);
  EXPECT_EQ(r.programs, 64u);
  EXPECT_EQ(r.compiled, 50u);
  ASSERT_EQ(p.sets.size(), 4u);
  EXPECT_EQ(p.sets[0].factor, 4u);
  EXPECT_EQ(p.sets[3].factor, 3u);
  EXPECT_EQ(p.sets[3].stages, std::vector<std::string>{"fragment"});
  EXPECT_EQ(p.variants.size(), 48u);
}

// PhongMultiLight.shader's ForwardBase: multi_compile_fwdbase's 83
// combinations, of which the 4 without lightmap, shadowmask and vertex-light
// keywords are reachable and built; the report names the others.
TEST(ReportLadderTest, UnreachableShortcutKeywordsAreCountedAndNamed) {
  ShaderReport r = report_of(example("PhongMultiLight.shader"));
  ASSERT_GE(r.passes.size(), 1u);
  const PassReport& base = r.passes[0];
  EXPECT_EQ(ladder(base, "pass").full, BigCount(83));
  EXPECT_EQ(ladder(base, "pass").reachable, BigCount(8));
  EXPECT_EQ(ladder(base, "pass").after_strip, 8u);
  std::vector<std::string> expected = {"LIGHTMAP_ON", "DIRLIGHTMAP_COMBINED", "DYNAMICLIGHTMAP_ON", "SHADOWS_SHADOWMASK",
                                       "LIGHTMAP_SHADOW_MIXING"};
  std::vector<std::string> names = base.unreachable_keywords;
  std::sort(names.begin(), names.end());
  std::sort(expected.begin(), expected.end());
  EXPECT_EQ(names, expected);
  std::string text = to_text({r});
  EXPECT_NE(text.find("unreachable: "), std::string::npos) << text;
  EXPECT_NE(text.find("not built unless --build-unreachable"), std::string::npos) << text;
  auto json = nlohmann::json::parse(to_json({r}));
  EXPECT_EQ(json["shaders"][0]["passes"][0]["ladder"][0]["reachable"], 8);
  EXPECT_EQ(json["shaders"][0]["passes"][0]["unreachable_keywords"].size(), 5u);
  // ForwardAdd's shortcut has no unreachable keywords.
  ASSERT_GE(r.passes.size(), 2u);
  EXPECT_TRUE(r.passes[1].unreachable_keywords.empty());
  EXPECT_EQ(ladder(r.passes[1], "pass").reachable, ladder(r.passes[1], "pass").full);
}

TEST(ReportFindingsTest, FreeAndDeadKeywords) {
  ShaderReport keywords = report_of(example("Keywords.shader"));
  const PassReport& k = keywords.passes.at(0);
  EXPECT_TRUE(has_finding(k, FindingKind::free_in_stage, "_EMISSION", "vertex"));
  EXPECT_TRUE(has_finding(k, FindingKind::free_in_stage, "FACET_DEBUG_NORMALS", "vertex"));
  EXPECT_FALSE(has_finding(k, FindingKind::free_in_stage, "FOG_LINEAR", "vertex"));
  EXPECT_FALSE(has_finding(k, FindingKind::dead, "_OVERLAY_NONE")) << "a default entry needs no #if";

  // The book's Phong shader declares fwdbase and calls ShadeSH9 whatever the
  // keywords (LIGHTPROBE_SH changes nothing), while LIGHT_ATTENUATION samples
  // the shadow map under SHADOWS_SCREEN (AutoLight.cginc).
  ShaderReport phong = report_of(example("PhongMultiLight.shader"));
  const PassReport& base = phong.passes.at(0);
  EXPECT_TRUE(has_finding(base, FindingKind::dead, "LIGHTPROBE_SH"));
  EXPECT_FALSE(has_finding(base, FindingKind::dead, "SHADOWS_SCREEN"));
  // Eight variants: eight vertex programs (VERTEXLIGHT_ON applies to the
  // vertex stage only) and four fragment programs.
  EXPECT_EQ(ladder(base, "pass").programs, 12u);
  EXPECT_EQ(ladder(base, "pass").unique_tokens, 4u);
}

TEST(ReportFindingsTest, MisspeltKeywordIsUndeclaredWithASuggestion) {
  fs::path dir = fs::temp_directory_path() / ("facet_report_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  std::ofstream(dir / "typo.shader") << R"(Shader "T/Typo" {
  SubShader { Pass {
    CGPROGRAM
    #pragma vertex vert
    #pragma fragment frag
    #pragma shader_feature _EMISSION
    float4 vert(float4 v : POSITION) : SV_POSITION { return v; }
    float4 frag() : SV_Target {
    #ifdef _EMMISION
      return 2;
    #endif
      return 1;
    }
    ENDCG
  } }
})";
  ShaderReport r = report_of((dir / "typo.shader").string());
  fs::remove_all(dir);
  const PassReport& p = r.passes.at(0);
  EXPECT_TRUE(has_finding(p, FindingKind::dead, "_EMISSION"));
  ASSERT_TRUE(has_finding(p, FindingKind::undeclared, "_EMMISION"));
  for (const Finding& f : p.findings) {
    if (f.kind == FindingKind::undeclared) {
      EXPECT_NE(f.detail.find("did you mean '_EMISSION'?"), std::string::npos);
    }
  }
}

TEST(ReportLadderTest, MaterialsRestrictShaderFeatureSets) {
  // One material enabling _EMISSION and the default overlay: shader_feature
  // sets keep one state each; multi_compile sets stay whole.
  ShaderReport r = report_of(example("Keywords.shader"), {.materials = std::vector<variants::KeywordList>{
                                                               {"_EMISSION", "_OVERLAY_ADD"}}});
  const PassReport& p = r.passes.at(0);
  EXPECT_TRUE(ladder(p, "pass").has_materials);
  EXPECT_EQ(ladder(p, "pass").after_materials, BigCount(8));   // 4 fog x 2 debug
  EXPECT_EQ(ladder(p, "vertex").after_materials, BigCount(8));
  bool shader_feature_what_if = std::any_of(p.what_ifs.begin(), p.what_ifs.end(), [](const WhatIf& w) {
    return w.change.find("make 'multi_compile _ FACET_DEBUG_NORMALS' shader_feature") != std::string::npos &&
           w.programs_saved > 0;
  });
  EXPECT_TRUE(shader_feature_what_if);
}

ShaderReport stripped_report(const std::vector<variants::KeywordList>& materials, const variants::StripFilter& strip) {
  Compiler compiler;
  SourceMap sources;
  Diagnostics diags;
  auto shader = compiler.load(example("Keywords.shader"), sources, diags);
  EXPECT_TRUE(shader) << render_text(diags, sources);
  if (!shader) return {};
  CompileOptions options{.jobs = 2};
  options.materials = materials;
  options.strip = strip;
  auto passes = compiler.select_passes(*shader, options, diags);
  auto compiled = compiler.compile(*shader, options, sources, diags);
  EXPECT_TRUE(compiled) << render_text(diags, sources);
  if (!compiled) return {};
  return build_report(*shader, *passes, *compiled, sources, {.materials = materials});
}

// The build holds only the material's shader_feature states, so holding
// _EMISSION or the overlay at its default would leave no variant: those
// steps are never taken. The plan's count is what the strip rules build.
TEST(ReportStripPlanTest, StepsNeverEmptyAPassAndPredictTheStrippedBuild) {
  const std::vector<variants::KeywordList> materials = {{"_EMISSION", "_OVERLAY_ADD"}};
  ShaderReport r = stripped_report(materials, {});
  StripPlan plan = strip_plan(r);
  EXPECT_EQ(plan.programs_now, ladder(r.passes.at(0), "pass").programs);
  ASSERT_EQ(plan.steps.size(), 2u) << "fog and debug normals: the only sets with a built default";
  EXPECT_EQ(plan.steps[0].step.always_off, (std::vector<std::string>{"FOG_LINEAR", "FOG_EXP", "FOG_EXP2"}));
  EXPECT_EQ(plan.steps[1].step.always_off, (std::vector<std::string>{"FACET_DEBUG_NORMALS"}));
  variants::StripFilter strip;
  for (const PlannedStep& s : plan.steps) {
    strip.rules.push_back({.kind = variants::StripKind::always_off, .keywords = s.step.always_off,
                           .pass = std::to_string(s.pass)});
  }
  ShaderReport after = stripped_report(materials, strip);
  EXPECT_EQ(ladder(after.passes.at(0), "pass").programs, plan.programs_after);
  EXPECT_EQ(strip_plan(after).steps.size(), 0u) << "nothing left to hold";
}

TEST(ReportRenderTest, JsonTextAndHtmlCarryTheNumbers) {
  std::vector<ShaderReport> reports = {report_of(example("Keywords.shader"))};
  auto json = nlohmann::json::parse(to_json(reports));
  const auto& pass = json["shaders"][0]["passes"][0];
  EXPECT_EQ(pass["ladder"][0]["scope"], "pass");
  EXPECT_EQ(pass["ladder"][0]["full"], 48);
  EXPECT_EQ(pass["ladder"][1]["unique_after_preprocessing"], 2);
  EXPECT_TRUE(pass["ladder"][0]["after_materials"].is_null());
  EXPECT_EQ(pass["variants"].size(), 48u);
  std::string text = to_text(reports);
  EXPECT_NE(text.find("shader 'Examples/Keywords'"), std::string::npos);
  EXPECT_NE(text.find("free: '_EMISSION' in vertex"), std::string::npos);
  std::string html = to_html(reports);
  EXPECT_EQ(html.rfind("<!DOCTYPE html>", 0), 0u);
  EXPECT_NE(html.find("<svg class=\"chart-sets\""), std::string::npos);
  EXPECT_NE(html.find("<svg class=\"chart-time\""), std::string::npos);
  EXPECT_EQ(html.find("http://"), html.find("http://www.w3.org/2000/svg")) << "no external resources";
  EXPECT_EQ(html.find("<script"), std::string::npos);
}

}  // namespace
}  // namespace facet::report
