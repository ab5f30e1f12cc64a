// Reflection of one compiled stage with SPIRV-Cross: interface variables with
// their locations and HLSL semantics, uniform blocks with full member layout,
// textures and samplers, push constants, specialization constants, and which
// material property feeds which uniform (property_bindings).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "facet/diagnostics.h"
#include "facet/ir.h"
#include "facet/reflection.h"
#include "facet/result.h"

namespace facet::backend {

struct ReflectOptions {
  Stage stage = Stage::vertex;
  std::string entry_point;
  // HLSL and GLSL name matrices the other way round; this decides how
  // "float3x4" and row_major are derived from the SPIR-V (docs/binding-model.md).
  bool hlsl = true;
};

// Reads `spirv` (before the HLSL semantic decorations are stripped, so that
// StageVariable::semantic is filled). SPIRV-Cross exceptions become a
// backend_reflection_failed diagnostic.
Result<StageReflection> reflect_stage(const std::vector<uint32_t>& spirv, const ReflectOptions& options,
                                      Diagnostics& diags);

// Fills reflection.property_bindings from the shader's Properties: a property
// feeds the top-level uniform member of the same name ("value"), a texture
// feeds the resource of its name ("texture"), the resource "sampler<Name>"
// ("sampler"), and the members <Name>_ST ("scale_offset"), <Name>_TexelSize
// ("texel_size") and <Name>_HDR ("hdr_decode").
void bind_properties(const std::vector<ir::Property>& properties, StageReflection& reflection);

}  // namespace facet::backend
