// .facetpkg: round trips of a package with every field set, deterministic
// bytes, a reader that rejects every truncation, corruption and oversized
// count without crashing, and a stable JSON view.
#include "facet/package.h"

#include <gtest/gtest.h>
#include <xxhash.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <fstream>
#include <iterator>
#include <limits>
#include <nlohmann/json.hpp>
#include <optional>
#include <random>
#include <tuple>
#include <type_traits>

namespace facet::package {
namespace {

// ---- Deep equality (SourceSpans are not stored, so not compared) ----------

auto fields(const ir::PropertyAttribute& a) { return std::tie(a.name, a.args); }
auto fields(const ir::Property& p) {
  return std::tie(p.name, p.display_name, p.type, p.attributes, p.range_min, p.range_max, p.default_value,
                  p.default_texture);
}
auto fields(const ir::Tag& t) { return std::tie(t.key, t.value); }
auto fields(const ir::StateValue& v) { return std::tie(v.literal, v.property); }
auto fields(const ir::BlendState& b) {
  return std::tie(b.render_target, b.off, b.src, b.dst, b.src_alpha, b.dst_alpha);
}
auto fields(const ir::BlendOpState& b) { return std::tie(b.render_target, b.color_op, b.alpha_op); }
auto fields(const ir::ColorMaskState& c) { return std::tie(c.render_target, c.mask); }
auto fields(const ir::StencilState& s) {
  return std::tie(s.ref, s.read_mask, s.write_mask, s.comp, s.pass, s.fail, s.zfail, s.comp_back, s.pass_back,
                  s.fail_back, s.zfail_back, s.comp_front, s.pass_front, s.fail_front, s.zfail_front);
}
auto fields(const ir::RenderState& s) {
  return std::tie(s.cull, s.ztest, s.zwrite, s.alpha_to_mask, s.zclip, s.conservative, s.offset_factor,
                  s.offset_units, s.blend, s.blend_op, s.color_mask, s.stencil);
}
auto fields(const variants::KeywordSet& s) { return std::tie(s.directive, s.local, s.stages, s.keywords, s.pragma); }
auto fields(const variants::KeywordRule& r) { return std::tie(r.kind, r.keyword, r.others); }
auto fields(const variants::KeywordCombinations& c) { return std::tie(c.sets, c.choices, c.pragma); }
auto fields(const variants::KeywordSpace& s) {
  return std::tie(s.sets, s.dynamic_branch_keywords, s.skip_variants, s.rules, s.combinations, s.unreachable_keywords);
}
auto fields(const StageVariable& v) { return std::tie(v.name, v.semantic, v.location, v.type, v.array_size); }
auto fields(const BlockMember& m) {
  return std::tie(m.name, m.type, m.offset, m.size, m.array_dims, m.array_stride, m.matrix_stride, m.row_major,
                  m.members);
}
auto fields(const UniformBlock& b) {
  return std::tie(b.name, b.set, b.binding, b.size, b.push_constant, b.members);
}
auto fields(const ResourceBinding& r) {
  return std::tie(r.name, r.kind, r.dim, r.arrayed, r.set, r.binding, r.array_size);
}
auto fields(const SpecConstant& c) { return std::tie(c.name, c.id, c.type, c.default_value); }
auto fields(const PropertyBinding& b) { return std::tie(b.property, b.role, b.block, b.member); }
auto fields(const StageReflection& r) {
  return std::tie(r.stage, r.entry_point, r.inputs, r.outputs, r.uniform_blocks, r.resources, r.spec_constants,
                  r.property_bindings);
}
auto fields(const PackageStage& s) { return std::tie(s.stage, s.blob, s.reflection); }
auto fields(const PackageVariant& v) { return std::tie(v.key.choice, v.keywords, v.stages); }
auto fields(const PackagePass& p) {
  return std::tie(p.name, p.tags, p.state, p.keywords, p.variants, p.grab_before, p.source_index);
}
auto fields(const Package& p) {
  return std::tie(p.version, p.shader_name, p.properties, p.subshader_tags, p.lod, p.fallback, p.custom_editor,
                  p.passes, p.spirv_blobs);
}

template <class T>
struct IsVector : std::false_type {};
template <class T>
struct IsVector<std::vector<T>> : std::true_type {};
template <class T>
struct IsOptional : std::false_type {};
template <class T>
struct IsOptional<std::optional<T>> : std::true_type {};
template <class T>
struct IsArray : std::false_type {};
template <class T, size_t N>
struct IsArray<std::array<T, N>> : std::true_type {};
template <class T>
struct IsTuple : std::false_type {};
template <class... T>
struct IsTuple<std::tuple<T...>> : std::true_type {};

template <class T>
bool same(const T& a, const T& b) {
  if constexpr (std::is_same_v<T, float>) {
    return std::bit_cast<uint32_t>(a) == std::bit_cast<uint32_t>(b);  // NaN and -0 exactly
  } else if constexpr (IsVector<T>::value || IsArray<T>::value) {
    if (a.size() != b.size()) return false;
    for (size_t i = 0; i < a.size(); ++i) {
      if (!same(a[i], b[i])) return false;
    }
    return true;
  } else if constexpr (IsOptional<T>::value) {
    return a.has_value() == b.has_value() && (!a || same(*a, *b));
  } else if constexpr (IsTuple<T>::value) {
    return std::apply([&](const auto&... x) { return std::apply([&](const auto&... y) { return (same(x, y) && ...); }, b); },
                      a);
  } else if constexpr (requires { fields(a); }) {
    return same(fields(a), fields(b));
  } else {
    return a == b;
  }
}

void expect_same(const Package& a, const Package& b) {
  EXPECT_TRUE(same(a, b)) << "expected:\n" << package_to_json(a) << "\nactual:\n" << package_to_json(b);
}

// ---- A package with every field set ---------------------------------------

SourceSpan span(uint32_t b) { return SourceSpan{0, b, b + 3}; }
ir::StateValue lit(std::string s) { return ir::StateValue{std::move(s), "", span(1)}; }
ir::StateValue prop(std::string s) { return ir::StateValue{"", std::move(s), span(2)}; }

std::vector<ir::Property> rich_properties() {
  ir::Property color{"_Color", "Main Color", ir::PropertyType::color, {}, 0, 0, {1, 0.5f, 0.25f, 1}, "", span(3)};
  color.attributes = {{"HDR", {}, span(4)}, {"Header", {"Surface options", ""}, span(5)}};
  ir::Property range{"_Gloss", "Smoothness", ir::PropertyType::range, {}, -1.5f, 2.75f, {0.1f, 0, 0, 0}, "", span(6)};
  range.attributes = {{"PowerSlider", {"3.0"}, span(7)}};
  ir::Property tex{"_MainTex", "Albedo (RGB)", ir::PropertyType::tex2d, {}, 0, 0, {}, "white", span(8)};
  tex.attributes = {{"NoScaleOffset", {}, {}}, {"MainTexture", {}, {}}};
  ir::Property special{"_Weird", "Ünïcode \xE2\x9C\x93 and \"quotes\"", ir::PropertyType::vector, {}, 0, 0, {}, "",
                       {}};
  special.default_value = {-0.0f, std::numeric_limits<float>::denorm_min(), std::numeric_limits<float>::quiet_NaN(),
                           -std::numeric_limits<float>::infinity()};
  std::vector<ir::Property> props = {color, range, tex, special};
  for (ir::PropertyType t : {ir::PropertyType::float_, ir::PropertyType::int_, ir::PropertyType::integer,
                             ir::PropertyType::tex3d, ir::PropertyType::cube, ir::PropertyType::tex2d_array,
                             ir::PropertyType::cube_array}) {
    props.push_back({"_P" + std::to_string(int(t)), "P", t, {}, 0, 0, {float(int(t)), 0, 0, 0}, "bump", {}});
  }
  props.push_back({std::string("nul\0inside", 10), "", ir::PropertyType::float_, {}, 0, 0, {}, "", {}});
  return props;
}

ir::RenderState rich_state() {
  ir::RenderState s;
  s.cull = prop("_Cull");
  s.ztest = lit("LEqual");
  s.zwrite = lit("Off");
  s.alpha_to_mask = lit("On");
  s.zclip = lit("False");
  s.conservative = lit("True");
  s.offset_factor = lit("-1");
  s.offset_units = prop("_OffsetUnits");
  s.blend = {{-1, false, prop("_SrcBlend"), lit("OneMinusSrcAlpha"), lit("One"), prop("_DstAlpha")},
             {1, true, {}, {}, std::nullopt, std::nullopt},
             {2, false, lit("One"), lit("One"), std::nullopt, lit("Zero")}};
  s.blend_op = {{-1, lit("Add"), lit("Max")}, {3, prop("_BlendOp"), std::nullopt}};
  s.color_mask = {{-1, lit("RGBA")}, {1, lit("0")}, {2, prop("_Mask")}};
  ir::StencilState st;
  st.ref = prop("_StencilRef");
  st.read_mask = lit("255");
  st.write_mask = lit("127");
  st.comp = lit("Equal");
  st.pass = lit("Replace");
  st.fail = lit("Keep");
  st.zfail = lit("IncrSat");
  st.comp_back = lit("Always");
  st.pass_back = lit("DecrWrap");
  st.fail_back = lit("Invert");
  st.zfail_back = lit("Zero");
  st.comp_front = prop("_StencilComp");
  st.pass_front = lit("IncrWrap");
  st.fail_front = lit("DecrSat");
  st.zfail_front = lit("Keep");
  st.span = span(9);
  s.stencil = st;
  return s;
}

variants::KeywordSpace rich_keywords() {
  variants::KeywordSpace space;
  space.sets = {
      {variants::KeywordDirective::multi_compile, false, kAllStages, {"", "FOG_LINEAR", "FOG_EXP"}, "multi_compile_fog",
       span(10)},
      {variants::KeywordDirective::shader_feature, true, stage_bit(Stage::fragment), {"", "_NORMALMAP"},
       "shader_feature_local_fragment", span(11)},
      {variants::KeywordDirective::multi_compile, false, stage_bit(Stage::vertex) | stage_bit(Stage::geometry),
       {"SHADOWS_OFF", "SHADOWS_ON"}, "multi_compile_vertex", {}},
      {variants::KeywordDirective::dynamic_branch, true, kAllStages, {"_A", "_B"}, "dynamic_branch_local", {}},
  };
  space.dynamic_branch_keywords = {"_DYN_A", "_DYN_B"};
  space.skip_variants = {"FOG_EXP", "_B"};
  // Format 4: what draw-time selection needs beyond the sets.
  space.rules = {{variants::RuleKind::implies, "_NORMALMAP", {"FOG_LINEAR"}, span(12)},
                 {variants::RuleKind::excludes, "SHADOWS_ON", {"_NORMALMAP", "FOG_EXP"}, {}}};
  space.combinations = {{{0, 2}, {{0, 0}, {1, 1}, {2, 0}}, "multi_compile_fwdbase", span(13)}};
  space.unreachable_keywords = {"SHADOWS_ON"};
  return space;
}

StageReflection rich_reflection(Stage stage) {
  StageReflection r;
  r.stage = stage;
  r.entry_point = stage == Stage::vertex ? "vert" : "frag";
  r.inputs = {{"in.var.POSITION", "POSITION", 0, "float4", 0}, {"in.var.TEXCOORD0", "TEXCOORD0", 1, "float2", 0}};
  r.outputs = {{"out.var.TEXCOORD1", "TEXCOORD1", 2, "float3", 4}};
  BlockMember inner{"dir", "float3", 0, 12, {}, 0, 0, false, {}};
  BlockMember light{"lights", "struct", 64, 128, {4, 2}, 32, 0, false, {inner, {"intensity", "float", 12, 4}}};
  BlockMember matrix{"_World", "float4x4", 0, 64, {}, 0, 16, true, {}};
  r.uniform_blocks = {{"$Globals", 1, 0, 192, false, {matrix, light}},
                      {"PushConstants", 0, 0, 16, true, {{"_Time", "float4", 0, 16}}}};
  r.resources = {{"_MainTex", ResourceKind::combined_image_sampler, "2D", false, 0, 1, 0},
                 {"_Arr", ResourceKind::separate_image, "2D", true, 0, 2, 8},
                 {"_Samp", ResourceKind::separate_sampler, "", false, 0, 3, 0},
                 {"_Img", ResourceKind::storage_image, "3D", false, 2, 0, 0},
                 {"_Buf", ResourceKind::storage_buffer, "", false, 2, 1, 0},
                 {"_Texel", ResourceKind::uniform_texel_buffer, "Buffer", false, 2, 2, 0}};
  r.spec_constants = {{"QUALITY", 7, "int", "2"}, {"USE_FOO", 9, "bool", "true"}};
  r.property_bindings = {{"_Color", "value", "$Globals", "_Color"},
                         {"_MainTex", "texture", "", "_MainTex"},
                         {"_MainTex", "scale_offset", "$Globals", "_MainTex_ST"}};
  return r;
}

PackageVariant variant(std::vector<uint32_t> key, std::vector<std::string> keywords, uint32_t vs, uint32_t fs) {
  return {{std::move(key)},
          std::move(keywords),
          {{Stage::vertex, vs, rich_reflection(Stage::vertex)}, {Stage::fragment, fs, rich_reflection(Stage::fragment)}}};
}

Package rich_package() {
  Package p;
  p.shader_name = "Custom/Rich";
  p.properties = rich_properties();
  p.subshader_tags = {{"RenderType", "Opaque", span(12)}, {"Queue", "Geometry+1", {}}, {"", "", {}}};
  p.lod = -200;
  p.fallback = "Diffuse";
  p.custom_editor = "RichShaderGUI";
  PackagePass forward{"FORWARD", {{"LightMode", "ForwardBase", span(13)}}, rich_state(), rich_keywords(), {}};
  forward.grab_before = {"_GrabTexture", "_SharedGrab"};
  forward.variants = {
      variant({0, 0, 0, 0}, {"SHADOWS_OFF", "_A"}, 0, 1),
      variant({0, 1, 1, variants::kOffChoice}, {"_NORMALMAP", "SHADOWS_ON"}, 0, 2),
      variant({1, 0, 0, 0}, {"FOG_LINEAR", "SHADOWS_OFF", "_A"}, 3, 1),
  };
  forward.variants[2].stages.push_back({Stage::geometry, 4, rich_reflection(Stage::geometry)});
  PackagePass shadow{"ShadowCaster", {{"LightMode", "ShadowCaster", {}}}, {}, {}, {}};
  shadow.variants = {{{}, {}, {{Stage::vertex, 0, {}}}}};
  shadow.source_index = 3;  // a build that kept some of the SubShader's passes
  PackagePass empty{"", {}, {}, {}, {}};
  empty.source_index = 7;
  p.passes = {forward, shadow, empty};
  p.spirv_blobs = {{0x07230203, 0x00010000, 0, 42, 0}, {0x07230203, 1, 2, 3}, {}, {0xdeadbeef}, {0x01020304, 5}};
  return p;
}

// ---- Byte helpers ---------------------------------------------------------

uint32_t get32(const std::vector<uint8_t>& b, size_t at) {
  return uint32_t(b[at]) | uint32_t(b[at + 1]) << 8 | uint32_t(b[at + 2]) << 16 | uint32_t(b[at + 3]) << 24;
}
void put32(std::vector<uint8_t>& b, size_t at, uint32_t v) {
  for (int i = 0; i < 4; ++i) b[at + size_t(i)] = uint8_t(v >> (8 * i));
}
void put64(std::vector<uint8_t>& b, size_t at, uint64_t v) {
  for (int i = 0; i < 8; ++i) b[at + size_t(i)] = uint8_t(v >> (8 * i));
}
// Recomputes the checksum after a deliberate edit (docs/package-format.md).
void reseal(std::vector<uint8_t>& b) { put64(b, 24, XXH64(b.data() + 32, b.size() - 32, 0)); }
// Offset of section `id` (1 = strings ... 7 = blobs) from the section table.
size_t section_offset(const std::vector<uint8_t>& b, uint32_t id) {
  size_t entry = 40 + 24 * size_t(id - 1);
  return size_t(get32(b, entry + 8));
}

Result<Package> read(const std::vector<uint8_t>& bytes, Diagnostics& diags, bool verify_checksum = true) {
  return read_package(bytes, diags, ReadOptions{.verify_checksum = verify_checksum});
}

// The single diagnostic of a failed read.
std::string read_error(const std::vector<uint8_t>& bytes, bool verify_checksum = true) {
  Diagnostics diags;
  auto result = read(bytes, diags, verify_checksum);
  EXPECT_FALSE(result.has_value());
  EXPECT_EQ(diags.size(), 1u);
  if (diags.size() != 1) return {};
  const Diagnostic& d = diags.all()[0];
  EXPECT_EQ(d.id, DiagId::package_corrupt);
  EXPECT_EQ(d.severity, Severity::error);
  EXPECT_FALSE(d.span.has_location());
  return d.message;
}

// ---- Round trip -----------------------------------------------------------

class PackageRoundTripTest : public ::testing::Test {
 protected:
  Package package_ = rich_package();
};

TEST_F(PackageRoundTripTest, RichPackageIsValid) {
  Diagnostics diags;
  EXPECT_TRUE(validate_package(package_, diags));
  EXPECT_EQ(diags.size(), 0u);
}

TEST_F(PackageRoundTripTest, EveryFieldReadsBackEqual) {
  std::vector<uint8_t> bytes = write_package(package_);
  Diagnostics diags;
  auto back = read_package(bytes, diags);
  ASSERT_TRUE(back.has_value()) << (diags.size() ? diags.all()[0].message : "");
  EXPECT_EQ(diags.size(), 0u);
  expect_same(package_, *back);
}

TEST_F(PackageRoundTripTest, EmptyPackageReadsBackEqual) {
  Package empty;
  Diagnostics diags;
  auto back = read_package(write_package(empty), diags);
  ASSERT_TRUE(back.has_value());
  expect_same(empty, *back);
}

TEST_F(PackageRoundTripTest, BytesAreDeterministic) {
  std::vector<uint8_t> first = write_package(package_);
  EXPECT_EQ(first, write_package(package_));
  EXPECT_EQ(first, write_package(rich_package()));
  Diagnostics diags;
  auto back = read_package(first, diags);
  ASSERT_TRUE(back.has_value());
  EXPECT_EQ(first, write_package(*back));
}

TEST_F(PackageRoundTripTest, SpansReadBackAsDefault) {
  Diagnostics diags;
  auto back = read_package(write_package(package_), diags);
  ASSERT_TRUE(back.has_value());
  EXPECT_EQ(back->properties[0].span, SourceSpan{});
  EXPECT_EQ(back->properties[0].attributes[0].span, SourceSpan{});
  EXPECT_EQ(back->subshader_tags[0].span, SourceSpan{});
  EXPECT_EQ(back->passes[0].state.cull->span, SourceSpan{});
  EXPECT_EQ(back->passes[0].state.stencil->span, SourceSpan{});
  EXPECT_EQ(back->passes[0].keywords.sets[0].span, SourceSpan{});
}

// Format 5: the GrabPasses before a pass; a texture needs a name.
TEST_F(PackageRoundTripTest, AnEmptyGrabPassTextureNameIsCorrupt) {
  package_.passes[0].grab_before = {"_GrabTexture", ""};
  EXPECT_NE(read_error(write_package(package_)).find("empty GrabPass texture name"), std::string::npos);
}

TEST_F(PackageRoundTripTest, VersionIsTheFormatVersion) {
  package_.version = 99;  // informational: the writer always writes kFormatVersion
  Diagnostics diags;
  auto back = read_package(write_package(package_), diags);
  ASSERT_TRUE(back.has_value());
  EXPECT_EQ(back->version, kFormatVersion);
}

TEST_F(PackageRoundTripTest, StringsAreStoredOnce) {
  std::vector<uint8_t> bytes = write_package(package_);
  std::string text(bytes.begin(), bytes.end());
  for (std::string s : {"RichShaderGUI", "_MainTex_ST", "in.var.POSITION", "shader_feature_local_fragment"}) {
    size_t first = text.find(s);
    ASSERT_NE(first, std::string::npos) << s;
    EXPECT_EQ(text.find(s, first + 1), std::string::npos) << s << " is stored twice";
  }
}

TEST_F(PackageRoundTripTest, SpirvWordsAreAligned) {
  std::vector<uint8_t> bytes = write_package(package_);
  EXPECT_EQ(section_offset(bytes, 7) % 8, 0u);
  const uint8_t deadbeef[] = {0xef, 0xbe, 0xad, 0xde};
  auto it = std::search(bytes.begin(), bytes.end(), std::begin(deadbeef), std::end(deadbeef));
  ASSERT_NE(it, bytes.end());
  EXPECT_EQ((it - bytes.begin()) % 4, 0);
}

TEST_F(PackageRoundTripTest, DeduplicateBlobsMergesAndDropsUnused) {
  Package p;
  p.spirv_blobs = {{1, 2}, {9}, {1, 2}, {3}};
  p.passes.push_back({"P", {}, {}, {}, {}});
  p.passes[0].variants = {{{}, {}, {{Stage::vertex, 2, {}}, {Stage::fragment, 0, {}}, {Stage::geometry, 3, {}}}}};
  deduplicate_blobs(p);
  EXPECT_EQ(p.spirv_blobs, (std::vector<std::vector<uint32_t>>{{1, 2}, {3}}));
  EXPECT_EQ(p.passes[0].variants[0].stages[0].blob, 0u);
  EXPECT_EQ(p.passes[0].variants[0].stages[1].blob, 0u);
  EXPECT_EQ(p.passes[0].variants[0].stages[2].blob, 1u);
}

// Format 4's keyword combinations must name sets of the space and fit them.
TEST_F(PackageRoundTripTest, ACombinationOutsideItsSetsIsNotRead) {
  Package p = rich_package();
  p.passes[0].keywords.combinations[0].sets = {0, 9};
  EXPECT_NE(read_error(write_package(p)).find("a combination names keyword set 9 (sets ascending, below 4)"),
            std::string::npos);
  p = rich_package();
  p.passes[0].keywords.combinations[0].choices[1] = {1, 7};
  EXPECT_NE(read_error(write_package(p)).find("a keyword combination does not match its sets"), std::string::npos);
}

// Packages that break an invariant are written, but neither validated nor read.
struct InvalidCase {
  const char* name;
  void (*edit)(Package&);
  const char* message;
};

class PackageInvalidTest : public ::testing::TestWithParam<InvalidCase> {};

TEST_P(PackageInvalidTest, ValidateAndReadReject) {
  Package p = rich_package();
  GetParam().edit(p);
  Diagnostics diags;
  EXPECT_FALSE(validate_package(p, diags));
  ASSERT_GE(diags.size(), 1u);
  EXPECT_NE(diags.all()[0].message.find(GetParam().message), std::string::npos) << diags.all()[0].message;
  std::string error = read_error(write_package(p));
  EXPECT_NE(error.find(GetParam().message), std::string::npos) << error;
}

INSTANTIATE_TEST_SUITE_P(
    Invariants, PackageInvalidTest,
    ::testing::Values(
        InvalidCase{"BlobIndex", [](Package& p) { p.passes[0].variants[1].stages[1].blob = 5; },
                    "blob index 5 out of range (5 blobs)"},
        InvalidCase{"Unsorted", [](Package& p) { std::swap(p.passes[0].variants[0], p.passes[0].variants[1]); },
                    "is not greater than the previous key"},
        InvalidCase{"Duplicate", [](Package& p) { p.passes[0].variants[1] = p.passes[0].variants[0]; },
                    "is not greater than the previous key"},
        InvalidCase{"ChoiceCount", [](Package& p) { p.passes[0].variants[0].key.choice.pop_back(); },
                    "has 3 choices for 4 keyword sets"},
        InvalidCase{"ChoiceRange", [](Package& p) { p.passes[0].variants[2].key.choice[2] = 2; },
                    "chooses keyword 2 of set 2, which has 2"},
        InvalidCase{"StageOrder",
                    [](Package& p) { std::swap(p.passes[0].variants[0].stages[0], p.passes[0].variants[0].stages[1]); },
                    "not in strictly increasing stage order"},
        InvalidCase{"DeepMembers",
                    [](Package& p) {
                      BlockMember m{"leaf", "float", 0, 4};
                      for (int i = 0; i < 40; ++i) m = BlockMember{"s", "struct", 0, 4, {}, 0, 0, false, {m}};
                      p.passes[1].variants[0].stages[0].reflection.uniform_blocks = {{"B", 0, 0, 4, false, {m}}};
                    },
                    "nested deeper than 32 levels"}),
    [](const auto& info) { return std::string(info.param.name); });

TEST_F(PackageRoundTripTest, AmbiguousStateValueIsInvalid) {
  package_.passes[0].state.blend[0].src = ir::StateValue{"One", "_Src", {}};
  Diagnostics diags;
  EXPECT_FALSE(validate_package(package_, diags));
  EXPECT_NE(diags.all()[0].message.find("both a literal and a property"), std::string::npos);
}

// ---- Reader ---------------------------------------------------------------

class PackageReaderTest : public ::testing::Test {
 protected:
  std::vector<uint8_t> bytes_ = write_package(rich_package());
};

TEST_F(PackageReaderTest, EveryTruncationIsRejected) {
  for (bool verify : {true, false}) {
    for (size_t n = 0; n < bytes_.size(); ++n) {
      Diagnostics diags;
      auto result = read_package(std::span(bytes_.data(), n), diags, ReadOptions{.verify_checksum = verify});
      ASSERT_FALSE(result.has_value()) << "prefix of " << n << " bytes was accepted";
      ASSERT_EQ(diags.size(), 1u);
      EXPECT_NE(diags.all()[0].message.find("byte offset"), std::string::npos);
    }
  }
}

// Truncated sections inside a file whose header and table were fixed up, so
// that the section decoders themselves meet the end.
TEST_F(PackageReaderTest, EveryTruncatedLastSectionIsRejected) {
  size_t blobs = section_offset(bytes_, 7);
  for (size_t n = blobs; n < bytes_.size(); ++n) {
    std::vector<uint8_t> cut(bytes_.begin(), bytes_.begin() + std::ptrdiff_t(n));
    put64(cut, 16, cut.size());
    put64(cut, 40 + 24 * 6 + 16, n - blobs);
    reseal(cut);
    std::string error = read_error(cut);
    EXPECT_FALSE(error.empty()) << n;
  }
}

TEST_F(PackageReaderTest, RandomByteFlipsAreRejectedOrReadConsistently) {
  std::mt19937 rng(20240611);
  int accepted = 0;
  for (int i = 0; i < 4000; ++i) {
    std::vector<uint8_t> bytes = bytes_;
    int flips = 1 + int(rng() % 3);
    for (int f = 0; f < flips; ++f) bytes[rng() % bytes.size()] ^= uint8_t(1 + rng() % 255);
    // With the checksum, every corruption is caught.
    Diagnostics checked;
    ASSERT_FALSE(read(bytes, checked).has_value()) << "iteration " << i;
    ASSERT_EQ(checked.size(), 1u);
    // Without it, the structural checks alone hold: an error, or a package
    // that writes and reads back the same.
    Diagnostics diags;
    auto result = read(bytes, diags, /*verify_checksum=*/false);
    if (!result) {
      ASSERT_EQ(diags.size(), 1u);
      EXPECT_EQ(diags.all()[0].id, DiagId::package_corrupt);
      continue;
    }
    ++accepted;
    EXPECT_EQ(diags.size(), 0u);
    Diagnostics valid;
    EXPECT_TRUE(validate_package(*result, valid)) << (valid.size() ? valid.all()[0].message : "");
    Diagnostics again_diags;
    auto again = read_package(write_package(*result), again_diags);
    ASSERT_TRUE(again.has_value()) << "iteration " << i << ": " << again_diags.all()[0].message;
    expect_same(*result, *again);
  }
  // Flips in SPIR-V words, reflection numbers and floats read fine.
  EXPECT_GT(accepted, 0);
}

TEST_F(PackageReaderTest, EmptyInput) {
  EXPECT_EQ(read_error({}), "corrupt package: file ends inside the 32-byte header at byte offset 0");
}

TEST_F(PackageReaderTest, WrongMagic) {
  bytes_[3] = 'X';
  EXPECT_EQ(read_error(bytes_),
            "corrupt package: bad magic (expected \"FACETPKG\"; not a facet package) at byte offset 0");
}

TEST_F(PackageReaderTest, NewerVersion) {
  put32(bytes_, 8, kFormatVersion + 1);
  EXPECT_EQ(read_error(bytes_), "package format version " + std::to_string(kFormatVersion + 1) +
                                    " is newer than supported " + std::to_string(kFormatVersion) +
                                    " (at byte offset 8)");
}

TEST_F(PackageReaderTest, VersionZero) {
  put32(bytes_, 8, 0);
  EXPECT_EQ(read_error(bytes_), "corrupt package: invalid format version 0 at byte offset 8");
}

TEST_F(PackageReaderTest, UnknownFlags) {
  put32(bytes_, 12, 4);
  EXPECT_EQ(read_error(bytes_), "corrupt package: unknown flags 0x0000000000000004 at byte offset 12");
}

TEST_F(PackageReaderTest, ChecksumMismatch) {
  bytes_.back() ^= 1;
  EXPECT_NE(read_error(bytes_).find("checksum mismatch"), std::string::npos);
}

TEST_F(PackageReaderTest, TrailingData) {
  bytes_.push_back(0);
  EXPECT_NE(read_error(bytes_).find("trailing data after the package: header says"), std::string::npos);
}

TEST_F(PackageReaderTest, HugeCountInSmallFileIsRejected) {
  std::vector<uint8_t> bytes = write_package(Package{});
  ASSERT_LT(bytes.size(), 300u);
  for (uint32_t id : {1, 3, 4, 5, 6, 7}) {  // the shader section starts with a string index
    std::vector<uint8_t> b = bytes;
    put32(b, section_offset(b, id), 0xFFFFFFFFu);
    reseal(b);
    EXPECT_NE(read_error(b).find("count 4294967295 exceeds"), std::string::npos) << "section " << id;
  }
}

TEST_F(PackageReaderTest, HugeSectionLengthIsRejected) {
  put64(bytes_, 40 + 24 * 2 + 16, 0xFFFFFFFFFFFFFFF0ull);
  reseal(bytes_);
  EXPECT_NE(read_error(bytes_).find("extends past the end of the file"), std::string::npos);
}

TEST_F(PackageReaderTest, HugeStringLengthIsRejected) {
  size_t strings = section_offset(bytes_, 1);
  put32(bytes_, strings + 4, 0x7FFFFFFFu);  // length of string 0
  reseal(bytes_);
  EXPECT_NE(read_error(bytes_).find("string length 2147483647 exceeds"), std::string::npos);
}

TEST_F(PackageReaderTest, BadStringIndex) {
  put32(bytes_, section_offset(bytes_, 2), 0x00ABCDEF);  // shader name
  reseal(bytes_);
  std::string error = read_error(bytes_);
  EXPECT_NE(error.find("string index 11259375 out of range"), std::string::npos) << error;
  EXPECT_NE(error.find("at byte offset " + std::to_string(section_offset(bytes_, 2))), std::string::npos);
}

TEST_F(PackageReaderTest, BadEnumValue) {
  size_t type = section_offset(bytes_, 3) + 4 + 8;  // count, name, display name
  bytes_[type] = 200;
  reseal(bytes_);
  EXPECT_EQ(read_error(bytes_),
            "corrupt package: invalid property type 200 (at most 11) at byte offset " + std::to_string(type));
}

TEST_F(PackageReaderTest, BadBoolean) {
  size_t cull_flag = section_offset(bytes_, 4) + 4 + 4 + 4 + 8;  // count, name, 1 tag
  bytes_[cull_flag] = 2;
  reseal(bytes_);
  EXPECT_NE(read_error(bytes_).find("invalid optional presence flag 2"), std::string::npos);
}

TEST_F(PackageReaderTest, NonZeroPaddingIsRejected) {
  size_t next = section_offset(bytes_, 2);
  size_t strings_end = section_offset(bytes_, 1) + get32(bytes_, 40 + 16);
  if (strings_end == next) GTEST_SKIP() << "no padding after the string table";
  bytes_[strings_end] = 1;
  reseal(bytes_);
  EXPECT_NE(read_error(bytes_).find("padding byte is not zero"), std::string::npos);
}

TEST_F(PackageReaderTest, StringExpansionIsBounded) {
  Package p;
  std::string big(100000, 'k');
  for (int i = 0; i < 200; ++i) p.subshader_tags.push_back({big, big, {}});
  EXPECT_NE(read_error(write_package(p)).find("strings expand past the decoding limit"), std::string::npos);
}

// ---- JSON -----------------------------------------------------------------

class PackageJsonTest : public ::testing::Test {};

TEST_F(PackageJsonTest, IsStableAndSurvivesRoundTrip) {
  Package p = rich_package();
  std::string json = package_to_json(p);
  EXPECT_EQ(json, package_to_json(rich_package()));
  Diagnostics diags;
  auto back = read_package(write_package(p), diags);
  ASSERT_TRUE(back.has_value());
  EXPECT_EQ(json, package_to_json(*back));
}

TEST_F(PackageJsonTest, ParsesWithFixedKeyOrder) {
  auto j = nlohmann::ordered_json::parse(package_to_json(rich_package()), nullptr, false);
  ASSERT_FALSE(j.is_discarded());
  std::vector<std::string> keys;
  for (auto& [key, value] : j.items()) keys.push_back(key);
  EXPECT_EQ(keys, (std::vector<std::string>{"format_version", "shader", "properties", "passes", "spirv_blobs"}));
  EXPECT_EQ(j["spirv_blobs"][0]["words"], 5);
  EXPECT_EQ(j["spirv_blobs"][0]["xxh64"].get<std::string>().size(), 16u);
  EXPECT_EQ(j["properties"][1]["default"][0], 0.1);
  EXPECT_EQ(j["properties"][3]["default"][2], "nan");
  EXPECT_EQ(j["passes"][0]["state"]["cull"]["property"], "_Cull");
  EXPECT_EQ(j["passes"][0]["state"]["stencil"]["zfail_front"], "Keep");
  EXPECT_EQ(j["passes"][0]["variants"][1]["key"][3], "off");
  EXPECT_EQ(j["passes"][0]["keywords"]["sets"][1]["stages"], nlohmann::ordered_json::array({"fragment"}));
  EXPECT_EQ(j["passes"][0]["variants"][0]["stages"][0]["reflection"]["uniform_blocks"][0]["members"][1]["members"][0]
             ["name"],
            "dir");
}

TEST_F(PackageJsonTest, SmallPackageText) {
  Package p;
  p.shader_name = "S";
  p.properties = {{"_F", "F", ir::PropertyType::range, {{"Toggle", {"_ON"}, {}}}, 0, 1, {0.5f, 0, 0, 0}, "", {}}};
  p.passes = {{"P", {{"LightMode", "Always", {}}}, {}, {}, {}}};
  p.passes[0].state.zwrite = lit("Off");
  p.passes[0].keywords.sets = {{variants::KeywordDirective::multi_compile, false, kAllStages, {"", "_ON"},
                                "multi_compile", {}}};
  p.passes[0].variants = {{{{1}}, {"_ON"}, {{Stage::fragment, 0, {}}}}};
  p.spirv_blobs = {{}};
  const char* expected = R"({
  "format_version": 6,
  "shader": {
    "name": "S",
    "lod": 0,
    "fallback": "",
    "custom_editor": "",
    "tags": [],
    "build": {
      "shard": 0,
      "shards": 1,
      "id": "0000000000000000"
    }
  },
  "properties": [
    {
      "name": "_F",
      "display_name": "F",
      "type": "Range",
      "attributes": [
        {
          "name": "Toggle",
          "args": [
            "_ON"
          ]
        }
      ],
      "range": [
        0.0,
        1.0
      ],
      "default": [
        0.5,
        0.0,
        0.0,
        0.0
      ],
      "default_texture": ""
    }
  ],
  "passes": [
    {
      "name": "P",
      "index": 0,
      "tags": [
        [
          "LightMode",
          "Always"
        ]
      ],
      "state": {
        "zwrite": "Off"
      },
      "keywords": {
        "sets": [
          {
            "directive": "multi_compile",
            "pragma": "multi_compile",
            "local": false,
            "stages": [
              "vertex",
              "fragment",
              "geometry",
              "hull",
              "domain"
            ],
            "keywords": [
              "",
              "_ON"
            ]
          }
        ],
        "dynamic_branch": [],
        "skip_variants": []
      },
      "variants": [
        {
          "key": [
            1
          ],
          "keywords": [
            "_ON"
          ],
          "stages": [
            {
              "stage": "fragment",
              "blob": 0,
              "reflection": {
                "stage": "vertex",
                "entry_point": "",
                "inputs": [],
                "outputs": [],
                "uniform_blocks": [],
                "resources": [],
                "spec_constants": [],
                "property_bindings": []
              }
            }
          ]
        }
      ]
    }
  ],
  "spirv_blobs": [
    {
      "words": 0,
      "xxh64": "ef46db3751d8e999"
    }
  ]
}
)";
  EXPECT_EQ(package_to_json(p), expected);
}

TEST_F(PackageJsonTest, InvalidUtf8DoesNotThrow) {
  Package p;
  p.shader_name = "\xff\xfe broken";
  std::string json = package_to_json(p);
  EXPECT_NE(json.find("broken"), std::string::npos);
}

// ---- Format 2: reflections shared between stages ------------------------------

size_t section_length(const std::vector<uint8_t>& b, uint32_t id) {
  uint64_t v = 0;
  for (int i = 7; i >= 0; --i) v = (v << 8) | b[40 + 24 * (id - 1) + 16 + size_t(i)];
  return size_t(v);
}

Package variants_sharing_one_reflection(size_t count) {
  Package p;
  p.shader_name = "Shared";
  p.passes = {{"P", {}, {}, {}, {}}};
  p.passes[0].keywords.sets = {{variants::KeywordDirective::multi_compile, false, kAllStages, {}, "multi_compile", {}}};
  for (size_t i = 0; i < count; ++i) {
    p.passes[0].keywords.sets[0].keywords.push_back("K" + std::to_string(i));
    p.passes[0].variants.push_back({{{uint32_t(i)}}, {"K" + std::to_string(i)},
                                    {{Stage::vertex, 0, rich_reflection(Stage::vertex)}}});
  }
  p.spirv_blobs = {{0x07230203, 1, 2}};
  return p;
}

TEST(PackageFormat2Test, AReflectionSharedByStagesIsStoredOnce) {
  std::vector<uint8_t> one = write_package(variants_sharing_one_reflection(1));
  std::vector<uint8_t> many = write_package(variants_sharing_one_reflection(64));
  size_t reflection_bytes = section_length(one, 6);  // one reflection dominates the variants section
  ASSERT_GT(reflection_bytes, 100u);
  // Each further variant adds its key, keyword and stage entry, not a reflection.
  EXPECT_LT(section_length(many, 6) - section_length(one, 6), 63 * 32u);
  Diagnostics diags;
  auto back = read_package(many, diags);
  ASSERT_TRUE(back.has_value()) << diags.all()[0].message;
  expect_same(variants_sharing_one_reflection(64), *back);
}

TEST(PackageFormat2Test, DifferentReflectionsOfOneBlobBothSurvive) {
  Package p = variants_sharing_one_reflection(2);
  p.passes[0].variants[1].stages[0].reflection.entry_point = "other";
  Diagnostics diags;
  auto back = read_package(write_package(p), diags);
  ASSERT_TRUE(back.has_value());
  expect_same(p, *back);
}

TEST(PackageFormat2Test, ReflectionIndexOutOfRangeIsAnError) {
  std::vector<uint8_t> b = write_package(variants_sharing_one_reflection(1));
  size_t index_at = section_offset(b, 6) + section_length(b, 6) - 4;  // the last stage's reflection index
  put32(b, index_at, 5);
  reseal(b);
  EXPECT_EQ(read_error(b), "corrupt package: reflection index 5 out of range (table has 1 reflections) at byte offset " +
                               std::to_string(index_at));
}

TEST(PackageFormat2Test, ReflectionReferencesAreChargedToTheDecodingBudget) {
  // 2,000 stages naming one large reflection: the decoded size is bounded by the budget, not by trust.
  Package p = variants_sharing_one_reflection(2000);
  for (int i = 0; i < 400; ++i) {
    p.passes[0].variants[0].stages[0].reflection.inputs.push_back({std::string(1000, 'x'), "", uint32_t(i), "float4", 0});
  }
  for (PackageVariant& v : p.passes[0].variants) v.stages[0].reflection = p.passes[0].variants[0].stages[0].reflection;
  std::vector<uint8_t> b = write_package(p);
  ASSERT_LT(b.size(), 200'000u);  // 2,000 x 400 KB decoded would be 800 MB
  std::string error = read_error(b);
  EXPECT_NE(error.find("reflection references expand past the decoding limit"), std::string::npos) << error;
}

TEST(PackageFormat1Test, AFormat1FileStillReads) {
  // Written by facetc 0.1.0 before format 2 (examples/shaders/VertexColor.shader, --all-variants).
  std::ifstream in(std::string(FACET_TESTDATA_DIR) + "/package/vertex_color_format1.facetpkg", std::ios::binary);
  std::vector<uint8_t> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  ASSERT_FALSE(bytes.empty());
  Diagnostics diags;
  auto v1 = read_package(bytes, diags);
  ASSERT_TRUE(v1.has_value()) << diags.all()[0].message;
  EXPECT_EQ(v1->version, 1u);
  ASSERT_FALSE(v1->passes.empty());
  ASSERT_FALSE(v1->passes[0].variants.empty());
  EXPECT_FALSE(v1->passes[0].variants[0].stages[0].reflection.inputs.empty());
  auto v2 = read_package(write_package(*v1), diags);
  ASSERT_TRUE(v2.has_value());
  EXPECT_EQ(v2->version, kFormatVersion);
  v2->version = 1;
  expect_same(*v1, *v2);
  // Before format 6 a pass's SubShader index is not recorded: its position stands in.
  for (size_t i = 0; i < v1->passes.size(); ++i) EXPECT_EQ(v1->passes[i].source_index, i);
}

}  // namespace
}  // namespace facet::package
