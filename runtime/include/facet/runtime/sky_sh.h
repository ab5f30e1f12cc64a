// The procedural sky of a scene's `ambient` (docs/scene-format.md) and its
// L2 spherical harmonics in Unity's packing, so that ShadeSH9 (FacetSHEval in
// stdlib/FacetCore.hlsl) returns the sky's irradiance divided by pi, which is
// the ambient colour itself for a flat sky.
//
//   SkyRadiance sky = linear_sky(scene_sky);
//   UnitySh packed = pack_unity_sh(project_sh([&](glm::vec3 d) { return sky_radiance(sky, d); }));
//   glm::vec3 ambient_up = eval_unity_sh(packed, {0, 1, 0});
#pragma once

#include <array>
#include <functional>
#include <glm/glm.hpp>
#include <vector>

#include "facet/runtime/scene.h"

namespace facet::runtime {

// Linear radiance colours of the gradient, intensity applied.
struct SkyRadiance {
  glm::vec3 zenith{0}, horizon{0}, ground{0};
};

SkyRadiance linear_sky(const SceneSky& sky);

// Radiance towards unit direction d (world space, Y up): horizon -> zenith
// linearly in d.y above the horizon, horizon -> ground linearly in -d.y below.
glm::vec3 sky_radiance(const SkyRadiance& sky, const glm::vec3& d);

// The sky's sun, resolved against its light: a disc of uniform radiance
// around `to_sun`, cos_radius the cosine of its angular radius.
struct SkySun {
  glm::vec3 to_sun{0, 1, 0};
  glm::vec3 radiance{0};
  float cos_radius = 1;
};

// The sun's radiance towards unit direction d: `radiance` inside the disc,
// 0 outside, linear across the outer tenth of its radius (so that a cube's
// supersampling sees a disc, not a step).
glm::vec3 sun_radiance(const SkySun& sun, const glm::vec3& d);

// Projection coefficients of a radiance function on the real SH basis of
// bands 0..2, in the order (l, m) = (0,0), (1,-1), (1,0), (1,1), (2,-2),
// (2,-1), (2,0), (2,1), (2,2), where Y(1,-1) ~ y, Y(1,0) ~ z, Y(1,1) ~ x.
using ShCoefficients = std::array<glm::vec3, 9>;

// The real SH basis functions at unit direction d, in ShCoefficients order.
std::array<float, 9> sh_basis(const glm::vec3& d);

// Numerical projection: Gauss-Legendre in y on each hemisphere separately
// (a sky has a kink at the horizon) times `azimuth_steps` even steps in the
// azimuth. Deterministic; exact for radiance that is a polynomial of degree
// <= 2 * `height_nodes` - 3 in y on each hemisphere (a gradient is degree 1).
ShCoefficients project_sh(const std::function<glm::vec3(const glm::vec3&)>& radiance, int height_nodes = 16,
                          int azimuth_steps = 32);

// unity_SHAr/g/b, unity_SHBr/g/b, unity_SHC for irradiance / pi of the
// radiance whose projection is `radiance`: bands scaled by the clamped cosine's
// convolution factors (pi, 2 pi / 3, pi / 4) over pi, and the basis constants
// folded in, so that FacetSHEval is
//   dot(A, (n, 1)) + dot(B, n.xyzz * n.yzzx) + C * (n.x^2 - n.y^2).
struct UnitySh {
  std::array<glm::vec4, 3> a{};  // r, g, b
  std::array<glm::vec4, 3> b{};
  glm::vec4 c{0};
};

UnitySh pack_unity_sh(const ShCoefficients& radiance);
// The packing of a flat ambient colour: L0 only, (0, 0, 0, colour).
UnitySh flat_unity_sh(const glm::vec3& ambient);

// The sum of two packings: the SH of both light distributions together.
UnitySh operator+(const UnitySh& a, const UnitySh& b);

// The projection of a light of colour `color` arriving from unit direction
// `to_light` (a directional light, or a point light seen from far away):
// a delta scaled so that its packing gives color * max(0, n.to_light) up to
// the L2 truncation (1.0625 * color facing the light, 0.0625 * color at
// its back), as Unity's SH lights do.
ShCoefficients light_sh(const glm::vec3& to_light, const glm::vec3& color);

// The sun's projection: a disc so small next to band 2 that it is the
// delta of its power, radiance x solid angle 2 pi (1 - cos_radius), at
// to_sun (numerical projection would miss it between nodes).
ShCoefficients sun_sh(const SkySun& sun);

// The CPU twin of FacetSHEval (clamped at 0 as the shader does).
glm::vec3 eval_unity_sh(const UnitySh& sh, const glm::vec3& n);

// The world direction of texel centre (s, t) in 0..1 of cube face `face`.
glm::vec3 cube_direction(int face, float s, float t);

}  // namespace facet::runtime
