// The glTF test generator: a small textured model written as .gltf (buffer
// as a base64 data: URI, or as a .bin file beside it) or as .glb (buffer in
// the BIN chunk), with PNG textures beside it. An `edit` callback changes
// the JSON or the buffer bytes before writing, which is how the hostile
// cases are made from the good file.
//
// The model: one quad of 4 vertices and 2 triangles (unsigned short
// indices) with POSITION, NORMAL, TANGENT, TEXCOORD_0, TEXCOORD_1 and
// COLOR_0, facing glTF's -Z, under two nodes: nodes[0] scales by 1.5 and
// has nodes[1] as its child, which moves by 0.25 along glTF's +X and holds
// the mesh. In facet's space (x negated) the quad faces -Z and spans x from
// -1.125 to 0.375 and y from -0.75 to 0.75; a camera on -Z looking at +Z
// sees its textures upright, quadrants red top-left, green top-right, blue
// bottom-left, white bottom-right (sample_quadrant_colors).
#pragma once

#include <OpenImageIO/imageio.h>

#include <array>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace facet::runtime::test_support {

struct GltfSampleOptions {
  enum class Buffer { data_uri, bin_file, glb } buffer = Buffer::data_uri;
  bool material = true;  // a material with all four textures (and their PNG files)
  std::function<void(nlohmann::json& gltf, std::string& buffer)> edit;
};

// The four colours of the textures' quadrants, as 8-bit sRGB: top-left,
// top-right, bottom-left, bottom-right of the image.
inline const std::array<std::array<uint8_t, 3>, 4>& sample_quadrant_colors() {
  static const std::array<std::array<uint8_t, 3>, 4> colors = {
      {{255, 0, 0}, {0, 255, 0}, {0, 0, 255}, {255, 255, 255}}};
  return colors;
}

namespace gltf_detail {

inline std::string base64(const std::string& bytes) {
  static const char* digits = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  for (size_t i = 0; i < bytes.size(); i += 3) {
    uint32_t n = uint32_t(uint8_t(bytes[i])) << 16;
    if (i + 1 < bytes.size()) n |= uint32_t(uint8_t(bytes[i + 1])) << 8;
    if (i + 2 < bytes.size()) n |= uint32_t(uint8_t(bytes[i + 2]));
    out += digits[(n >> 18) & 63];
    out += digits[(n >> 12) & 63];
    out += i + 1 < bytes.size() ? digits[(n >> 6) & 63] : '=';
    out += i + 2 < bytes.size() ? digits[n & 63] : '=';
  }
  return out;
}

template <typename T>
void put(std::string& buffer, const std::vector<T>& values) {
  size_t at = buffer.size();
  buffer.resize(at + values.size() * sizeof(T));
  std::memcpy(buffer.data() + at, values.data(), values.size() * sizeof(T));
  while (buffer.size() % 4) buffer.push_back('\0');
}

// An 8 x 8 RGBA PNG in four 4 x 4 quadrants of the given colours.
inline void write_quadrant_png(const std::filesystem::path& path, const std::array<std::array<uint8_t, 4>, 4>& q) {
  std::vector<uint8_t> pixels(8 * 8 * 4);
  for (int y = 0; y < 8; ++y) {
    for (int x = 0; x < 8; ++x) {
      const auto& c = q[size_t((y >= 4 ? 2 : 0) + (x >= 4 ? 1 : 0))];
      std::memcpy(&pixels[size_t(y * 8 + x) * 4], c.data(), 4);
    }
  }
  auto out = OIIO::ImageOutput::create(path.string());
  OIIO::ImageSpec spec(8, 8, 4, OIIO::TypeDesc::UINT8);
  out->open(path.string(), spec);
  out->write_image(OIIO::TypeDesc::UINT8, pixels.data());
  out->close();
}

inline void write_glb(const std::filesystem::path& path, const std::string& json_text, const std::string& bin) {
  std::string json = json_text;
  while (json.size() % 4) json.push_back(' ');
  std::string out;
  auto u32 = [&](uint32_t v) { out.append(reinterpret_cast<const char*>(&v), 4); };
  uint32_t length = uint32_t(12 + 8 + json.size() + (bin.empty() ? 0 : 8 + bin.size()));
  u32(0x46546C67);
  u32(2);
  u32(length);
  u32(uint32_t(json.size()));
  u32(0x4E4F534A);
  out += json;
  if (!bin.empty()) {
    u32(uint32_t(bin.size()));
    u32(0x004E4942);
    out += bin;
  }
  std::ofstream(path, std::ios::binary) << out;
}

}  // namespace gltf_detail

// Writes <dir>/<name>.gltf or .glb (and its PNGs, <name>_*.png, and .bin)
// and returns the model's path.
inline std::string write_gltf_sample(const std::filesystem::path& dir, const std::string& name,
                                     const GltfSampleOptions& options = {}) {
  using nlohmann::json;
  using namespace gltf_detail;
  // Corners in glTF space; as seen from -Z (glTF's +X to the left): v0
  // bottom-left, v1 bottom-right, v2 top-right, v3 top-left; counter-clockwise.
  std::vector<float> positions = {0.5f, -0.5f, 0, -0.5f, -0.5f, 0, -0.5f, 0.5f, 0, 0.5f, 0.5f, 0};
  std::vector<float> normals = {0, 0, -1, 0, 0, -1, 0, 0, -1, 0, 0, -1};
  std::vector<float> tangents = {-1, 0, 0, 1, -1, 0, 0, 1, -1, 0, 0, 1, -1, 0, 0, 1};
  std::vector<float> uv0 = {0, 1, 1, 1, 1, 0, 0, 0};  // glTF: (0, 0) is the image's top-left
  std::vector<float> uv1 = {0.25f, 0.75f, 0.75f, 0.75f, 0.75f, 0.25f, 0.25f, 0.25f};
  std::vector<float> colors = {1, 0, 0, 1, 0, 1, 0, 1, 0, 0, 1, 1, 1, 1, 1, 0.5f};
  std::vector<uint16_t> indices = {0, 1, 2, 0, 2, 3};
  std::string buffer;
  json views = json::array(), accessors = json::array();
  auto add = [&](const auto& values, int components, const char* type, int component_type, size_t count) {
    size_t at = buffer.size();
    put(buffer, values);
    views.push_back({{"buffer", 0}, {"byteOffset", at}, {"byteLength", values.size() * sizeof(values[0])}});
    accessors.push_back(
        {{"bufferView", views.size() - 1}, {"componentType", component_type}, {"count", count}, {"type", type}});
    (void)components;
  };
  add(positions, 3, "VEC3", 5126, 4);
  accessors.back()["min"] = {-0.5, -0.5, 0};
  accessors.back()["max"] = {0.5, 0.5, 0};
  add(normals, 3, "VEC3", 5126, 4);
  add(tangents, 4, "VEC4", 5126, 4);
  add(uv0, 2, "VEC2", 5126, 4);
  add(uv1, 2, "VEC2", 5126, 4);
  add(colors, 4, "VEC4", 5126, 4);
  add(indices, 1, "SCALAR", 5123, 6);
  json primitive = {
      {"attributes",
       {{"POSITION", 0}, {"NORMAL", 1}, {"TANGENT", 2}, {"TEXCOORD_0", 3}, {"TEXCOORD_1", 4}, {"COLOR_0", 5}}},
      {"indices", 6},
      {"mode", 4}};
  json gltf = {{"asset", {{"version", "2.0"}, {"generator", "facet tests"}}},
               {"scene", 0},
               {"scenes", {{{"nodes", {0}}}}},
               {"nodes",
                {{{"name", "root"}, {"scale", {1.5, 1.5, 1.5}}, {"children", {1}}},
                 {{"name", "quad"}, {"translation", {0.25, 0, 0}}, {"mesh", 0}}}},
               {"meshes", {{{"name", "quad"}, {"primitives", {primitive}}}}},
               {"accessors", accessors},
               {"bufferViews", views}};
  if (options.material) {
    gltf["meshes"][0]["primitives"][0]["material"] = 0;
    const auto& q = sample_quadrant_colors();
    auto rgba = [&](size_t i) { return std::array<uint8_t, 4>{q[i][0], q[i][1], q[i][2], 255}; };
    std::array<std::array<uint8_t, 4>, 4> albedo = {rgba(0), rgba(1), rgba(2), rgba(3)};
    // metallicRoughness: roughness (G) 0.25 everywhere, metallic (B) 0 left, 1 right.
    std::array<std::array<uint8_t, 4>, 4> mr = {
        {{0, 64, 0, 255}, {0, 64, 255, 255}, {0, 64, 0, 255}, {0, 64, 255, 255}}};
    std::array<std::array<uint8_t, 4>, 4> flat = {
        {{128, 128, 255, 255}, {128, 128, 255, 255}, {128, 128, 255, 255}, {128, 128, 255, 255}}};
    const char* kinds[] = {"albedo", "mr", "normal", "emission"};
    const std::array<std::array<uint8_t, 4>, 4>* texels[] = {&albedo, &mr, &flat, &albedo};
    json images = json::array(), textures = json::array();
    for (size_t i = 0; i < 4; ++i) {
      std::string file = name + "_" + kinds[i] + ".png";
      write_quadrant_png(dir / file, *texels[i]);
      images.push_back({{"uri", file}});
      textures.push_back({{"source", i}});
    }
    gltf["images"] = images;
    gltf["textures"] = textures;
    gltf["materials"] = {{{"name", "quadrants"},
                          {"pbrMetallicRoughness",
                           {{"baseColorTexture", {{"index", 0}}},
                            {"baseColorFactor", {1, 1, 1, 1}},
                            {"metallicRoughnessTexture", {{"index", 1}}},
                            {"metallicFactor", 1},
                            {"roughnessFactor", 1}}},
                          {"normalTexture", {{"index", 2}, {"scale", 1}}},
                          {"emissiveTexture", {{"index", 3}}},
                          {"emissiveFactor", {1, 1, 1}}}};
  }
  using Buffer = GltfSampleOptions::Buffer;
  json buffer_json = {{"byteLength", buffer.size()}};
  if (options.buffer == Buffer::data_uri) buffer_json["uri"] = "data:application/octet-stream;base64,";
  if (options.buffer == Buffer::bin_file) buffer_json["uri"] = name + ".bin";
  gltf["buffers"] = {buffer_json};
  if (options.edit) options.edit(gltf, buffer);
  // The buffer's bytes go in after the edit, so that an edit of them counts.
  if (options.buffer == Buffer::data_uri && gltf["buffers"][0].contains("uri") &&
      gltf["buffers"][0]["uri"] == "data:application/octet-stream;base64,") {
    gltf["buffers"][0]["uri"] = "data:application/octet-stream;base64," + base64(buffer);
  }
  std::filesystem::path path = dir / (name + (options.buffer == Buffer::glb ? ".glb" : ".gltf"));
  if (options.buffer == Buffer::bin_file) std::ofstream(dir / (name + ".bin"), std::ios::binary) << buffer;
  if (options.buffer == Buffer::glb) {
    write_glb(path, gltf.dump(), buffer);
  } else {
    std::ofstream(path, std::ios::binary) << gltf.dump(1);
  }
  return path.string();
}

}  // namespace facet::runtime::test_support
