// SPIRV-Tools behind plain functions: spirv-opt levels, stripping of the
// HLSL reflection decorations, and the target environments. validate() and
// disassemble() themselves are public (facet/backend.h).
#pragma once

#include <spirv-tools/libspirv.h>

#include <cstdint>
#include <vector>

#include "facet/backend.h"

namespace facet::backend {

spv_target_env spirv_env(TargetEnv target);

// Validates what glslang produced (with the relaxed rules that hold before
// HLSL legalisation), so that a glslang bug becomes a diagnostic rather than
// an optimiser crash. False and a backend_invalid_spirv diagnostic if invalid.
bool check_generated(const std::vector<uint32_t>& spirv, bool hlsl, TargetEnv target, Diagnostics& diags);

// spirv-opt's HLSL legalisation passes (inlining, scalar replacement, ...),
// required before HLSL-derived SPIR-V is valid for Vulkan.
bool legalize_hlsl(std::vector<uint32_t>& spirv, TargetEnv target, Diagnostics& diags);

// -O: performance passes, -Os: size passes, -O0: nothing beyond
// legalisation. False and a diagnostic when spirv-opt fails.
bool optimize(std::vector<uint32_t>& spirv, OptLevel level, TargetEnv target, Diagnostics& diags);

// The largest iteration count of a loop marked for unrolling ([unroll],
// LoopControl Unroll) whose count is a constant, 0 when there is none.
// spirv-opt's unroller (part of HLSL legalisation and -O) copies the body
// that many times, with no limit of its own; the count is read from a copy
// of the module brought into SSA form, as the unroller sees it.
uint64_t longest_unrolled_loop(const std::vector<uint32_t>& spirv, TargetEnv target);

// Removes SPV_GOOGLE_hlsl_functionality1 / user_type decorations, which were
// only there for reflection (drivers need not support them).
bool strip_reflection_info(std::vector<uint32_t>& spirv, TargetEnv target, Diagnostics& diags);

}  // namespace facet::backend
