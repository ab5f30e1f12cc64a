// Word-level edits of the SPIR-V that glslang produced, before optimisation:
//  * the HLSL loose-uniform block "$Global" is renamed "$Globals";
//  * resources of the material set get bindings that do not depend on the
//    stage: "$Globals" first, then every declared resource in declaration
//    order (unused ones keep their number, so all stages agree);
//  * HLSL stage inputs and outputs get locations from their semantics
//    (POSITION -> 0, TEXCOORDn -> n, ...; table in docs/binding-model.md), so
//    a vertex stage and a fragment stage compiled apart still match.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "glslang_frontend.h"
#include "facet/stage.h"

namespace facet::backend {

struct FixupReport {
  // Semantics whose locations would overlap; when non-empty the stage kept
  // glslang's sequential locations for that storage class.
  std::vector<std::string> overlapping_semantics;
};

FixupReport fix_up_spirv(std::vector<uint32_t>& spirv, const std::vector<DeclaredResource>& declared, Stage stage,
                         bool hlsl);

// The location a semantic gets; nullopt for semantics without a fixed slot
// (those are numbered after the fixed ones in alphabetical order).
// `input` is the storage class as seen by `stage`.
std::optional<uint32_t> semantic_location(std::string_view semantic, Stage stage, bool input);

// Bindings of the material set by resource key ("$Global" and "$Globals"
// name the loose-uniform block).
std::vector<std::pair<std::string, uint32_t>> material_bindings(const std::vector<DeclaredResource>& declared);

}  // namespace facet::backend
