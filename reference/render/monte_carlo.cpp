#include "facet/reference/monte_carlo.h"

#include <algorithm>
#include <cmath>
#include <random>
#include <thread>

#include "facet/reference/hlsl_math.h"
#include "facet/reference/sampling.h"

namespace facet::reference::monte_carlo {
namespace {

using glm::dvec3;

// An orthonormal frame around n (Duff et al. 2017, "Building an Orthonormal
// Basis, Revisited"): continuous everywhere but at n.z = -1.
struct Frame {
  dvec3 t, b, n;
  dvec3 to_local(const dvec3& w) const { return {glm::dot(w, t), glm::dot(w, b), glm::dot(w, n)}; }
  dvec3 to_world(const dvec3& w) const { return w.x * t + w.y * b + w.z * n; }
};
Frame frame_around(const dvec3& n) {
  double sign = std::copysign(1.0, n.z);
  double a = -1.0 / (sign + n.z), b = n.x * n.y * a;
  return {dvec3(1.0 + sign * n.x * n.x * a, sign * b, -sign * n.x), dvec3(b, sign + n.y * n.y * a, -n.y), n};
}

double sky_radiance(const Sky& sky, const dvec3& w) {
  double base = w.y >= 0 ? lerp(sky.horizon, sky.zenith, w.y) : sky.ground;
  return base + sky.sun_radiance * std::exp(sky.sun_sharpness * (glm::dot(w, sky.sun_direction) - 1.0));
}

// The sun's lobe as a density: a von Mises-Fisher distribution around s.
double sun_pdf(const Sky& sky, const dvec3& w, const dvec3& s) {
  double k = sky.sun_sharpness;
  return k / (2.0 * kPi * (1.0 - std::exp(-2.0 * k))) * std::exp(k * (glm::dot(w, s) - 1.0));
}
dvec3 sample_sun(const Sky& sky, const dvec3& s, double u1, double u2) {
  double k = sky.sun_sharpness;
  double cos_theta = 1.0 + std::log(u1 + (1.0 - u1) * std::exp(-2.0 * k)) / k;
  return frame_around(s).to_world(spherical_direction(std::clamp(cos_theta, -1.0, 1.0), 2.0 * kPi * u2));
}

// The density of a light direction l reached through a visible normal.
double visible_normal_pdf(const dvec3& v, const dvec3& l, double alpha) {
  dvec3 h = v + l;
  if (glm::dot(h, h) <= 0) return 0.0;
  h = glm::normalize(h);
  double VoH = glm::dot(v, h);
  return VoH > 0 ? pdf_ggx_vndf(v, h, alpha) / (4.0 * VoH) : 0.0;
}

enum class Technique { cosine, visible_normals, sun };

// The techniques of one group of samples, in the proportions of the
// mixture's weights (mixture_weights): every group holds each technique its
// fixed number of times (stratified by technique), so that the choice of
// technique adds no variance; groups are independent and identically
// distributed, and the standard error is computed over them.
std::vector<Technique> group_of(Lighting lighting) {
  using enum Technique;
  if (lighting == Lighting::sky) return {cosine, visible_normals, visible_normals, sun};
  return {cosine, visible_normals};
}

// The mixture's techniques at one shading point, in its local frame.
struct Sampler {
  MixtureWeights weights;
  dvec3 v;
  double alpha;
  const Sky* sky;
  dvec3 sun;  // the sun's direction, local

  dvec3 sample(Technique t, double u1, double u2) const {
    switch (t) {
      case Technique::cosine: return sample_cosine(u1, u2);
      case Technique::visible_normals: {
        dvec3 h = sample_ggx_vndf(v, u1, u2, alpha);
        return 2.0 * glm::dot(v, h) * h - v;
      }
      case Technique::sun: return sample_sun(*sky, sun, u1, u2);
    }
    return dvec3(0, 0, 1);
  }
  double pdf(const dvec3& l) const {
    double p = weights.cosine * pdf_cosine(l) + weights.visible_normals * visible_normal_pdf(v, l, alpha);
    if (weights.sun > 0) p += weights.sun * sun_pdf(*sky, l, sun);
    return p;
  }
};

// Mean and standard error from running sums.
Estimate estimate_of(double sum, double sum_squares, uint32_t n) {
  double mean = sum / n;
  double variance = n > 1 ? std::max(0.0, (sum_squares - n * mean * mean) / (n - 1)) : 0.0;
  return {mean, std::sqrt(variance / n)};
}

// Each pixel has its own generator, seeded from (seed, pixel), so the image
// does not depend on the thread count or the order of pixels.
std::mt19937_64 pixel_generator(uint64_t seed, size_t pixel) {
  std::seed_seq seq{uint32_t(seed), uint32_t(seed >> 32), uint32_t(pixel), uint32_t(uint64_t(pixel) >> 32)};
  return std::mt19937_64(seq);
}

void render_point(const Scene& scene, const std::vector<Model>& models, const std::vector<Contrast>& contrasts,
                  const RenderOptions& options, size_t index, Rendering& out) {
  const ShadingPoint& point = out.points[index];
  const Frame frame = frame_around(point.n);
  const dvec3 v = frame.to_local(point.v);
  std::vector<Brdf> brdfs;
  brdfs.reserve(models.size());
  for (const Model& m : models) brdfs.push_back(m(point));

  if (scene.lighting == Lighting::directional) {
    const dvec3 l = frame.to_local(scene.light_direction);
    std::vector<double> values(brdfs.size(), 0.0);
    if (l.z > 0) {
      for (size_t m = 0; m < brdfs.size(); ++m) values[m] = brdfs[m](v, l) * l.z * kPi;
    }
    for (size_t m = 0; m < brdfs.size(); ++m) out.models[m][index] = {values[m], 0.0};
    for (size_t c = 0; c < contrasts.size(); ++c) {
      out.contrasts[c][index] = {values[contrasts[c].first] - values[contrasts[c].second], 0.0};
    }
    return;
  }

  const Sampler sampler{.weights = mixture_weights(scene.lighting),
                        .v = v,
                        .alpha = std::max(point.material.roughness * point.material.roughness, 1e-4),
                        .sky = &scene.sky,
                        .sun = frame.to_local(scene.sky.sun_direction)};
  std::mt19937_64 rng = pixel_generator(options.seed, size_t(point.y) * image_width(scene) + point.x);
  auto u01 = [&] { return double(rng() >> 11) * 0x1.0p-53; };
  const std::vector<Technique> group = group_of(scene.lighting);
  const uint32_t groups = std::max<uint32_t>(1, (options.samples + uint32_t(group.size()) - 1) / uint32_t(group.size()));
  std::vector<double> sum(brdfs.size(), 0.0), sum_sq(brdfs.size(), 0.0);
  std::vector<double> csum(contrasts.size(), 0.0), csum_sq(contrasts.size(), 0.0);
  std::vector<double> group_values(brdfs.size());
  for (uint32_t g = 0; g < groups; ++g) {
    std::fill(group_values.begin(), group_values.end(), 0.0);
    for (Technique t : group) {
      double u1 = u01(), u2 = u01();
      dvec3 l = sampler.sample(t, u1, u2);
      double pdf = l.z > 0 ? sampler.pdf(l) : 0.0;
      if (pdf <= 0) continue;
      double weight = environment_radiance(scene, frame.to_world(l)) * l.z / pdf / double(group.size());
      for (size_t m = 0; m < brdfs.size(); ++m) group_values[m] += brdfs[m](v, l) * weight;
    }
    for (size_t m = 0; m < brdfs.size(); ++m) {
      sum[m] += group_values[m];
      sum_sq[m] += group_values[m] * group_values[m];
    }
    for (size_t c = 0; c < contrasts.size(); ++c) {
      double d = group_values[contrasts[c].first] - group_values[contrasts[c].second];
      csum[c] += d;
      csum_sq[c] += d * d;
    }
  }
  for (size_t m = 0; m < brdfs.size(); ++m) out.models[m][index] = estimate_of(sum[m], sum_sq[m], groups);
  for (size_t c = 0; c < contrasts.size(); ++c) {
    out.contrasts[c][index] = estimate_of(csum[c], csum_sq[c], groups);
  }
}

}  // namespace

std::vector<Scene> study_scenes() {
  Scene directional{.name = "directional", .lighting = Lighting::directional};
  Scene uniform{.name = "uniform", .lighting = Lighting::uniform};
  Scene sky{.name = "sky", .lighting = Lighting::sky};
  return {directional, uniform, sky};
}

int image_width(const Scene& scene) { return int(scene.roughness.size()) * scene.sphere_pixels; }
int image_height(const Scene& scene) { return int(scene.metallic.size()) * scene.sphere_pixels; }

std::vector<ShadingPoint> shading_points(const Scene& scene) {
  std::vector<ShadingPoint> out;
  const int cell = scene.sphere_pixels;
  for (int y = 0; y < image_height(scene); ++y) {
    for (int x = 0; x < image_width(scene); ++x) {
      // The pixel's centre in the cell, in units of the sphere's radius (y up).
      double px = ((x % cell) + 0.5) / cell * 2.0 - 1.0;
      double py = 1.0 - ((y % cell) + 0.5) / cell * 2.0;
      double r2 = px * px + py * py;
      if (r2 >= 1.0) continue;
      ShadingPoint p{.x = x, .y = y, .n = dvec3(px, py, std::sqrt(1.0 - r2)), .v = dvec3(0, 0, 1)};
      p.material = {.roughness = scene.roughness[size_t(x / cell)], .metallic = scene.metallic[size_t(y / cell)]};
      out.push_back(p);
    }
  }
  return out;
}

double environment_radiance(const Scene& scene, const dvec3& w) {
  switch (scene.lighting) {
    case Lighting::uniform: return 1.0;
    case Lighting::sky: return sky_radiance(scene.sky, w);
    case Lighting::directional: return 0.0;
  }
  return 0.0;
}

MixtureWeights mixture_weights(Lighting lighting) {
  switch (lighting) {
    case Lighting::uniform: return {.cosine = 0.5, .visible_normals = 0.5, .sun = 0};
    case Lighting::sky: return {.cosine = 0.25, .visible_normals = 0.5, .sun = 0.25};
    case Lighting::directional: return {};
  }
  return {};
}

Rendering render(const Scene& scene, const std::vector<Model>& models, const std::vector<Contrast>& contrasts,
                 const RenderOptions& options) {
  Rendering out;
  out.points = shading_points(scene);
  out.models.assign(models.size(), std::vector<Estimate>(out.points.size()));
  out.contrasts.assign(contrasts.size(), std::vector<Estimate>(out.points.size()));
  unsigned threads = options.threads ? options.threads : std::max(1u, std::thread::hardware_concurrency());
  threads = std::min<unsigned>(threads, unsigned(std::max<size_t>(1, out.points.size())));
  // Points are dealt round-robin; each writes only its own slots.
  auto work = [&](unsigned first) {
    for (size_t i = first; i < out.points.size(); i += threads) render_point(scene, models, contrasts, options, i, out);
  };
  std::vector<std::thread> pool;
  for (unsigned t = 1; t < threads; ++t) pool.emplace_back(work, t);
  work(0);
  for (std::thread& t : pool) t.join();
  return out;
}

}  // namespace facet::reference::monte_carlo
