// Material manifests: which materials use which shader with which keywords
// and property values (so Toggle/KeywordEnum keywords count too).
//
//   {"materials": [{"name": "Brick", "shader": "Examples/Keywords",
//                   "keywords": ["_EMISSION"], "properties": {"_Overlay": 1}}]}
#include <fmt/format.h>

#include "report_mode.h"

namespace facet::tools {
namespace {

using Json = nlohmann::json;

// Manifest problems: the JSON path says where, since values carry no position.
struct ManifestErrors {
  FileId file;
  Diagnostics& diags;
  bool failed = false;
  void add(const std::string& where, const std::string& what) {
    diags.add(DiagId::materials_bad_manifest, SourceSpan{file, 0, 0}, fmt::format("{}: {}", where, what));
    failed = true;
  }
};

void read_material(const Json& m, const std::string& where, ManifestErrors& errors,
                   std::vector<ManifestMaterial>& out) {
  if (!m.is_object()) return errors.add(where, "expected an object");
  ManifestMaterial mat;
  for (auto it = m.begin(); it != m.end(); ++it) {
    const std::string& key = it.key();
    const Json& v = it.value();
    std::string at = where + "." + key;
    if (key == "name" || key == "shader") {
      if (!v.is_string()) return errors.add(at, "expected a string");
      (key == "name" ? mat.name : mat.shader) = v.get<std::string>();
    } else if (key == "keywords") {
      if (!v.is_array()) return errors.add(at, "expected an array of keyword strings");
      for (size_t i = 0; i < v.size(); ++i) {
        if (!v[i].is_string()) return errors.add(fmt::format("{}[{}]", at, i), "expected a string");
        mat.keywords.push_back(v[i].get<std::string>());
      }
    } else if (key == "properties") {
      if (!v.is_object()) return errors.add(at, "expected an object of property values");
      for (auto p = v.begin(); p != v.end(); ++p) {
        if (!p.value().is_number()) return errors.add(at + "." + p.key(), "expected a number");
        mat.properties.push_back({p.key(), p.value().get<float>()});
      }
    } else {
      return errors.add(at, "unknown key; a material has 'name', 'shader', 'keywords' and 'properties'");
    }
  }
  if (mat.shader.empty()) return errors.add(where, "a material needs 'shader', the name in Shader \"...\"");
  out.push_back(std::move(mat));
}

// nlohmann's parser recurses per nesting level; refuse hostile depths first.
std::optional<size_t> excessive_nesting(const std::string& text, int limit = 64) {
  int depth = 0;
  bool in_string = false;
  for (size_t i = 0; i < text.size(); ++i) {
    char c = text[i];
    if (in_string) {
      if (c == '\\') ++i;
      else if (c == '"') in_string = false;
    } else if (c == '"') {
      in_string = true;
    } else if (c == '[' || c == '{') {
      if (++depth > limit) return i;
    } else if (c == ']' || c == '}') {
      --depth;
    }
  }
  return std::nullopt;
}

}  // namespace

Result<std::vector<ManifestMaterial>> read_material_manifest(const std::string& path, SourceMap& sources,
                                                             Diagnostics& diags) {
  auto text = read_file(path, kMaxShaderBytes, diags);
  FACET_TRY(text);
  FileId file = sources.add_file(path, *text);
  if (auto at = excessive_nesting(*text)) {
    diags.add(DiagId::materials_bad_manifest, SourceSpan{file, uint32_t(*at), uint32_t(*at) + 1},
              "JSON nests more than 64 deep");
    return failure("bad manifest");
  }
  Json doc;
  try {
    doc = Json::parse(*text);
  } catch (const Json::parse_error& e) {
    uint32_t at = e.byte > 0 ? uint32_t(std::min<size_t>(e.byte - 1, text->size())) : 0;
    std::string what = e.what();
    if (auto colon = what.rfind(": "); colon != std::string::npos) what = what.substr(colon + 2);
    diags.add(DiagId::materials_bad_manifest, SourceSpan{file, at, at + 1}, "invalid JSON: " + what);
    return failure("bad manifest");
  }
  ManifestErrors errors{file, diags};
  std::vector<ManifestMaterial> out;
  if (!doc.is_object() || !doc.contains("materials") || !doc["materials"].is_array()) {
    errors.add("$", "expected an object with a 'materials' array");
    return failure("bad manifest");
  }
  const Json& list = doc["materials"];
  for (size_t i = 0; i < list.size(); ++i) read_material(list[i], fmt::format("materials[{}]", i), errors, out);
  if (errors.failed) return failure("bad manifest");
  return out;
}

}  // namespace facet::tools
