// Reflection checked against the SPIR-V itself: the test walks the module's
// words (OpName, OpMemberName, OpMemberDecorate Offset, ...) on its own and
// compares every number that reflection reports.
#include <gtest/gtest.h>

#include <map>

#include "backend_test_util.h"
#include "facet/reflection_json.h"

namespace facet::backend {
namespace {

using testing::load_shader;
using testing::TestShader;

// What the test reads from the module, independently of SPIRV-Cross.
struct SpirvFacts {
  struct Member {
    std::string name;
    uint32_t type = 0;
    std::optional<uint32_t> offset, matrix_stride;
  };
  std::map<uint32_t, std::string> names;
  std::map<uint32_t, std::vector<Member>> structs;  // struct id -> members
  std::map<uint32_t, uint32_t> array_elements, array_strides;
  std::map<uint32_t, uint32_t> sets, bindings, locations;

  static std::string string_at(const std::vector<uint32_t>& w, size_t first, size_t end) {
    std::string s;
    for (size_t i = first; i < end; ++i) {
      for (int b = 0; b < 4; ++b) {
        char c = char((w[i] >> (8 * b)) & 0xff);
        if (!c) return s;
        s += c;
      }
    }
    return s;
  }

  explicit SpirvFacts(const std::vector<uint32_t>& w) {
    for (size_t i = 5; i < w.size();) {
      uint32_t count = w[i] >> 16, op = w[i] & 0xffff;
      const uint32_t* a = &w[i + 1];
      switch (op) {
        case 5: names[a[0]] = string_at(w, i + 2, i + count); break;                    // OpName
        case 6: member(a[0], a[1]).name = string_at(w, i + 3, i + count); break;        // OpMemberName
        case 30:                                                                       // OpTypeStruct
          for (uint32_t m = 0; m + 2 < count; ++m) member(a[0], m).type = a[1 + m];
          break;
        case 28: array_elements[a[0]] = a[1]; break;                                   // OpTypeArray
        case 71:                                                                       // OpDecorate
          if (a[1] == 6) array_strides[a[0]] = a[2];
          if (a[1] == 34) sets[a[0]] = a[2];
          if (a[1] == 33) bindings[a[0]] = a[2];
          if (a[1] == 30) locations[a[0]] = a[2];
          break;
        case 72:                                                                       // OpMemberDecorate
          if (a[2] == 35) member(a[0], a[1]).offset = a[3];
          if (a[2] == 7) member(a[0], a[1]).matrix_stride = a[3];
          break;
        default: break;
      }
      i += count;
    }
  }

  Member& member(uint32_t s, uint32_t index) {
    auto& list = structs[s];
    if (list.size() <= index) list.resize(index + 1);
    return list[index];
  }

  std::optional<uint32_t> struct_named(const std::string& name) const {
    for (const auto& [id, n] : names) {
      if (n == name && structs.count(id)) return id;
    }
    return std::nullopt;
  }

  uint32_t strip_arrays(uint32_t type) const {
    while (array_elements.count(type)) type = array_elements.at(type);
    return type;
  }
};

void expect_members_match(const SpirvFacts& facts, uint32_t struct_id, const std::vector<BlockMember>& members,
                          const std::string& path) {
  const auto& expected = facts.structs.at(struct_id);
  ASSERT_EQ(members.size(), expected.size()) << path;
  for (size_t i = 0; i < members.size(); ++i) {
    const BlockMember& m = members[i];
    const SpirvFacts::Member& e = expected[i];
    std::string where = path + "." + m.name;
    EXPECT_EQ(m.name, e.name) << where;
    ASSERT_TRUE(e.offset) << where;
    EXPECT_EQ(m.offset, *e.offset) << where;
    EXPECT_EQ(m.matrix_stride, e.matrix_stride.value_or(0)) << where;
    if (facts.array_strides.count(e.type)) {
      EXPECT_EQ(m.array_stride, facts.array_strides.at(e.type)) << where;
    } else {
      EXPECT_EQ(m.array_stride, 0u) << where;
    }
    if (!m.members.empty()) expect_members_match(facts, facts.strip_arrays(e.type), m.members, where);
  }
}

class BackendReflectTest : public ::testing::Test {
 protected:
  void SetUp() override {
    t_ = load_shader("layout.shader");
    using P = ir::PropertyType;
    for (auto [name, type] : {std::pair{"_MainTex", P::tex2d}, std::pair{"_Cube", P::cube},
                              std::pair{"_Color", P::color}, std::pair{"_Gloss", P::range},
                              std::pair{"_Unused", P::float_}}) {
      t_.shader.properties.push_back(testing::property(name, type));
    }
  }
  CompiledVariant compile(Stage stage, OptLevel opt = OptLevel::performance) {
    BackendOptions options;
    options.opt = opt;
    auto compiled = backend_.compile(t_.shader, t_.program, stage, {}, options, t_.sources, diags_);
    EXPECT_TRUE(compiled) << render_text(diags_, t_.sources);
    return compiled ? std::move(*compiled) : CompiledVariant{};
  }
  static const UniformBlock* block(const StageReflection& r, const std::string& name) {
    for (const UniformBlock& b : r.uniform_blocks) {
      if (b.name == name) return &b;
    }
    return nullptr;
  }
  static const BlockMember* member(const UniformBlock& b, const std::string& name) {
    for (const BlockMember& m : b.members) {
      if (m.name == name) return &m;
    }
    return nullptr;
  }

  Backend backend_;
  Diagnostics diags_;
  TestShader t_;
};

TEST_F(BackendReflectTest, OffsetsAndStridesEqualTheSpirvDecorations) {
  for (OptLevel opt : {OptLevel::none, OptLevel::performance}) {
    for (Stage stage : {Stage::vertex, Stage::fragment}) {
      CompiledVariant c = compile(stage, opt);
      SpirvFacts facts(c.spirv);
      ASSERT_FALSE(c.reflection.uniform_blocks.empty());
      for (const UniformBlock& b : c.reflection.uniform_blocks) {
        auto id = facts.struct_named(b.name);
        ASSERT_TRUE(id) << b.name;
        expect_members_match(facts, *id, b.members, b.name);
      }
    }
  }
}

TEST_F(BackendReflectTest, SetsBindingsAndLocationsEqualTheSpirvDecorations) {
  for (Stage stage : {Stage::vertex, Stage::fragment}) {
    CompiledVariant c = compile(stage);
    SpirvFacts facts(c.spirv);
    auto id_of = [&](const std::string& name) {
      for (const auto& [id, n] : facts.names) {
        if (n == name && (facts.bindings.count(id) || facts.locations.count(id))) return id;
      }
      return 0u;
    };
    for (const ResourceBinding& r : c.reflection.resources) {
      uint32_t id = id_of(r.name);
      ASSERT_NE(id, 0u) << r.name;
      EXPECT_EQ(r.set, facts.sets.at(id)) << r.name;
      EXPECT_EQ(r.binding, facts.bindings.at(id)) << r.name;
    }
    for (const auto* list : {&c.reflection.inputs, &c.reflection.outputs}) {
      for (const StageVariable& v : *list) EXPECT_EQ(v.location, facts.locations.at(id_of(v.name))) << v.name;
    }
  }
}

TEST_F(BackendReflectTest, BlockLayoutDetails) {
  CompiledVariant c = compile(Stage::fragment);
  const UniformBlock* scene = block(c.reflection, "Scene");
  ASSERT_TRUE(scene);
  EXPECT_EQ(scene->set, kMaterialSet);
  const BlockMember* rig = member(*scene, "_Rig");
  ASSERT_TRUE(rig);
  EXPECT_EQ(rig->type, "struct");
  ASSERT_EQ(rig->members.size(), 3u);
  EXPECT_EQ(rig->members[0].name, "bones");
  EXPECT_EQ(rig->members[0].array_dims, std::vector<uint32_t>{2});
  EXPECT_EQ(rig->members[0].array_stride, 64u);
  EXPECT_EQ(rig->members[1].members.size(), 3u);  // Light: direction, intensity, color
  EXPECT_EQ(rig->members[1].members[1].offset, 12u);  // float after float3 shares the register
  const BlockMember* affine = member(*scene, "_Affine");
  ASSERT_TRUE(affine);
  EXPECT_EQ(affine->type, "float3x4");  // HLSL's rows x columns
  EXPECT_FALSE(affine->row_major);      // HLSL's default column_major packing
  EXPECT_EQ(affine->size, 64u);         // four columns of float3, 16 bytes apart
  const BlockMember* row_major = member(*scene, "_RowMajor");
  ASSERT_TRUE(row_major);
  EXPECT_TRUE(row_major->row_major);
  const BlockMember* weights = member(*scene, "_Weights");
  ASSERT_TRUE(weights);
  EXPECT_EQ(weights->array_dims, std::vector<uint32_t>{5});
  EXPECT_EQ(weights->array_stride, 16u);
  EXPECT_EQ(member(*scene, "_Flags")->type, "int4");
  EXPECT_GE(scene->size, member(*scene, "_Flags")->offset + 16);
}

TEST_F(BackendReflectTest, PushConstantsComeLast) {
  CompiledVariant c = compile(Stage::fragment);
  ASSERT_FALSE(c.reflection.uniform_blocks.empty());
  const UniformBlock& push = c.reflection.uniform_blocks.back();
  EXPECT_TRUE(push.push_constant);
  EXPECT_EQ(push.size, 20u);
  ASSERT_EQ(push.members.size(), 2u);
  EXPECT_EQ(push.members[1].name, "_PushScale");
  EXPECT_EQ(push.members[1].offset, 16u);
  EXPECT_EQ(std::count_if(c.reflection.uniform_blocks.begin(), c.reflection.uniform_blocks.end(),
                          [](const UniformBlock& b) { return b.push_constant; }),
            1);
  EXPECT_TRUE(std::is_sorted(c.reflection.uniform_blocks.begin(), c.reflection.uniform_blocks.end() - 1,
                             [](const auto& a, const auto& b) {
                               return std::tie(a.set, a.binding) < std::tie(b.set, b.binding);
                             }));
}

TEST_F(BackendReflectTest, GlobalsBlockHoldsLooseUniformsAtBindingZero) {
  for (Stage stage : {Stage::vertex, Stage::fragment}) {
    CompiledVariant c = compile(stage);
    const UniformBlock* globals = block(c.reflection, kGlobalsBlock);
    ASSERT_TRUE(globals);
    EXPECT_EQ(globals->set, kMaterialSet);
    EXPECT_EQ(globals->binding, 0u);
    const BlockMember* tint = member(*globals, "_Tint");
    const BlockMember* after = member(*globals, "_After");
    ASSERT_TRUE(tint && after);
    EXPECT_EQ(tint->type, "float3");
    EXPECT_EQ(after->offset, tint->offset + 12);  // packed into the float3's register
  }
}

TEST_F(BackendReflectTest, BuiltinBlocksHaveTheirFixedSets) {
  CompiledVariant c = compile(Stage::vertex);
  const UniformBlock* frame = block(c.reflection, "FacetPerFrame");
  const UniformBlock* draw = block(c.reflection, "FacetPerDraw");
  ASSERT_TRUE(frame && draw);
  EXPECT_EQ(frame->set, kFrameSet);
  EXPECT_EQ(frame->binding, 0u);
  EXPECT_EQ(draw->set, kDrawSet);
  EXPECT_EQ(member(*draw, "unity_ObjectToWorld")->offset, 0u);
  EXPECT_EQ(member(*draw, "unity_WorldToObject")->offset, 64u);
}

TEST_F(BackendReflectTest, MaterialBindingsAgreeAcrossStages) {
  CompiledVariant vs = compile(Stage::vertex);
  CompiledVariant fs = compile(Stage::fragment);
  const UniformBlock* vs_scene = block(vs.reflection, "Scene");
  const UniformBlock* fs_scene = block(fs.reflection, "Scene");
  ASSERT_TRUE(vs_scene && fs_scene);
  EXPECT_EQ(vs_scene->binding, fs_scene->binding);
  EXPECT_EQ(vs_scene->size, fs_scene->size);
  // The textures exist only in the fragment stage; their numbers come after
  // every block and texture declared before them, used or not.
  std::map<std::string, uint32_t> bindings;
  for (const ResourceBinding& r : fs.reflection.resources) bindings[r.name] = r.binding;
  EXPECT_EQ(bindings.at("_MainTex"), 2u);  // $Globals 0, Scene 1
  EXPECT_EQ(bindings.at("_Cube"), 3u);
  EXPECT_EQ(bindings.at("_Volume"), 4u);
  EXPECT_EQ(bindings.at("_Layers"), 5u);
  EXPECT_EQ(bindings.at("sampler_Layers"), 6u);
}

TEST_F(BackendReflectTest, InterfaceLocationsFollowSemantics) {
  CompiledVariant vs = compile(Stage::vertex);
  CompiledVariant fs = compile(Stage::fragment);
  std::map<std::string, uint32_t> in, out, frag_in;
  for (const StageVariable& v : vs.reflection.inputs) in[v.semantic] = v.location;
  for (const StageVariable& v : vs.reflection.outputs) out[v.semantic] = v.location;
  for (const StageVariable& v : fs.reflection.inputs) frag_in[v.semantic] = v.location;
  EXPECT_EQ(in, (std::map<std::string, uint32_t>{
                    {"POSITION", 0}, {"NORMAL", 1}, {"TANGENT", 2}, {"COLOR", 3}, {"TEXCOORD0", 4}}));
  EXPECT_EQ(out, (std::map<std::string, uint32_t>{{"TEXCOORD0", 0}, {"TEXCOORD3", 3}, {"COLOR", 16}, {"NORMAL", 18}}));
  EXPECT_EQ(out, frag_in);
  ASSERT_EQ(fs.reflection.outputs.size(), 1u);
  EXPECT_EQ(fs.reflection.outputs[0].semantic, "SV_TARGET");
  EXPECT_TRUE(std::is_sorted(vs.reflection.inputs.begin(), vs.reflection.inputs.end(),
                             [](const auto& a, const auto& b) { return a.location < b.location; }));
}

TEST_F(BackendReflectTest, ResourcesHaveKindsAndDimensions) {
  CompiledVariant c = compile(Stage::fragment);
  std::map<std::string, ResourceBinding> by_name;
  for (const ResourceBinding& r : c.reflection.resources) by_name[r.name] = r;
  EXPECT_EQ(by_name.at("_MainTex").kind, ResourceKind::combined_image_sampler);
  EXPECT_EQ(by_name.at("_MainTex").dim, "2D");
  EXPECT_EQ(by_name.at("_Cube").dim, "Cube");
  EXPECT_EQ(by_name.at("_Volume").dim, "3D");
  EXPECT_EQ(by_name.at("_Layers").kind, ResourceKind::separate_image);
  EXPECT_TRUE(by_name.at("_Layers").arrayed);
  EXPECT_EQ(by_name.at("sampler_Layers").kind, ResourceKind::separate_sampler);
  ASSERT_EQ(c.reflection.spec_constants.size(), 1u);
  EXPECT_EQ(c.reflection.spec_constants[0].name, "kTaps");
  EXPECT_EQ(c.reflection.spec_constants[0].id, 7u);
  EXPECT_EQ(c.reflection.spec_constants[0].type, "int");
  EXPECT_EQ(c.reflection.spec_constants[0].default_value, "4");
}

TEST_F(BackendReflectTest, PropertiesBindToUniformsAndTextures) {
  CompiledVariant c = compile(Stage::fragment);
  std::vector<std::string> got;
  for (const PropertyBinding& p : c.reflection.property_bindings) {
    got.push_back(p.property + " " + p.role + " " + p.block + "." + p.member);
  }
  EXPECT_EQ(got, (std::vector<std::string>{
                     "_MainTex texture ._MainTex",
                     "_MainTex scale_offset $Globals._MainTex_ST",
                     "_MainTex texel_size $Globals._MainTex_TexelSize",
                     "_MainTex hdr_decode $Globals._MainTex_HDR",
                     "_Cube texture ._Cube",
                     "_Color value $Globals._Color",
                     "_Gloss value $Globals._Gloss",
                 }));
}

TEST_F(BackendReflectTest, SemanticDecorationsAreStrippedFromTheOutput) {
  CompiledVariant c = compile(Stage::fragment);
  std::string text = disassemble(c.spirv);
  EXPECT_EQ(text.find("UserSemantic"), std::string::npos);
  EXPECT_EQ(text.find("SPV_GOOGLE_hlsl_functionality1"), std::string::npos);
  EXPECT_NE(text.find("\"$Globals\""), std::string::npos);
}

TEST_F(BackendReflectTest, JsonRoundTripsAndIsDeterministic) {
  CompiledVariant c = compile(Stage::fragment);
  std::string text = reflection_to_json_text(c.reflection);
  auto back = reflection_from_json_text(text);
  ASSERT_TRUE(back) << back.error().reason;
  EXPECT_EQ(reflection_to_json_text(*back), text);
  EXPECT_EQ(reflection_to_json_text(compile(Stage::fragment).reflection), text);
  EXPECT_FALSE(reflection_from_json_text("{\"stage\": \"fragment\"}"));
  EXPECT_FALSE(reflection_from_json_text("not json"));
  EXPECT_FALSE(reflection_from_json_text(
      R"({"stage":"nope","entry_point":"","inputs":[],"outputs":[],"uniform_blocks":[],"resources":[],)"
      R"("spec_constants":[],"property_bindings":[]})"));
}

}  // namespace
}  // namespace facet::backend
