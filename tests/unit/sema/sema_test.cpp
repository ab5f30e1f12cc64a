// sema::analyze: properties, tags, passes and the IR goldens.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>

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
  std::string text(SourceSpan s) const { return sources.text(file).substr(s.begin, s.end - s.begin); }
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

std::string with_properties(std::string_view lines) {
  return "Shader \"T\" {\n  Properties {\n" + std::string(lines) + "\n  }\n}";
}

// --- Properties ---------------------------------------------------------------

struct PropertyCase {
  const char* name;
  const char* line;
  ir::PropertyType type;
  std::array<float, 4> value;
  const char* texture;
};

class SemaPropertiesTest : public testing::TestWithParam<PropertyCase> {};

TEST_P(SemaPropertiesTest, LowersTypeAndDefault) {
  const PropertyCase& c = GetParam();
  auto a = analyze_text(with_properties(c.line));
  ASSERT_TRUE(a->ir) << render_text(a->diags, a->sources);
  const ir::Property& p = a->ir->properties.at(0);
  EXPECT_EQ(p.type, c.type);
  EXPECT_EQ(p.default_value, c.value);
  EXPECT_EQ(p.default_texture, c.texture);
}

using PT = ir::PropertyType;
INSTANTIATE_TEST_SUITE_P(
    Types, SemaPropertiesTest,
    testing::Values(PropertyCase{"float", "_A (\"a\", Float) = 0.5", PT::float_, {0.5f, 0, 0, 0}, ""},
                    PropertyCase{"int", "_A (\"a\", int) = 3", PT::int_, {3, 0, 0, 0}, ""},
                    PropertyCase{"integer", "_A (\"a\", INTEGER) = -3", PT::integer, {-3, 0, 0, 0}, ""},
                    PropertyCase{"range", "_A (\"a\", Range(0, 2)) = 1", PT::range, {1, 0, 0, 0}, ""},
                    PropertyCase{"color4", "_A (\"a\", Color) = (1, 0.5, 0, 0)", PT::color, {1, 0.5f, 0, 0}, ""},
                    PropertyCase{"color3_is_opaque", "_A (\"a\", Color) = (0, 0, 0)", PT::color, {0, 0, 0, 1}, ""},
                    PropertyCase{"vector", "_A (\"a\", Vector) = (1, 2, 3, 4)", PT::vector, {1, 2, 3, 4}, ""},
                    PropertyCase{"tex2d", "_A (\"a\", 2d) = \"bump\" {}", PT::tex2d, {0, 0, 0, 0}, "bump"},
                    PropertyCase{"tex3d", "_A (\"a\", 3D) = \"\" {}", PT::tex3d, {0, 0, 0, 0}, ""},
                    PropertyCase{"cube", "_A (\"a\", CUBE) = \"white\" {}", PT::cube, {0, 0, 0, 0}, "white"},
                    PropertyCase{"array", "_A (\"a\", 2DArray) = \"black\" {}", PT::tex2d_array, {0, 0, 0, 0}, "black"},
                    PropertyCase{"cube_array", "_A (\"a\", CubeArray) = \"grey\" {}", PT::cube_array, {0, 0, 0, 0},
                                 "grey"}),
    [](const testing::TestParamInfo<PropertyCase>& info) { return std::string(info.param.name); });

TEST(SemaPropertiesTest, RangeAndAttributesAreKept) {
  auto a = analyze_text(with_properties("[KeywordEnum(A, B C, D)] [MyDrawer] _R (\"r\", Range(0.03, 128)) = 1"));
  ASSERT_TRUE(a->ir);
  const ir::Property& p = a->ir->properties[0];
  EXPECT_EQ(p.range_min, 0.03f);
  EXPECT_EQ(p.range_max, 128.0f);
  ASSERT_EQ(p.attributes.size(), 2u);
  EXPECT_EQ(p.attributes[0].args, (std::vector<std::string>{"A", "B C", "D"}));
  EXPECT_EQ(p.attributes[1].name, "MyDrawer");
  EXPECT_EQ(a->ir->find_property("_R"), &p);
  EXPECT_EQ(a->ir->find_property("_r"), nullptr);
}

TEST(SemaPropertiesTest, MisspeltTypeSuggestsAndFixes) {
  auto a = analyze_text(with_properties("    _Shininess (\"Shininess\", Flaot) = 10"));
  EXPECT_FALSE(a->ir);
  const Diagnostic* d = a->find(DiagId::sema_unknown_property_type);
  ASSERT_NE(d, nullptr);
  EXPECT_EQ(d->message, "unknown property type 'Flaot'");
  EXPECT_EQ(a->at(d->span).line, 3u);
  EXPECT_EQ(a->at(d->span).column, 30u);
  ASSERT_EQ(d->notes.size(), 1u);
  EXPECT_EQ(d->notes[0].message, "did you mean 'Float'?");
  ASSERT_EQ(d->fixits.size(), 1u);
  EXPECT_EQ(a->text(d->fixits[0].span), "Flaot");
  EXPECT_EQ(d->fixits[0].replacement, "Float");
}

TEST(SemaPropertiesTest, UnrelatedTypeListsValidTypes) {
  auto a = analyze_text(with_properties("_A (\"a\", Banana) = 1"));
  const Diagnostic* d = a->find(DiagId::sema_unknown_property_type);
  ASSERT_NE(d, nullptr);
  EXPECT_EQ(d->notes.at(0).message,
            "valid types are Float, Int, Integer, Range, Color, Vector, 2D, 3D, Cube, 2DArray, CubeArray, Any");
}

TEST(SemaPropertiesTest, DuplicateNameWarnsKeepsTheFirstAndPointsAtIt) {
  auto a = analyze_text(with_properties("_A (\"a\", Float) = 1\n_B (\"b\", Float) = 1\n  _A (\"c\", Color) = (1,1,1)"));
  ASSERT_TRUE(a->ir);
  ASSERT_EQ(a->ir->properties.size(), 2u);
  EXPECT_EQ(a->ir->properties[0].type, ir::PropertyType::float_);
  EXPECT_EQ(a->ir->properties[0].display_name, "a");
  const Diagnostic* d = a->find(DiagId::sema_duplicate_property);
  ASSERT_NE(d, nullptr);
  EXPECT_EQ(d->severity, Severity::warning);
  EXPECT_EQ(d->message, "property '_A' is declared twice; the first declaration is used");
  EXPECT_EQ(a->at(d->span).line, 5u);
  EXPECT_EQ(a->at(d->span).column, 3u);
  ASSERT_EQ(d->notes.size(), 1u);
  EXPECT_EQ(a->at(d->notes[0].span).line, 3u);
}

struct BadPropertyCase {
  const char* name;
  const char* line;
  DiagId id;
  const char* message;
};

class SemaBadPropertyTest : public testing::TestWithParam<BadPropertyCase> {};

TEST_P(SemaBadPropertyTest, Reports) {
  const BadPropertyCase& c = GetParam();
  auto a = analyze_text(with_properties(c.line));
  const Diagnostic* d = a->find(c.id);
  ASSERT_NE(d, nullptr) << render_text(a->diags, a->sources);
  EXPECT_EQ(d->message, c.message);
  EXPECT_EQ(a->at(d->span).line, 3u);
  EXPECT_EQ(a->ir.has_value(), d->severity != Severity::error);
}

INSTANTIATE_TEST_SUITE_P(
    Defaults, SemaBadPropertyTest,
    testing::Values(
        BadPropertyCase{"texture_for_float", "_A (\"a\", Float) = \"white\" {}", DiagId::sema_bad_property_default,
                        "Float property '_A' needs a number as its default"},
        BadPropertyCase{"number_for_texture", "_A (\"a\", 2D) = 1", DiagId::sema_bad_property_default,
                        "2D property '_A' needs a texture name such as '\"white\" {}' as its default"},
        BadPropertyCase{"two_number_color", "_A (\"a\", Color) = (1, 1)", DiagId::sema_bad_property_default,
                        "Color property '_A' needs '(r, g, b)' or '(r, g, b, a)' as its default"},
        BadPropertyCase{"five_number_vector", "_A (\"a\", Vector) = (1,2,3,4,5)", DiagId::sema_bad_property_default,
                        "Vector property '_A' needs '(x, y, z, w)' as its default"},
        BadPropertyCase{"range_without_bounds", "_A (\"a\", Range) = 1", DiagId::sema_bad_property_type,
                        "'Range' needs two numbers, as in 'Range(0, 1)'"},
        BadPropertyCase{"float_with_args", "_A (\"a\", Float(1)) = 1", DiagId::sema_bad_property_type,
                        "property type 'Float' takes no arguments"},
        BadPropertyCase{"range_reversed", "_A (\"a\", Range(1, 0)) = 1", DiagId::sema_bad_property_range,
                        "the minimum of range property '_A' is greater than its maximum"},
        BadPropertyCase{"unknown_texture", "_A (\"a\", 2D) = \"whte\" {}", DiagId::sema_unknown_texture_default,
                        "unknown default texture 'whte'; it reads as gray"}),
    [](const testing::TestParamInfo<BadPropertyCase>& info) { return std::string(info.param.name); });

// --- Tags -----------------------------------------------------------------------

struct QueueCase {
  const char* value;
  bool valid;
  int number = 0;  // the queue sema resolves, for a valid value
};

class SemaQueueTest : public testing::TestWithParam<QueueCase> {};

TEST_P(SemaQueueTest, Validates) {
  auto a = analyze_text("Shader \"T\" { SubShader { Tags { \"Queue\"=\"" + std::string(GetParam().value) + "\" } } }");
  EXPECT_EQ(a->ir.has_value(), GetParam().valid) << render_text(a->diags, a->sources);
  if (!GetParam().valid) {
    EXPECT_NE(a->find(DiagId::sema_bad_queue), nullptr);
  } else if (a->ir) {
    EXPECT_EQ(a->ir->subshaders.at(0).queue, GetParam().number);
  }
}

INSTANTIATE_TEST_SUITE_P(Queues, SemaQueueTest,
                         testing::Values(QueueCase{"Background", true, 1000}, QueueCase{"Geometry", true, 2000},
                                         QueueCase{"AlphaTest", true, 2450}, QueueCase{"Transparent", true, 3000},
                                         QueueCase{"Overlay", true, 4000}, QueueCase{"Geometry+1", true, 2001},
                                         QueueCase{"Transparent-100", true, 2900}, QueueCase{"geometry-99", true, 1901},
                                         QueueCase{"Geometry + 200", true, 2200}, QueueCase{" 2450 ", true, 2450},
                                         QueueCase{"Geomtry", false}, QueueCase{"Geometry+x", false},
                                         QueueCase{"Geometry+", false}, QueueCase{"Front", false},
                                         QueueCase{"Geometry+-1", false}, QueueCase{"", false}));

TEST(SemaTagsTest, TheQueueIsGeometryWithoutATagAndInheritedFromACategory) {
  auto a = analyze_text(R"(Shader "T" { SubShader { Pass { } }
    Category { Tags { "Queue"="Overlay+5" } SubShader { Pass { } } SubShader { Tags { "Queue"="Background" } Pass { } } } })");
  ASSERT_TRUE(a->ir) << render_text(a->diags, a->sources);
  ASSERT_EQ(a->ir->subshaders.size(), 3u);
  EXPECT_EQ(a->ir->subshaders[0].queue, 2000);
  EXPECT_EQ(a->ir->subshaders[1].queue, 4005);
  EXPECT_EQ(a->ir->subshaders[2].queue, 1000);
}

TEST(SemaTagsTest, BadQueueSuggests) {
  auto a = analyze_text("Shader \"T\" { SubShader { Tags { \"Queue\"=\"Transparnt+1\" } } }");
  const Diagnostic* d = a->find(DiagId::sema_bad_queue);
  ASSERT_NE(d, nullptr);
  EXPECT_EQ(d->message, "unknown render queue 'Transparnt+1'");
  EXPECT_EQ(d->notes.at(0).message, "did you mean 'Transparent'?");
  EXPECT_EQ(a->at(d->span).column, 41u);  // the value's opening quote
}

// Book listings 5-2, 5-3 and 6-5 put LightMode in the SubShader's Tags.
constexpr const char* kSubShaderLightMode = R"(Shader "Custom/DiffuseShader" {
  SubShader {
    Tags { "LightMode" = "ForwardBase" }
    Pass {
      CGPROGRAM
      ENDCG
    }
    Pass { Tags { "RenderType"="Opaque" } }
    Pass { Tags { "LightMode"="ForwardAdd" } }
    UsePass "A/B"
  }
})";

TEST(SemaTagsTest, SubShaderLightModeWarnsAndIsCopiedIntoPasses) {
  auto a = analyze_text(kSubShaderLightMode);
  ASSERT_TRUE(a->ir) << render_text(a->diags, a->sources);
  const Diagnostic* d = a->find(DiagId::sema_lightmode_in_subshader);
  ASSERT_NE(d, nullptr);
  EXPECT_EQ(d->severity, Severity::warning);
  EXPECT_EQ(diag_group(d->id), "misplaced-tag");
  EXPECT_EQ(a->at(d->span).line, 3u);
  EXPECT_EQ(a->text(d->span), "\"LightMode\" = \"ForwardBase\"");
  ASSERT_FALSE(d->notes.empty());
  // Remove from the SubShader, insert into the two passes that have none.
  ASSERT_EQ(d->fixits.size(), 3u);
  EXPECT_EQ(d->fixits[0].replacement, "");
  EXPECT_EQ(d->fixits[1].replacement, " Tags { \"LightMode\"=\"ForwardBase\" }");
  EXPECT_EQ(a->at(d->fixits[1].span).line, 4u);
  EXPECT_EQ(d->fixits[2].replacement, " \"LightMode\"=\"ForwardBase\"");
  EXPECT_EQ(a->at(d->fixits[2].span).line, 8u);

  const auto& passes = a->ir->subshaders[0].passes;
  EXPECT_EQ(passes[0].tag("LightMode"), "ForwardBase");
  EXPECT_EQ(passes[1].tag("lightmode"), "ForwardBase");
  EXPECT_EQ(passes[1].tag("RenderType"), "Opaque");
  EXPECT_EQ(passes[2].tag("LightMode"), "ForwardAdd");
  EXPECT_EQ(passes[3].tag("LightMode"), "");
}

TEST(SemaTagsTest, LightModeIsNotCopiedWhenOptionsSayNo) {
  auto a = analyze_text(kSubShaderLightMode, {.propagate_subshader_lightmode = false});
  ASSERT_TRUE(a->ir);
  EXPECT_NE(a->find(DiagId::sema_lightmode_in_subshader), nullptr);
  EXPECT_EQ(a->ir->subshaders[0].passes[0].tag("LightMode"), "");
}

TEST(SemaTagsTest, CategoryTagsAreInheritedAndOverridden) {
  auto a = analyze_text(R"(Shader "T" { Category { Tags { "Queue"="Transparent" "RenderType"="Transparent" }
      SubShader { Tags { "renderType"="Opaque" } } } })");
  ASSERT_TRUE(a->ir);
  const auto& tags = a->ir->subshaders[0].tags;
  ASSERT_EQ(tags.size(), 2u);
  EXPECT_EQ(tags[0].key, "Queue");
  EXPECT_EQ(tags[1].value, "Opaque");
}

// --- Shader-level pieces --------------------------------------------------------

TEST(SemaShaderTest, FallbackEditorAndPasses) {
  auto a = analyze_text(R"(Shader "Custom/X" {
    SubShader { LOD 200
      UsePass "Legacy Shaders/VertexLit/SHADOWCASTER"
      GrabPass { "_Bg" }
      Pass { Name "Forward" Tags { "LightMode"="ForwardBase" } }
    }
    Fallback "VertexLit"
    CustomEditor "MyGUI" })");
  ASSERT_TRUE(a->ir) << render_text(a->diags, a->sources);
  const ir::Shader& s = *a->ir;
  EXPECT_EQ(s.name, "Custom/X");
  EXPECT_EQ(s.fallback, "VertexLit");
  EXPECT_EQ(s.custom_editor, "MyGUI");
  EXPECT_EQ(s.file, a->file);
  const ir::SubShader& sub = s.subshaders[0];
  EXPECT_EQ(sub.lod, 200);
  ASSERT_EQ(sub.passes.size(), 3u);
  EXPECT_EQ(sub.passes[0].kind, ir::PassKind::use_pass);
  EXPECT_EQ(sub.passes[0].use_pass, "Legacy Shaders/VertexLit/SHADOWCASTER");
  EXPECT_EQ(sub.passes[0].name, "SHADOWCASTER");
  EXPECT_EQ(sub.passes[1].kind, ir::PassKind::grab_pass);
  EXPECT_EQ(sub.passes[1].grab_texture, "_Bg");
  EXPECT_EQ(sub.passes[2].name, "Forward");
  EXPECT_FALSE(sub.passes[2].program.has_value());
}

TEST(SemaShaderTest, FallbackOffIsAbsent) {
  auto off = analyze_text("Shader \"T\" { Fallback Off }");
  ASSERT_TRUE(off->ir);
  EXPECT_FALSE(off->ir->fallback.has_value());
  auto quoted = analyze_text("Shader \"T\" { Fallback \"off\" }");
  ASSERT_TRUE(quoted->ir);
  EXPECT_FALSE(quoted->ir->fallback.has_value());
}

TEST(SemaShaderTest, BadUsePass) {
  auto a = analyze_text("Shader \"T\" { SubShader { UsePass \"NoSlash\" } }");
  EXPECT_FALSE(a->ir);
  EXPECT_NE(a->find(DiagId::sema_bad_use_pass), nullptr);
}

TEST(SemaShaderTest, LegacyCommandsLeaveOnlyNotes) {
  auto a = analyze_text(R"(Shader "T" { SubShader { Pass {
      Lighting Off Fog { Color (0,0,0,0) } SetTexture [_MainTex] { combine texture * primary }
      ZWrite Off } } })");
  ASSERT_TRUE(a->ir) << render_text(a->diags, a->sources);
  EXPECT_EQ(a->diags.error_count() + a->diags.warning_count(), 0u);
  EXPECT_EQ(a->ir->subshaders[0].passes[0].state.zwrite->literal, "Off");
}

// Deterministic mutations of a valid file: whatever parses must analyze
// and dump without crashing, with every span inside the file.
TEST(SemaShaderTest, MutatedFilesNeverCrash) {
  std::ifstream in(FACET_TESTDATA_DIR "/shaderlab/book_constructs.shader", std::ios::binary);
  std::stringstream buffer;
  buffer << in.rdbuf();
  const std::string text = buffer.str();
  ASSERT_FALSE(text.empty());
  const std::string alphabet = "{}()[]\",=#\n\\-+.0aZ/*";
  uint32_t seed = 99;
  auto next = [&] { return seed = seed * 1664525u + 1013904223u; };
  for (int round = 0; round < 1500; ++round) {
    std::string mutated = text;
    for (int k = 0; k < 1 + round % 3; ++k) mutated[next() % mutated.size()] = alphabet[next() % alphabet.size()];
    auto a = analyze_text(mutated);
    if (a->ir) ir_to_json(*a->ir);
    for (const Diagnostic& d : a->diags.all()) {
      EXPECT_LE(d.span.end, mutated.size()) << d.message;
      for (const DiagNote& n : d.notes) EXPECT_TRUE(!n.span.has_location() || n.span.end <= mutated.size());
    }
  }
}

// --- IR goldens -----------------------------------------------------------------

namespace fs = std::filesystem;

std::string read_file(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

std::vector<std::string> golden_names() {
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(FACET_TESTDATA_DIR "/shaderlab")) {
    if (entry.path().extension() == ".shader") names.push_back(entry.path().stem().string());
  }
  std::sort(names.begin(), names.end());
  return names;
}

class SemaIrJsonTest : public testing::TestWithParam<std::string> {};

TEST_P(SemaIrJsonTest, MatchesGolden) {
  fs::path dir = FACET_TESTDATA_DIR "/shaderlab";
  auto a = analyze_text(read_file(dir / (GetParam() + ".shader")));
  ASSERT_TRUE(a->ir) << render_text(a->diags, a->sources);
  EXPECT_EQ(a->diags.error_count() + a->diags.warning_count(), 0u) << render_text(a->diags, a->sources);
  std::string actual = ir_to_json(*a->ir);
  EXPECT_EQ(actual, ir_to_json(*a->ir));
  fs::path golden = dir / (GetParam() + ".ir.json");
  if (std::getenv("FACET_UPDATE_GOLDENS")) {
    std::ofstream(golden, std::ios::binary) << actual;
    GTEST_SKIP() << "rewrote " << golden;
  }
  ASSERT_TRUE(fs::exists(golden)) << "missing " << golden << "; run with FACET_UPDATE_GOLDENS=1";
  EXPECT_EQ(actual, read_file(golden));
}

INSTANTIATE_TEST_SUITE_P(Goldens, SemaIrJsonTest, testing::ValuesIn(golden_names()),
                         [](const testing::TestParamInfo<std::string>& info) { return info.param; });

TEST(SemaIrJsonTest, ExampleShadersAnalyzeCleanly) {
  size_t files = 0;
  for (const auto& entry : fs::directory_iterator(FACET_SOURCE_DIR "/examples/shaders")) {
    if (entry.path().extension() != ".shader") continue;
    SCOPED_TRACE(entry.path().string());
    auto a = analyze_text(read_file(entry.path()));
    EXPECT_TRUE(a->ir) << render_text(a->diags, a->sources);
    ++files;
  }
  EXPECT_GT(files, 0u);
}

}  // namespace
}  // namespace facet::sema
