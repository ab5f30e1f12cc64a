// What the back end hands to glslang.
#include "source_assembly.h"

#include <gtest/gtest.h>

namespace facet::backend {
namespace {

ir::Program program(ir::ProgramLanguage language, std::string body, uint32_t first_line) {
  ir::Program p;
  p.language = language;
  p.body.text = std::move(body);
  p.body.first_line = first_line;
  p.shader_target = 30;
  return p;
}

size_t line_of(const std::string& text, const std::string& needle) {
  size_t at = text.find(needle);
  return at == std::string::npos ? 0 : 1 + size_t(std::count(text.begin(), text.begin() + at, '\n'));
}

TEST(SourceAssemblyTest, CgPreludeDefinesThenImplicitIncludesThenChunks) {
  ir::Program p = program(ir::ProgramLanguage::cg, "float4 body;", 20);
  ir::SourceChunk include;
  include.text = "float4 shared;\n";
  include.first_line = 5;
  p.includes.push_back(include);
  BackendOptions options;
  options.defines = {{"X", "2"}};
  AssembledSource s = assemble_source(p, Stage::vertex, {"FOG_EXP", ""}, options, "/p/a.shader");
  const std::string& t = s.text;
  EXPECT_EQ(t.rfind("#line 2 \"<prelude>\"\n", 0), 0u) << t;
  EXPECT_LT(line_of(t, "#define SHADER_STAGE_VERTEX 1"), line_of(t, "#define FOG_EXP 1"));
  EXPECT_LT(line_of(t, "#define FOG_EXP 1"), line_of(t, "#define X 2"));
  EXPECT_LT(line_of(t, "#define X 2"), line_of(t, "#include <HLSLSupport.cginc>"));
  EXPECT_NE(t.find("#define SHADER_TARGET 30\n"), std::string::npos);
  EXPECT_NE(t.find("#define SHADER_API_VULKAN 1\n"), std::string::npos);
  EXPECT_NE(t.find("#line 5 \"/p/a.shader\"\nfloat4 shared;\n#line 20 \"/p/a.shader\"\nfloat4 body;\n"),
            std::string::npos)
      << t;
  EXPECT_EQ(s.root_name, "/p/a.shader");
  EXPECT_EQ(t.rfind(s.prelude, 0), 0u);
  EXPECT_EQ(s.prelude.find("float4"), std::string::npos);
}

TEST(SourceAssemblyTest, HlslProgramHasNoImplicitIncludes) {
  AssembledSource s = assemble_source(program(ir::ProgramLanguage::hlsl, "x", 1), Stage::fragment, {}, {}, "a");
  EXPECT_EQ(s.text.find("#include"), std::string::npos);
  EXPECT_NE(s.text.find("#define SHADER_STAGE_FRAGMENT 1"), std::string::npos);
}

TEST(SourceAssemblyTest, UnityFiveNamesAProgramUsesAreMappedToTheirNewNames) {
  ir::Program p = program(ir::ProgramLanguage::cg,
                          "float4 w = mul(_Object2World, v);\nfloat3 n = mul(v.normal, (float3x3)_World2Object);\n"
                          "float4 s = mul(_World2Shadow1, w); // _LightMatrix0 only in a comment\n",
                          3);
  AssembledSource s = assemble_source(p, Stage::vertex, {}, {}, "a.shader");
  EXPECT_NE(s.prelude.find("#define _Object2World unity_ObjectToWorld\n"), std::string::npos) << s.prelude;
  EXPECT_NE(s.prelude.find("#define _World2Object unity_WorldToObject\n"), std::string::npos);
  EXPECT_NE(s.prelude.find("#define _World2Shadow1 unity_WorldToShadow[1]\n"), std::string::npos);
  EXPECT_EQ(s.prelude.find("_LightMatrix0"), std::string::npos) << "only names the code uses";
  EXPECT_EQ(s.prelude.find("_World2Shadow "), std::string::npos);
}

TEST(SourceAssemblyTest, AProgramThatDeclaresAnOldNameOrOptsOutKeepsIt) {
  ir::Program own = program(ir::ProgramLanguage::hlsl, "float4x4 _Object2World;\nfloat4 w = mul(_Object2World, v);\n", 3);
  EXPECT_EQ(assemble_source(own, Stage::vertex, {}, {}, "a").prelude.find("_Object2World"), std::string::npos);
  ir::Program opted = program(ir::ProgramLanguage::cg, "// UNITY_SHADER_NO_UPGRADE\nfloat4 w = mul(_Object2World, v);\n", 3);
  EXPECT_EQ(assemble_source(opted, Stage::vertex, {}, {}, "a").prelude.find("_Object2World"), std::string::npos);
}

TEST(SourceAssemblyTest, GlslStartsWithVersionAndDefinesTheStage) {
  AssembledSource s = assemble_source(program(ir::ProgramLanguage::glsl, "void main() {}\n", 9), Stage::fragment, {},
                                      {}, "/p/g.shader");
  EXPECT_EQ(s.text.rfind("#version 450\n", 0), 0u) << s.text;
  EXPECT_NE(s.text.find("#define FRAGMENT 1\n"), std::string::npos);
  EXPECT_NE(s.text.find("#line 9 \"/p/g.shader\"\nvoid main() {}\n"), std::string::npos);
  // The prelude's #line keeps prelude line numbers equal to text line numbers.
  EXPECT_EQ(line_of(s.text, "#define FRAGMENT 1"), 4u);
  EXPECT_NE(s.text.find("#line 4 \"<prelude>\"\n#define FRAGMENT"), std::string::npos) << s.text;
}

TEST(SourceAssemblyTest, GlslVersionOfTheBodyIsLiftedToTheTop) {
  AssembledSource s = assemble_source(program(ir::ProgramLanguage::glsl, "  #version 460\nvoid main() {}\n", 3),
                                      Stage::vertex, {}, {}, "g");
  EXPECT_EQ(s.text.rfind("#version 460\n", 0), 0u) << s.text;
  // The body keeps its line count; the directive became blanks.
  EXPECT_NE(s.text.find("#line 3 \"g\"\n              \nvoid main() {}\n"), std::string::npos) << s.text;
}

TEST(SourceAssemblyTest, PathsAreSafeInsideLineDirectives) {
  AssembledSource s = assemble_source(program(ir::ProgramLanguage::cg, "x", 1), Stage::vertex, {}, {},
                                      "C:\\dir\\\"q\".shader");
  EXPECT_EQ(s.root_name, "C:/dir/'q'.shader");
  EXPECT_EQ(assemble_source(program(ir::ProgramLanguage::cg, "x", 1), Stage::vertex, {}, {}, "").root_name,
            "<shader>");
}

}  // namespace
}  // namespace facet::backend
