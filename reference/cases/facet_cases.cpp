#include "case_helpers.h"

namespace facet::reference {

// The table of facet's own lighting library. Every stdlib/Facet*.hlsl function
// has at least one case; functions with a parameter (roughness, exponent,
// IOR...) have one per setting. Inputs cover each function's documented range
// except where a comment says why a part of it is left out.
std::vector<FunctionCase> facet_model_cases() {
  std::vector<FunctionCase> out;
  cases::add_diffuse_cases(out);
  cases::add_specular_cases(out);
  cases::add_fresnel_cases(out);
  cases::add_lobe_cases(out);
  cases::add_disney_cases(out);
  cases::add_ibl_cases(out);
  cases::add_tonemap_cases(out);
  return out;
}

}  // namespace facet::reference
