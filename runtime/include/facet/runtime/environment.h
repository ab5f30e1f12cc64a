// A scene's environment as Unity's reflection probes hold it: a cube whose
// mip 0 is the radiance itself and whose mip m is that radiance convolved
// with the GGX lobe of the perceptual roughness Unity's shaders look up at
// mip m (r (1.7 - 0.7 r) * UNITY_SPECCUBE_LOD_STEPS, steps = 6), so that
// Unity_GlossyEnvironment's textureLod reads the prefiltered reflection.
//
//   CubeMips cube = cube_from_radiance([&](glm::vec3 d) { return radiance(d); }, 128);
//   CubeMips probe = prefilter_ggx(cube, {});
//   glm::vec3 rough = sample_cube(probe, dir, 6);  // fully rough reflection
#pragma once

#include <functional>
#include <glm/glm.hpp>
#include <vector>

namespace facet::runtime {

// Faces in Vulkan's order (+X, -X, +Y, -Y, +Z, -Z), each face's rows from
// t = 0 (cube_direction in facet/runtime/sky_sh.h), RGBA floats per texel;
// mips[0] has `size` texels a side, each next mip half as many.
struct CubeMips {
  uint32_t size = 0;
  std::vector<std::vector<float>> mips;
};

// The mips Unity's shaders address: 0 (mirror) .. 6 (perceptual roughness 1).
inline constexpr int kSpecCubeLodSteps = 6;

// The perceptual roughness whose Unity mip level is `mip` (0..steps):
// the root in [0, 1] of r (1.7 - 0.7 r) = mip / steps.
float unity_mip_roughness(float mip, int steps = kSpecCubeLodSteps);

// Mip 0 by evaluating `radiance` at every texel centre of a `size` cube (or
// averaging it over `supersample` x `supersample` points spread over each
// texel), then every smaller mip down to 1 texel by a 2x2 box filter.
CubeMips cube_from_radiance(const std::function<glm::vec3(const glm::vec3&)>& radiance, uint32_t size,
                            uint32_t supersample = 1);

// Adds the 2x2 box-filtered mips below mips[0] (whatever mips there were).
void build_box_mips(CubeMips& cube);

// Bilinear within a face (edge texels clamped), linear between mips; lod in
// mip units, clamped to the chain.
glm::vec3 sample_cube(const CubeMips& cube, const glm::vec3& direction, float lod);

struct PrefilterOptions {
  uint32_t samples = 256;  // GGX samples per texel (Hammersley points)
  int steps = kSpecCubeLodSteps;
};

// The reflection-probe chain of a box-filtered `source` (cube_from_radiance):
// mip 0 copied, mips 1..steps the GGX prefiltering (n = v = r) of the source
// at unity_mip_roughness(m), by importance sampling with each sample read
// from the source mip whose texel matches the sample's solid angle
// (filtered importance sampling, so that few samples leave no fireflies);
// the weights are n.l, normalised, so a uniform environment stays exactly
// uniform. Mips after `steps` are box-filtered. Deterministic.
CubeMips prefilter_ggx(const CubeMips& source, const PrefilterOptions& options);

// The integral a prefiltered texel approximates, by brute force: the n.l
// weighted mean of `radiance` (evaluated exactly, no cube) over the GGX
// lobe of `roughness` around n (n = v), on a regular grid of `height_steps`
// x 64 points in (u, phi) of the GGX sampling. The reference the prefilter
// is measured against (tests, bench/prefilter_bench.cpp).
glm::vec3 ggx_lobe_reference(const std::function<glm::vec3(const glm::vec3&)>& radiance, const glm::vec3& n,
                             float roughness, uint32_t height_steps);

// An equirectangular (latitude-longitude) image as Unity's Skybox/Panoramic
// reads it: u = 0.5 - atan2(z, x) / 2pi, row 0 looking up (+Y), linear RGB.
struct Equirect {
  uint32_t width = 0, height = 0;
  int channels = 0;            // floats per pixel
  std::vector<float> pixels;   // row 0 at the top
};

// Bilinear lookup, wrapping in longitude, clamped at the poles.
glm::vec3 sample_equirect(const Equirect& image, const glm::vec3& direction);

}  // namespace facet::runtime
