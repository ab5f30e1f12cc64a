// What a scene's environment gives every draw: the reflection cube that
// unity_SpecCube0 samples and the ambient SH (unity_SHAr...).
#pragma once

#include <string>

#include "facet/result.h"
#include "facet/runtime/environment.h"
#include "facet/runtime/scene.h"
#include "facet/runtime/sky_sh.h"

namespace facet::runtime {

struct EnvironmentLighting {
  CubeMips cube;    // GGX-prefiltered mips (environment.h), or one texel of the flat ambient
  UnitySh ambient;  // the environment's SH unless the scene gives `ambient`
};

// From scene.environment (an HDR image or a uniform radiance), else the
// ambient's procedural sky, else the flat ambient colour. Errors (an
// unreadable image) name "<scene>: environment.file".
Result<EnvironmentLighting, std::string> environment_lighting(const Scene& scene);

}  // namespace facet::runtime
