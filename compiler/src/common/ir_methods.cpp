// The few member functions of the plain IR types (facet/ir.h), beside the
// types in the common stage so that a reader of IR (the runtime) needs no sema.
#include "facet/ir.h"
#include "facet/support/text.h"

namespace facet::ir {

std::string Pass::tag(std::string_view key) const {
  // The last pair wins, as a later Tags entry overrides an earlier one.
  for (auto it = tags.rbegin(); it != tags.rend(); ++it) {
    if (iequals(it->key, key)) return it->value;
  }
  return {};
}

const Property* Shader::find_property(std::string_view name) const {
  // Property names are HLSL identifiers: case-sensitive.
  for (const Property& p : properties) {
    if (p.name == name) return &p;
  }
  return nullptr;
}

}  // namespace facet::ir
