// The camera's sky background (camera "clear": "sky"): one draw of the
// stdlib's procedural sky shader (stdlib/Shaders/ProceduralSky.shader) on a
// full-screen quad, first in the camera's pass, with the colours of the
// scene's ambient sky; nothing is drawn or compiled for a flat clear colour.
#pragma once

#include <vector>

#include "render/draw_list.h"
#include "render/failure.h"

namespace facet::runtime {

// Appends the background's object to `objects` (its `scene` points at
// `source`, which must outlive the frame) and puts its draw first in `list`.
Result<void, Diagnostics> add_sky_background(const Context& context, const Scene& scene, ShaderLibrary& library,
                                             GpuMesh* quad, const LightValues* none, SceneObject& source,
                                             std::vector<ObjectState>& objects, DrawListResult& list);

}  // namespace facet::runtime
