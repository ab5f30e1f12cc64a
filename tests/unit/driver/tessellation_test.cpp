// Geometry, hull and domain stages: each compiles to valid SPIR-V with the
// execution modes its attributes ask for and a reflection of its own; a
// surface shader with tessellate:/tessphong: gets hull and domain stages;
// and the errors for a half-declared tessellation pipeline, a missing
// tessellation function and a geometry function without [maxvertexcount].
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <string>
#include <vector>

#include "facet/compiler.h"

namespace facet {
namespace {

std::string example(const std::string& name) { return std::string(FACET_SOURCE_DIR) + "/examples/shaders/" + name; }

struct Built {
  SourceMap sources;
  Diagnostics diags;
  std::optional<ir::Shader> shader;
  std::optional<CompiledShader> compiled;

  std::string messages() const { return render_text(diags, sources); }
};

std::unique_ptr<Built> build(const Compiler& compiler, const std::string& path, const std::string* text = nullptr) {
  auto out = std::make_unique<Built>();
  auto shader = text ? compiler.load_source(path, *text, out->sources, out->diags)
                     : compiler.load(path, out->sources, out->diags);
  if (!shader) return out;
  out->shader = std::move(*shader);
  auto compiled = compiler.compile(*out->shader, {}, out->sources, out->diags);
  if (compiled) out->compiled = std::move(*compiled);
  return out;
}

std::unique_ptr<Built> build_text(const Compiler& compiler, const std::string& text) {
  return build(compiler, "tessellation_test.shader", &text);
}

std::vector<Stage> stages_of(const package::PackageVariant& v) {
  std::vector<Stage> out;
  for (const package::PackageStage& s : v.stages) out.push_back(s.stage);
  return out;
}

const package::PackageStage* find_stage(const package::PackageVariant& v, Stage stage) {
  for (const package::PackageStage& s : v.stages) {
    if (s.stage == stage) return &s;
  }
  return nullptr;
}

// semantic -> (location, array size)
std::map<std::string, std::pair<uint32_t, uint32_t>> interface(const std::vector<StageVariable>& vars) {
  std::map<std::string, std::pair<uint32_t, uint32_t>> out;
  for (const StageVariable& v : vars) out[v.semantic] = {v.location, v.array_size};
  return out;
}

std::map<std::string, uint32_t> locations(const std::vector<StageVariable>& vars) {
  std::map<std::string, uint32_t> out;
  for (const StageVariable& v : vars) out[v.semantic] = v.location;
  return out;
}

bool has(const std::string& text, const std::string& what) { return text.find(what) != std::string::npos; }

// Every blob of the package passes spirv-val.
void expect_valid(const Built& b) {
  for (const std::vector<uint32_t>& blob : b.compiled->package.spirv_blobs) {
    Diagnostics check;
    EXPECT_TRUE(backend::validate(blob, backend::TargetEnv::vulkan1_1, check)) << render_text(check, b.sources);
  }
}

std::string disassembly(const Built& b, const package::PackageStage& s) {
  return backend::disassemble(b.compiled->package.spirv_blobs[s.blob]);
}

// ---------------------------------------------------------------- geometry

std::string geometry_shader(const std::string& input, const std::string& stream, int count) {
  return R"(Shader "T/Geometry" { SubShader { Pass {
CGPROGRAM
#pragma vertex vert
#pragma geometry geom
#pragma fragment frag
#include "UnityCG.cginc"
struct v2g { float4 pos : SV_POSITION; float3 normal : NORMAL; };
struct g2f { float4 pos : SV_POSITION; float4 color : COLOR0; float2 bary : TEXCOORD3; };
v2g vert(appdata_base v) { v2g o; o.pos = UnityObjectToClipPos(v.vertex); o.normal = v.normal; return o; }
[maxvertexcount()" + std::to_string(count) + R"()]
void geom()" + input + R"(, uint prim : SV_PrimitiveID, inout )" + stream + R"(<g2f> s) {
  g2f o;
  o.pos = IN[0].pos; o.color = float4(IN[0].normal, 1); o.bary = float2(prim, 0);
  s.Append(o);
  s.RestartStrip();
}
fixed4 frag(g2f i) : SV_Target { return i.color + i.bary.x; }
ENDCG
} } })";
}

struct GeometryCase {
  const char* name;
  std::string input, stream;
  std::vector<std::string> modes;  // OpExecutionMode operands expected
  uint32_t input_array;
};

class GeometryStageTest : public testing::TestWithParam<GeometryCase> {};

TEST_P(GeometryStageTest, CompilesWithItsPrimitiveTypesAndReflection) {
  Compiler compiler;
  const GeometryCase& c = GetParam();
  auto b = build_text(compiler, geometry_shader(c.input, c.stream, 7));
  ASSERT_TRUE(b->compiled) << b->messages();
  EXPECT_FALSE(b->diags.has_errors()) << b->messages();
  expect_valid(*b);
  const package::PackageVariant& v = b->compiled->package.passes.at(0).variants.at(0);
  EXPECT_EQ(stages_of(v), (std::vector<Stage>{Stage::vertex, Stage::fragment, Stage::geometry}));
  const package::PackageStage* vs = find_stage(v, Stage::vertex);
  const package::PackageStage* gs = find_stage(v, Stage::geometry);
  const package::PackageStage* fs = find_stage(v, Stage::fragment);
  ASSERT_TRUE(vs && gs && fs);
  EXPECT_EQ(gs->reflection.entry_point, "geom");
  EXPECT_EQ(gs->reflection.stage, Stage::geometry);
  // One input element per vertex of the primitive; the outputs are the
  // fragment stage's inputs, at the same locations.
  auto in = interface(gs->reflection.inputs);
  ASSERT_EQ(in.count("NORMAL"), 1u);
  EXPECT_EQ(in["NORMAL"].second, c.input_array);
  EXPECT_EQ(locations(vs->reflection.outputs), locations(gs->reflection.inputs));
  EXPECT_EQ(locations(gs->reflection.outputs), locations(fs->reflection.inputs));
  EXPECT_EQ(locations(gs->reflection.outputs), (std::map<std::string, uint32_t>{{"COLOR0", 16}, {"TEXCOORD3", 3}}));
  std::string text = disassembly(*b, *gs);
  EXPECT_TRUE(has(text, "OutputVertices 7")) << text.substr(0, 2000);
  for (const std::string& mode : c.modes) EXPECT_TRUE(has(text, mode)) << mode;
  EXPECT_TRUE(has(text, "BuiltIn PrimitiveId"));
}

INSTANTIATE_TEST_SUITE_P(
    Primitives, GeometryStageTest,
    testing::Values(GeometryCase{"PointToPoints", "point v2g IN[1]", "PointStream", {"InputPoints", "OutputPoints"}, 1},
                    GeometryCase{"LineToLines", "line v2g IN[2]", "LineStream", {"InputLines", "OutputLineStrip"}, 2},
                    GeometryCase{"TriangleToTriangles", "triangle v2g IN[3]", "TriangleStream",
                                 {"Triangles", "OutputTriangleStrip"}, 3},
                    GeometryCase{"LineAdjacency", "lineadj v2g IN[4]", "LineStream",
                                 {"InputLinesAdjacency", "OutputLineStrip"}, 4},
                    GeometryCase{"TriangleAdjacency", "triangleadj v2g IN[6]", "TriangleStream",
                                 {"InputTrianglesAdjacency", "OutputTriangleStrip"}, 6}),
    [](const auto& info) { return std::string(info.param.name); });

TEST(GeometryStageTest, ExampleExtrudesEveryTriangle) {
  Compiler compiler;
  auto b = build(compiler, example("GeometryExtrude.shader"));
  ASSERT_TRUE(b->compiled) << b->messages();
  expect_valid(*b);
  for (const package::PackageVariant& v : b->compiled->package.passes.at(0).variants) {
    const package::PackageStage* gs = find_stage(v, Stage::geometry);
    ASSERT_TRUE(gs);
    std::string text = disassembly(*b, *gs);
    EXPECT_TRUE(has(text, "OutputVertices 15"));
    EXPECT_TRUE(has(text, "OutputTriangleStrip"));
  }
}

TEST(GeometryStageTest, MissingMaxVertexCountIsAnErrorAtTheUsersLine) {
  Compiler compiler;
  std::string text = geometry_shader("triangle v2g IN[3]", "TriangleStream", 3);
  text.replace(text.find("[maxvertexcount(3)]"), std::string("[maxvertexcount(3)]").size(), "");
  auto b = build_text(compiler, text);
  ASSERT_FALSE(b->compiled);
  ASSERT_TRUE(b->diags.has_errors());
  const Diagnostic* error = nullptr;
  for (const Diagnostic& d : b->diags.all()) {
    if (d.severity == Severity::error && !error) error = &d;
  }
  ASSERT_TRUE(error);
  EXPECT_TRUE(has(error->message, "max_vertices") || has(error->message, "maxvertexcount")) << b->messages();
  ASSERT_TRUE(error->span.has_location()) << b->messages();
  EXPECT_EQ(b->sources.path(error->span.file), "tessellation_test.shader") << b->messages();
  // The geom function's line (the attribute's line is now empty).
  EXPECT_EQ(b->sources.line_column(error->span.file, error->span.begin).line, 11u) << b->messages();
}

// ------------------------------------------------------------ hull, domain

std::string tessellation_shader(const std::string& domain, const std::string& partitioning,
                                const std::string& topology) {
  bool quad = domain == "quad", isoline = domain == "isoline";
  std::string factors = quad ? "float edge[4] : SV_TessFactor; float inside[2] : SV_InsideTessFactor;"
                        : isoline ? "float edge[2] : SV_TessFactor;"
                                  : "float edge[3] : SV_TessFactor; float inside : SV_InsideTessFactor;";
  std::string fill = quad ? "o.edge[0] = o.edge[1] = o.edge[2] = o.edge[3] = f; o.inside[0] = o.inside[1] = f;"
                     : isoline ? "o.edge[0] = 1; o.edge[1] = f;"
                               : "float4 t = UnityEdgeLengthBasedTess(p[0].vertex, p[1].vertex, p[2].vertex, f);"
                                 " o.edge[0] = t.x; o.edge[1] = t.y; o.edge[2] = t.z; o.inside = t.w;";
  int points = quad ? 4 : isoline ? 2 : 3;
  std::string location = quad ? "float2 uv : SV_DomainLocation" : isoline ? "float2 uv : SV_DomainLocation"
                                                                          : "float3 uv : SV_DomainLocation";
  std::string position = quad ? "lerp(lerp(p[0].vertex, p[1].vertex, uv.x), lerp(p[3].vertex, p[2].vertex, uv.x), uv.y)"
                         : isoline ? "lerp(p[0].vertex, p[1].vertex, uv.x)"
                                   : "p[0].vertex * uv.x + p[1].vertex * uv.y + p[2].vertex * uv.z";
  std::string n = std::to_string(points);
  return R"(Shader "T/Tess" { Properties { _Tess ("Tess", Range(1, 32)) = 4 } SubShader { Pass {
CGPROGRAM
#pragma vertex vert
#pragma hull hull
#pragma domain domain
#pragma fragment frag
#pragma target 4.6
#include "UnityCG.cginc"
#include "Tessellation.cginc"
float _Tess;
struct cp { float4 vertex : INTERNALTESSPOS; float3 normal : NORMAL; float2 uv : TEXCOORD0; };
struct pc { )" + factors + R"( float3 tint : TEXCOORD5; };
struct v2f { float4 pos : SV_POSITION; float2 uv : TEXCOORD0; float3 tint : TEXCOORD1; };
cp vert(appdata_base v) { cp o; o.vertex = v.vertex; o.normal = v.normal; o.uv = v.texcoord.xy; return o; }
pc patch(InputPatch<cp, )" + n + R"(> p, uint id : SV_PrimitiveID) {
  pc o; float f = _Tess; )" + fill + R"( o.tint = float3(id & 1, 0, 0); return o;
}
[UNITY_domain(")" + domain + R"(")]
[UNITY_partitioning(")" + partitioning + R"(")]
[UNITY_outputtopology(")" + topology + R"(")]
[UNITY_patchconstantfunc("patch")]
[UNITY_outputcontrolpoints()" + n + R"()]
cp hull(InputPatch<cp, )" + n + R"(> p, uint id : SV_OutputControlPointID) { return p[id]; }
[UNITY_domain(")" + domain + R"(")]
v2f domain(pc f, const OutputPatch<cp, )" + n + R"(> p, )" + location + R"() {
  v2f o;
  o.pos = UnityObjectToClipPos()" + position + R"();
  o.uv = p[0].uv;
  o.tint = f.tint;
  return o;
}
fixed4 frag(v2f i) : SV_Target { return fixed4(i.uv, i.tint.x, 1); }
ENDCG
} } })";
}

struct TessCase {
  const char* name;
  std::string domain, partitioning, topology;
  std::vector<std::string> modes;  // in the hull or domain stage's execution modes
  uint32_t control_points;
};

class TessellationStageTest : public testing::TestWithParam<TessCase> {};

TEST_P(TessellationStageTest, HullAndDomainCompileWithTheirAttributesAndReflection) {
  Compiler compiler;
  const TessCase& c = GetParam();
  auto b = build_text(compiler, tessellation_shader(c.domain, c.partitioning, c.topology));
  ASSERT_TRUE(b->compiled) << b->messages();
  EXPECT_FALSE(b->diags.has_errors()) << b->messages();
  expect_valid(*b);
  EXPECT_EQ(b->shader->subshaders[0].passes[0].program->shader_target, 46);
  const package::PackageVariant& v = b->compiled->package.passes.at(0).variants.at(0);
  EXPECT_EQ(stages_of(v), (std::vector<Stage>{Stage::vertex, Stage::fragment, Stage::hull, Stage::domain}));
  const package::PackageStage* vs = find_stage(v, Stage::vertex);
  const package::PackageStage* hs = find_stage(v, Stage::hull);
  const package::PackageStage* ds = find_stage(v, Stage::domain);
  const package::PackageStage* fs = find_stage(v, Stage::fragment);
  ASSERT_TRUE(vs && hs && ds && fs);
  EXPECT_EQ(hs->reflection.entry_point, "hull");
  EXPECT_EQ(ds->reflection.entry_point, "domain");
  // The hull reads the patch and writes the output control points, arrays of
  // outputcontrolpoints; the domain reads them at the same locations.
  auto hull_in = interface(hs->reflection.inputs), hull_out = interface(hs->reflection.outputs);
  ASSERT_EQ(hull_out.count("INTERNALTESSPOS"), 1u);
  EXPECT_EQ(hull_in["INTERNALTESSPOS"].second, c.control_points);
  EXPECT_EQ(hull_out["INTERNALTESSPOS"].second, c.control_points);
  EXPECT_EQ(hull_out["TEXCOORD0"].second, c.control_points);
  EXPECT_EQ(locations(vs->reflection.outputs), locations(hs->reflection.inputs));
  auto domain_in = interface(ds->reflection.inputs);
  for (const auto& [semantic, at] : domain_in) {
    if (semantic == "TEXCOORD5") continue;  // the patch constant
    ASSERT_EQ(hull_out.count(semantic), 1u) << semantic;
    EXPECT_EQ(at.first, hull_out[semantic].first) << semantic;
  }
  // The user's patch constant travels per patch, from hull to domain.
  ASSERT_EQ(hull_out.count("TEXCOORD5"), 1u);
  ASSERT_EQ(domain_in.count("TEXCOORD5"), 1u);
  EXPECT_EQ(hull_out["TEXCOORD5"], domain_in["TEXCOORD5"]);
  EXPECT_EQ(locations(ds->reflection.outputs), locations(fs->reflection.inputs));
  // _Tess is read by the patch-constant function, in the hull stage.
  bool tess_bound = std::any_of(hs->reflection.property_bindings.begin(), hs->reflection.property_bindings.end(),
                                [](const PropertyBinding& p) { return p.property == "_Tess"; });
  EXPECT_TRUE(tess_bound);

  std::string hull = disassembly(*b, *hs), domain = disassembly(*b, *ds);
  EXPECT_TRUE(has(hull, "OutputVertices " + std::to_string(c.control_points))) << hull.substr(0, 1500);
  EXPECT_TRUE(has(hull, "BuiltIn TessLevelOuter"));
  EXPECT_TRUE(has(domain, "BuiltIn TessCoord"));
  for (const std::string& mode : c.modes) EXPECT_TRUE(has(hull, mode) || has(domain, mode)) << mode;
}

INSTANTIATE_TEST_SUITE_P(
    Attributes, TessellationStageTest,
    testing::Values(TessCase{"TriFractionalOddCw", "tri", "fractional_odd", "triangle_cw",
                             {"Triangles", "SpacingFractionalOdd", "VertexOrderCw"}, 3},
                    TessCase{"TriIntegerCcw", "tri", "integer", "triangle_ccw",
                             {"Triangles", "SpacingEqual", "VertexOrderCcw"}, 3},
                    TessCase{"QuadFractionalEven", "quad", "fractional_even", "triangle_cw",
                             {"Quads", "SpacingFractionalEven"}, 4},
                    TessCase{"QuadCcw", "quad", "integer", "triangle_ccw", {"Quads", "VertexOrderCcw"}, 4},
                    TessCase{"Isoline", "isoline", "integer", "line", {"Isolines", "SpacingEqual"}, 2}),
    [](const auto& info) { return std::string(info.param.name); });

// SPIR-V has no power-of-two spacing, and glslang refuses it: an error at
// the hull function's line (glslang reads the attributes with the function).
TEST(TessellationStageTest, Pow2PartitioningIsALocatedError) {
  Compiler compiler;
  auto b = build_text(compiler, tessellation_shader("tri", "pow2", "triangle_cw"));
  ASSERT_FALSE(b->compiled);
  const Diagnostic& d = b->diags.all().at(0);
  EXPECT_TRUE(has(d.message, "'pow2': unsupported partitioning type")) << b->messages();
  ASSERT_TRUE(d.span.has_location());
  EXPECT_EQ(b->sources.line_column(d.span.file, d.span.begin).line, 23u) << b->messages();
}

TEST(TessellationStageTest, MissingControlPointCountAndDomainAreLocatedErrors) {
  Compiler compiler;
  std::string text = tessellation_shader("tri", "fractional_odd", "triangle_cw");
  std::string hull_text = text, domain_text = text;
  hull_text.replace(hull_text.find("[UNITY_outputcontrolpoints(3)]"), 30, "");
  auto hull = build_text(compiler, hull_text);
  ASSERT_FALSE(hull->compiled);
  EXPECT_TRUE(has(hull->diags.all().at(0).message, "needs a [outputcontrolpoints(...)] attribute")) << hull->messages();
  EXPECT_EQ(hull->sources.line_column(hull->diags.all()[0].span.file, hull->diags.all()[0].span.begin).line, 23u);  // cp hull(
  size_t second = domain_text.rfind("[UNITY_domain(\"tri\")]");
  domain_text.replace(second, std::string("[UNITY_domain(\"tri\")]").size(), "");
  auto domain = build_text(compiler, domain_text);
  ASSERT_FALSE(domain->compiled);
  EXPECT_TRUE(has(domain->diags.all().at(0).message, "needs a [domain(...)] attribute")) << domain->messages();
  EXPECT_EQ(domain->sources.line_column(domain->diags.all()[0].span.file, domain->diags.all()[0].span.begin).line, 25u);  // v2f domain(
}

TEST(TessellationStageTest, ReflectionListsEveryStage) {
  Compiler compiler;
  auto b = build_text(compiler, tessellation_shader("tri", "fractional_odd", "triangle_cw"));
  ASSERT_TRUE(b->compiled) << b->messages();
  // The package round-trips all four stages and their reflection.
  auto bytes = package::write_package(b->compiled->package);
  Diagnostics diags;
  auto back = package::read_package(bytes, diags);
  ASSERT_TRUE(back);
  const package::PackageVariant& v = back->passes.at(0).variants.at(0);
  ASSERT_EQ(v.stages.size(), 4u);
  for (size_t i = 0; i < v.stages.size(); ++i) {
    EXPECT_EQ(v.stages[i].reflection, b->compiled->package.passes[0].variants[0].stages[i].reflection);
  }
}

struct MissingCase {
  const char* name;
  std::string pragmas, present, missing;
};

class TessellationPairingTest : public testing::TestWithParam<MissingCase> {};

TEST_P(TessellationPairingTest, HullWithoutDomainIsALocatedError) {
  Compiler compiler;
  std::string text = "Shader \"T\" { SubShader { Pass {\nCGPROGRAM\n#pragma vertex vert\n#pragma fragment frag\n" +
                     GetParam().pragmas +
                     "float4 vert(float4 v : POSITION) : SV_POSITION { return v; }\n"
                     "fixed4 frag() : SV_Target { return 1; }\nENDCG\n} } }";
  SourceMap sources;
  Diagnostics diags;
  auto shader = compiler.load_source("pairing.shader", text, sources, diags);
  ASSERT_FALSE(shader);
  ASSERT_TRUE(diags.has_errors());
  const Diagnostic& d = diags.all()[0];
  EXPECT_EQ(d.id, DiagId::sema_missing_stage) << render_text(diags, sources);
  EXPECT_TRUE(has(d.message, "has a " + GetParam().present + " function but no " + GetParam().missing)) << d.message;
  ASSERT_TRUE(d.span.has_location());
  EXPECT_EQ(sources.line_column(d.span.file, d.span.begin).line, 2u);  // CGPROGRAM
  ASSERT_FALSE(d.notes.empty());
  EXPECT_EQ(sources.line_column(d.notes[0].span.file, d.notes[0].span.begin).line, 5u);  // the pragma
}

INSTANTIATE_TEST_SUITE_P(Stages, TessellationPairingTest,
                         testing::Values(MissingCase{"HullOnly", "#pragma hull h\n", "hull", "domain"},
                                         MissingCase{"DomainOnly", "#pragma domain d\n", "domain", "hull"}),
                         [](const auto& info) { return std::string(info.param.name); });

// --------------------------------------------------------- surface shaders

TEST(SurfaceTessellationTest, GeneratedPassesHaveHullAndDomainStages) {
  Compiler compiler;
  auto b = build(compiler, example("SurfaceTessellation.shader"));
  ASSERT_TRUE(b->compiled) << b->messages();
  EXPECT_FALSE(b->diags.has_errors()) << b->messages();
  expect_valid(*b);
  const package::Package& pkg = b->compiled->package;
  std::vector<std::string> names;
  for (const package::PackagePass& pass : pkg.passes) names.push_back(pass.name);
  EXPECT_EQ(names, (std::vector<std::string>{"FORWARD", "FORWARD_DELTA", "DEFERRED", "ShadowCaster"}));
  for (const package::PackagePass& pass : pkg.passes) {
    ASSERT_FALSE(pass.variants.empty()) << pass.name;
    for (const package::PackageVariant& v : pass.variants) {
      ASSERT_EQ(stages_of(v), (std::vector<Stage>{Stage::vertex, Stage::fragment, Stage::hull, Stage::domain}))
          << pass.name;
      EXPECT_EQ(find_stage(v, Stage::vertex)->reflection.entry_point, "tessvert_surf");
      EXPECT_EQ(find_stage(v, Stage::hull)->reflection.entry_point, "hs_surf");
      EXPECT_EQ(find_stage(v, Stage::domain)->reflection.entry_point, "ds_surf");
    }
    // No instancing keywords: the instance ID would have to cross the hull and domain.
    for (const variants::KeywordSet& set : pass.keywords.sets) EXPECT_NE(set.pragma, "multi_compile_instancing");
  }
  const package::PackageVariant& base = pkg.passes[0].variants[0];
  // The vertex stage passes the appdata on (POSITION as INTERNALTESSPOS);
  // the domain stage writes what the fragment stage reads.
  auto vs_out = interface(find_stage(base, Stage::vertex)->reflection.outputs);
  EXPECT_EQ(vs_out.count("INTERNALTESSPOS"), 1u);
  EXPECT_EQ(vs_out.count("NORMAL"), 1u);
  EXPECT_EQ(vs_out.count("TEXCOORD0"), 1u);
  EXPECT_EQ(locations(find_stage(base, Stage::domain)->reflection.outputs),
            locations(find_stage(base, Stage::fragment)->reflection.inputs));
  // The height texture is sampled where the vertex modifier now runs: the domain stage.
  const StageReflection& ds = find_stage(base, Stage::domain)->reflection;
  EXPECT_TRUE(std::any_of(ds.resources.begin(), ds.resources.end(),
                          [](const ResourceBinding& r) { return r.name == "_HeightTex"; }));
  const StageReflection& hs = find_stage(base, Stage::hull)->reflection;
  EXPECT_TRUE(std::any_of(hs.property_bindings.begin(), hs.property_bindings.end(),
                          [](const PropertyBinding& p) { return p.property == "_EdgeLength"; }));
  EXPECT_TRUE(std::any_of(ds.property_bindings.begin(), ds.property_bindings.end(),
                          [](const PropertyBinding& p) { return p.property == "_Phong"; }));
}

std::string surface_text(const std::string& options, const std::string& functions) {
  return "Shader \"T\" { SubShader {\nCGPROGRAM\n#pragma surface surf Lambert " + options +
         "\n#include \"Tessellation.cginc\"\n"
         "struct appdata { float4 vertex : POSITION; float3 normal : NORMAL; float4 texcoord : TEXCOORD0; };\n"
         "struct Input { float2 uv_MainTex; };\nsampler2D _MainTex;\n" +
         functions + "void surf(Input IN, inout SurfaceOutput o) { o.Albedo = tex2D(_MainTex, IN.uv_MainTex).rgb; }\n"
                     "ENDCG\n} }";
}

TEST(SurfaceTessellationTest, FixedFactorsAndAUniformFloatCompile) {
  Compiler compiler;
  for (const char* fn : {"float4 tess() { return 5; }\n", "float tess() { return 3; }\n"}) {
    auto b = build_text(compiler, surface_text("tessellate:tess noforwardadd", fn));
    ASSERT_TRUE(b->compiled) << b->messages();
    expect_valid(*b);
    const package::PackageVariant& v = b->compiled->package.passes.at(0).variants.at(0);
    EXPECT_EQ(stages_of(v), (std::vector<Stage>{Stage::vertex, Stage::fragment, Stage::hull, Stage::domain}));
  }
}

TEST(SurfaceTessellationTest, DistanceBasedWithPhongAndAVertexModifier) {
  Compiler compiler;
  auto b = build_text(compiler,
                      surface_text("tessellate:tess tessphong:0.5 vertex:disp addshadow",
                                   "float4 tess(appdata a, appdata b, appdata c) {\n"
                                   "  return UnityDistanceBasedTess(a.vertex, b.vertex, c.vertex, 2, 20, 8);\n}\n"
                                   "void disp(inout appdata v) { v.vertex.xyz += v.normal * 0.1; }\n"));
  ASSERT_TRUE(b->compiled) << b->messages();
  EXPECT_FALSE(b->diags.has_errors()) << b->messages();
  expect_valid(*b);
  for (const package::PackagePass& pass : b->compiled->package.passes) {
    EXPECT_EQ(stages_of(pass.variants.at(0)).size(), 4u) << pass.name;
  }
}

struct SurfaceBad {
  const char* name;
  std::string options, functions, message;
};

class SurfaceTessellationBadTest : public testing::TestWithParam<SurfaceBad> {};

TEST_P(SurfaceTessellationBadTest, IsALocatedError) {
  Compiler compiler;
  SourceMap sources;
  Diagnostics diags;
  auto shader = compiler.load_source("bad.shader", surface_text(GetParam().options, GetParam().functions), sources,
                                     diags);
  ASSERT_FALSE(shader);
  ASSERT_TRUE(diags.has_errors());
  const Diagnostic* error = nullptr;
  for (const Diagnostic& d : diags.all()) {
    if (d.severity == Severity::error && !error) error = &d;
  }
  ASSERT_TRUE(error);
  EXPECT_TRUE(has(error->message, GetParam().message)) << render_text(diags, sources);
  ASSERT_TRUE(error->span.has_location());
  EXPECT_EQ(sources.path(error->span.file), "bad.shader");
  EXPECT_EQ(sources.line_column(error->span.file, error->span.begin).line, 3u);  // #pragma surface
}

INSTANTIATE_TEST_SUITE_P(
    Cases, SurfaceTessellationBadTest,
    testing::Values(
        SurfaceBad{"MissingTessellateFunction", "tessellate:nowhere", "",
                   "the tessellation function 'nowhere' is not defined"},
        SurfaceBad{"TessellateWithWrongParameters", "tessellate:tess", "float4 tess(float4 a) { return a; }\n",
                   "tessellation function 'tess' has the wrong parameters"},
        SurfaceBad{"TessellateReturnsAStruct", "tessellate:tess vertex:disp",
                   "appdata tess(appdata a, appdata b, appdata c) { return a; }\nvoid disp(inout appdata v) {}\n",
                   "tessellation function 'tess' returns 'appdata'"},
        SurfaceBad{"VertexModifierFillsInput", "tessellate:tess vertex:disp",
                   "float4 tess() { return 2; }\nvoid disp(inout appdata v, out Input o) { o.uv_MainTex = 0; }\n",
                   "must take only 'inout appdata v'"},
        SurfaceBad{"PhongWithoutTessellate", "tessphong:0.5", "", "'tessphong:0.5' needs 'tessellate:<function>'"}),
    [](const auto& info) { return std::string(info.param.name); });

}  // namespace
}  // namespace facet
