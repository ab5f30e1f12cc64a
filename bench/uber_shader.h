// A generated Standard-like uber shader for the variant-build benchmark:
// keyword sets like the Standard shader's, each changing real code, written
// in HLSL 5 style (Texture2D + SamplerState) so that glslc compiles it too.
#pragma once

#include <string>

namespace facet::bench {

// About 10 keyword sets, 2,048 variants in one ForwardBase pass.
std::string uber_shader_text();

// A small shader for the parse + enumerate corpus: `index` picks its sets.
std::string corpus_shader_text(int index);

}  // namespace facet::bench
