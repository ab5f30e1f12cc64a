// Hostile input through `facet render`: OBJ meshes, scene JSON and image
// files that once crashed it (each case is the input a fuzzing probe found,
// or one of its kind). Each must give exit code 1, one message naming the
// file and where in it, and no output file.
#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>
#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <tuple>
#include <sstream>
#include <string>
#include <vector>

#include "facet/commands.h"
#include "facet/runtime/mesh.h"
#include "render_test_support.h"

namespace facet::runtime {
namespace {

using test_support::example_shader;
using test_support::small_scene;
using test_support::test_dir;
using test_support::write_scene;

using Outcome = test_support::RenderOutcome;
using test_support::render_expecting_failure;

std::string write_file(const std::string& name, const std::string& bytes) {
  std::filesystem::path path = test_dir() / name;
  std::ofstream(path, std::ios::binary) << bytes;
  return path.string();
}

// ---------------------------------------------------------------- OBJ meshes

constexpr const char* kTriangle = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";

struct ObjCase {
  const char* name;
  std::string obj;
  std::string expected;  // after "<name>.obj:": "line:col: why", or " why" for the whole file
};

std::ostream& operator<<(std::ostream& os, const ObjCase& c) { return os << c.name; }

std::string many_corners(int n) {
  std::string text = kTriangle;
  text += "f";
  for (int i = 0; i < n; ++i) text += " " + std::to_string(1 + i % 3);
  return text + "\n";
}

const ObjCase kObjCases[] = {
    {"index_past_the_end", std::string(kTriangle) + "f 1 2 4\n",
     "4:7: face index 4 refers past the 3 vertices defined so far"},
    {"huge_index", std::string(kTriangle) + "f 1 2 99999999\n",
     "4:7: face index 99999999 refers past the 3 vertices defined so far"},
    {"index_past_64_bits", std::string(kTriangle) + "f 1 2 99999999999999999999999\n",
     "4:7: face index 99999999999999999999999 refers past the 3 vertices defined so far"},
    {"relative_index_before_the_start", std::string(kTriangle) + "f -1 -2 -9\n",
     "4:9: relative face index -9 refers before the first vertex (only 3 vertices defined so far)"},
    {"bad_uv_index", std::string(kTriangle) + "vt 0 0\nvn 0 0 1\nf 1/99/1 2/1/1 3/1/1\n",
     "6:5: texture coordinate index 99 refers past the 1 texture coordinate defined so far"},
    {"bad_normal_index", std::string(kTriangle) + "vn 0 0 1\nf 1//77 2//1 3//1\n",
     "5:6: normal index 77 refers past the 1 normal defined so far"},
    {"faces_without_vertices", "f 1 2 3\n", "1:3: face index 1 refers past the 0 vertices defined so far"},
    {"index_defined_later", "v 0 0 0\nv 1 0 0\nf 1 2 3\nv 0 1 0\n",
     "3:7: face index 3 refers past the 2 vertices defined so far"},
    {"index_zero", std::string(kTriangle) + "f 0 1 2\n", "4:3: face index 0 is not allowed"},
    {"index_not_a_number", std::string(kTriangle) + "f 1 2 three\n", "4:7: 'three' is not a face index"},
    {"index_with_junk", std::string(kTriangle) + "f 1 2 3x\n", "4:7: '3x' is not a face index"},
    {"corner_with_four_parts", std::string(kTriangle) + "f 1/1/1/1 2 3\n", "4:3: '1/1/1/1' is not a face corner"},
    {"corner_missing_uv", std::string(kTriangle) + "f 1/ 2 3\n", "4:5: missing texture coordinate index in '1/'"},
    {"two_corner_face", std::string(kTriangle) + "f 1 2\n", "4:1: a face needs at least 3 corners, this one has 2"},
    {"empty_face", std::string(kTriangle) + "f\n", "4:1: a face needs at least 3 corners, this one has 0"},
    {"polygon_of_100000_corners", many_corners(100000), "4:1: a face of 100000 corners (at most 512 are supported)"},
    {"nan_coordinate", "v nan 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", "1:3: 'nan' is not a number"},
    {"infinite_coordinate", "v 0 0 0\nv 1 0 inf\nv 0 1 0\nf 1 2 3\n", "2:7: 'inf' is not a number"},
    {"coordinate_past_float", "v 0 0 0\nv 1e39 0 0\nv 0 1 0\nf 1 2 3\n", "2:3: '1e39' is out of range"},
    {"coordinate_past_double", "v 0 0 0\nv 1e400 0 0\nv 0 1 0\nf 1 2 3\n", "2:3: '1e400' is out of range"},
    {"vertex_of_two_numbers", "v 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", "1:1: a vertex needs 3 numbers, this one has 2"},
    {"bounds_past_float", "v -3e38 0 0\nv 3e38 0 0\nv 0 1 0\nf 1 2 3\n",
     " the mesh is too large (its bounding sphere does not fit a float)"},
    // fuzz_obj found these: tinyobjloader casts a skin weight's joint number to int unchecked.
    {"skin_weight_joint_past_int", std::string(kTriangle) + "f 1 2 3\nvw 0 1e30 0.5\n",
     "5:6: '1e30' is out of range (the numbers of a skin weight line must fit an int"},
    {"skin_weight_joint_of_many_digits", std::string(kTriangle) + "f 1 2 3\nvw 0 0777777777777777777777 1\n",
     "5:6: '0777777777777777777777' is out of range"},
    {"skin_weight_infinite_joint", std::string(kTriangle) + "f 1 2 3\nvw 0 inf 1\n", "5:6: 'inf' is not a number"},
    {"skin_weight_without_vertex", std::string(kTriangle) + "f 1 2 3\nvw\t\n",
     "5:1: a skin weight line needs a vertex index"},
    {"crlf_and_cr_lines", "v 0 0 0\r\nv 1 0 0\rv 0 1 0\r\nf 1 2 4\r\n",
     "4:7: face index 4 refers past the 3 vertices defined so far"},
};

class HostileObj : public ::testing::TestWithParam<ObjCase> {};

TEST_P(HostileObj, RenderExitsOneWithTheLocatedMessage) {
  const ObjCase& c = GetParam();
  std::string obj = write_file(std::string(c.name) + ".obj", c.obj);
  std::string scene = small_scene(R"([{"mesh": ")" + obj + R"(", "material": {"shader": ")" +
                                  example_shader("Unlit.shader") + R"("}}])");
  Outcome r = render_expecting_failure(c.name, write_scene(c.name, scene));
  EXPECT_EQ(r.code, 1) << r.err;
  EXPECT_NE(r.err.find(std::string(c.name) + ".obj:" + c.expected), std::string::npos) << r.err;
  EXPECT_TRUE(test_support::has_error_at(r.err, c.name + std::string(".json"), "objects[0].mesh: ")) << r.err;
}

INSTANTIATE_TEST_SUITE_P(Cases, HostileObj, ::testing::ValuesIn(kObjCases),
                         [](const ::testing::TestParamInfo<ObjCase>& info) { return std::string(info.param.name); });

// The negative controls: valid files of the same shapes still load, and a
// relative index means what it should.
TEST(HostileObjControl, RelativeIndicesCommentsAndQuadsStillLoad) {
  std::string obj = write_file("control.obj",
                               "# a quad, then a triangle by relative indices\n"
                               "v 0 0 0 # trailing comment\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvt 0 0\nvn 0 0 -1\n"
                               "f 1/1/1 2/1/1 3/1/1 4/1/1\nf -4//1 -3//1 -2//1\n");
  Diagnostics error;
  std::optional<MeshData> mesh = load_obj(obj, error);
  ASSERT_TRUE(mesh) << test_support::message_of(error);
  ASSERT_EQ(mesh->indices.size(), 9u);
  EXPECT_EQ(mesh->vertices[6].position, (std::array<float, 3>{0, 0, 0}));
  EXPECT_EQ(mesh->vertices[8].position, (std::array<float, 3>{1, 1, 0}));
  EXPECT_EQ(mesh->vertices[8].normal, (std::array<float, 3>{0, 0, -1}));
}

TEST(HostileObjControl, SkinWeightsThatFitAnIntStillLoad) {
  std::string obj = write_file("weights.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvw 0 0 0.25 1 0.75\nvw 2 3 1\nf 1 2 3\n");
  Diagnostics error;
  std::optional<MeshData> mesh = load_obj(obj, error);
  ASSERT_TRUE(mesh) << test_support::message_of(error);
  EXPECT_EQ(mesh->indices.size(), 3u);
}

// ---------------------------------------------------------------- scene JSON

struct JsonCase {
  const char* name;
  std::string json;
  std::string expected;        // the message of the error located in <name>.json
  const char* place = nullptr;  // its "line:column", where the case pins it
};

std::ostream& operator<<(std::ostream& os, const JsonCase& c) { return os << c.name; }

std::string unlit_objects() {
  return R"([{"mesh": "sphere", "material": {"shader": ")" + example_shader("Unlit.shader") + R"("}}])";
}

// small_scene with `fields` (a JSON text of members and a trailing comma) in front.
std::string scene_with(const std::string& fields) {
  std::string json = small_scene(unlit_objects());
  json.insert(1, fields);
  return json;
}

std::string deeply_nested_post(size_t depth) {
  std::string value = std::string(depth, '[') + "1" + std::string(depth, ']');
  return scene_with(R"("post": [{"shader": ")" + example_shader("ImageEffects.shader") +
                    R"(", "properties": {"_Deep": )" + value + "}}], ");
}

std::string long_name_mesh() {
  std::string name(100000, 'a');
  return small_scene(R"([{"mesh": ")" + name + R"(", "material": {"shader": ")" + example_shader("Unlit.shader") +
                     R"("}}])");
}

// A scene of the given size (the first members of the scene).
std::string sized_scene(const std::string& size) {
  return "{" + size + R"(, "camera": {"position": [0, 0, -3], "look_at": [0, 0, 0]}, "objects": )" + unlit_objects() +
         "}";
}

std::string probes(int count, int resolution) {
  std::string list;
  for (int i = 0; i < count; ++i) {
    list +=
        (i ? ", " : "") + std::string(R"({"position": [0, 0, 0], "resolution": )") + std::to_string(resolution) + "}";
  }
  return scene_with(R"("reflection_probes": [)" + list + "], ");
}

std::string many_keywords(size_t count) {
  std::string list;
  for (size_t i = 0; i < count; ++i) list += (i ? ", \"K" : "\"K") + std::to_string(i) + "\"";
  return small_scene(R"([{"mesh": "sphere", "material": {"shader": ")" + example_shader("Unlit.shader") +
                     R"(", "keywords": [)" + list + "]}}]");
}

const JsonCase kJsonCases[] = {
    // The documented largest side took 12 GB; 8192 x 8192 3.4 GB.
    {"frame_of_16384_squared", sized_scene(R"("width": 16384, "height": 16384)"),
     "height: a frame of 16384 x 16384 is more than 16777216 pixels (4096 x 4096)"},
    {"frame_wide_and_tall", sized_scene(R"("width": 16384, "height": 1025)"),
     "height: a frame of 16384 x 1025 is more than 16777216 pixels (4096 x 4096)"},
    {"probe_of_512", probes(1, 512), "reflection_probes[0].resolution: expected an integer from 16 to 256"},
    {"probes_past_their_texels", probes(5, 256),
     "reflection_probes[4]: the probes render more than 1572864 texels together"},
    {"material_of_2000_keywords", many_keywords(2000), "objects[0].material.keywords: more than 1024 keywords"},
    {"number_past_double", "{\n  \"time\": 1e400,\n  \"camera\": {}, \"objects\": []}",
     "invalid JSON: number overflow parsing '1e400'", "2:11"},
    {"negative_number_past_double", R"({"camera": {"fov": -1e400}, "objects": []})",
     "invalid JSON: number overflow parsing '-1e400'", "1:20"},
    {"number_past_float", scene_with(R"("time": 1e39, )"), "time: the number 1e+39 is out of range"},
    {"colour_past_float", scene_with(R"("ambient": [1, 1e300, 0], )"), "ambient[1]: the number 1e+300 is out of range"},
    {"nesting_a_million_deep", deeply_nested_post(1000000), "invalid JSON: nested deeper than 64 levels"},
    {"mesh_name_too_long_for_the_file_system", long_name_mesh(), "objects[0].mesh: not a built-in mesh"},
};

class HostileSceneJson : public ::testing::TestWithParam<JsonCase> {};

TEST_P(HostileSceneJson, RenderExitsOneWithTheMessage) {
  const JsonCase& c = GetParam();
  Outcome r = render_expecting_failure(c.name, write_scene(c.name, c.json));
  EXPECT_EQ(r.code, 1) << r.err;
  if (c.place) {
    EXPECT_NE(r.err.find(c.name + std::string(".json:") + c.place + ": error: " + c.expected), std::string::npos)
        << r.err.substr(0, 2000);
  } else {
    EXPECT_TRUE(test_support::has_error_at(r.err, c.name + std::string(".json"), c.expected)) << r.err.substr(0, 2000);
  }
}

INSTANTIATE_TEST_SUITE_P(Cases, HostileSceneJson, ::testing::ValuesIn(kJsonCases),
                         [](const ::testing::TestParamInfo<JsonCase>& info) { return std::string(info.param.name); });

TEST(HostileSceneJsonDepth, NestingPastTheLimitNamesWhereItStarts) {
  std::string json = deeply_nested_post(1000);
  // The root, "post", its effect and "properties" are levels 1 to 4, so the
  // value's 61st '[' opens level 65 (all on line 1).
  size_t column = json.find("[[") + 60 + 1;
  Outcome r = render_expecting_failure("nesting_columns", write_scene("nesting_columns", json));
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("nesting_columns.json:1:" + std::to_string(column) +
                       ": error: invalid JSON: nested deeper than 64 levels"),
            std::string::npos)
      << r.err.substr(0, 2000);
}

// ---------------------------------------------------------------- PNG files

uint32_t crc32(const std::string& bytes) {
  uint32_t crc = 0xffffffffu;
  for (unsigned char b : bytes) {
    crc ^= b;
    for (int k = 0; k < 8; ++k) crc = (crc >> 1) ^ (0xedb88320u & (0u - (crc & 1u)));
  }
  return ~crc;
}

std::string big_endian(uint32_t v) {
  return {char(v >> 24), char(v >> 16), char(v >> 8), char(v)};
}

std::string chunk(const std::string& type, const std::string& data) {
  return big_endian(uint32_t(data.size())) + type + data + big_endian(crc32(type + data));
}

// Deflate bits, least significant first; Huffman codes go most significant first.
struct BitWriter {
  std::string bytes;
  int used = 8;
  void bit(unsigned b) {
    if (used == 8) {
      bytes.push_back(0);
      used = 0;
    }
    bytes.back() = char(uint8_t(bytes.back()) | (b << used++));
  }
  void code(uint32_t value, int length) {
    for (int i = length - 1; i >= 0; --i) bit((value >> i) & 1);
  }
};

// A zlib stream of `n` zero bytes in one fixed-Huffman block: a literal 0,
// then copies of 258 bytes at distance 1 (13 bits each, a ratio of ~160:1).
std::string zlib_zeros(uint64_t n) {
  BitWriter w;
  w.bit(1);  // BFINAL
  w.bit(1);  // BTYPE = 01 (fixed Huffman), low bit first
  w.bit(0);
  uint64_t left = n;
  auto literal_zero = [&] {
    w.code(0x30, 8);  // literal 0
    --left;
  };
  if (left) literal_zero();
  for (; left >= 258; left -= 258) {
    w.code(0xc5, 8);  // length code 285: 258 bytes
    w.code(0, 5);     // distance code 0: 1 byte back
  }
  while (left) literal_zero();
  w.code(0, 7);  // end of block
  uint32_t adler = (uint32_t(n % 65521) << 16) | 1u;  // a = 1 + 0s, b = n * a
  return std::string("\x78\x01", 2) + w.bytes + big_endian(adler);
}

// An 8-bit greyscale PNG of `width` x `height` whose IDAT inflates to
// `rows` rows of zeros (all of them for a real image, a few for a header
// that only claims a size).
std::string grey_png(uint32_t width, uint32_t height, uint64_t rows) {
  std::string ihdr = big_endian(width) + big_endian(height) + std::string("\x08\x00\x00\x00\x00", 5);
  return std::string("\x89PNG\r\n\x1a\n", 8) + chunk("IHDR", ihdr) + chunk("IDAT", zlib_zeros(rows * (uint64_t(width) + 1))) +
         chunk("IEND", "");
}

std::string textured_scene(const std::string& png) {
  return small_scene(R"([{"mesh": "sphere", "material": {"shader": ")" + example_shader("TexturedAmbient.shader") +
                     R"(", "properties": {"_MainTex": ")" + png + R"("}}}])");
}

struct PngCase {
  const char* name;
  uint32_t width, height;
  uint64_t rows;  // rows of pixels the IDAT holds
  std::string expected;
};

std::ostream& operator<<(std::ostream& os, const PngCase& c) { return os << c.name; }

const PngCase kPngCases[] = {
    {"million_squared_header", 1000000, 1000000, 0,
     "the image is 1000000x1000000 pixels; a side may have at most 16384"},
    {"one_by_a_million", 1, 1000000, 1000000, "the image is 1x1000000 pixels; a side may have at most 16384"},
    {"a_million_by_one", 1000000, 1, 1, "the image is 1000000x1 pixels; a side may have at most 16384"},
    {"decompression_bomb", 9000, 9000, 9000,
     "the image is 9000x9000 pixels (81000000 in all); at most 67108864 are decoded (facet's pixel budget)"},
};

class HostilePng : public ::testing::TestWithParam<PngCase> {};

TEST_P(HostilePng, RenderExitsOneNamingTheTexture) {
  const PngCase& c = GetParam();
  std::string png = write_file(std::string(c.name) + ".png", grey_png(c.width, c.height, c.rows));
  Outcome r = render_expecting_failure(c.name, write_scene(c.name, textured_scene(png)));
  EXPECT_EQ(r.code, 1) << r.err;
  EXPECT_TRUE(test_support::has_error_at(r.err, c.name + std::string(".json"),
                                         "objects[0].material.properties._MainTex: " + png + ": " + c.expected))
      << r.err;
}

INSTANTIATE_TEST_SUITE_P(Cases, HostilePng, ::testing::ValuesIn(kPngCases),
                         [](const ::testing::TestParamInfo<PngCase>& info) { return std::string(info.param.name); });

// The negative control: the same hand-made PNG at a size within the budget
// decodes and renders, so the cases above fail for their size alone.
TEST(HostilePngControl, AHandMadePngWithinTheBudgetRenders) {
  std::string png = write_file("small_grey.png", grey_png(300, 200, 200));
  std::string out = (test_dir() / "small_grey.out.png").string();
  std::string scene = write_scene("small_grey", textured_scene(png));
  std::vector<const char*> argv = {"render", scene.c_str(), "-o", out.c_str()};
  std::ostringstream o, e;
  EXPECT_EQ(tool::render_command(int(argv.size()), argv.data(), o, e), 0) << e.str();
  EXPECT_TRUE(std::filesystem::exists(out));
}

// ---------------------------------------------------------------- EXR headers

// A real 8x8 half-float EXR, written by OpenImageIO.
std::string small_exr_bytes() {
  std::filesystem::path path = test_dir() / "small_written.exr";
  OIIO::ImageBuf image(OIIO::ImageSpec(8, 8, 4, OIIO::TypeDesc::HALF));
  const float grey[4] = {0.5f, 0.5f, 0.5f, 1.0f};
  OIIO::ImageBufAlgo::fill(image, grey);
  EXPECT_TRUE(image.write(path.string())) << image.geterror();
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

std::string little_endian(int32_t v) {
  auto u = uint32_t(v);
  return {char(u), char(u >> 8), char(u >> 16), char(u >> 24)};
}

// The real file with one more attribute at the head of its header.
std::string exr_with_first_attribute(const std::string& attribute) {
  std::string real = small_exr_bytes();
  return real.substr(0, 8) + attribute + real.substr(8);
}

struct ExrCase {
  const char* name;
  std::string attribute;  // put before the real file's first attribute
  std::string expected;
};

std::ostream& operator<<(std::ostream& os, const ExrCase& c) { return os << c.name; }

// OpenEXR allocates an attribute's value at its declared size before reading
// it: the first case (a fuzzer's, reduced) made it allocate 1.7 GB for a
// file of a few hundred bytes.
const ExrCase kExrCases[] = {
    {"attribute_past_the_end", std::string("comment\0string\0", 15) + little_endian(1700000000),
     "the EXR attribute 'comment' declares 1700000000 bytes; the file has "},
    {"negative_attribute_size", std::string("comment\0string\0", 15) + little_endian(-5),
     "the EXR attribute 'comment' declares -5 bytes"},
    {"name_without_its_end", std::string(40, 'v'),
     "the EXR header of part 0 has an attribute name without its end (at most 31 characters)"},
};

class HostileExr : public ::testing::TestWithParam<ExrCase> {};

TEST_P(HostileExr, RenderExitsOneNamingTheTexture) {
  const ExrCase& c = GetParam();
  std::string exr = write_file(std::string(c.name) + ".exr", exr_with_first_attribute(c.attribute));
  Outcome r = render_expecting_failure(c.name, write_scene(c.name, textured_scene(exr)));
  EXPECT_EQ(r.code, 1) << r.err;
  EXPECT_TRUE(test_support::has_error_at(r.err, c.name + std::string(".json"),
                                         "objects[0].material.properties._MainTex: " + exr + ": " + c.expected))
      << r.err;
}

INSTANTIATE_TEST_SUITE_P(Cases, HostileExr, ::testing::ValuesIn(kExrCases),
                         [](const ::testing::TestParamInfo<ExrCase>& info) { return std::string(info.param.name); });

// Inputs fuzz_image found (16 workers on the GPU host, 2026-12-04), kept in
// tests/fuzz/corpus/image: a 54-byte RLE BMP declaring 738,197,508 rows made
// OpenImageIO throw std::length_error while opening it (an uncaught
// exception: the process ended); EXR files whose dataWindow is 50 million
// pixels wide made OpenEXR allocate and free for over 30 s under ASan.
// Both headers are checked before OpenImageIO opens the file. On 2026-12-06
// it found JPEGs whose Photoshop IPTC block (APP13) declares more bytes of
// records than its marker holds (in the second file, its third APP13 block):
// OpenImageIO 2.4 reads past the marker's data while opening them (ASan:
// heap-buffer-overflow in decode_iptc_iim); the blocks are checked first too
// (jpeg_header.h). The same run reported EXR files that took 26-28 s under
// ASan: OpenEXR found a 50-million-pixel-wide dataWindow where the header
// walk found none, and allocated 1.6 GB for it; a header without a
// dataWindow the walk can read is now refused. A local run afterwards found
// the JPEG walk itself calling memcmp with a null pointer on an empty APP13
// marker (UBSan), which OpenImageIO's strcmp would read past: refused too.
// A 16-worker run on 2026-12-06 found a BMP declaring RLE8 compression at
// 24 bits a pixel, which OpenImageIO decodes out of bounds (SEGV); BMP's
// own pairings of bits and compression are checked first now. CI's smoke
// run on 2026-12-07 (ASan's strict string checks on) found a JPEG whose APP1
// marker holds 6 bytes and no NUL: OpenImageIO 2.4 compares APP1, APP2 and
// APP13 data with identifiers by strcmp, reading past such a marker; every
// such marker without a NUL is refused now (with one holding "Exif" and one
// holding "ICC_PROFILE" without their NULs, made by hand).
// The next local run (strict checks on) found a 169-byte EXR whose channel
// list declares 17 bytes and holds 19: OpenEXR reads a channel list by its
// entries, not its declared size, so its reading of the header went 2 bytes
// astray of the header walk's, onto a string declaring 1.98 GB, which it
// allocated (2.35 GB resident). Values OpenEXR reads by their own layout are
// checked against their declared sizes now. The run after that found that
// check's own overflow (UBSan): a preview of 2^32 - 1 squared pixels, whose
// byte count is now computed without overflowing.
struct FuzzFoundImage {
  const char* file;
  const char* expected;
};

class FuzzFoundImages : public ::testing::TestWithParam<FuzzFoundImage> {};

TEST_P(FuzzFoundImages, RenderExitsOneNamingTheTexture) {
  const FuzzFoundImage& c = GetParam();
  std::string image = std::string(FACET_SOURCE_DIR) + "/tests/fuzz/corpus/image/" + c.file;
  std::string name = std::string("fuzz_found_") + std::to_string(std::hash<std::string>{}(c.file) % 100000);
  Outcome r = render_expecting_failure(name, write_scene(name, textured_scene(image)));
  EXPECT_EQ(r.code, 1) << r.err;
  EXPECT_TRUE(test_support::has_error_at(r.err, name + ".json",
                                         "objects[0].material.properties._MainTex: " + image + ": " + c.expected))
      << r.err;
}

INSTANTIATE_TEST_SUITE_P(
    Inputs, FuzzFoundImages,
    ::testing::Values(FuzzFoundImage{"bmp-rle-738197508-rows.bmp", "the BMP header: the image is 4x738197508 pixels"},
                      FuzzFoundImage{"bmp-rle-tall-2.bmp", "the BMP header: "},
                      // An 800-byte GIF whose logical screen OpenImageIO allocated (1.5 GB) before failing.
                      FuzzFoundImage{"gif-screen-16000-squared.gif",
                                     "the GIF header: the image is 16000x16000 pixels (256000000 in all); at most "
                                     "67108864 are decoded (facet's pixel budget)"},
                      FuzzFoundImage{"bmp-rle8-at-24-bits.bmp",
                                     "the BMP header declares 24 bits a pixel with compression 1, a pairing BMP does "
                                     "not define"},
                      FuzzFoundImage{"exr-data-window-50331655-wide.exr", "the EXR dataWindow: the image is "},
                      FuzzFoundImage{"exr-slow-data-window.exr", "the EXR dataWindow: the image is "},
                      // Its channel list's size is wrong too, the cause of the two walks parting.
                      FuzzFoundImage{"exr-data-window-only-openexr-finds.exr",
                                     "the EXR attribute 'channels' declares 19 bytes, but OpenEXR reads 20 bytes for "
                                     "its chlist value"},
                      FuzzFoundImage{"exr-chlist-shorter-than-its-channels.exr",
                                     "the EXR attribute 'channels' declares 17 bytes, but OpenEXR reads 19 bytes for "
                                     "its chlist value"},
                      FuzzFoundImage{"exr-preview-size-overflows.exr", "the EXR attribute "},
                      FuzzFoundImage{"jpeg-empty-app13.jpg", "the JPEG has an empty APP13 marker"},
                      FuzzFoundImage{"jpeg-app1-without-nul.jpg",
                                     "the JPEG's APP1 marker holds 6 bytes and no NUL-terminated identifier"},
                      FuzzFoundImage{"jpeg-app1-exif-without-nul.jpg",
                                     "the JPEG's APP1 marker holds 4 bytes and no NUL-terminated identifier"},
                      FuzzFoundImage{"jpeg-app2-icc-without-nul.jpg",
                                     "the JPEG's APP2 marker holds 11 bytes and no NUL-terminated identifier"},
                      FuzzFoundImage{"jpeg-iptc-past-its-marker.jpg",
                                     "the JPEG's IPTC block (APP13) declares 28761 bytes of records, but its marker "
                                     "holds 89"},
                      FuzzFoundImage{"jpeg-iptc-third-block-past-its-marker.jpg",
                                     "the JPEG's IPTC block (APP13) declares 217 bytes of records, but its marker "
                                     "holds 89"},
                      FuzzFoundImage{"png-text-chunk-past-the-end.png",
                                     "the PNG's chunk 'tEXt' at byte 139 declares 1157627990 bytes of data, past the "
                                     "end of the 284-byte file"},
                      FuzzFoundImage{"png-text-chunk-past-the-end-rgba.png",
                                     "the PNG's chunk 'tEXt' at byte 54 declares 2113929318 bytes of data, past the "
                                     "end of the 375-byte file"}),
    [](const ::testing::TestParamInfo<FuzzFoundImage>& info) { return "case" + std::to_string(info.index); });

// `facet render` of a one-quad scene textured with `image` succeeds and writes its PNG.
void expect_textured_render(const std::string& name, const std::string& image) {
  std::string out = (test_dir() / (name + ".out.png")).string();
  std::string scene = write_scene(name, textured_scene(image));
  std::vector<const char*> argv = {"render", scene.c_str(), "-o", out.c_str()};
  std::ostringstream o, e;
  EXPECT_EQ(tool::render_command(int(argv.size()), argv.data(), o, e), 0) << e.str();
  EXPECT_TRUE(std::filesystem::exists(out)) << name;
}

// A JPEG APP13 marker holding `data`.
std::string app13(const std::string& data) {
  size_t length = data.size() + 2;
  return std::string("\xff\xed", 2) + char(length >> 8) + char(length & 0xff) + data;
}

// A texture is read by the reader its extension names, never by every
// reader OpenImageIO has (camera RAW, JPEG 2000, DICOM, ...) in turn: a
// valid PNG named .tga is a Targa error, and the same bytes named .png
// render (the control).
TEST(TextureFormatByName, APngNamedTgaIsATargaErrorAndRendersNamedPng) {
  const std::string bytes = grey_png(4, 4, 4);
  std::string tga = write_file("png_named.tga", bytes);
  Outcome r = render_expecting_failure("png_named_tga", write_scene("png_named_tga", textured_scene(tga)));
  EXPECT_EQ(r.code, 1) << r.err;
  EXPECT_NE(r.err.find("_MainTex: " + tga + ": cannot read the image as targa ("), std::string::npos) << r.err;

  expect_textured_render("png_named_png", write_file("png_named.png", bytes));
}

TEST(TextureFormatByName, AnExtensionNoReaderKnowsIsAnErrorNamingIt) {
  std::string file = write_file("grey.notanimage", grey_png(4, 4, 4));
  Outcome r = render_expecting_failure("unknown_extension", write_scene("unknown_extension", textured_scene(file)));
  EXPECT_EQ(r.code, 1) << r.err;
  EXPECT_NE(r.err.find("_MainTex: " + file + ": no image reader for '.notanimage' files"), std::string::npos)
      << r.err;
}

// chunk() declaring `declared_length` bytes, whatever its data.
std::string chunk_declaring(const std::string& type, const std::string& data, uint32_t declared_length) {
  return big_endian(declared_length) + chunk(type, data).substr(4);
}

// The control of the PNG chunk walk: a text chunk after the header renders;
// the same chunk declaring more bytes than the file holds, or more than PNG
// allows, is refused before libpng allocates for it.
TEST(PngChunkControl, ATextChunkRendersAndOneDeclaringTooMuchIsRefused) {
  const std::string png = grey_png(4, 4, 4);
  const size_t after_header = 8 + 12 + 13;
  const std::string text("Comment\0a grey square", 21);  // keyword, NUL, text
  auto with_chunk = [&](uint32_t declared) {
    return png.substr(0, after_header) + chunk_declaring("tEXt", text, declared) + png.substr(after_header);
  };
  expect_textured_render("png_text", write_file("png_text.png", with_chunk(uint32_t(text.size()))));
  const std::string size = std::to_string(png.size() + 12 + text.size());
  for (const auto& [name, declared, expected] :
       {std::tuple{"png_past_end", uint32_t(png.size()), "declares " + std::to_string(png.size()) +
                                                               " bytes of data, past the end of the " + size +
                                                               "-byte file"},
        std::tuple{"png_over_limit", uint32_t(0x80000000u),
                   std::string("declares 2147483648 bytes, more than PNG allows (2147483647)")}}) {
    std::string file = write_file(std::string(name) + ".png", with_chunk(declared));
    Outcome refused = render_expecting_failure(name, write_scene(name, textured_scene(file)));
    EXPECT_EQ(refused.code, 1) << name;
    EXPECT_NE(refused.err.find(file + ": the PNG's chunk 'tEXt' at byte 33 " + expected), std::string::npos)
        << refused.err;
  }
}

// The control of the BMP format check: a 24-bit BMP as oiiotool writes it
// renders; the same file declaring RLE8 compression (which BMP defines for
// 8 bits a pixel only) is refused before OpenImageIO decodes it.
TEST(BmpFormatControl, A24BitBmpRendersAndOneDeclaringRle8IsRefused) {
  std::ifstream in(std::string(FACET_SOURCE_DIR) + "/tests/fuzz/corpus/image/small.bmp", std::ios::binary);
  const std::string bmp{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  ASSERT_GT(bmp.size(), 34u);
  expect_textured_render("bmp_24", write_file("bmp_24.bmp", bmp));
  std::string rle8 = bmp;
  rle8[30] = 1;  // biCompression: BI_RLE8
  std::string file = write_file("bmp_rle8_24.bmp", rle8);
  Outcome refused = render_expecting_failure("bmp_rle8_24", write_scene("bmp_rle8_24", textured_scene(file)));
  EXPECT_EQ(refused.code, 1);
  EXPECT_NE(refused.err.find(file + ": the BMP header declares 24 bits a pixel with compression 1, a pairing BMP "
                                    "does not define"),
            std::string::npos)
      << refused.err;
}

// The negative control: the real file renders, so the header walk passes
// what OpenEXR writes and the cases above fail for their attribute alone.
TEST(HostileExrControl, TheRealExrRenders) {
  expect_textured_render("fits", write_file("fits.exr", small_exr_bytes()));
}

// The control of the identifier check: APP1 and APP2 markers whose
// identifiers end with their NUL (XMP, an ICC profile's header) render.
TEST(JpegIdentifierControl, AJpegWithNulTerminatedApp1AndApp2IdentifiersRenders) {
  std::ifstream in(std::string(FACET_SOURCE_DIR) + "/tests/fuzz/corpus/image/small.jpg", std::ios::binary);
  std::string jpeg((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  ASSERT_GT(jpeg.size(), 2u);
  auto marker = [](char code, const std::string& data) {
    size_t length = data.size() + 2;
    return std::string("\xff", 1) + code + char(length >> 8) + char(length & 0xff) + data;
  };
  const std::string xmp = marker('\xe1', std::string("http://ns.adobe.com/xap/1.0/", 29) + "<x:xmpmeta xmlns:x=\"adobe:ns:meta/\"/>");
  const std::string icc = marker('\xe2', std::string("ICC_PROFILE", 12) + std::string("\x01\x01", 2) + "not a profile");
  expect_textured_render("with_xmp_icc", write_file("with_xmp_icc.jpg", jpeg.substr(0, 2) + xmp + icc + jpeg.substr(2)));
}

// The control of the JPEG IPTC check: a real JPEG (tests/fuzz/corpus/image/
// small.jpg, written by oiiotool) with a well-formed Photoshop IPTC block in
// an APP13 marker after its SOI renders.
TEST(JpegIptcControl, AJpegWithAWellFormedIptcBlockRenders) {
  std::ifstream in(std::string(FACET_SOURCE_DIR) + "/tests/fuzz/corpus/image/small.jpg", std::ios::binary);
  std::string jpeg((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  ASSERT_GT(jpeg.size(), 2u);
  const std::string caption = "a caption";
  std::string records = std::string("\x1c\x02\x78", 3) + char(0) + char(caption.size()) + caption;
  std::string block = std::string("Photoshop 3.0", 14) + "8BIM" + std::string("\x04\x04", 2) + std::string(4, '\0') +
                      char(records.size() >> 8) + char(records.size() & 0xff) + records;
  expect_textured_render("with_iptc", write_file("with_iptc.jpg", jpeg.substr(0, 2) + app13(block) + jpeg.substr(2)));
  // The same block declaring one byte more than its records is refused.
  block[block.size() - records.size() - 1] = char(records.size() + 1);
  std::string bad = jpeg.substr(0, 2) + app13(block) + jpeg.substr(2);
  std::string bad_path = write_file("bad_iptc.jpg", bad);
  Outcome r = render_expecting_failure("bad_iptc", write_scene("bad_iptc", textured_scene(bad_path)));
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find(bad_path + ": the JPEG's IPTC block (APP13) declares " + std::to_string(records.size() + 1) +
                       " bytes of records, but its marker holds " + std::to_string(records.size())),
            std::string::npos)
      << r.err;
  // After the scan too (libjpeg reads a progressive file's later markers
  // before OpenImageIO looks at them), and a marker holding "Photoshop 3.0"
  // without its NUL (OpenImageIO's strcmp would read past it).
  const size_t eoi = jpeg.rfind(std::string("\xff\xd9", 2));
  ASSERT_NE(eoi, std::string::npos);
  std::string late = jpeg.substr(0, eoi) + app13(block) + jpeg.substr(eoi);
  std::string unended = jpeg.substr(0, 2) + app13("Photoshop 3.0") + jpeg.substr(2);
  for (const auto& [name, bytes, expected] :
       {std::tuple{"late_iptc", late, std::string("declares ") + std::to_string(records.size() + 1) + " bytes"},
        std::tuple{"unended_iptc", unended, std::string("the JPEG's APP13 marker holds 13 bytes and no NUL-terminated identifier")}}) {
    std::string file = write_file(std::string(name) + ".jpg", bytes);
    Outcome refused = render_expecting_failure(name, write_scene(name, textured_scene(file)));
    EXPECT_EQ(refused.code, 1) << name;
    EXPECT_NE(refused.err.find(file + ": the JPEG's "), std::string::npos) << refused.err;
    EXPECT_NE(refused.err.find(expected), std::string::npos) << refused.err;
  }
}

}  // namespace
}  // namespace facet::runtime
