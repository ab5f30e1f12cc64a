// Reflection probes (docs/rendering.md, "Reflection probes"): each renders
// the scene from its position into a cube once, when the scene loads, and is
// GGX-prefiltered like the environment; each object reflects the one or two
// probes whose boxes hold its centre, as Unity's "Blend Probes" mode picks
// them, through unity_SpecCube0/1 and their box and blend values.
#pragma once

#include <glm/glm.hpp>

#include <vector>

#include "facet/result.h"
#include "facet/runtime/environment.h"
#include "facet/runtime/renderer.h"
#include "facet/runtime/scene.h"
#include "facet/runtime/uniforms.h"
#include "render/failure.h"

namespace facet::runtime {

// The prefiltered cube of every probe of the scene, in order: the scene
// (without its probes, image effects and tone mapping) rendered through six
// 90-degree faces at the probe (render_scene, with `options`' shaders),
// times the probe's intensity. Errors name "reflection_probes[i]".
Result<std::vector<CubeMips>, Diagnostics> render_probes(Context& context, const Scene& scene,
                                                         const RenderOptions& options);

// The probes an object at `centre` reflects: probe 0 and probe 1 (-1: the
// environment) and probe 0's weight in their blend (unity_SpecCube0_BoxMin.w).
// The probes whose box holds the centre, most important first, then the
// smallest; a probe's weight falls from 1 to 0 over its blend distance
// inside its box; the second probe (or the environment) takes the rest.
struct ProbeChoice {
  int probe0 = -1, probe1 = -1;
  float blend = 1;
};
ProbeChoice choose_probes(const Scene& scene, const glm::vec3& centre);

// unity_SpecCube0/1_BoxMin, _BoxMax, _ProbePosition and _HDR of a choice.
void add_probe_values(UniformValues& values, const Scene& scene, const ProbeChoice& choice);

}  // namespace facet::runtime
