// glTF files through tinygltf (Debian's libtinygltf): the file is read and
// its container checked here, tinygltf parses the JSON and decodes the
// buffers (embedded data: URIs, the GLB's BIN chunk, or .bin files beside
// it), mesh/gltf_geometry.cpp turns the default scene into facet meshes,
// and the materials' PBR inputs are read for the scene's material mapping.
// tinygltf reaches the file system only through callbacks set here: no
// path expansion (its default runs wordexp), nothing outside the glTF
// file's folder, nothing over the size limit. Images are never decoded by
// tinygltf; the renderer loads texture files itself.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <new>
#include <regex>
#include <sstream>

#include "facet/result.h"
#include "facet/runtime/gltf.h"
#include "mesh/gltf_geometry.h"
#include "mesh/tinygltf.h"

namespace facet::runtime {
namespace {

namespace fs = std::filesystem;

// The whole file, refused before reading when it is over `max_bytes`.
std::optional<std::string> read_bytes(const std::string& path, uint64_t max_bytes, std::string& why) {
  std::error_code ec;
  uint64_t size = fs::file_size(path, ec);
  if (ec) {
    why = fmt::format("cannot read the file ({})", ec.message());
    return std::nullopt;
  }
  if (size > max_bytes) {
    why = fmt::format("the file has {} bytes, more than the {} a glTF file may have", size, max_bytes);
    return std::nullopt;
  }
  std::ifstream in(path, std::ios::binary);
  std::ostringstream bytes;
  bytes << in.rdbuf();
  if (!in && !in.eof()) {
    why = "cannot read the file";
    return std::nullopt;
  }
  return std::move(bytes).str();
}

uint32_t le32(const std::string& bytes, size_t at) {
  uint32_t v;
  std::memcpy(&v, bytes.data() + at, 4);
  return v;  // glTF is little-endian, as every machine facet runs on
}

constexpr uint32_t kGlbMagic = 0x46546C67;   // "glTF"
constexpr uint32_t kJsonChunk = 0x4E4F534A;  // "JSON"
constexpr uint32_t kBinChunk = 0x004E4942;   // "BIN\0"

// The GLB container (header, JSON chunk, optional BIN chunk) against the
// file's real size; returns the JSON chunk's text.
std::optional<std::string_view> glb_json(const std::string& bytes, std::string& why) {
  if (bytes.size() < 12) {
    why = fmt::format("the file has {} bytes, less than the 12 of a GLB header", bytes.size());
    return std::nullopt;
  }
  if (le32(bytes, 0) != kGlbMagic) {
    why = "not a GLB file (it does not start with the magic 'glTF')";
    return std::nullopt;
  }
  if (uint32_t version = le32(bytes, 4); version != 2) {
    why = fmt::format("GLB version {} is not supported (only glTF 2.0)", version);
    return std::nullopt;
  }
  if (uint32_t length = le32(bytes, 8); length != bytes.size()) {
    why = fmt::format("the GLB header gives a length of {} bytes, the file has {} (truncated or padded)", length,
                      bytes.size());
    return std::nullopt;
  }
  if (bytes.size() < 20 || le32(bytes, 16) != kJsonChunk) {
    why = "the GLB file's first chunk is not its JSON chunk";
    return std::nullopt;
  }
  uint64_t json_length = le32(bytes, 12), json_end = 20 + json_length;
  if (json_end > bytes.size()) {
    why = fmt::format("the GLB JSON chunk of {} bytes runs past the end of the file ({} bytes)", json_length,
                      bytes.size());
    return std::nullopt;
  }
  if (json_end % 4 != 0) {
    why = "the GLB JSON chunk's length is not a multiple of 4 (chunks are 4-byte aligned)";
    return std::nullopt;
  }
  if (json_end < bytes.size()) {
    if (json_end + 8 > bytes.size() || le32(bytes, size_t(json_end) + 4) != kBinChunk) {
      why = "the GLB file's second chunk is not a BIN chunk";
      return std::nullopt;
    }
    uint64_t bin_length = le32(bytes, size_t(json_end));
    if (json_end + 8 + bin_length > bytes.size()) {
      why = fmt::format("the GLB BIN chunk of {} bytes runs past the end of the file ({} bytes)", bin_length,
                        bytes.size());
      return std::nullopt;
    }
  }
  return std::string_view(bytes).substr(20, size_t(json_length));
}

// Deeper than any glTF file needs, and shallow enough that tinygltf's
// recursive walk of `extras` cannot overflow the stack.
constexpr size_t kMaxJsonDepth = 64;

bool too_deep(std::string_view text) {
  size_t depth = 0;
  bool in_string = false;
  for (size_t i = 0; i < text.size(); ++i) {
    char c = text[i];
    if (in_string) {
      if (c == '\\')
        ++i;
      else if (c == '"')
        in_string = false;
    } else if (c == '"') {
      in_string = true;
    } else if (c == '[' || c == '{') {
      if (++depth > kMaxJsonDepth) return true;
    } else if ((c == ']' || c == '}') && depth > 0) {
      --depth;
    }
  }
  return false;
}

// What tinygltf may read: files inside `folder`, under the size limit.
struct FileAccess {
  fs::path folder;
  uint64_t max_bytes = 0;
  std::string refusal;             // why the last read was refused, if it was
  std::vector<std::string> files;  // what was read
};

// Whether `path` (tinygltf joins the folder and the URI) stays inside the folder.
bool inside(const fs::path& folder, const std::string& path) {
  fs::path relative = fs::path(path).lexically_normal().lexically_relative(folder.lexically_normal());
  return !relative.empty() && *relative.begin() != ".." && !relative.is_absolute();
}

// tinygltf asks this before it reads a buffer's file; a refusal says why,
// in place of tinygltf's "File not found".
bool file_exists(const std::string& path, void* user) {
  FileAccess& access = *static_cast<FileAccess*>(user);
  // tinygltf looks in the folder, then in the working directory: never the latter.
  if (path.rfind("./", 0) == 0 && access.folder != ".") return false;
  std::string shown = fs::path(path).lexically_normal().string();
  std::error_code ec;
  if (!inside(access.folder, path)) {
    access.refusal = fmt::format("buffer file '{}' lies outside the glTF file's folder", shown);
    return false;
  }
  if (!fs::is_regular_file(path, ec)) {
    access.refusal = fmt::format("buffer file '{}' not found", shown);
    return false;
  }
  access.refusal.clear();
  return true;
}

std::string expand_path(const std::string& path, void*) { return path; }

bool read_whole_file(std::vector<unsigned char>* out, std::string* err, const std::string& path, void* user) {
  FileAccess& access = *static_cast<FileAccess*>(user);
  access.refusal.clear();
  std::string why;
  std::optional<std::string> bytes;
  if (!inside(access.folder, path)) {
    why = fmt::format("'{}' lies outside the glTF file's folder", path);
  } else if (!(bytes = read_bytes(path, access.max_bytes, why))) {
    why = fmt::format("{}: {}", path, why);
  }
  if (!bytes) {
    access.refusal = why;
    if (err) *err += why + "\n";
    return false;
  }
  out->assign(bytes->begin(), bytes->end());
  access.files.push_back(fs::path(path).lexically_normal().string());
  return true;
}

bool write_whole_file(std::string* err, const std::string&, const std::vector<unsigned char>&, void*) {
  if (err) *err += "facet does not write glTF files\n";
  return false;
}

// Images stay undecoded: only materials name them, as files.
bool keep_image(tinygltf::Image*, const int, std::string*, std::string*, int, int, const unsigned char*, int, void*) {
  return true;
}

// tinygltf's error, readable: nlohmann's exception names dropped, and a
// data: URI (which tinygltf quotes whole) not repeated.
std::string tinygltf_error(std::string text) {
  while (!text.empty() && (text.back() == '\n' || text.back() == '\r')) text.pop_back();
  if (text.empty()) return "tinygltf cannot read the file";
  if (text.rfind("[json.exception.", 0) == 0) {
    size_t bracket = text.find("] ");
    return "invalid JSON: " + (bracket == std::string::npos ? text : text.substr(bracket + 2));
  }
  std::smatch size;
  static const std::regex mismatch("File size mismatch : (.*), requestedBytes ([0-9]+), but got ([0-9]+)");
  if (std::regex_match(text, size, mismatch)) {
    return fmt::format("buffer file '{}' has {} bytes, its byteLength says {}", size[1].str(), size[3].str(),
                       size[2].str());
  }
  if (text.rfind("Failed to decode 'uri' : data:", 0) == 0) {
    return "a buffer's data: URI does not decode to its byteLength (truncated, or not base64)";
  }
  return text;
}

// The model, and in `files` the buffer files it read.
std::optional<tinygltf::Model> parse_model(const std::string& path, const std::string& bytes, bool binary,
                                           const GltfLimits& limits, std::vector<std::string>& files,
                                           std::string& why) {
  std::optional<std::string_view> json = binary ? glb_json(bytes, why) : std::string_view(bytes);
  if (!json) return std::nullopt;
  if (too_deep(*json)) {
    why = fmt::format("invalid JSON: nested deeper than {} levels", kMaxJsonDepth);
    return std::nullopt;
  }
  FileAccess access{fs::path(path).parent_path(), limits.max_file_bytes, {}};
  if (access.folder.empty()) access.folder = ".";
  tinygltf::TinyGLTF loader;
  loader.SetFsCallbacks({&file_exists, &expand_path, &read_whole_file, &write_whole_file, &access});
  loader.SetImageLoader(&keep_image, nullptr);
  tinygltf::Model model;
  std::string err, warn, base = access.folder.string();
  bool ok = binary
                ? loader.LoadBinaryFromMemory(&model, &err, &warn, reinterpret_cast<const unsigned char*>(bytes.data()),
                                              unsigned(bytes.size()), base)
                : loader.LoadASCIIFromString(&model, &err, &warn, bytes.data(), unsigned(bytes.size()), base);
  if (!ok) {
    why = !access.refusal.empty() ? access.refusal : tinygltf_error(err);
    return std::nullopt;
  }
  files = std::move(access.files);
  return model;
}

// ---------------------------------------------------------------- materials

std::string percent_decoded(const std::string& uri) {
  std::string out;
  for (size_t i = 0; i < uri.size(); ++i) {
    if (uri[i] == '%' && i + 2 < uri.size() && std::isxdigit(static_cast<unsigned char>(uri[i + 1])) &&
        std::isxdigit(static_cast<unsigned char>(uri[i + 2]))) {
      out += char(std::stoi(uri.substr(i + 1, 2), nullptr, 16));
      i += 2;
    } else {
      out += uri[i];
    }
  }
  return out;
}

struct MaterialReader {
  const tinygltf::Model& model;
  fs::path folder;

  // The image file of texture `index`; `at` names the texture reference.
  Result<std::string, std::string> image_file(int index, const std::string& at) const {
    if (index < 0 || size_t(index) >= model.textures.size()) {
      return unexpected(
          fmt::format("{}.index: texture {} does not exist (the file has {})", at, index, model.textures.size()));
    }
    int source = model.textures[size_t(index)].source;
    std::string texture_at = fmt::format("textures[{}]", index);
    if (source < 0 || size_t(source) >= model.images.size()) {
      return unexpected(
          fmt::format("{}.source: image {} does not exist (the file has {})", texture_at, source, model.images.size()));
    }
    const tinygltf::Image& image = model.images[size_t(source)];
    std::string image_at = fmt::format("images[{}]", source);
    if (image.uri.empty() || image.uri.rfind("data:", 0) == 0) {
      return unexpected(
          fmt::format("{}: the image is embedded in the file ({}); facet reads material textures from "
                      "image files beside the glTF file (export them as separate files)",
                      image_at, image.uri.empty() ? "in a buffer view" : "a data: URI"));
    }
    fs::path relative(percent_decoded(image.uri));
    fs::path file = (folder / relative).lexically_normal();
    if (relative.is_absolute() || !inside(folder, file.string())) {
      return unexpected(fmt::format("{}.uri: '{}' lies outside the glTF file's folder", image_at, image.uri));
    }
    std::error_code ec;
    if (!fs::is_regular_file(file, ec)) {
      return unexpected(fmt::format("{}.uri: image file '{}' not found", image_at, file.string()));
    }
    return file.string();
  }

  Result<std::optional<GltfTexture>, std::string> texture(int index, int texcoord, const std::string& at) const {
    if (index < 0) return std::optional<GltfTexture>();
    if (texcoord < 0 || texcoord > 1) {
      return unexpected(
          fmt::format("{}.texCoord: TEXCOORD_{} is not read (facet reads TEXCOORD_0 and TEXCOORD_1)", at, texcoord));
    }
    Result<std::string, std::string> file = image_file(index, at);
    if (!file) return unexpected(file.error());
    return std::optional<GltfTexture>(GltfTexture{*file, texcoord});
  }

  Result<GltfMaterial, std::string> material(size_t i) const {
    const tinygltf::Material& m = model.materials[i];
    const tinygltf::PbrMetallicRoughness& pbr = m.pbrMetallicRoughness;
    std::string at = fmt::format("materials[{}]", i);
    GltfMaterial out;
    out.name = m.name;
    auto finite = [](double v) { return std::isfinite(v) && std::abs(v) < 1e30; };
    if (pbr.baseColorFactor.size() != 4 ||
        !std::all_of(pbr.baseColorFactor.begin(), pbr.baseColorFactor.end(), finite)) {
      return unexpected(at + ".pbrMetallicRoughness.baseColorFactor: expected 4 finite numbers");
    }
    if (m.emissiveFactor.size() != 3 || !std::all_of(m.emissiveFactor.begin(), m.emissiveFactor.end(), finite)) {
      return unexpected(at + ".emissiveFactor: expected 3 finite numbers");
    }
    if (!finite(pbr.metallicFactor) || !finite(pbr.roughnessFactor) || !finite(m.normalTexture.scale)) {
      return unexpected(at + ": a factor is not a finite number");
    }
    for (size_t k = 0; k < 4; ++k) out.base_color[k] = float(pbr.baseColorFactor[k]);
    for (size_t k = 0; k < 3; ++k) out.emissive[k] = float(m.emissiveFactor[k]);
    out.metallic = float(pbr.metallicFactor);
    out.roughness = float(pbr.roughnessFactor);
    out.normal_scale = float(m.normalTexture.scale);
    struct Slot {
      const char* key;
      int index, texcoord;
      std::optional<GltfTexture>* to;
    };
    for (const Slot& s :
         {Slot{"pbrMetallicRoughness.baseColorTexture", pbr.baseColorTexture.index, pbr.baseColorTexture.texCoord,
               &out.base_color_texture},
          Slot{"pbrMetallicRoughness.metallicRoughnessTexture", pbr.metallicRoughnessTexture.index,
               pbr.metallicRoughnessTexture.texCoord, &out.metallic_roughness_texture},
          Slot{"normalTexture", m.normalTexture.index, m.normalTexture.texCoord, &out.normal_texture},
          Slot{"emissiveTexture", m.emissiveTexture.index, m.emissiveTexture.texCoord, &out.emissive_texture}}) {
      Result<std::optional<GltfTexture>, std::string> t = texture(s.index, s.texcoord, at + "." + s.key);
      if (!t) return unexpected(t.error());
      *s.to = *t;
    }
    return out;
  }
};

bool bounds_are_finite(const std::vector<GltfPart>& parts) {
  for (const GltfPart& part : parts) {
    Bounds b = mesh_bounds(part.mesh);
    if (!std::isfinite(b.radius) || !std::isfinite(b.center[0]) || !std::isfinite(b.center[1]) ||
        !std::isfinite(b.center[2])) {
      return false;
    }
  }
  return true;
}

std::optional<GltfModel> read_gltf(const std::string& path, const GltfOptions& options, std::string& why) {
  std::optional<std::string> bytes = read_bytes(path, options.limits.max_file_bytes, why);
  if (!bytes) return std::nullopt;
  std::string extension = fs::path(path).extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return char(std::tolower(c)); });
  bool binary = extension == ".glb" || (bytes->size() >= 4 && le32(*bytes, 0) == kGlbMagic);
  GltfModel out;
  std::optional<tinygltf::Model> model = parse_model(path, *bytes, binary, options.limits, out.buffer_files, why);
  if (!model) return std::nullopt;
  std::optional<std::vector<GltfPart>> parts = gltf_parts(*model, options.limits, why);
  if (!parts) return std::nullopt;
  if (!bounds_are_finite(*parts)) {
    why = "the mesh is too large (its bounding sphere does not fit a float)";
    return std::nullopt;
  }
  out.parts = std::move(*parts);
  if (options.materials) {
    MaterialReader reader{*model, fs::path(path).parent_path().empty() ? fs::path(".") : fs::path(path).parent_path()};
    for (size_t i = 0; i < model->materials.size(); ++i) {
      Result<GltfMaterial, std::string> m = reader.material(i);
      if (!m) {
        why = m.error();
        return std::nullopt;
      }
      out.materials.push_back(std::move(*m));
    }
  }
  return out;
}

}  // namespace

bool is_gltf_path(const std::string& path) {
  std::string extension = fs::path(path).extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return char(std::tolower(c)); });
  return extension == ".gltf" || extension == ".glb";
}

std::optional<GltfModel> load_gltf(const std::string& path, Diagnostics& diags, const GltfOptions& options) {
  std::string why;
  try {
    std::optional<GltfModel> model = read_gltf(path, options, why);
    if (model) return model;
  } catch (const std::bad_alloc&) {
    why = "not enough memory to read the glTF file";
  } catch (const std::exception& e) {
    why = e.what();  // what tinygltf or nlohmann may still throw
  }
  diags.add(DiagId::mesh_invalid, SourceSpan{}, fmt::format("{}: {}", path, why));
  return std::nullopt;
}

MeshData merge_gltf_parts(const GltfModel& model, std::optional<int> material) {
  MeshData out;
  for (const GltfPart& part : model.parts) {
    if (material && part.material != *material) continue;
    uint32_t base = uint32_t(out.vertices.size());
    out.vertices.insert(out.vertices.end(), part.mesh.vertices.begin(), part.mesh.vertices.end());
    for (uint32_t i : part.mesh.indices) out.indices.push_back(base + i);
  }
  return out;
}

}  // namespace facet::runtime
