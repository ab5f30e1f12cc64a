// The HLSL Unity would generate around a surface shader, per pass.
#pragma once

#include <functional>
#include <string>

#include "directive.h"
#include "shape.h"

namespace facet::surface {

enum class GeneratedPass : uint8_t { forward_base, forward_add, deferred, shadow_caster, fallback_shadow_caster };

struct GeneratedCode {
  std::string prologue;  // before the user's code: pass define, includes, INTERNAL_DATA
  std::string epilogue;  // after it: v2f_surf, vert_surf, frag_surf
};

// `declared(name)` tells whether the user's code declares `name` already
// (a <Tex>_ST it wrote itself is not declared again).
GeneratedCode generate(GeneratedPass pass, const Directive& directive, const Shape& shape,
                       const std::vector<std::string>& output_fields,
                       const std::function<bool(const std::string&)>& declared);

// The prologue the code is analysed with: every Unity include and the
// INTERNAL_DATA members, under SHADER_TARGET_SURFACE_ANALYSIS.
std::string analysis_prologue();

}  // namespace facet::surface
