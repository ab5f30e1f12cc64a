#include "stability/models.h"

#include <stdexcept>

namespace facet::stability {

const std::vector<Model>& models() {
  static const std::vector<Model> list = [] {
    std::vector<Model> out;
    for (const Model& m : reference::lighting_models())
      if (!m.hlsl.empty()) out.push_back(m);
    return out;
  }();
  return list;
}

const Model& model(const std::string& name) {
  for (const Model& m : models())
    if (m.name == name) return m;
  throw std::out_of_range("no stability model named " + name);
}

}  // namespace facet::stability
