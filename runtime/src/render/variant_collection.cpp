// The variant collection of a rendered frame (renderer.h).
#include <nlohmann/json.hpp>

#include <algorithm>
#include <map>
#include <set>

#include "facet/runtime/renderer.h"

namespace facet::runtime {

std::string variant_collection_json(const RenderedFrame& frame, const std::vector<std::string>& scene_shaders) {
  const std::set<std::string> named(scene_shaders.begin(), scene_shaders.end());
  std::map<std::string, std::string> sources;  // by shader name
  struct Pass {
    std::string name;
    std::set<std::vector<std::string>> variants;
  };
  std::map<std::string, std::map<size_t, Pass>> shaders;
  for (const DrawRecord& d : frame.draws) {
    if (!d.drawn) continue;
    Pass& pass = shaders[d.shader][d.pass_index];
    if (named.count(d.shader_path)) sources[d.shader] = d.shader_path;
    pass.name = d.pass_name;
    std::vector<std::string> keywords = d.keywords;
    std::sort(keywords.begin(), keywords.end());
    pass.variants.insert(std::move(keywords));
  }
  nlohmann::ordered_json list = nlohmann::ordered_json::array();
  for (const auto& [name, passes] : shaders) {
    nlohmann::ordered_json shader = {{"shader", name}};
    if (auto source = sources.find(name); source != sources.end()) shader["source"] = source->second;
    shader["passes"] = nlohmann::ordered_json::array();
    for (const auto& [index, pass] : passes) {
      nlohmann::ordered_json entry = {{"pass", index}};
      if (!pass.name.empty()) entry["name"] = pass.name;
      entry["variants"] = pass.variants;
      shader["passes"].push_back(std::move(entry));
    }
    list.push_back(std::move(shader));
  }
  return nlohmann::ordered_json{{"shaders", std::move(list)}}.dump(2) + "\n";
}

}  // namespace facet::runtime
