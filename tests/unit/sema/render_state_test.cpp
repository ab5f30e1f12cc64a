// Render state: canonical spellings, symbolic [_Prop] values, errors with
// the valid list, and Category -> SubShader -> Pass merging.
#include <gtest/gtest.h>

#include <memory>
#include <nlohmann/json.hpp>

#include "facet/sema.h"

namespace facet::sema {
namespace {

struct Analyzed {
  SourceMap sources;
  Diagnostics diags;
  FileId file = kNoFile;
  std::optional<ir::Shader> ir;

  const Diagnostic* find(DiagId id) const {
    for (const Diagnostic& d : diags.all()) {
      if (d.id == id) return &d;
    }
    return nullptr;
  }
  LineColumn at(SourceSpan s) const { return sources.line_column(s.file, s.begin); }
};

std::unique_ptr<Analyzed> analyze_text(std::string text, const SemaOptions& options = {}) {
  auto a = std::make_unique<Analyzed>();
  a->file = a->sources.add_file("test.shader", std::move(text));
  auto ast = shaderlab::parse(a->file, a->sources, {}, a->diags);
  if (!ast) return a;
  auto ir = analyze(*ast, a->sources, options, a->diags);
  if (ir) a->ir = std::move(*ir);
  return a;
}

std::string in_pass(std::string_view commands) {
  return "Shader \"T\" { SubShader { Pass {\n" + std::string(commands) + "\n} } }";
}

// The pass's state as compact JSON, as ir_to_json (and the package dump) write it.
std::string pass_state(const Analyzed& a) {
  auto j = nlohmann::ordered_json::parse(ir_to_json(*a.ir));
  return j["subshaders"][0]["passes"][0]["state"].dump();
}

struct CanonicalCase {
  const char* name;
  const char* commands;
  const char* state;
};

class SemaRenderStateTest : public testing::TestWithParam<CanonicalCase> {};

TEST_P(SemaRenderStateTest, Canonicalises) {
  const CanonicalCase& c = GetParam();
  auto a = analyze_text(in_pass(c.commands));
  ASSERT_TRUE(a->ir) << render_text(a->diags, a->sources);
  EXPECT_EQ(pass_state(*a), c.state);
}

INSTANTIATE_TEST_SUITE_P(
    Values, SemaRenderStateTest,
    testing::Values(
        CanonicalCase{"cull", "cull back", R"({"cull":"Back"})"},
        CanonicalCase{"cull_off", "CULL OFF", R"({"cull":"Off"})"},
        CanonicalCase{"ztest", "ZTest lequal", R"({"ztest":"LEqual"})"},
        CanonicalCase{"ztest_gequal", "ZTest GEQUAL", R"({"ztest":"GEqual"})"},
        CanonicalCase{"ztest_prop", "ZTest [unity_GUIZTestMode]", R"({"ztest":{"property":"unity_GUIZTestMode"}})"},
        CanonicalCase{"zwrite", "zwrite on", R"({"zwrite":"On"})"},
        CanonicalCase{"alpha_to_mask", "AlphaToMask off", R"({"alpha_to_mask":"Off"})"},
        CanonicalCase{"zclip", "ZClip false", R"({"zclip":"False"})"},
        // Unity accepts either pair of words for every boolean command.
        CanonicalCase{"zclip_on", "ZClip On", R"({"zclip":"True"})"},
        CanonicalCase{"zwrite_true", "ZWrite True", R"({"zwrite":"On"})"},
        CanonicalCase{"alpha_to_mask_true", "AlphaToMask True", R"({"alpha_to_mask":"On"})"},
        CanonicalCase{"conservative_off", "Conservative Off", R"({"conservative":"False"})"},
        // "ZTest Off" is Unity's alias of Always.
        CanonicalCase{"ztest_off", "ZTest Off", R"({"ztest":"Always"})"},
        // "ZTest On" (old shaders): depth testing as by default.
        CanonicalCase{"ztest_on", "ZTest On", R"({"ztest":"LEqual"})"},
        CanonicalCase{"conservative", "Conservative TRUE", R"({"conservative":"True"})"},
        CanonicalCase{"offset", "Offset -1, -1", R"({"offset_factor":"-1","offset_units":"-1"})"},
        CanonicalCase{"offset_prop", "Offset [_F], 0.5", R"({"offset_factor":{"property":"_F"},"offset_units":"0.5"})"},
        CanonicalCase{"blend", "Blend srcalpha oneminussrcalpha",
                      R"({"blend":[{"target":-1,"off":false,"src":"SrcAlpha","dst":"OneMinusSrcAlpha"}]})"},
        CanonicalCase{"blend_props", "Blend [_SrcBlend] [_DstBlend]",
                      R"({"blend":[{"target":-1,"off":false,"src":{"property":"_SrcBlend"},"dst":{"property":"_DstBlend"}}]})"},
        CanonicalCase{"blend_separate", "Blend One One, zero oneminusdstcolor",
                      R"({"blend":[{"target":-1,"off":false,"src":"One","dst":"One","src_alpha":"Zero","dst_alpha":"OneMinusDstColor"}]})"},
        CanonicalCase{"blend_off", "Blend off", R"({"blend":[{"target":-1,"off":true,"src":"","dst":""}]})"},
        CanonicalCase{"blend_per_rt", "Blend One One\nBlend 2 srcalphasaturate Zero",
                      R"({"blend":[{"target":-1,"off":false,"src":"One","dst":"One"},{"target":2,"off":false,"src":"SrcAlphaSaturate","dst":"Zero"}]})"},
        CanonicalCase{"blend_all_replaces_rt", "Blend 2 One Zero\nBlend One One",
                      R"({"blend":[{"target":-1,"off":false,"src":"One","dst":"One"}]})"},
        CanonicalCase{"blend_op", "BlendOp revsub, MAX", R"({"blend_op":[{"target":-1,"color_op":"RevSub","alpha_op":"Max"}]})"},
        CanonicalCase{"blend_op_logical", "BlendOp 1 logicalxor", R"({"blend_op":[{"target":1,"color_op":"LogicalXor"}]})"},
        CanonicalCase{"blend_op_advanced", "BlendOp hslluminosity", R"({"blend_op":[{"target":-1,"color_op":"HSLLuminosity"}]})"},
        CanonicalCase{"color_mask", "ColorMask rgb", R"({"color_mask":[{"target":-1,"mask":"RGB"}]})"},
        CanonicalCase{"color_mask_order", "ColorMask AR", R"({"color_mask":[{"target":-1,"mask":"RA"}]})"},
        CanonicalCase{"color_mask_zero", "ColorMask 0 1", R"({"color_mask":[{"target":1,"mask":"0"}]})"},
        CanonicalCase{"color_mask_prop", "ColorMask [_Mask]", R"({"color_mask":[{"target":-1,"mask":{"property":"_Mask"}}]})"},
        CanonicalCase{"stencil", "Stencil { ref 2 comp lequal pass incrsat zfailback decrwrap compfront [_C] }",
                      R"({"stencil":{"ref":"2","comp":"LEqual","pass":"IncrSat","zfail_back":"DecrWrap","comp_front":{"property":"_C"}}})"},
        CanonicalCase{"stencil_masks", "Stencil { Ref [_Ref] ReadMask 255 WriteMask 0 }",
                      R"({"stencil":{"ref":{"property":"_Ref"},"read_mask":"255","write_mask":"0"}})"}),
    [](const testing::TestParamInfo<CanonicalCase>& info) { return std::string(info.param.name); });

struct ErrorCase {
  const char* name;
  const char* commands;
  DiagId id;
  uint32_t column;  // on line 2, where the commands start
  const char* message;
  const char* note;  // a substring of some note, "" for none
};

class SemaRenderStateErrorTest : public testing::TestWithParam<ErrorCase> {};

TEST_P(SemaRenderStateErrorTest, ReportsAtTheValue) {
  const ErrorCase& c = GetParam();
  auto a = analyze_text(in_pass(c.commands));
  EXPECT_FALSE(a->ir);
  const Diagnostic* d = a->find(c.id);
  ASSERT_NE(d, nullptr) << render_text(a->diags, a->sources);
  EXPECT_EQ(d->message, c.message);
  EXPECT_EQ(a->at(d->span).line, 2u);
  EXPECT_EQ(a->at(d->span).column, c.column);
  if (*c.note == '\0') return;
  bool found = false;
  for (const DiagNote& n : d->notes) found = found || n.message.find(c.note) != std::string::npos;
  EXPECT_TRUE(found) << c.note;
}

INSTANTIATE_TEST_SUITE_P(
    Errors, SemaRenderStateErrorTest,
    testing::Values(
        ErrorCase{"cull", "Cull Sideways", DiagId::sema_unknown_state_value, 6, "unknown value 'Sideways' for 'Cull'",
                  "valid values are Back, Front, Off, or a property"},
        ErrorCase{"ztest_suggest", "ZTest LessEqual", DiagId::sema_unknown_state_value, 7,
                  "unknown value 'LessEqual' for 'ZTest'", "did you mean 'LEqual'?"},
        ErrorCase{"blend_suggest", "Blend SrcAlpha OneMinusSrcAlfa", DiagId::sema_unknown_state_value, 16,
                  "unknown value 'OneMinusSrcAlfa' for 'Blend'", "did you mean 'OneMinusSrcAlpha'?"},
        ErrorCase{"zwrite_number", "ZWrite 1", DiagId::sema_unknown_state_value, 8, "unknown value '1' for 'ZWrite'",
                  "On, Off"},
        ErrorCase{"blend_op", "BlendOp Plus", DiagId::sema_unknown_state_value, 9, "unknown value 'Plus' for 'BlendOp'",
                  "Add, Sub, RevSub"},
        ErrorCase{"color_mask_letter", "ColorMask RGBX", DiagId::sema_unknown_state_value, 11,
                  "unknown value 'RGBX' for 'ColorMask'", "R, G, B, A"},
        ErrorCase{"color_mask_repeat", "ColorMask RR", DiagId::sema_unknown_state_value, 11,
                  "unknown value 'RR' for 'ColorMask'", ""},
        ErrorCase{"render_target", "Blend 9 One One", DiagId::sema_bad_render_target, 7,
                  "render target index must be an integer from 0 to 7, not '9'", ""},
        ErrorCase{"stencil_ref_negative", "Stencil { Ref -1 }", DiagId::sema_unknown_state_value, 15,
                  "'Stencil Ref' expects an integer from 0 to 255, not '-1'", "[_Prop]"},
        ErrorCase{"stencil_mask_fraction", "Stencil { ReadMask 2.5 }", DiagId::sema_unknown_state_value, 20,
                  "'Stencil ReadMask' expects an integer from 0 to 4294967295, not '2.5'", "[_Prop]"},
        ErrorCase{"stencil_ref_past_32_bits", "Stencil { Ref 4294967296 }", DiagId::sema_unknown_state_value, 15,
                  "'Stencil Ref' expects an integer from 0 to 4294967295, not '4294967296'", "[_Prop]"},
        ErrorCase{"stencil_comp", "Stencil { Comp Replace }", DiagId::sema_unknown_state_value, 16,
                  "unknown value 'Replace' for 'Stencil Comp'", "Less, Greater, LEqual"},
        ErrorCase{"stencil_op", "Stencil { PassBack Always }", DiagId::sema_unknown_state_value, 20,
                  "unknown value 'Always' for 'Stencil PassBack'", "Keep, Zero, Replace"},
        ErrorCase{"offset_word", "Offset Off, 1", DiagId::sema_unknown_state_value, 8,
                  "'Offset' expects a number or '[_Prop]', not 'Off'", ""},
        ErrorCase{"zclip_word", "ZClip Yes", DiagId::sema_unknown_state_value, 7, "unknown value 'Yes' for 'ZClip'",
                  "On, Off, True, False"}),
    [](const testing::TestParamInfo<ErrorCase>& info) { return std::string(info.param.name); });

TEST(SemaRenderStateTest, SuggestionCarriesAFix) {
  auto a = analyze_text(in_pass("Cull Bakc"));
  const Diagnostic* d = a->find(DiagId::sema_unknown_state_value);
  ASSERT_NE(d, nullptr);
  ASSERT_EQ(d->fixits.size(), 1u);
  EXPECT_EQ(d->fixits[0].replacement, "Back");
  EXPECT_EQ(d->fixits[0].span, d->span);
}

TEST(SemaRenderStateTest, PassWinsOverSubShaderPerField) {
  auto a = analyze_text(R"(Shader "T" { SubShader {
      Cull Off ZWrite Off Blend One One ColorMask RGB
      Pass { Cull Back ColorMask A 1 }
      Pass { }
    } })");
  ASSERT_TRUE(a->ir) << render_text(a->diags, a->sources);
  const ir::SubShader& sub = a->ir->subshaders[0];
  EXPECT_EQ(sub.state.cull->literal, "Off");
  const ir::RenderState& p0 = sub.passes[0].state;
  EXPECT_EQ(p0.cull->literal, "Back");
  EXPECT_EQ(p0.zwrite->literal, "Off");
  ASSERT_EQ(p0.blend.size(), 1u);
  ASSERT_EQ(p0.color_mask.size(), 2u);  // RGB for all targets, A for target 1
  EXPECT_EQ(p0.color_mask[1].render_target, 1);
  EXPECT_EQ(sub.passes[1].state.cull->literal, "Off");
}

TEST(SemaRenderStateTest, CategoryStateIsInheritedThroughNesting) {
  auto a = analyze_text(R"(Shader "T" {
    Category { Blend SrcAlpha One Cull Off
      Category { ZWrite Off Cull Front
        SubShader { ColorMask RGB Pass { Cull Back } }
      }
      SubShader { Pass { } }
    }
    SubShader { Pass { } } })");
  ASSERT_TRUE(a->ir) << render_text(a->diags, a->sources);
  ASSERT_EQ(a->ir->subshaders.size(), 3u);
  const ir::RenderState& inner = a->ir->subshaders[0].passes[0].state;
  EXPECT_EQ(inner.blend.at(0).src.literal, "SrcAlpha");
  EXPECT_EQ(inner.zwrite->literal, "Off");
  EXPECT_EQ(inner.cull->literal, "Back");
  EXPECT_EQ(inner.color_mask.at(0).mask.literal, "RGB");
  EXPECT_EQ(a->ir->subshaders[0].state.cull->literal, "Front");
  EXPECT_EQ(a->ir->subshaders[1].state.cull->literal, "Off");
  EXPECT_FALSE(a->ir->subshaders[1].state.zwrite.has_value());
  EXPECT_FALSE(a->ir->subshaders[2].state.cull.has_value());
}

TEST(SemaRenderStateTest, ErrorInSubShaderStateIsReportedOnce) {
  auto a = analyze_text("Shader \"T\" { SubShader { Cull Sideways Pass { } Pass { } Pass { } } }");
  EXPECT_FALSE(a->ir);
  EXPECT_EQ(a->diags.error_count(), 1u);
}

TEST(SemaRenderStateTest, DuplicateCommandWarnsAndLastWins) {
  auto a = analyze_text(in_pass("Cull Off\nCull Back\nBlend 1 One One\nBlend 2 One One"));
  ASSERT_TRUE(a->ir);
  const Diagnostic* d = a->find(DiagId::sema_duplicate_state);
  ASSERT_NE(d, nullptr);
  EXPECT_EQ(d->severity, Severity::warning);
  EXPECT_EQ(diag_group(d->id), "redundant");
  EXPECT_EQ(a->at(d->span).line, 3u);
  EXPECT_EQ(a->at(d->notes.at(0).span).line, 2u);
  EXPECT_EQ(a->diags.warning_count(), 1u);  // different render targets are not duplicates
  EXPECT_EQ(a->ir->subshaders[0].passes[0].state.cull->literal, "Back");
}

// Unity accepts a 32-bit stencil value and the GPU compares 8 bits of it.
TEST(SemaRenderStateTest, StencilValueWiderThanEightBitsWarnsAndKeepsItsLowByte) {
  auto a = analyze_text(in_pass("Stencil { Ref 901 WriteMask 256 Comp Always }"));
  ASSERT_TRUE(a->ir) << render_text(a->diags, a->sources);
  EXPECT_EQ(pass_state(*a), R"({"stencil":{"ref":"133","write_mask":"0","comp":"Always"}})");
  ASSERT_EQ(a->diags.warning_count(), 2u);
  const Diagnostic* d = a->find(DiagId::sema_stencil_value_truncated);
  ASSERT_NE(d, nullptr);
  EXPECT_EQ(d->severity, Severity::warning);
  EXPECT_EQ(diag_group(d->id), "stencil");
  EXPECT_EQ(a->at(d->span).line, 2u);
  EXPECT_EQ(a->at(d->span).column, 15u);
  EXPECT_EQ(d->message, "'Stencil Ref 901' is wider than the 8-bit stencil buffer; its low 8 bits, 133, are used");
}

TEST(SemaRenderStateTest, PropertyReferencesStaySymbolic) {
  auto a = analyze_text(in_pass("ZWrite [_ZWrite]"));
  ASSERT_TRUE(a->ir);
  const ir::StateValue& v = *a->ir->subshaders[0].passes[0].state.zwrite;
  EXPECT_TRUE(v.is_property());
  EXPECT_EQ(v.property, "_ZWrite");
  EXPECT_TRUE(v.literal.empty());
  EXPECT_EQ(a->at(v.span).column, 8u);
}

}  // namespace
}  // namespace facet::sema
