// The passes a shader takes from other shaders, found as Unity finds them
// when it draws: `UsePass "Other/PASS"`, and the Fallback chain's
// ShadowCaster (every pass, for a shader with no SubShader).
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "facet/diagnostics.h"
#include "facet/ir.h"
#include "facet/result.h"
#include "facet/shader_search.h"
#include "facet/source.h"

namespace facet {

// Loads a .shader as written (parse, sema, surface lowering), its own
// UsePass and Fallback not followed yet.
using LoadWrittenShader = std::function<Result<ir::Shader>(const std::string& path, Diagnostics& diags)>;

// Where a shader's UsePass and Fallback names are looked up: its own folder
// and the -I folders (not their subfolders), then the stdlib's Shaders/ with
// its subfolders.
std::vector<ShaderDir> shader_search_dirs(const std::string& shader_path, const std::vector<std::string>& include_dirs,
                                          const std::string& stdlib_dir);

// Replaces each UsePass naming another shader by a copy of that pass, and
// adds the Fallback's passes; what cannot be found is a warning and stays
// as written. Never fails: a missing pass is Unity's behaviour too.
void link_shader(ir::Shader& shader, const std::vector<ShaderDir>& search, const LoadWrittenShader& load,
                 Diagnostics& diags);

}  // namespace facet
