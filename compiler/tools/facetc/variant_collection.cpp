#include "variant_collection.h"

#include <fmt/format.h>

#include <algorithm>

#include "facet/support/text.h"
#include "json_input.h"

namespace facet::tools {
namespace {

using Json = nlohmann::json;

void read_pass(const Json& p, const std::string& where, JsonInputErrors& errors,
               std::map<size_t, CollectedPass>& passes) {
  if (!p.is_object()) return errors.add(where, "expected an object");
  if (!p.contains("pass") || !p["pass"].is_number_unsigned()) {
    return errors.add(where + ".pass", "expected the pass's 0-based index in its SubShader");
  }
  CollectedPass& out = passes[p["pass"].get<size_t>()];
  if (p.contains("name")) {
    if (!p["name"].is_string()) return errors.add(where + ".name", "expected the pass's name");
    out.name = p["name"].get<std::string>();
  }
  if (!p.contains("variants") || !p["variants"].is_array()) {
    return errors.add(where + ".variants", "expected an array of keyword arrays");
  }
  for (size_t i = 0; i < p["variants"].size(); ++i) {
    const Json& set = p["variants"][i];
    std::string at = fmt::format("{}.variants[{}]", where, i);
    if (!set.is_array()) return errors.add(at, "expected an array of keywords ([] for none)");
    std::vector<std::string> keywords;
    for (size_t k = 0; k < set.size(); ++k) {
      if (!set[k].is_string()) return errors.add(fmt::format("{}[{}]", at, k), "expected a keyword string");
      keywords.push_back(set[k].get<std::string>());
    }
    std::sort(keywords.begin(), keywords.end());
    out.variants.insert(std::move(keywords));
  }
}

}  // namespace

Result<VariantCollection> read_variant_collection(const std::string& path, SourceMap& sources, Diagnostics& diags) {
  auto doc = read_json_input(path, sources, diags);
  FACET_TRY(doc);
  JsonInputErrors errors{doc->file, diags};
  const Json& root = doc->json;
  if (!root.is_object() || !root.contains("shaders") || !root["shaders"].is_array()) {
    errors.add("$", "expected an object with a 'shaders' array");
    return failure("bad collection");
  }
  VariantCollection out;
  for (size_t i = 0; i < root["shaders"].size(); ++i) {
    const Json& s = root["shaders"][i];
    std::string where = fmt::format("shaders[{}]", i);
    if (!s.is_object() || !s.contains("shader") || !s["shader"].is_string()) {
      errors.add(where + ".shader", "expected the shader's name, as its Shader line gives it");
      continue;
    }
    if (!s.contains("passes") || !s["passes"].is_array()) {
      errors.add(where + ".passes", "expected an array of passes");
      continue;
    }
    const std::string name = s["shader"].get<std::string>();
    if (s.contains("source")) {
      if (!s["source"].is_string()) {
        errors.add(where + ".source", "expected the path of the shader's .shader file");
        continue;
      }
      out.sources[name] = s["source"].get<std::string>();
    }
    auto& passes = out.shaders[name];
    for (size_t p = 0; p < s["passes"].size(); ++p) {
      read_pass(s["passes"][p], fmt::format("{}.passes[{}]", where, p), errors, passes);
    }
  }
  if (errors.failed) return failure("bad collection");
  return out;
}

std::optional<std::string> collection_problem(const VariantCollection& collection, const ir::Shader& shader) {
  auto found = collection.shaders.find(shader.name);
  if (found == collection.shaders.end()) {
    return fmt::format("shader '{}' is not in the variant collection (--variants): nothing of it would be built",
                       shader.name);
  }
  const std::vector<ir::Pass>& passes = shader.subshaders.empty() ? std::vector<ir::Pass>{} : shader.subshaders[0].passes;
  for (const auto& [index, pass] : found->second) {
    if (index >= passes.size()) {
      return fmt::format("the variant collection lists pass {} of shader '{}', which has {} passes", index,
                         shader.name, passes.size());
    }
    if (!pass.name.empty() && !iequals(pass.name, passes[index].name)) {
      return fmt::format("the variant collection lists pass {} of shader '{}' as '{}', but that pass is '{}'", index,
                         shader.name, pass.name, passes[index].name);
    }
  }
  return std::nullopt;
}

void apply_collection(CompileOptions& options, const VariantCollection& collection, const ir::Shader& shader) {
  auto found = collection.shaders.find(shader.name);
  if (found == collection.shaders.end()) return;
  options.passes.clear();
  for (const auto& [index, pass] : found->second) options.passes.push_back(std::to_string(index));
  std::map<size_t, CollectedPass> passes = found->second;
  auto earlier = options.variant_filter;
  options.variant_filter = [passes, earlier](const VariantInfo& v) {
    if (earlier && !earlier(v)) return false;
    auto pass = passes.find(v.pass_index);
    if (pass == passes.end()) return false;
    std::vector<std::string> keywords = v.keywords;
    std::sort(keywords.begin(), keywords.end());
    return pass->second.variants.count(keywords) > 0;
  };
}

}  // namespace facet::tools
