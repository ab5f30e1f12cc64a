// glTF meshes (mesh/gltf.cpp, mesh/gltf_geometry.cpp) and their materials
// in scenes (scene/gltf_material.cpp): the generator's sample loads with
// its node transforms in facet's space, renders with its textures upright
// on lavapipe (.gltf with a data: URI or a .bin file, and .glb), maps onto
// the Standard shader, and every kind of broken file gives exit code 1, one
// message naming the file and the glTF value, and no output.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>

#include "facet/commands.h"
#include "facet/runtime/gltf.h"
#include "gltf_sample.h"
#include "render_test_support.h"

namespace facet::runtime {
namespace {

using test_support::example_shader;
using test_support::GltfSampleOptions;
using test_support::small_scene;
using test_support::test_dir;
using test_support::write_gltf_sample;
using test_support::write_scene;
using Buffer = GltfSampleOptions::Buffer;

// A shader that shows one texture property through `show` (an HLSL
// expression of its texel `t`), unlit.
std::string texture_shader(const std::string& name, const std::string& property, const std::string& show) {
  std::filesystem::path path = test_dir() / (name + ".shader");
  std::ofstream(path) << "Shader \"Test/" << name << "\" {\n    Properties { " << property
                      << R"( ("Texture", 2D) = "white" {} _Color ("Color", Color) = (1, 1, 1, 1) }
    SubShader { Pass {
        CGPROGRAM
        #pragma vertex vert
        #pragma fragment frag
        #include "UnityCG.cginc"
        sampler2D )" << property
                      << "; float4 " << property << R"(_ST; float4 _Color;
        struct appdata { float4 vertex : POSITION; float2 uv : TEXCOORD0; };
        struct v2f { float4 pos : SV_POSITION; float2 uv : TEXCOORD0; };
        v2f vert(appdata v) {
            v2f o;
            o.pos = UnityObjectToClipPos(v.vertex);
            o.uv = TRANSFORM_TEX(v.uv, )"
                      << property << R"();
            return o;
        }
        fixed4 frag(v2f i) : SV_Target { float4 t = tex2D()"
                      << property << ", i.uv); return " << show << R"(; }
        ENDCG
    } }
})";
  return path.string();
}

std::string unlit_texture_shader() { return texture_shader("GltfUnlitTexture", "_MainTex", "t * _Color"); }

std::string gltf_object(const std::string& mesh, const std::string& shader, const std::string& extra = "") {
  return R"([{"mesh": ")" + mesh + R"(", "gltf_materials": true)" + extra + R"(, "material": {"shader": ")" + shader +
         R"("}}])";
}

// ---------------------------------------------------------------- loading

TEST(GltfLoad, TheSampleIsInFacetsSpaceWithItsNodeTransforms) {
  Diagnostics error;
  std::optional<GltfModel> model = load_gltf(write_gltf_sample(test_dir(), "space"), error);
  ASSERT_TRUE(model) << test_support::message_of(error);
  ASSERT_EQ(model->parts.size(), 1u);
  EXPECT_EQ(model->parts[0].material, 0);
  const MeshData& mesh = model->parts[0].mesh;
  ASSERT_EQ(mesh.vertices.size(), 4u);
  // glTF (0.5, -0.5, 0), moved by 0.25 and scaled by 1.5, then x negated.
  const Vertex& v0 = mesh.vertices[0];
  EXPECT_FLOAT_EQ(v0.position[0], -1.125f);
  EXPECT_FLOAT_EQ(v0.position[1], -0.75f);
  EXPECT_EQ(v0.normal, (std::array<float, 3>{0, 0, -1}));
  EXPECT_EQ(v0.tangent, (std::array<float, 4>{1, 0, 0, -1}));  // glTF (-1, 0, 0, +1)
  EXPECT_EQ(v0.uv0, (std::array<float, 2>{0, 0}));             // glTF (0, 1): the image's bottom-left
  EXPECT_EQ(v0.uv1, (std::array<float, 2>{0.25f, 0.25f}));
  EXPECT_EQ(mesh.vertices[3].color, (std::array<float, 4>{1, 1, 1, 0.5f}));
  // Rewound: facet's cross(b - a, c - a) points out of the surface (-Z).
  ASSERT_EQ(mesh.indices, (std::vector<uint32_t>{0, 2, 1, 0, 3, 2}));
}

TEST(GltfLoad, ComputedTangentsAgreeWithTheFilesTangents) {
  Diagnostics error;
  std::string path = write_gltf_sample(test_dir(), "no_tangents", {.edit = [](nlohmann::json& g, std::string&) {
                                         g["meshes"][0]["primitives"][0]["attributes"].erase("TANGENT");
                                       }});
  std::optional<GltfModel> model = load_gltf(path, error);
  ASSERT_TRUE(model) << test_support::message_of(error);
  for (const Vertex& v : model->parts[0].mesh.vertices) {
    EXPECT_NEAR(v.tangent[0], 1, 1e-6);
    EXPECT_NEAR(v.tangent[1], 0, 1e-6);
    EXPECT_NEAR(v.tangent[2], 0, 1e-6);
    EXPECT_EQ(v.tangent[3], -1);
  }
}

TEST(GltfLoad, MissingNormalsBecomeFlatNormalsFacingOut) {
  Diagnostics error;
  std::string path = write_gltf_sample(test_dir(), "no_normals", {.edit = [](nlohmann::json& g, std::string&) {
                                         g["meshes"][0]["primitives"][0]["attributes"].erase("NORMAL");
                                       }});
  std::optional<GltfModel> model = load_gltf(path, error);
  ASSERT_TRUE(model) << test_support::message_of(error);
  ASSERT_EQ(model->parts[0].mesh.vertices.size(), 6u);  // one vertex per corner
  for (const Vertex& v : model->parts[0].mesh.vertices) EXPECT_EQ(v.normal, (std::array<float, 3>{0, 0, -1}));
}

TEST(GltfLoad, BinFileAndGlbLoadTheSameMesh) {
  Diagnostics error;
  std::optional<GltfModel> uri = load_gltf(write_gltf_sample(test_dir(), "same_uri"), error);
  ASSERT_TRUE(uri) << test_support::message_of(error);
  for (Buffer buffer : {Buffer::bin_file, Buffer::glb}) {
    std::optional<GltfModel> other =
        load_gltf(write_gltf_sample(test_dir(), "same_" + std::to_string(int(buffer)), {.buffer = buffer}), error,
                  {.materials = true, .limits = {}});
    ASSERT_TRUE(other) << test_support::message_of(error);
    ASSERT_EQ(other->parts[0].mesh.vertices.size(), uri->parts[0].mesh.vertices.size());
    EXPECT_EQ(other->parts[0].mesh.indices, uri->parts[0].mesh.indices);
    EXPECT_EQ(other->parts[0].mesh.vertices[2].position, uri->parts[0].mesh.vertices[2].position);
    ASSERT_EQ(other->materials.size(), 1u);
    ASSERT_TRUE(other->materials[0].normal_texture);
  }
}

// The scene side: the glTF material onto the Standard shader's properties.
TEST(GltfScene, MaterialsMapOntoTheStandardShadersProperties) {
  std::string mesh = write_gltf_sample(test_dir(), "mapped");
  std::string json =
      small_scene(gltf_object(mesh, std::string(FACET_SOURCE_DIR) + "/stdlib/Shaders/Standard.shader"));
  auto scene = parse_scene(json, write_scene("mapped", json));
  ASSERT_TRUE(scene) << scene.error().message;
  ASSERT_EQ(scene->objects.size(), 1u);
  const SceneMaterial& m = scene->objects[0].material;
  EXPECT_EQ(scene->objects[0].gltf_material, 0);
  std::map<std::string, const SceneProperty*> by_name;
  for (const SceneProperty& p : m.properties) by_name[p.name] = &p;
  for (const char* name : {"_Color", "_MainTex", "_Metallic", "_Glossiness", "_MetallicGlossMap", "_GlossMapScale",
                           "_BumpMap", "_BumpScale", "_EmissionColor", "_EmissionMap"}) {
    ASSERT_TRUE(by_name.count(name)) << name;
    EXPECT_TRUE(by_name[name]->if_declared) << name;
  }
  EXPECT_EQ(by_name["_MainTex"]->texture->name, (test_dir() / "mapped_albedo.png").string());
  EXPECT_TRUE(by_name["_MainTex"]->texture->srgb);
  EXPECT_FALSE(by_name["_BumpMap"]->texture->srgb);
  EXPECT_FALSE(by_name["_MetallicGlossMap"]->texture->srgb);
  EXPECT_EQ(by_name["_MetallicGlossMap"]->texture->gltf_metallic_roughness, (std::array<float, 2>{1, 1}));
  EXPECT_EQ(by_name["_Glossiness"]->numbers, (std::vector<float>{0}));
  EXPECT_EQ(m.keywords, (std::vector<std::string>{"_METALLICGLOSSMAP", "_NORMALMAP", "_EMISSION"}));
}

TEST(GltfScene, APrimitiveWithoutAMaterialGetsGltfsDefaultMaterial) {
  std::string mesh = write_gltf_sample(test_dir(), "default_material", {.material = false});
  std::string json = small_scene(gltf_object(mesh, unlit_texture_shader()));
  auto scene = parse_scene(json, write_scene("default_material", json));
  ASSERT_TRUE(scene) << scene.error().message;
  ASSERT_EQ(scene->objects.size(), 1u);
  EXPECT_EQ(scene->objects[0].gltf_material, -1);
  std::map<std::string, std::vector<float>> numbers;
  for (const SceneProperty& p : scene->objects[0].material.properties) numbers[p.name] = p.numbers;
  EXPECT_EQ(numbers["_Color"], (std::vector<float>{1, 1, 1, 1}));
  EXPECT_EQ(numbers["_Metallic"], (std::vector<float>{1}));
  EXPECT_EQ(numbers["_Glossiness"], (std::vector<float>{0}));
  EXPECT_FALSE(numbers.count("_MainTex"));
  EXPECT_TRUE(scene->objects[0].material.keywords.empty());
}

TEST(GltfScene, TheScenesOwnPropertiesWin) {
  std::string mesh = write_gltf_sample(test_dir(), "own");
  std::string objects = R"([{"mesh": ")" + mesh + R"(", "gltf_materials": true, "material": {"shader": ")" +
                        unlit_texture_shader() + R"(", "properties": {"_MainTex": "red"}}}])";
  std::string json = small_scene(objects);
  auto scene = parse_scene(json, write_scene("own", json));
  ASSERT_TRUE(scene) << scene.error().message;
  int main_tex = 0;
  for (const SceneProperty& p : scene->objects[0].material.properties) {
    if (p.name != "_MainTex") continue;
    ++main_tex;
    EXPECT_EQ(p.texture->name, "red");
  }
  EXPECT_EQ(main_tex, 1);
}

// ---------------------------------------------------------------- rendering

class GltfRender : public test_support::RenderTest {
 protected:
  // The colour at the centre of each texture quadrant (sample_quadrant_colors order).
  static void expect_quadrants(const RenderedFrame& frame) {
    ASSERT_EQ(frame.width, 64);
    // The quad's quadrant centres in facet's space, projected by the
    // 64 x 64 camera at z = -3 with a 40 degree field of view.
    const double half = 3 * std::tan(20 * 3.14159265358979 / 180);
    const std::array<std::array<double, 2>, 4> centres = {{{-0.75, 0.375}, {0, 0.375}, {-0.75, -0.375}, {0, -0.375}}};
    for (size_t q = 0; q < 4; ++q) {
      int x = int(32 + centres[q][0] / half * 32), y = int(32 - centres[q][1] / half * 32);
      const uint8_t* p = &frame.ldr[size_t(y * 64 + x) * 4];
      for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(p[c], test_support::sample_quadrant_colors()[q][size_t(c)], 3)
            << "quadrant " << q << " channel " << c << " at (" << x << ", " << y << ")";
      }
    }
    // Outside the quad (right of it): the black clear colour.
    const uint8_t* outside = &frame.ldr[size_t(32 * 64 + 56) * 4];
    EXPECT_EQ(outside[0] + outside[1] + outside[2], 0);
  }
};

TEST_F(GltfRender, TheBaseColourTextureShowsUprightThroughAnUnlitShader) {
  for (Buffer buffer : {Buffer::data_uri, Buffer::bin_file, Buffer::glb}) {
    std::string name = "unlit_" + std::to_string(int(buffer));
    std::string mesh = write_gltf_sample(test_dir(), name, {.buffer = buffer});
    RenderedFrame frame = render(name, small_scene(gltf_object(mesh, unlit_texture_shader())));
    SCOPED_TRACE(name);
    expect_quadrants(frame);
  }
}

// A file written by Blender's own glTF exporter (Blender 3.4, Debian's
// package; tests/data/gltf/blender/make_quad.py regenerates it): a 2 x 2
// quad facing the camera whose base colour texture has a red, green, blue
// and white quadrant. It renders upright, not mirrored, with its texture.
TEST_F(GltfRender, AQuadExportedByBlenderRendersWithItsTexture) {
  std::string mesh = std::string(FACET_SOURCE_DIR) + "/tests/data/gltf/blender/quad.gltf";
  RenderedFrame frame = render("blender_quad", small_scene(gltf_object(mesh, unlit_texture_shader())));
  ASSERT_EQ(frame.width, 64);
  // Quadrant centres at (+-0.5, +-0.5) on the plane z = 0, 3 units from the
  // camera with a 40 degree field of view: 14.6 pixels from the centre.
  struct Probe {
    int x, y;
    std::array<int, 3> colour;
  };
  for (const Probe& p : {Probe{17, 17, {255, 0, 0}}, Probe{47, 17, {0, 255, 0}}, Probe{17, 47, {0, 0, 255}},
                         Probe{47, 47, {255, 255, 255}}}) {
    const uint8_t* px = &frame.ldr[size_t(p.y * 64 + p.x) * 4];
    for (int c = 0; c < 3; ++c) {
      // Bilinear filtering of the 2 x 2 texture blends a little of the
      // neighbouring texels in (up to 52 of 255 after sRGB encoding).
      EXPECT_NEAR(px[c], p.colour[size_t(c)], 64) << "(" << p.x << ", " << p.y << ") channel " << c;
    }
  }
  const uint8_t* outside = &frame.ldr[size_t(32 * 64 + 63) * 4];
  EXPECT_EQ(outside[0] + outside[1] + outside[2], 0) << "the quad ends before the image's edge";
}

// The same quad as a triangle strip (1, 2, 0, 3) and a fan (0, 1, 2, 3).
TEST_F(GltfRender, StripsAndFansDrawTheSameQuad) {
  for (auto [mode, order] :
       {std::pair{5, std::vector<uint16_t>{1, 2, 0, 3}}, std::pair{6, std::vector<uint16_t>{0, 1, 2, 3}}}) {
    std::string name = "mode_" + std::to_string(mode);
    std::string mesh = write_gltf_sample(test_dir(), name, {.edit = [mode, order](nlohmann::json& g, std::string& b) {
                                           g["meshes"][0]["primitives"][0]["mode"] = mode;
                                           g["accessors"][6]["count"] = 4;
                                           std::memcpy(b.data() + 288, order.data(), 8);
                                         }});
    RenderedFrame frame = render(name, small_scene(gltf_object(mesh, unlit_texture_shader())));
    SCOPED_TRACE(name);
    expect_quadrants(frame);
  }
}

// The Standard shader in the dark (no lights, black ambient): what shows is
// the emission, the glTF emissive texture times its factor.
TEST_F(GltfRender, TheEmissionTextureShowsThroughTheStandardShader) {
  std::string mesh = write_gltf_sample(test_dir(), "standard");
  std::string json =
      small_scene(gltf_object(mesh, std::string(FACET_SOURCE_DIR) + "/stdlib/Shaders/Standard.shader"));
  json.insert(1, R"("ambient": [0, 0, 0], )");
  RenderedFrame frame = render("standard", json);
  expect_quadrants(frame);
}

// glTF's roughness (G) and metallic (B), with the factors, become Unity's
// metallic (R) and smoothness (A); the shader shows them as red and green.
TEST_F(GltfRender, TheMetallicRoughnessTextureBecomesUnitysMetallicGlossMap) {
  std::string mesh = write_gltf_sample(test_dir(), "metal", {.edit = [](nlohmann::json& g, std::string&) {
                                         g["materials"][0]["pbrMetallicRoughness"]["metallicFactor"] = 0.5;
                                         g["materials"][0]["pbrMetallicRoughness"]["roughnessFactor"] = 0.5;
                                       }});
  std::string shader = texture_shader("GltfMetallicGloss", "_MetallicGlossMap", "float4(t.r, t.a, t.g + t.b, 1)");
  RenderedFrame frame = render("metal", small_scene(gltf_object(mesh, shader)));
  ASSERT_EQ(frame.hdr.size(), size_t(64 * 64 * 4));
  const double half = 3 * std::tan(20 * 3.14159265358979 / 180);
  double smoothness = 1 - 0.5 * 64 / 255.0;
  // The texture's left half has metallic 0, its right half 1 (times the factor 0.5).
  for (auto [x_world, metallic] : {std::pair{-0.75, 0.0}, std::pair{0.0, 0.5}}) {
    for (double y_world : {0.375, -0.375}) {
      int x = int(32 + x_world / half * 32), y = int(32 - y_world / half * 32);
      const float* p = &frame.hdr[size_t(y * 64 + x) * 4];
      EXPECT_NEAR(p[0], metallic, 0.01) << x << ", " << y;
      EXPECT_NEAR(p[1], smoothness, 0.01) << x << ", " << y;
      EXPECT_NEAR(p[2], 0, 0.01) << x << ", " << y;
    }
  }
}

// ---------------------------------------------------------------- bad files

using Outcome = test_support::RenderOutcome;
using test_support::render_expecting_failure;

struct HostileGltfCase {
  const char* name;
  GltfSampleOptions options;
  std::string expected;                                // after "<name>.gltf: " (or .glb); {dir} is test_dir()
  std::function<void(const std::string& path)> after;  // changes the written files
  bool mesh_only = false;  // without "gltf_materials": the renderer reads the mesh, not the scene reader
};

std::ostream& operator<<(std::ostream& os, const HostileGltfCase& c) { return os << c.name; }

using nlohmann::json;

GltfSampleOptions edit(std::function<void(json&, std::string&)> f, Buffer buffer = Buffer::data_uri) {
  return {.buffer = buffer, .material = true, .edit = std::move(f)};
}

json& primitive(json& g) { return g["meshes"][0]["primitives"][0]; }

const HostileGltfCase kHostileGltf[] = {
    {"truncated_buffer", edit([](json&, std::string& b) { b.resize(b.size() - 40); }),
     "a buffer's data: URI does not decode to its byteLength (truncated, or not base64)"},
    {"truncated_bin_file", edit([](json&, std::string&) {}, Buffer::bin_file),
     "buffer file '{dir}/truncated_bin_file.bin' has 260 bytes, its byteLength says 300",
     [](const std::string& path) {
       std::filesystem::path bin = std::filesystem::path(path).replace_extension(".bin");
       std::filesystem::resize_file(bin, std::filesystem::file_size(bin) - 40);
     }},
    {"truncated_glb", edit([](json&, std::string&) {}, Buffer::glb),
     "the GLB header gives a length of 2060 bytes, the file has 2020 (truncated or padded)",
     [](const std::string& path) { std::filesystem::resize_file(path, std::filesystem::file_size(path) - 40); }},
    {"wrong_glb_magic", edit([](json&, std::string&) {}, Buffer::glb),
     "not a GLB file (it does not start with the magic 'glTF')",
     [](const std::string& path) {
       std::fstream f(path, std::ios::in | std::ios::out | std::ios::binary);
       f.seekp(3);
       f.put('X');
     }},
    {"bad_json", edit([](json&, std::string&) {}),
     "invalid JSON: parse error at line 1, column 41: syntax error while parsing value - unexpected '}'; expected '[', "
     "'{', or a literal",
     [](const std::string& path) { std::ofstream(path) << "{\"asset\": {\"version\": \"2.0\"}, \"nodes\": [}"; }},
    {"accessor_past_its_buffer_view", edit([](json& g, std::string&) { g["accessors"][0]["count"] = 1000; }),
     "meshes[0].primitives[0].attributes.POSITION: accessors[0]: its 1000 elements end at byte 12000 of buffer view 0, "
     "which has 48 bytes"},
    {"accessor_offset_past_its_buffer_view", edit([](json& g, std::string&) { g["accessors"][3]["byteOffset"] = 16; }),
     "meshes[0].primitives[0].attributes.TEXCOORD_0: accessors[3]: its 4 elements end at byte 48 of buffer view 3, "
     "which has 32 bytes"},
    {"buffer_view_past_its_buffer", edit([](json& g, std::string&) { g["bufferViews"][6]["byteLength"] = 4000; }),
     "meshes[0].primitives[0].indices: bufferViews[6]: bytes 288 to 4288 lie past the end of buffer 0, "
     "which has 300 bytes"},
    {"accessor_that_does_not_exist", edit([](json& g, std::string&) { primitive(g)["attributes"]["TEXCOORD_1"] = 99; }),
     "meshes[0].primitives[0].attributes.TEXCOORD_1: accessor 99 does not exist (the file has 7)"},
    {"index_past_the_vertices", edit([](json&, std::string& b) {
       uint16_t big = 99;
       std::memcpy(b.data() + 288 + 4, &big, 2);
     }),
     "meshes[0].primitives[0].indices: index 99 (element 2 of accessors[6]) is past the 4 vertices of the primitive"},
    {"index_past_the_vertices_mesh_only", edit([](json&, std::string& b) {
       uint16_t big = 99;
       std::memcpy(b.data() + 288 + 4, &big, 2);
     }),
     "meshes[0].primitives[0].indices: index 99 (element 2 of accessors[6]) is past the 4 vertices of the primitive",
     nullptr, true},
    {"wrong_attribute_type", edit([](json& g, std::string&) { g["accessors"][1]["type"] = "VEC2"; }),
     "meshes[0].primitives[0].attributes.NORMAL: accessors[1]: the accessor is VEC2 of component type 5126; expected "
     "VEC3 of float"},
    {"no_positions", edit([](json& g, std::string&) { primitive(g)["attributes"].erase("POSITION"); }),
     "meshes[0].primitives[0].attributes: the primitive has no POSITION"},
    {"lines", edit([](json& g, std::string&) { primitive(g)["mode"] = 1; }),
     "meshes[0].primitives[0].mode: primitive mode 1 is not supported (only triangles: lists, strips and fans, modes 4 "
     "to 6)"},
    {"node_cycle", edit([](json& g, std::string&) { g["nodes"][1]["children"] = {0}; }),
     "nodes[1].children[0]: nodes[0] is reached twice (glTF nodes form a tree: one parent each, no cycles)"},
    {"missing_image", edit([](json&, std::string&) {}),
     "images[0].uri: image file '{dir}/missing_image_albedo.png' not found",
     [](const std::string& path) {
       std::filesystem::remove(std::filesystem::path(path).replace_filename("missing_image_albedo.png"));
     }},
    {"image_outside_the_folder", edit([](json& g, std::string&) { g["images"][2]["uri"] = "../elsewhere.png"; }),
     "images[2].uri: '../elsewhere.png' lies outside the glTF file's folder"},
    {"image_embedded_in_the_glb",
     edit(
         [](json& g, std::string&) {
           g["images"][0] = {{"bufferView", 0}, {"mimeType", "image/png"}};
         },
         Buffer::glb),
     "images[0]: the image is embedded in the file (in a buffer view); facet reads material textures from image files "
     "beside the glTF file (export them as separate files)"},
    {"buffer_outside_the_folder",
     edit([](json& g, std::string&) { g["buffers"][0]["uri"] = "../../etc/passwd"; }, Buffer::bin_file),
     "buffer file '/etc/passwd' lies outside the glTF file's folder"},
    {"missing_bin_file", edit([](json&, std::string&) {}, Buffer::bin_file),
     "buffer file '{dir}/missing_bin_file.bin' not found",
     [](const std::string& path) { std::filesystem::remove(std::filesystem::path(path).replace_extension(".bin")); }},
    {"texture_that_does_not_exist",
     edit([](json& g, std::string&) { g["materials"][0]["normalTexture"]["index"] = 9; }),
     "materials[0].normalTexture.index: texture 9 does not exist (the file has 4)"},
};

class HostileGltf : public ::testing::TestWithParam<HostileGltfCase> {};

TEST_P(HostileGltf, RenderExitsOneWithTheLocatedMessage) {
  const HostileGltfCase& c = GetParam();
  std::string mesh = write_gltf_sample(test_dir(), c.name, c.options);
  if (c.after) c.after(mesh);
  std::string objects = c.mesh_only ? test_support::object_json(mesh, "Unlit.shader").insert(0, "[") + "]"
                                    : gltf_object(mesh, unlit_texture_shader());
  Outcome r = render_expecting_failure(c.name, write_scene(c.name, small_scene(objects)));
  EXPECT_EQ(r.code, 1) << r.err;
  std::string expected = c.expected;
  if (size_t at = expected.find("{dir}"); at != std::string::npos) expected.replace(at, 5, test_dir().string());
  EXPECT_TRUE(test_support::has_error_at(r.err, std::string(c.name) + ".json", "objects[0].mesh: " + mesh + ": " + expected))
      << r.err;
}

INSTANTIATE_TEST_SUITE_P(Cases, HostileGltf, ::testing::ValuesIn(kHostileGltf),
                         [](const ::testing::TestParamInfo<HostileGltfCase>& info) {
                           return std::string(info.param.name);
                         });

// The negative control: the same scene and sample, unbroken, renders.
TEST(HostileGltfControl, TheUnbrokenSampleRenders) {
  std::string mesh = write_gltf_sample(test_dir(), "control");
  std::string scene_path = write_scene("control", small_scene(gltf_object(mesh, unlit_texture_shader())));
  std::string png = (test_dir() / "control.out.png").string();
  std::vector<const char*> argv = {"render", scene_path.c_str(), "-o", png.c_str()};
  std::ostringstream out, err;
  EXPECT_EQ(tool::render_command(int(argv.size()), argv.data(), out, err), 0) << err.str();
  EXPECT_TRUE(std::filesystem::exists(png));
}

// Nodes that reuse one mesh multiply its vertices: 600 nodes of a mesh of
// 1000 primitives of one quad (a 100 KB file) asked for 2.4 million
// vertices. The model's vertices are counted after instancing and refused
// past 2^21 (at about 400 bytes a vertex in all, under 2 GB).
TEST(HostileGltfControl, NodesReusingAMeshAreCountedAgainstTheVertexLimit) {
  GltfSampleOptions amplified = edit([](json& g, std::string&) {
    json quad = primitive(g);
    g["meshes"][0]["primitives"] = json::array();
    for (int i = 0; i < 1000; ++i) g["meshes"][0]["primitives"].push_back(quad);
    for (int i = 0; i < 600; ++i) {
      g["scenes"][0]["nodes"].push_back(g["nodes"].size());
      g["nodes"].push_back({{"mesh", 0}});
    }
  });
  std::string mesh = write_gltf_sample(test_dir(), "amplified", amplified);
  Outcome r = render_expecting_failure(
      "amplified", write_scene("amplified", small_scene(gltf_object(mesh, unlit_texture_shader()))));
  EXPECT_EQ(r.code, 1) << r.err;
  EXPECT_NE(r.err.find("the model has more than 2097152 vertices (the limit of one glTF mesh)"), std::string::npos)
      << r.err.substr(0, 2000);
}

// A glTF mesh's .bin file is an input of the render: listed in the depfile
// (with the textures its material names), and never overwritten by an output.
TEST(GltfInputs, TheBinFileIsInTheDepfileAndAnOutputOverItIsRefused) {
  std::string mesh = write_gltf_sample(test_dir(), "inputs", {.buffer = Buffer::bin_file});
  std::string scene = write_scene("inputs", small_scene(gltf_object(mesh, unlit_texture_shader())));
  std::string png = (test_dir() / "inputs.out.png").string(), depfile = png + ".d";
  std::string bin = (test_dir() / "inputs.bin").string();
  std::vector<const char*> argv = {"render", scene.c_str(), "-o", png.c_str(), "--depfile", depfile.c_str()};
  std::ostringstream out, err;
  ASSERT_EQ(tool::render_command(int(argv.size()), argv.data(), out, err), 0) << err.str();
  std::ifstream in(depfile);
  std::string rule((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_NE(rule.find(bin), std::string::npos) << rule;
  EXPECT_NE(rule.find((test_dir() / "inputs_albedo.png").string()), std::string::npos) << rule;

  uintmax_t size = std::filesystem::file_size(bin);
  std::vector<const char*> clash = {"render", scene.c_str(), "-o", bin.c_str()};
  std::ostringstream out2, err2;
  EXPECT_EQ(tool::render_command(int(clash.size()), clash.data(), out2, err2), 1);
  EXPECT_NE(err2.str().find("is also an input of this render (a buffer of a glTF mesh of the scene)"),
            std::string::npos)
      << err2.str();
  EXPECT_EQ(std::filesystem::file_size(bin), size);
}

}  // namespace
}  // namespace facet::runtime
