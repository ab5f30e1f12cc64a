// Material manifests: which materials use which shader with which keywords
// and property values (so Toggle/KeywordEnum keywords count too).
//
//   {"materials": [{"name": "Brick", "shader": "Examples/Keywords",
//                   "keywords": ["_EMISSION"], "properties": {"_Overlay": 1}}]}
#include <fmt/format.h>

#include "json_input.h"
#include "report_mode.h"

namespace facet::tools {
namespace {

using Json = nlohmann::json;

using ManifestErrors = JsonInputErrors;

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

}  // namespace

Result<std::vector<ManifestMaterial>> read_material_manifest(const std::string& path, SourceMap& sources,
                                                             Diagnostics& diags) {
  auto doc = read_json_input(path, sources, diags);
  FACET_TRY(doc);
  FileId file = doc->file;
  ManifestErrors errors{file, diags};
  std::vector<ManifestMaterial> out;
  const Json& root = doc->json;
  if (!root.is_object() || !root.contains("materials") || !root["materials"].is_array()) {
    errors.add("$", "expected an object with a 'materials' array");
    return failure("bad manifest");
  }
  const Json& list = root["materials"];
  for (size_t i = 0; i < list.size(); ++i) read_material(list[i], fmt::format("materials[{}]", i), errors, out);
  if (errors.failed) return failure("bad manifest");
  return out;
}

}  // namespace facet::tools
