// ShaderLab as Unity accepts it, as real shaders (Unity's built-in ones and
// community collections) write it: constructs facet once rejected.
#include <gtest/gtest.h>

#include "facet/sema.h"
#include "facet/shaderlab.h"

namespace facet {
namespace {

struct Checked {
  SourceMap sources;
  Diagnostics diags;
  std::optional<shaderlab::ast::Shader> ast;
  std::optional<ir::Shader> ir;

  const Diagnostic* find(DiagId id) const {
    for (const Diagnostic& d : diags.all()) {
      if (d.id == id) return &d;
    }
    return nullptr;
  }
  LineColumn at(const SourceSpan& s) const { return sources.line_column(s.file, s.begin); }
};

std::unique_ptr<Checked> check(std::string text) {
  auto c = std::make_unique<Checked>();
  FileId file = c->sources.add_file("real.shader", std::move(text));
  auto ast = shaderlab::parse(file, c->sources, {}, c->diags);
  if (!ast) return c;
  c->ast = std::move(*ast);
  auto ir = sema::analyze(*c->ast, c->sources, {}, c->diags);
  if (ir) c->ir = std::move(*ir);
  return c;
}

TEST(RealWorldShaderLabTest, TextureTypeAnyInAnyCaseIsATexture) {
  for (const char* spelling : {"any", "Any", "ANY"}) {
    auto c = check(std::string("Shader \"T\" { Properties { _MainTex (\"Tex\", ") + spelling +
                   ") = \"white\" {} } SubShader { Pass { } } }");
    ASSERT_TRUE(c->ir) << spelling << "\n" << render_text(c->diags, c->sources);
    EXPECT_EQ(c->ir->properties.at(0).type, ir::PropertyType::tex_any);
    EXPECT_TRUE(c->ir->properties.at(0).is_texture());
    EXPECT_EQ(ir::property_type_name(c->ir->properties.at(0).type), "Any");
  }
}

TEST(RealWorldShaderLabTest, LegacyRectTextureIsA2DTexture) {
  auto c = check("Shader \"T\" { Properties { _R (\"R\", RECT) = \"black\" {} } SubShader { Pass { } } }");
  ASSERT_TRUE(c->ir) << render_text(c->diags, c->sources);
  EXPECT_EQ(c->ir->properties.at(0).type, ir::PropertyType::tex2d);
}

TEST(RealWorldShaderLabTest, LodInACategoryIsInheritedBySubShadersWithoutTheirOwn) {
  auto c = check("Shader \"T\" { Category { LOD 150 SubShader { Pass { } } SubShader { LOD 300 Pass { } } } }");
  ASSERT_TRUE(c->ir) << render_text(c->diags, c->sources);
  EXPECT_EQ(c->ir->subshaders.at(0).lod, 150);
  EXPECT_EQ(c->ir->subshaders.at(1).lod, 300);
}

TEST(RealWorldShaderLabTest, LodInAPassIsAcceptedAndIgnored) {
  auto c = check("Shader \"T\" { SubShader { LOD 200 Pass {\n  LOD 100\n  ZWrite Off } } }");
  ASSERT_TRUE(c->ir) << render_text(c->diags, c->sources);
  EXPECT_EQ(c->ir->subshaders.at(0).lod, 200);
  const Diagnostic* note = c->find(DiagId::parse_ignored_command);
  ASSERT_NE(note, nullptr);
  EXPECT_EQ(c->at(note->span).line, 2u);
  EXPECT_EQ(c->at(note->span).column, 3u);
}

TEST(RealWorldShaderLabTest, DisplayNameMaySpanLines) {
  auto c = check("Shader \"T\" { Properties { _A (\"first line\nsecond line\", Float) = 1\n _B (\"b\", Float) = 2 } "
                 "SubShader { Pass { } } }");
  ASSERT_TRUE(c->ir) << render_text(c->diags, c->sources);
  ASSERT_EQ(c->ir->properties.size(), 2u);
  EXPECT_EQ(c->ir->properties[0].display_name, "first line\nsecond line");
  EXPECT_EQ(c->ir->properties[1].name, "_B");
}

TEST(RealWorldShaderLabTest, StringWithoutClosingQuoteIsReportedAtItsStart) {
  auto c = check("Shader \"T\" { Properties {\n  _A (\"never closed, Float) = 1\n } }");
  EXPECT_FALSE(c->ast);
  const Diagnostic* d = c->find(DiagId::parse_unterminated_string);
  ASSERT_NE(d, nullptr);
  EXPECT_EQ(c->at(d->span).line, 2u);
  EXPECT_EQ(c->at(d->span).column, 7u);
}

TEST(RealWorldShaderLabTest, ShaderWithOnlyAFallbackIsValid) {
  auto c = check("Shader \"Legacy/Alias\" {\n  Fallback \"Diffuse\"\n}");
  ASSERT_TRUE(c->ir) << render_text(c->diags, c->sources);
  EXPECT_TRUE(c->ir->subshaders.empty());
  EXPECT_EQ(c->ir->fallback.value_or(""), "Diffuse");
}

}  // namespace
}  // namespace facet
