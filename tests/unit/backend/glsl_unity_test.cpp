// GLSLPROGRAM with Unity's GLSL conventions (no #version, or GLSL 1.x / ES
// 3.0): gl_Vertex & co., varying, gl_FragColor, texture2D, the built-in
// matrices and loose uniforms, compiled for Vulkan through the real back end
// (docs/language.md §7.3, stdlib/FacetGLSLUnity.glslinc).
#include <gtest/gtest.h>

#include <map>

#include "source_assembly.h"
#include "backend_test_util.h"

namespace facet::backend {
namespace {

using testing::make_shader;
using testing::property;
using testing::TestShader;

std::string shader_text(const std::string& body) {
  return "Shader \"T\" {\nSubShader { Pass {\nGLSLPROGRAM\n" + body + "ENDGLSL\n} } }\n";
}

// `includes`: GLSLINCLUDE chunks (make_shader reads only CGINCLUDE).
TestShader glsl_shader(const std::string& body, const std::vector<std::string>& includes = {}) {
  TestShader t = make_shader(std::string(FACET_TESTDATA_DIR) + "/backend/glsl_unity.shader", shader_text(body));
  uint32_t line = 1000;
  for (const std::string& text : includes) {
    ir::SourceChunk chunk;
    chunk.text = text;
    chunk.span = t.program.body.span;
    chunk.first_line = line;
    line += 100;
    t.program.includes.push_back(chunk);
  }
  return t;
}

const StageVariable* find_variable(const std::vector<StageVariable>& list, const std::string& name) {
  for (const StageVariable& v : list) {
    if (v.name == name) return &v;
  }
  return nullptr;
}

const UniformBlock* find_block(const StageReflection& r, const std::string& name) {
  for (const UniformBlock& b : r.uniform_blocks) {
    if (b.name == name) return &b;
  }
  return nullptr;
}

const BlockMember* find_member(const UniformBlock& b, const std::string& name) {
  for (const BlockMember& m : b.members) {
    if (m.name == name) return &m;
  }
  return nullptr;
}

const ResourceBinding* find_resource(const StageReflection& r, const std::string& name) {
  for (const ResourceBinding& x : r.resources) {
    if (x.name == name) return &x;
  }
  return nullptr;
}

class GlslUnityTest : public ::testing::Test {
 protected:
  Result<CompiledVariant> compile(TestShader& t, Stage stage, const std::vector<std::string>& keywords = {}) {
    return backend_.compile(t.shader, t.program, stage, keywords, {}, t.sources, diags_);
  }
  std::string text(TestShader& t, Stage stage) {
    auto s = backend_.source_text(t.shader, t.program, {.stage = stage, .preprocess = false}, {}, t.sources, diags_);
    return s ? s->text : std::string();
  }
  std::string diagnostics(const TestShader& t) const { return render_text(diags_, t.sources); }

  Backend backend_;
  Diagnostics diags_;
};

// Every vertex attribute, matrix and texture function of the mapping.
constexpr const char* kEverything = R"(uniform float _Scale;
uniform vec4 _MainTex_ST;
uniform sampler2D _MainTex;
uniform samplerCube _Cube;
uniform sampler2DShadow _Shadow;
#ifdef VERTEX
attribute vec4 Tangent;
varying vec4 v_color;
varying vec2 v_uv;
varying vec4 v_extra;
varying mat3 v_basis;
void main()
{
    vec4 view = gl_ModelViewMatrix * gl_Vertex;
    vec3 n = gl_NormalMatrix * gl_Normal + (gl_ModelViewMatrixInverseTranspose * vec4(gl_Normal, 0.0)).xyz;
    v_basis = mat3(n, Tangent.xyz, cross(n, Tangent.xyz));
    v_color = gl_Color;
    v_uv = (gl_TextureMatrix[0] * gl_MultiTexCoord0).xy * _MainTex_ST.xy + _MainTex_ST.zw;
    v_extra = gl_MultiTexCoord1 + gl_MultiTexCoord2 + gl_MultiTexCoord3 + gl_ProjectionMatrix * view;
    gl_Position = gl_ModelViewProjectionMatrix * gl_Vertex * _Scale;
}
#endif
#ifdef FRAGMENT
varying vec2 v_uv;
varying vec4 v_color;
varying mat3 v_basis;
varying vec4 v_extra;
void main()
{
    vec4 c = texture2D(_MainTex, v_uv) + texture2DProj(_MainTex, vec3(v_uv, 1.0));
    c += textureCube(_Cube, v_basis[0]) + texture2DLod(_MainTex, v_uv, 0.0);
    c *= shadow2D(_Shadow, vec3(v_uv, 0.5)).r;
    gl_FragColor = c * v_color + v_extra;
}
#endif
)";

TEST_F(GlslUnityTest, BuiltInAttributesHaveFacetsVertexInputLocations) {
  TestShader t = glsl_shader(kEverything);
  auto vs = compile(t, Stage::vertex);
  ASSERT_TRUE(vs) << diagnostics(t) << text(t, Stage::vertex);
  const std::vector<StageVariable>& in = vs->reflection.inputs;
  std::map<std::string, uint32_t> expected = {{"facet_Vertex", 0},         {"facet_Normal", 1},
                                              {"Tangent", 2},              {"facet_Color", 3},
                                              {"facet_MultiTexCoord0", 4}, {"facet_MultiTexCoord1", 5},
                                              {"facet_MultiTexCoord2", 6}, {"facet_MultiTexCoord3", 7}};
  for (const auto& [name, location] : expected) {
    const StageVariable* v = find_variable(in, name);
    ASSERT_NE(v, nullptr) << name;
    EXPECT_EQ(v->location, location) << name;
  }
  EXPECT_EQ(find_variable(in, "facet_Vertex")->type, "float4");
  EXPECT_EQ(find_variable(in, "facet_Normal")->type, "float3");
  EXPECT_EQ(in.size(), expected.size());
}

TEST_F(GlslUnityTest, VaryingsGetLocationsByNameInBothStages) {
  TestShader t = glsl_shader(kEverything);
  auto vs = compile(t, Stage::vertex);
  auto fs = compile(t, Stage::fragment);
  ASSERT_TRUE(vs && fs) << diagnostics(t);
  // Alphabetical: v_basis (mat3: 3 locations), v_color, v_extra, v_uv; the
  // fragment section declares them in another order.
  std::map<std::string, uint32_t> expected = {{"v_basis", 0}, {"v_color", 3}, {"v_extra", 4}, {"v_uv", 5}};
  for (const auto& [name, location] : expected) {
    const StageVariable* out = find_variable(vs->reflection.outputs, name);
    const StageVariable* in = find_variable(fs->reflection.inputs, name);
    ASSERT_TRUE(out && in) << name;
    EXPECT_EQ(out->location, location) << name;
    EXPECT_EQ(in->location, location) << name;
  }
  EXPECT_NE(text(t, Stage::vertex).find("layout(location = 5) varying vec2 v_uv;"), std::string::npos);
}

TEST_F(GlslUnityTest, MatricesComeFromTheBuiltInBlocks) {
  TestShader t = glsl_shader(kEverything);
  auto vs = compile(t, Stage::vertex);
  ASSERT_TRUE(vs) << diagnostics(t);
  const UniformBlock* frame = find_block(vs->reflection, "FacetPerFrame");
  const UniformBlock* draw = find_block(vs->reflection, "FacetPerDraw");
  ASSERT_TRUE(frame && draw);
  EXPECT_EQ(frame->set, kFrameSet);
  EXPECT_EQ(frame->binding, 0u);
  EXPECT_EQ(draw->set, kDrawSet);
  EXPECT_EQ(draw->binding, 0u);
  for (const char* name : {"unity_MatrixV", "unity_MatrixInvV", "unity_MatrixP", "unity_MatrixVP"}) {
    EXPECT_NE(find_member(*frame, name), nullptr) << name;
  }
  EXPECT_NE(find_member(*draw, "unity_ObjectToWorld"), nullptr);
  EXPECT_FALSE(find_member(*draw, "unity_ObjectToWorld")->row_major);
  // The loose uniforms are the material's "$Globals"; textures follow it.
  const UniformBlock* globals = find_block(vs->reflection, kGlobalsBlock);
  ASSERT_NE(globals, nullptr);
  EXPECT_EQ(globals->set, kMaterialSet);
  EXPECT_EQ(globals->binding, 0u);
  EXPECT_NE(find_member(*globals, "_Scale"), nullptr);
  EXPECT_NE(find_member(*globals, "_MainTex_ST"), nullptr);
  EXPECT_EQ(find_member(*globals, "unity_ObjectToWorld"), nullptr);
}

// FacetPerFrame/FacetPerDraw in GLSL have the members and offsets of
// stdlib/FacetBuiltins.hlsl, so one runtime layout serves both languages.
TEST_F(GlslUnityTest, BuiltInBlocksMatchTheHlslLayout) {
  TestShader g = glsl_shader(kEverything);
  auto glsl = compile(g, Stage::vertex);
  TestShader h = make_shader("h.shader",
                             "Shader \"H\" { SubShader { Pass {\nCGPROGRAM\n#pragma vertex vert\n#pragma fragment frag\n"
                             "float4 vert(float4 p : POSITION) : SV_Position {\n"
                             "  return mul(unity_MatrixVP, mul(unity_ObjectToWorld, p)) + _Time; }\n"
                             "float4 frag() : SV_Target { return 1; }\nENDCG\n} } }\n");
  auto hlsl = compile(h, Stage::vertex);
  ASSERT_TRUE(glsl && hlsl) << diagnostics(g);
  for (const char* name : {"FacetPerFrame", "FacetPerDraw"}) {
    const UniformBlock* a = find_block(glsl->reflection, name);
    const UniformBlock* b = find_block(hlsl->reflection, name);
    ASSERT_TRUE(a && b) << name;
    EXPECT_EQ(a->set, b->set);
    EXPECT_EQ(a->binding, b->binding);
    EXPECT_EQ(a->size, b->size) << name;
    ASSERT_EQ(a->members.size(), b->members.size()) << name;
    for (size_t i = 0; i < a->members.size(); ++i) {
      EXPECT_EQ(a->members[i].name, b->members[i].name);
      EXPECT_EQ(a->members[i].offset, b->members[i].offset) << a->members[i].name;
      EXPECT_EQ(a->members[i].type, b->members[i].type) << a->members[i].name;
      EXPECT_EQ(a->members[i].row_major, b->members[i].row_major) << a->members[i].name;
    }
  }
}

TEST_F(GlslUnityTest, FragColorAndTextureFunctionsCompile) {
  TestShader t = glsl_shader(kEverything);
  t.shader.properties = {property("_MainTex", ir::PropertyType::tex2d), property("_Scale", ir::PropertyType::float_)};
  auto fs = compile(t, Stage::fragment);
  ASSERT_TRUE(fs) << diagnostics(t) << text(t, Stage::fragment);
  ASSERT_EQ(fs->reflection.outputs.size(), 1u);
  EXPECT_EQ(fs->reflection.outputs[0].name, "facet_FragColor");
  EXPECT_EQ(fs->reflection.outputs[0].location, 0u);
  EXPECT_EQ(fs->reflection.outputs[0].type, "float4");
  for (const char* name : {"_MainTex", "_Cube", "_Shadow"}) {
    const ResourceBinding* r = find_resource(fs->reflection, name);
    ASSERT_NE(r, nullptr) << name;
    EXPECT_EQ(r->set, kMaterialSet) << name;
    EXPECT_EQ(r->kind, ResourceKind::combined_image_sampler) << name;
  }
  EXPECT_EQ(find_resource(fs->reflection, "_Cube")->dim, "Cube");
  // Samplers in declaration order after "$Globals".
  EXPECT_EQ(find_resource(fs->reflection, "_MainTex")->binding, 1u);
  EXPECT_EQ(find_resource(fs->reflection, "_Cube")->binding, 2u);
  bool texture_bound = false;
  for (const PropertyBinding& b : fs->reflection.property_bindings) {
    if (b.property == "_MainTex" && b.role == "texture") texture_bound = true;
  }
  EXPECT_TRUE(texture_bound);
  auto vs = compile(t, Stage::vertex);
  ASSERT_TRUE(vs) << diagnostics(t);
  bool scale_bound = false;
  for (const PropertyBinding& b : vs->reflection.property_bindings) {
    if (b.property == "_Scale" && b.role == "value" && b.block == kGlobalsBlock) scale_bound = true;
  }
  EXPECT_TRUE(scale_bound);
}

TEST_F(GlslUnityTest, FragDataIsAnArrayOfTheTargetsWritten) {
  TestShader t = glsl_shader(
      "#ifdef VERTEX\nvoid main() { gl_Position = gl_Vertex; }\n#endif\n"
      "#ifdef FRAGMENT\nvoid main() { gl_FragData[0] = vec4(1.0); gl_FragData[2] = vec4(0.5); }\n#endif\n");
  auto fs = compile(t, Stage::fragment);
  ASSERT_TRUE(fs) << diagnostics(t);
  ASSERT_EQ(fs->reflection.outputs.size(), 1u);
  EXPECT_EQ(fs->reflection.outputs[0].name, "facet_FragData");
  EXPECT_EQ(fs->reflection.outputs[0].location, 0u);
  EXPECT_EQ(fs->reflection.outputs[0].array_size, 3u);
}

// Unity's Android video shaders: GLSLINCLUDE with UnityCG.glslinc,
// GL_OES_EGL_image_external, samplerExternalOES and textureExternal.
TEST_F(GlslUnityTest, ExternalImagesAreSampler2DAndTheExtensionIsDropped) {
  TestShader t = glsl_shader(R"(#extension GL_OES_EGL_image_external : require
#pragma glsl_es2
uniform vec4 _MainTex_ST;
#ifdef VERTEX
varying vec2 textureCoord;
void main()
{
    gl_Position = gl_ModelViewProjectionMatrix * gl_Vertex;
    textureCoord = TRANSFORM_TEX_ST(gl_MultiTexCoord0, _MainTex_ST);
}
#endif
#ifdef FRAGMENT
varying vec2 textureCoord;
uniform samplerExternalOES _MainTex;
void main()
{
    gl_FragColor.rgb = textureExternal(_MainTex, textureCoord).rgb;
    gl_FragColor.a = saturate(textureExternal(_MainTex, textureCoord).g);
}
#endif
)",
                             {"    #include \"UnityCG.glslinc\"\n"});
  for (Stage stage : {Stage::vertex, Stage::fragment}) {
    auto compiled = compile(t, stage);
    ASSERT_TRUE(compiled) << diagnostics(t) << text(t, stage);
    if (stage == Stage::fragment) {
      const ResourceBinding* tex = find_resource(compiled->reflection, "_MainTex");
      ASSERT_NE(tex, nullptr);
      EXPECT_EQ(tex->dim, "2D");
    }
  }
  EXPECT_EQ(text(t, Stage::fragment).find("#extension GL_OES"), std::string::npos);
  EXPECT_FALSE(diags_.has_errors()) << diagnostics(t);
}

// Old shaders declare the object matrices themselves, by Unity 4's names.
TEST_F(GlslUnityTest, OwnDeclarationsOfTheMatricesAreTheBuiltIns) {
  TestShader t = glsl_shader(
      "uniform mat4 _Object2World;\nuniform highp mat4 unity_WorldToObject;\nuniform vec3 _WorldSpaceCameraPos;\n"
      "uniform mat4 glstate_matrix_projection;\n"
      "#ifdef VERTEX\nvarying vec3 dir;\n"
      "void main() { vec4 w = _Object2World * gl_Vertex; dir = (unity_WorldToObject * w).xyz - "
      "_WorldSpaceCameraPos + (_World2Object * w).xyz;\n"
      " gl_Position = glstate_matrix_projection * unity_MatrixV * w; }\n#endif\n"
      "#ifdef FRAGMENT\nvarying vec3 dir;\nvoid main() { gl_FragColor = vec4(dir, 1.0); }\n#endif\n");
  auto vs = compile(t, Stage::vertex);
  ASSERT_TRUE(vs) << diagnostics(t) << text(t, Stage::vertex);
  const UniformBlock* globals = find_block(vs->reflection, kGlobalsBlock);
  ASSERT_NE(globals, nullptr);
  EXPECT_EQ(find_member(*globals, "_Object2World"), nullptr);
  EXPECT_EQ(find_member(*globals, "unity_WorldToObject"), nullptr);
  EXPECT_NE(find_member(*globals, "_WorldSpaceCameraPos"), nullptr);  // its own loose uniform
  EXPECT_EQ(find_member(*globals, "glstate_matrix_projection"), nullptr);
  EXPECT_NE(find_block(vs->reflection, "FacetPerDraw"), nullptr);
  EXPECT_NE(find_block(vs->reflection, "FacetPerFrame"), nullptr);
}

TEST_F(GlslUnityTest, OldVersionDirectivesAreUnityStyleAndBecome450) {
  for (const char* version : {"#version 120", "#version 100", "#version 300 es"}) {
    TestShader t = glsl_shader(std::string(version) +
                               "\n#ifdef VERTEX\nvoid main() { gl_Position = gl_ModelViewProjectionMatrix * gl_Vertex; }\n"
                               "#endif\n#ifdef FRAGMENT\nvoid main() { gl_FragColor = vec4(1.0); }\n#endif\n");
    for (Stage stage : {Stage::vertex, Stage::fragment}) {
      EXPECT_TRUE(compile(t, stage)) << version << "\n" << diagnostics(t);
      std::string s = text(t, stage);
      EXPECT_EQ(s.rfind("#version 450\n", 0), 0u) << s;
      EXPECT_NE(s.find("#include <FacetGLSLUnity.glslinc>"), std::string::npos);
    }
  }
}

TEST_F(GlslUnityTest, Version450KeepsPlainVulkanGlsl) {
  TestShader t = glsl_shader("#version 450\n#ifdef VERTEX\nlayout(location = 0) in vec4 p;\n"
                             "void main() { gl_Position = p; }\n#endif\n");
  auto vs = compile(t, Stage::vertex);
  ASSERT_TRUE(vs) << diagnostics(t);
  std::string s = text(t, Stage::vertex);
  EXPECT_EQ(s.find("FACET_GLSL_UNITY"), std::string::npos) << s;
  ASSERT_EQ(vs->reflection.inputs.size(), 1u);
  EXPECT_EQ(vs->reflection.inputs[0].location, 0u);

  // No mapping: `varying` and gl_Vertex are GLSL 1.x, not 450.
  TestShader old = glsl_shader("#version 450\n#ifdef VERTEX\nvarying vec2 uv;\n"
                               "void main() { gl_Position = gl_Vertex; }\n#endif\n");
  EXPECT_FALSE(compile(old, Stage::vertex));
  EXPECT_TRUE(diags_.has_errors());
}

// Modern code without #version (tests/data/backend/glsl.shader style) is
// untouched by the mapping: nothing it does not use is declared.
TEST_F(GlslUnityTest, UnusedMappingsDeclareNothing) {
  TestShader t = glsl_shader("#ifdef VERTEX\nlayout(location = 0) in vec4 p;\nlayout(location = 0) out vec2 uv;\n"
                             "void main() { uv = p.xy; gl_Position = p; }\n#endif\n"
                             "#ifdef FRAGMENT\nlayout(location = 0) in vec2 uv;\nlayout(location = 0) out vec4 c;\n"
                             "void main() { c = vec4(uv, 0.0, 1.0); }\n#endif\n");
  auto vs = compile(t, Stage::vertex);
  auto fs = compile(t, Stage::fragment);
  ASSERT_TRUE(vs && fs) << diagnostics(t);
  EXPECT_EQ(vs->reflection.inputs.size(), 1u);
  EXPECT_TRUE(vs->reflection.uniform_blocks.empty());
  ASSERT_EQ(fs->reflection.outputs.size(), 1u);
  EXPECT_EQ(fs->reflection.outputs[0].name, "c");
}

TEST_F(GlslUnityTest, CommentsDoNotCountAsUses) {
  TestShader t = glsl_shader("// gl_FragColor is not written here\n#ifdef VERTEX\n"
                             "void main() { gl_Position = gl_Vertex; /* gl_Normal */ }\n#endif\n"
                             "#ifdef FRAGMENT\nlayout(location = 0) out vec4 c;\nvoid main() { c = vec4(1.0); }\n#endif\n");
  auto vs = compile(t, Stage::vertex);
  auto fs = compile(t, Stage::fragment);
  ASSERT_TRUE(vs && fs) << diagnostics(t);
  EXPECT_EQ(vs->reflection.inputs.size(), 1u);
  ASSERT_EQ(fs->reflection.outputs.size(), 1u);
  EXPECT_EQ(fs->reflection.outputs[0].name, "c");
}

TEST_F(GlslUnityTest, ErrorsPointIntoTheShader) {
  // Line 4 of the .shader (GLSLPROGRAM is line 3) uses an undeclared name.
  TestShader t = glsl_shader("#ifdef VERTEX\nvoid main() { gl_Position = gl_Vertex * nope; }\n#endif\n"
                             "#ifdef FRAGMENT\nvoid main() { gl_FragColor = vec4(1.0); }\n#endif\n");
  EXPECT_FALSE(compile(t, Stage::vertex));
  std::string log = testing::headlines(diags_, t.sources);
  EXPECT_NE(log.find("glsl_unity.shader:5:"), std::string::npos) << log;
  EXPECT_NE(log.find("nope"), std::string::npos) << log;
}

TEST_F(GlslUnityTest, ProgramWithoutVertexSectionIsALocatedError) {
  TestShader t = glsl_shader("#ifdef FRAGMENT\nvoid main() { gl_FragColor = vec4(1.0); }\n#endif\n");
  EXPECT_TRUE(compile(t, Stage::fragment)) << diagnostics(t);
  EXPECT_FALSE(compile(t, Stage::vertex));
  bool found = std::any_of(diags_.all().begin(), diags_.all().end(),
                           [](const Diagnostic& d) { return d.id == DiagId::backend_no_entry_point; });
  EXPECT_TRUE(found) << diagnostics(t);
  std::string log = testing::headlines(diags_, t.sources);
  EXPECT_NE(log.find("glsl_unity.shader:4:1: error: program has no vertex stage"), std::string::npos) << log;
}

}  // namespace
}  // namespace facet::backend
