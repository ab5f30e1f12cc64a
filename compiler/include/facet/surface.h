// Surface-shader lowering: every `#pragma surface surf Model [options]`
// program of a SubShader becomes the passes Unity generates for it
// (ForwardBase, ForwardAdd, ShadowCaster), each a normal vertex/fragment pass
// in HLSL afterwards (docs/surface-shaders.md).
#pragma once

#include <functional>

#include "facet/diagnostics.h"
#include "facet/ir.h"
#include "facet/program_analysis.h"
#include "facet/result.h"
#include "facet/source.h"

namespace facet::surface {

// Reads what a program's code declares, as its fragment stage would be
// parsed, reporting parse errors at .shader positions. The driver passes the
// backend's (backend::Backend::analyze_program); this stage parses no HLSL itself.
using ProgramAnalyzer =
    std::function<Result<ProgramAnalysis>(const ir::Shader& shader, const ir::Program& program, SourceMap& sources,
                                          Diagnostics& diags)>;

// Replaces each SubShader's surface programs with their generated passes,
// placed where each program block is written among the SubShader's passes. Which Input fields `surf`
// reads, which outputs it writes and the lighting function's form are read
// from `analyze`'s reading of the user's code (facet/program_analysis.h). The
// generated code is added to `sources` as a file of its own, named
// "<shader path> [surface PASS]", so that messages in it have positions and
// `facetc -E` shows it; messages in the user's code keep their .shader lines.
Result<void> lower_surface_shaders(ir::Shader& shader, const ProgramAnalyzer& analyze, SourceMap& sources,
                                   Diagnostics& diags);

}  // namespace facet::surface
