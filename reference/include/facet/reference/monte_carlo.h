// The Monte Carlo reference renderer: the accuracy study's test scenes
// (a grid of spheres, perceptual roughness by column and metallic by row)
// rendered on the CPU in double precision by integrating, per pixel, the
// light a BRDF reflects towards the camera. No GPU, no approximation of the
// integral: directions are importance-sampled from a mixture of the cosine
// lobe, GGX visible normals at the sphere's roughness and (under the sky) the
// sun's lobe, weighted by the mixture's density (the balance heuristic), so
// the estimate is unbiased for any BRDF; each pixel carries its standard
// error. Samples come in groups that hold every technique in the mixture's
// proportions (stratified by technique); the error is computed over groups. Several BRDFs are integrated from the same samples, so that the
// difference of two (an approximation against its exact form) has a small
// error of its own. docs/accuracy.md describes the scenes and the protocol.
#pragma once

#include <glm/glm.hpp>

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace facet::reference::monte_carlo {

enum class Lighting {
  directional,  // one directional light, irradiance kPi at normal incidence
  uniform,      // a uniform environment of radiance 1 (the white furnace)
  sky,          // an HDR sky: a gradient, a darker ground and a sharp sun lobe
};

// The sky's radiance: zenith to horizon above (y up), a constant ground
// below, plus the sun, sun_radiance * exp(sun_sharpness * (cos - 1)) around
// sun_direction (a von Mises-Fisher lobe; the study's sun falls to half its
// radiance 1.5 degrees from its centre).
struct Sky {
  double zenith = 0.3, horizon = 0.8, ground = 0.15;
  glm::dvec3 sun_direction = glm::normalize(glm::dvec3(0.45, 0.55, 0.7));
  double sun_sharpness = 2000;
  double sun_radiance = 1500;
};

// The camera looks down -z at the grid (orthographic, one sphere per cell,
// y up); the background is not part of the image.
struct Scene {
  std::string name;
  Lighting lighting = Lighting::directional;
  glm::dvec3 light_direction = glm::normalize(glm::dvec3(-0.4, 0.6, 0.7));  // towards the light
  Sky sky;
  std::vector<double> roughness{0.1, 0.3, 0.5, 0.7, 0.9};  // perceptual, one per column
  std::vector<double> metallic{0.0, 1.0};                  // one per row
  int sphere_pixels = 20;                                  // a cell's width and height
};

// The study's three scenes: "directional", "uniform" and "sky".
std::vector<Scene> study_scenes();

struct Material {
  double roughness = 0.5;  // perceptual; alpha = roughness^2
  double metallic = 0;
};

// A pixel a sphere covers, in world space (n the sphere's normal, v towards
// the camera, +z), with the sphere's material.
struct ShadingPoint {
  int x = 0, y = 0;
  glm::dvec3 n{0, 0, 1}, v{0, 0, 1};
  Material material;
};

int image_width(const Scene& scene);
int image_height(const Scene& scene);
// The covered pixels, row by row from the top.
std::vector<ShadingPoint> shading_points(const Scene& scene);

// The light arriving from world direction `w` (environment lightings only).
double environment_radiance(const Scene& scene, const glm::dvec3& w);

// A BRDF without the cosine, in the local frame (n = +z), for unit v and l.
using Brdf = std::function<double(const glm::dvec3& v, const glm::dvec3& l)>;
// A model: the BRDF a shading point has (its material, and its view where a
// model depends on it beyond v, as the energy compensation does).
using Model = std::function<Brdf(const ShadingPoint& point)>;

struct Estimate {
  double value = 0;
  double std_error = 0;  // of the mean; 0 where nothing is sampled (directional)
};

struct RenderOptions {
  uint32_t samples = 256;  // per pixel, per environment scene; rounded up to whole groups
  uint64_t seed = 1;
  unsigned threads = 0;  // 0: the hardware's; the result does not depend on it
};

// A difference of two models' estimates (models[first] - models[second]),
// taken sample by sample, so that its standard error is that of the difference.
struct Contrast {
  size_t first = 0, second = 0;
};

struct Rendering {
  std::vector<ShadingPoint> points;
  std::vector<std::vector<Estimate>> models;     // [model][point]
  std::vector<std::vector<Estimate>> contrasts;  // [contrast][point]
};

// Every model at every shading point, all from the same directions. Under
// the directional light the value is f(v, l) n.l times the irradiance, exact.
Rendering render(const Scene& scene, const std::vector<Model>& models, const std::vector<Contrast>& contrasts,
                 const RenderOptions& options);

// Sampling densities of the mixture (per solid angle, local frame), exposed
// for the tests: the weights of the cosine, GGX-visible-normal and sun
// techniques for a scene's lighting.
struct MixtureWeights {
  double cosine = 0, visible_normals = 0, sun = 0;
};
MixtureWeights mixture_weights(Lighting lighting);

}  // namespace facet::reference::monte_carlo
