// facetc --scene scene.json: the packages a scene needs and nothing more, as
// Unity builds a player from a ShaderVariantCollection. Which passes and
// keyword sets a scene draws follows from the renderer's rules (lights,
// shadows, fog, the rendering path), so facetc asks the renderer: it runs
// `facet render --emit-variants` (the `facet` program beside facetc, or
// $FACET_RENDER_TOOL) on the scene, then builds each .shader the scene names
// with that collection as --variants. The collection is kept as
// <out-dir>/<scene stem>.variants.json; `facet render --packages <out-dir>
// --strict-variants` then draws the scene from the packages.
#pragma once

#include "args.h"
#include "run.h"

namespace facet::tools {

// Exit code as run_facetc's; 1 when the render fails or the collection names
// no shader of the scene.
int run_scene(const FacetcArgs& args, Console& console);

}  // namespace facet::tools
