// The stdlib shaders the renderer draws by itself (the skies, the
// screen-space shadow pass, the deferred light pass), built into packages
// by facetc when facet is built and carried in facet_render, so that a
// renderer without the development layer draws them too.
#pragma once

#include <cstdint>
#include <span>
#include <string_view>

namespace facet::runtime {

// The package built from stdlib/Shaders/<file> ("ProceduralSky.shader"), or
// empty for a file that is not built in.
std::span<const uint8_t> built_in_package(std::string_view file);

}  // namespace facet::runtime
