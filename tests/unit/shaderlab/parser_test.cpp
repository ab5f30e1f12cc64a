// The ShaderLab surface of SPEC §1, construct by construct.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>

#include "facet/shaderlab.h"

namespace facet::shaderlab {
namespace {

struct Parsed {
  SourceMap sources;
  Diagnostics diags;
  FileId file = kNoFile;
  std::optional<ast::Shader> shader;

  size_t count(DiagId id) const {
    size_t n = 0;
    for (const Diagnostic& d : diags.all()) n += d.id == id;
    return n;
  }
};

std::unique_ptr<Parsed> parse_text(std::string text) {
  auto p = std::make_unique<Parsed>();
  p->file = p->sources.add_file("test.shader", std::move(text));
  auto result = parse(p->file, p->sources, {}, p->diags);
  if (result) p->shader = std::move(*result);
  return p;
}

// Parses text that must have no errors; failures print the diagnostics.
std::unique_ptr<Parsed> parse_ok(std::string text) {
  auto p = parse_text(std::move(text));
  EXPECT_TRUE(p->shader.has_value()) << render_text(p->diags, p->sources);
  if (!p->shader) p->shader.emplace();
  return p;
}

std::string in_pass(std::string_view commands) {
  return "Shader \"T\" { SubShader { Pass { " + std::string(commands) + "\n } } }";
}

const ast::Pass& first_pass(const Parsed& p) { return p.shader->subshaders.at(0).passes.at(0); }

// --- Properties ---------------------------------------------------------------

struct PropertyCase {
  const char* name;
  const char* source;
  const char* type;
  std::vector<double> type_args;
  ast::PropertyDefault::Kind kind;
  std::vector<double> numbers;
  const char* texture;
};

class ShaderlabPropertyTest : public testing::TestWithParam<PropertyCase> {};

TEST_P(ShaderlabPropertyTest, ParsesTypeAndDefault) {
  const PropertyCase& c = GetParam();
  auto p = parse_ok("Shader \"T\" { Properties { " + std::string(c.source) + " } }");
  ASSERT_EQ(p->shader->properties.size(), 1u);
  const ast::Property& prop = p->shader->properties[0];
  EXPECT_EQ(prop.type, c.type);
  EXPECT_EQ(prop.type_args, c.type_args);
  EXPECT_EQ(prop.default_value.kind, c.kind);
  EXPECT_EQ(prop.default_value.numbers, c.numbers);
  EXPECT_EQ(prop.default_value.texture, c.texture);
}

using Kind = ast::PropertyDefault::Kind;
INSTANTIATE_TEST_SUITE_P(
    AllTypes, ShaderlabPropertyTest,
    testing::Values(
        PropertyCase{"float", "_F (\"F\", Float) = 10", "Float", {}, Kind::number, {10}, ""},
        PropertyCase{"int", "_I (\"I\", Int) = -2", "Int", {}, Kind::number, {-2}, ""},
        PropertyCase{"integer", "_I (\"I\", Integer) = 3", "Integer", {}, Kind::number, {3}, ""},
        PropertyCase{"range", "_R (\"R\", Range (0.03, 128)) = 0.078125", "Range", {0.03, 128}, Kind::number,
                     {0.078125}, ""},
        PropertyCase{"range_negative", "_R(\"R\",Range(-1,1))=0", "Range", {-1, 1}, Kind::number, {0}, ""},
        PropertyCase{"color4", "_C (\"C\", Color) = (1, 0, 0, 1)", "Color", {}, Kind::vector, {1, 0, 0, 1}, ""},
        PropertyCase{"color3", "_C (\"C\", Color) = (1, 1, 1)", "Color", {}, Kind::vector, {1, 1, 1}, ""},
        PropertyCase{"vector", "_V (\"V\", Vector) = (1,2,3,4)", "Vector", {}, Kind::vector, {1, 2, 3, 4}, ""},
        PropertyCase{"tex2d", "_T (\"T\", 2D) = \"white\" {}", "2D", {}, Kind::texture, {}, "white"},
        PropertyCase{"tex3d", "_T (\"T\", 3D) = \"\" {}", "3D", {}, Kind::texture, {}, ""},
        PropertyCase{"cube", "_T (\"T\", Cube) = \"grey\" {}", "Cube", {}, Kind::texture, {}, "grey"},
        PropertyCase{"array", "_T (\"T\", 2DArray) = \"black\" {}", "2DArray", {}, Kind::texture, {}, "black"},
        PropertyCase{"cube_array", "_T (\"T\", CubeArray) = \"gray\" {}", "CubeArray", {}, Kind::texture, {}, "gray"},
        PropertyCase{"no_braces", "_T (\"T\", 2D) = \"bump\"", "2D", {}, Kind::texture, {}, "bump"},
        PropertyCase{"lower_case", "_T (\"T\", cube) = \"linearGray\" {}", "cube", {}, Kind::texture, {},
                     "linearGray"},
        PropertyCase{"misspelt_type_kept", "_F (\"F\", Flaot) = 1", "Flaot", {}, Kind::number, {1}, ""}),
    [](const testing::TestParamInfo<PropertyCase>& info) { return std::string(info.param.name); });

TEST(ShaderlabParseTest, TextureDefaultKeepsLegacyOptions) {
  auto p = parse_ok("Shader \"T\" { Properties { _T (\"T\", Cube) = \"\" { TexGen CubeReflect } } }");
  const ast::PropertyDefault& d = p->shader->properties.at(0).default_value;
  EXPECT_TRUE(d.has_braces);
  EXPECT_EQ(d.texture_options, "TexGen CubeReflect");
}

TEST(ShaderlabParseTest, DisplayNamesKeepSpacesAndParentheses) {
  auto p = parse_ok("Shader \"T\" { Properties { _MainTex(\"Albedo (RGB) \\\"x\\\"\", 2D) = \"white\" {} } }");
  EXPECT_EQ(p->shader->properties.at(0).display_name, "Albedo (RGB) \"x\"");
}

struct AttributeCase {
  const char* name;
  const char* source;
  const char* attribute;
  bool has_parens;
  std::vector<std::string> args;
};

class ShaderlabAttributeTest : public testing::TestWithParam<AttributeCase> {};

TEST_P(ShaderlabAttributeTest, SplitsArguments) {
  const AttributeCase& c = GetParam();
  auto p = parse_ok("Shader \"T\" { Properties { " + std::string(c.source) + " _P (\"P\", Float) = 0 } }");
  const auto& attributes = p->shader->properties.at(0).attributes;
  ASSERT_EQ(attributes.size(), 1u);
  EXPECT_EQ(attributes[0].name, c.attribute);
  EXPECT_EQ(attributes[0].has_parens, c.has_parens);
  EXPECT_EQ(attributes[0].args, c.args);
}

INSTANTIATE_TEST_SUITE_P(
    Attributes, ShaderlabAttributeTest,
    testing::Values(
        AttributeCase{"flag", "[HideInInspector]", "HideInInspector", false, {}},
        AttributeCase{"toggle_kw", "[Toggle(_FOO_ON)]", "Toggle", true, {"_FOO_ON"}},
        AttributeCase{"toggle_off", "[ToggleOff]", "ToggleOff", false, {}},
        AttributeCase{"keyword_enum_spaces", "[KeywordEnum(A, B C, D)]", "KeywordEnum", true, {"A", "B C", "D"}},
        AttributeCase{"enum_pairs", "[Enum(Metallic Alpha,0,Albedo Alpha,1)]", "Enum", true,
                      {"Metallic Alpha", "0", "Albedo Alpha", "1"}},
        AttributeCase{"enum_type", "[Enum(UnityEngine.Rendering.BlendMode)]", "Enum", true,
                      {"UnityEngine.Rendering.BlendMode"}},
        AttributeCase{"power_slider", "[PowerSlider(3.0)]", "PowerSlider", true, {"3.0"}},
        AttributeCase{"header", "[Header(Surface: options, more)]", "Header", true, {"Surface: options", "more"}},
        AttributeCase{"space_empty", "[Space()]", "Space", true, {}},
        AttributeCase{"spaced", "[ Space ( 20 ) ]", "Space", true, {"20"}},
        AttributeCase{"unknown_kept", "[MyDrawer(x, (a, b))]", "MyDrawer", true, {"x", "(a, b)"}},
        AttributeCase{"leading_digits", "[KeywordEnum(6 Frames Layout, 8 Frames)]", "KeywordEnum", true,
                      {"6 Frames Layout", "8 Frames"}},
        AttributeCase{"nested_parens_unquoted", "[Header(Mask (R) and (G), done)]", "Header", true,
                      {"Mask (R) and (G)", "done"}},
        AttributeCase{"quoted_across_lines", "[MyDrawer(\"first\nsecond\", 2)]", "MyDrawer", true,
                      {"\"first\nsecond\"", "2"}}),
    [](const testing::TestParamInfo<AttributeCase>& info) { return std::string(info.param.name); });

// --- Render state -----------------------------------------------------------------

struct StateCase {
  const char* name;
  const char* source;
  ast::CommandKind kind;
  const char* render_target;  // "" when none
  std::vector<std::string> values;  // "[_P]" for property references
};

std::string show(const ast::Value& v) {
  return v.kind == ast::Value::Kind::property ? "[" + v.text + "]" : v.text;
}

class ShaderlabStateTest : public testing::TestWithParam<StateCase> {};

TEST_P(ShaderlabStateTest, ParsesCommand) {
  const StateCase& c = GetParam();
  auto p = parse_ok(in_pass(c.source));
  const auto& state = first_pass(*p).state;
  ASSERT_EQ(state.size(), 1u);
  EXPECT_EQ(state[0].kind, c.kind);
  EXPECT_EQ(state[0].render_target ? show(*state[0].render_target) : "", c.render_target);
  std::vector<std::string> values;
  for (const ast::Value& v : state[0].values) values.push_back(show(v));
  EXPECT_EQ(values, c.values);
}

using CK = ast::CommandKind;
INSTANTIATE_TEST_SUITE_P(
    Commands, ShaderlabStateTest,
    testing::Values(
        StateCase{"cull", "Cull Off", CK::cull, "", {"Off"}},
        StateCase{"cull_lower", "cull back", CK::cull, "", {"back"}},
        StateCase{"ztest", "ZTest LEqual", CK::ztest, "", {"LEqual"}},
        StateCase{"zwrite_prop", "ZWrite [_ZWrite]", CK::zwrite, "", {"[_ZWrite]"}},
        StateCase{"zwrite_odd_case", "Zwrite Off", CK::zwrite, "", {"Off"}},
        StateCase{"blend_off", "Blend Off", CK::blend, "", {"Off"}},
        StateCase{"blend_pair", "Blend One One", CK::blend, "", {"One", "One"}},
        StateCase{"blend_props", "Blend [_SrcBlend] [_DstBlend]", CK::blend, "", {"[_SrcBlend]", "[_DstBlend]"}},
        StateCase{"blend_separate", "Blend SrcAlpha OneMinusSrcAlpha, One Zero", CK::blend, "",
                  {"SrcAlpha", "OneMinusSrcAlpha", "One", "Zero"}},
        StateCase{"blend_rt", "Blend 1 One Zero", CK::blend, "1", {"One", "Zero"}},
        StateCase{"blend_rt_off", "Blend 2 Off", CK::blend, "2", {"Off"}},
        StateCase{"blend_op", "BlendOp RevSub", CK::blend_op, "", {"RevSub"}},
        StateCase{"blend_op_alpha", "BlendOp Add, Max", CK::blend_op, "", {"Add", "Max"}},
        StateCase{"blend_op_rt", "BlendOp 3 Min", CK::blend_op, "3", {"Min"}},
        StateCase{"color_mask", "ColorMask RGB", CK::color_mask, "", {"RGB"}},
        StateCase{"color_mask_zero_rt", "ColorMask 0 1", CK::color_mask, "1", {"0"}},
        StateCase{"color_mask_prop_rt", "ColorMask [_Mask] 2", CK::color_mask, "2", {"[_Mask]"}},
        StateCase{"offset", "Offset -1, -1", CK::offset, "", {"-1", "-1"}},
        StateCase{"offset_props", "Offset [_F], [_U]", CK::offset, "", {"[_F]", "[_U]"}},
        StateCase{"alpha_to_mask", "AlphaToMask On", CK::alpha_to_mask, "", {"On"}},
        StateCase{"zclip", "ZClip False", CK::zclip, "", {"False"}},
        StateCase{"conservative", "Conservative True", CK::conservative, "", {"True"}},
        StateCase{"prop_spaces", "Cull [ _CullMode ]", CK::cull, "", {"[_CullMode]"}}),
    [](const testing::TestParamInfo<StateCase>& info) { return std::string(info.param.name); });

TEST(ShaderlabParseTest, SeveralCommandsOnOneLine) {
  auto p = parse_ok(in_pass("Cull Off Zwrite Off ZTest Always Blend One One ColorMask RGB Lighting Off"));
  const auto& state = first_pass(*p).state;
  ASSERT_EQ(state.size(), 5u);
  EXPECT_EQ(state[3].values.size(), 2u);
  EXPECT_EQ(state[4].kind, CK::color_mask);
  EXPECT_FALSE(state[4].render_target.has_value());
}

TEST(ShaderlabParseTest, StencilWithAllFields) {
  auto p = parse_ok(in_pass(R"(Stencil {
      Ref 2 ReadMask [_RM] WriteMask 255
      Comp Always Pass Replace Fail Keep ZFail DecrSat
      CompBack Less PassBack IncrWrap FailBack Invert ZFailBack Zero
      compfront greater passfront keep failfront keep zfailfront keep
    })"));
  const ast::Command& c = first_pass(*p).state.at(0);
  EXPECT_EQ(c.kind, CK::stencil);
  ASSERT_EQ(c.stencil.size(), 15u);
  EXPECT_EQ(c.stencil[1].name, "ReadMask");
  EXPECT_EQ(c.stencil[1].value.kind, ast::Value::Kind::property);
  EXPECT_EQ(c.stencil[14].name, "zfailfront");
}

// --- Structure ----------------------------------------------------------------

TEST(ShaderlabParseTest, KeywordsAreCaseInsensitive) {
  auto p = parse_ok(R"(shader "X" { properties { _A ("a", float) = 1 }
    subshader { tags { "a"="b" } lod 100 PASS { NAME "n" zwrite off } }
    FALLBACK "Diffuse" customeditor "Ed" })");
  const ast::Shader& s = *p->shader;
  EXPECT_EQ(s.properties.size(), 1u);
  EXPECT_EQ(s.subshaders.at(0).lod, 100);
  EXPECT_EQ(first_pass(*p).name, "n");
  EXPECT_EQ(first_pass(*p).state.at(0).name, "zwrite");
  EXPECT_EQ(s.fallback, "Diffuse");
  EXPECT_EQ(s.custom_editor, "Ed");
}

TEST(ShaderlabParseTest, BracesMayStartTheNextLine) {
  auto p = parse_ok("Shader \"X\"\n{\n  SubShader\n  {\n    Pass\n    {\n    }\n  }\n}\n");
  EXPECT_EQ(p->shader->subshaders.at(0).passes.size(), 1u);
}

TEST(ShaderlabParseTest, TagsKeepEveryPairInOrder) {
  auto p = parse_ok(R"(Shader "X" { SubShader { Tags { "RenderType"="Opaque" "Queue" = "Geometry+1"
      "Custom"="a b" } Pass { } } })");
  const auto& tags = p->shader->subshaders.at(0).tags;
  ASSERT_EQ(tags.size(), 3u);
  EXPECT_EQ(tags[1].key, "Queue");
  EXPECT_EQ(tags[1].value, "Geometry+1");
  EXPECT_EQ(tags[2].value, "a b");
}

TEST(ShaderlabParseTest, PassKinds) {
  auto p = parse_ok(R"(Shader "X" { SubShader {
      UsePass "Legacy Shaders/VertexLit/SHADOWCASTER"
      GrabPass { }
      GrabPass { "_Background" Name "GRAB" Tags { "LightMode"="Always" } }
      Pass { Name "Keep Case" } } })");
  const auto& passes = p->shader->subshaders.at(0).passes;
  ASSERT_EQ(passes.size(), 4u);
  EXPECT_EQ(passes[0].kind, ast::PassKind::use_pass);
  EXPECT_EQ(passes[0].use_pass, "Legacy Shaders/VertexLit/SHADOWCASTER");
  EXPECT_EQ(passes[1].kind, ast::PassKind::grab_pass);
  EXPECT_EQ(passes[1].grab_texture, "");
  EXPECT_EQ(passes[2].grab_texture, "_Background");
  EXPECT_EQ(passes[2].name, "GRAB");
  EXPECT_EQ(passes[2].tags.size(), 1u);
  EXPECT_EQ(passes[3].name, "Keep Case");
}

TEST(ShaderlabParseTest, FallbackOffAndFallbackName) {
  auto off = parse_ok("Shader \"X\" { Fallback Off }");
  EXPECT_TRUE(off->shader->fallback_off);
  auto named = parse_ok("Shader \"X\" { FallBack \"VertexLit\" }");
  EXPECT_FALSE(named->shader->fallback_off);
  EXPECT_EQ(named->shader->fallback, "VertexLit");
}

TEST(ShaderlabParseTest, CategoriesNestAndOwnTheirSubShaders) {
  auto p = parse_ok(R"(Shader "X" {
    SubShader { }
    Category { Blend One One Tags { "Queue"="Transparent" }
      SubShader { }
      Category { Cull Off SubShader { } }
    } })");
  const ast::Shader& s = *p->shader;
  ASSERT_EQ(s.categories.size(), 2u);
  EXPECT_EQ(s.categories[0].parent, -1);
  EXPECT_EQ(s.categories[1].parent, 0);
  EXPECT_EQ(s.categories[0].state.size(), 1u);
  EXPECT_EQ(s.categories[0].tags.size(), 1u);
  ASSERT_EQ(s.subshaders.size(), 3u);
  EXPECT_EQ(s.subshaders[0].category, -1);
  EXPECT_EQ(s.subshaders[1].category, 0);
  EXPECT_EQ(s.subshaders[2].category, 1);
}

TEST(ShaderlabParseTest, ProgramBlocksKeepTextSpanAndFirstLine) {
  std::string src = "Shader \"X\" {\nCGINCLUDE\nint a;\nENDCG\nSubShader {\nHLSLINCLUDE\nint b;\nENDHLSL\n"
                    "Pass {\nCGPROGRAM\n#pragma vertex v\nENDCG\n}\n"
                    "Pass { GLSLPROGRAM\n#ifdef VERTEX\n#endif\nENDGLSL }\n"
                    "Pass { HLSLPROGRAM int c; ENDHLSL } } }";
  auto p = parse_ok(src);
  const ast::Shader& s = *p->shader;
  ASSERT_EQ(s.includes.size(), 1u);
  EXPECT_EQ(s.includes[0].text, "\nint a;\n");
  EXPECT_EQ(s.includes[0].first_line, 2u);
  const ast::SubShader& sub = s.subshaders.at(0);
  ASSERT_EQ(sub.includes.size(), 1u);
  EXPECT_EQ(sub.includes[0].language, ast::ProgramLanguage::hlsl);
  ASSERT_EQ(sub.passes.size(), 3u);
  const ast::ProgramBlock& cg = *sub.passes[0].program;
  EXPECT_EQ(cg.text, "\n#pragma vertex v\n");
  EXPECT_EQ(src.substr(cg.text_span.begin, cg.text_span.end - cg.text_span.begin), cg.text);
  EXPECT_EQ(cg.first_line, 10u);
  EXPECT_EQ(p->sources.line_column(p->file, cg.keyword_span.begin).line, 10u);
  EXPECT_EQ(sub.passes[1].program->language, ast::ProgramLanguage::glsl);
  EXPECT_EQ(sub.passes[2].program->text, " int c; ");
}

TEST(ShaderlabParseTest, ProgramDirectlyInSubShaderIsKept) {
  auto p = parse_ok("Shader \"X\" { SubShader { CGPROGRAM\n#pragma surface surf Lambert\nENDCG } }");
  const ast::SubShader& sub = p->shader->subshaders.at(0);
  EXPECT_EQ(sub.programs.size(), 1u);
  EXPECT_TRUE(sub.passes.empty());
}

TEST(ShaderlabParseTest, LegacyCommandsParseWithNotes) {
  auto p = parse_ok(in_pass(R"(
      Lighting Off
      SeparateSpecular On
      ColorMaterial AmbientAndDiffuse
      AlphaTest Greater [_Cutoff]
      AlphaTest Off
      Color (1, 1, 1, 1)
      Color [_Color]
      Fog { Color (0,0,0,0) } // in additive pass fog should be black
      Material { Diffuse [_Color] Ambient (1,1,1,1) }
      BindChannels { Bind "Vertex", vertex Bind "texcoord", texcoord }
      SetTexture [_MainTex] { combine texture * primary DOUBLE, texture }
      Cull Off)"));
  const ast::Pass& pass = first_pass(*p);
  EXPECT_EQ(pass.ignored.size(), 11u);
  EXPECT_EQ(p->count(DiagId::parse_legacy_command), 11u);
  EXPECT_EQ(diag_group(DiagId::parse_legacy_command), "legacy");
  for (const Diagnostic& d : p->diags.all()) EXPECT_EQ(d.severity, Severity::note);
  ASSERT_EQ(pass.state.size(), 1u);
  EXPECT_EQ(pass.state[0].kind, CK::cull);
}

TEST(ShaderlabParseTest, IgnoredMetadataCommands) {
  auto p = parse_ok(R"(Shader "X" { Dependency "BaseMapShader" = "Y"
      CustomEditorForRenderPipeline "Ed" "Pipeline"
      SubShader { PackageRequirements { "com.unity.render-pipelines.universal": "10.2.1" } } })");
  EXPECT_EQ(p->shader->ignored.size(), 2u);
  EXPECT_EQ(p->shader->subshaders.at(0).ignored.size(), 1u);
}

TEST(ShaderlabParseTest, ShaderCommandsInsideACategoryApplyToTheShader) {
  auto p = parse_ok(R"(Shader "X" { Category { CustomEditor "MyEditor" SubShader { Pass { } } Fallback "Diffuse" } })");
  EXPECT_EQ(p->shader->custom_editor, "MyEditor");
  EXPECT_EQ(p->shader->fallback, "Diffuse");
  EXPECT_EQ(p->shader->subshaders.size(), 1u);
}

TEST(ShaderlabParseTest, CommentsAnywhere) {
  auto p = parse_ok("// head\nShader /* a */ \"X\" // b\n{ /* { */ SubShader { // }\n Pass { } } }");
  EXPECT_EQ(p->shader->subshaders.at(0).passes.size(), 1u);
}

TEST(ShaderlabParseTest, ExampleShadersParseWithoutErrors) {
  size_t files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(FACET_SOURCE_DIR "/examples/shaders")) {
    if (entry.path().extension() != ".shader") continue;
    std::ifstream in(entry.path(), std::ios::binary);
    std::stringstream text;
    text << in.rdbuf();
    SCOPED_TRACE(entry.path().string());
    parse_ok(text.str());
    ++files;
  }
  EXPECT_GT(files, 0u);
}

}  // namespace
}  // namespace facet::shaderlab
