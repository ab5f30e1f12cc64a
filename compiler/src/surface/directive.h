// `#pragma surface surfFn Model [options]`, parsed and checked.
#pragma once

#include <string>
#include <vector>

#include "facet/diagnostics.h"
#include "facet/ir.h"
#include "facet/result.h"

namespace facet::surface {

enum class AlphaMode : uint8_t { none, fade, premultiply };
enum class DecalMode : uint8_t { none, add, blend };

struct Directive {
  std::string surface_function;
  std::string model;  // "Standard", or a custom name: LightingModel
  std::string vertex_function, final_color_function;
  // tessellate:fn (hull and domain stages) and tessphong:amount (a property
  // name or a number, written into the domain stage as it is).
  std::string tessellate_function, tess_phong;
  AlphaMode alpha = AlphaMode::none;
  std::string alpha_test_property;  // alphatest:_Cutoff
  DecalMode decal = DecalMode::none;
  bool keep_alpha = false, add_shadow = false, full_forward_shadows = false, no_shadow = false;
  bool no_ambient = false, no_fog = false, no_forward_add = false, no_instancing = false;
  bool no_vertex_lights = false;  // novertexlights: ForwardBase without VERTEXLIGHT_ON
  bool exclude_forward = false;
  bool exclude_deferred = false;  // exclude_path:deferred: no Deferred pass
  SourceSpan span;

  bool tessellated() const { return !tessellate_function.empty(); }
  bool physically_based() const { return model == "Standard" || model == "StandardSpecular"; }
};

// Unknown options are warnings, accepted-but-inapplicable ones notes;
// a missing function or model is an error.
Result<Directive> parse_directive(const ir::Pragma& pragma, Diagnostics& diags);

}  // namespace facet::surface
