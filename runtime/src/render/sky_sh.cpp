#include "facet/runtime/sky_sh.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "facet/runtime/material.h"

namespace facet::runtime {
namespace {

constexpr double kPi = std::numbers::pi;

// Basis constants: sqrt(1/4pi), sqrt(3/4pi), sqrt(15/4pi), sqrt(5/16pi), sqrt(15/16pi).
constexpr double kY0 = 0.28209479177387814, kY1 = 0.4886025119029199, kY2 = 1.0925484305920792,
                 kY20 = 0.31539156525252005, kY22 = 0.5462742152960396;

struct Node {
  double x, w;
};

// Gauss-Legendre nodes and weights on [-1, 1] by Newton's iteration on P_n,
// started from the usual cosine estimate of each root.
std::vector<Node> gauss_legendre(int n) {
  std::vector<Node> nodes;
  for (int i = 0; i < n; ++i) {
    double x = std::cos(kPi * (i + 0.75) / (n + 0.5)), dp = 1;
    for (int iter = 0; iter < 100; ++iter) {
      double p0 = 1, p1 = x;
      for (int k = 2; k <= n; ++k) {
        double pk = ((2.0 * k - 1) * x * p1 - (k - 1.0) * p0) / k;
        p0 = p1;
        p1 = pk;
      }
      dp = n * (x * p1 - p0) / (x * x - 1);
      double step = p1 / dp;
      x -= step;
      if (std::abs(step) < 1e-16) break;
    }
    nodes.push_back({x, 2 / ((1 - x * x) * dp * dp)});
  }
  return nodes;
}

std::array<double, 9> basis(const glm::dvec3& d) {
  double x = d.x, y = d.y, z = d.z;
  return {kY0, kY1 * y, kY1 * z, kY1 * x, kY2 * x * y, kY2 * y * z, kY20 * (3 * z * z - 1), kY2 * x * z,
          kY22 * (x * x - y * y)};
}

}  // namespace

SkyRadiance linear_sky(const SceneSky& sky) {
  auto lin = [&](const Vec3& c) {
    return glm::vec3(float(srgb_to_linear(c[0])), float(srgb_to_linear(c[1])), float(srgb_to_linear(c[2]))) *
           sky.intensity;
  };
  return {lin(sky.zenith), lin(sky.horizon), lin(sky.ground)};
}

glm::vec3 sky_radiance(const SkyRadiance& sky, const glm::vec3& d) {
  float y = std::clamp(d.y, -1.0f, 1.0f);
  return y >= 0 ? glm::mix(sky.horizon, sky.zenith, y) : glm::mix(sky.horizon, sky.ground, -y);
}

std::array<float, 9> sh_basis(const glm::vec3& d) {
  std::array<double, 9> b = basis(glm::dvec3(d));
  std::array<float, 9> out;
  for (int i = 0; i < 9; ++i) out[i] = float(b[i]);
  return out;
}

ShCoefficients project_sh(const std::function<glm::vec3(const glm::vec3&)>& radiance, int height_nodes,
                          int azimuth_steps) {
  // dw = dy dphi; each hemisphere's y in [0, 1] (or [-1, 0]) maps to [-1, 1] with Jacobian 1/2.
  std::vector<Node> nodes = gauss_legendre(height_nodes);
  std::array<glm::dvec3, 9> sum{};
  double dphi = 2 * kPi / azimuth_steps;
  for (int hemisphere = 0; hemisphere < 2; ++hemisphere) {
    for (const Node& node : nodes) {
      double y = (hemisphere == 0 ? 1 : -1) * 0.5 * (node.x + 1), r = std::sqrt(std::max(0.0, 1 - y * y));
      for (int k = 0; k < azimuth_steps; ++k) {
        double phi = (k + 0.5) * dphi;
        glm::dvec3 d(r * std::cos(phi), y, r * std::sin(phi));
        glm::dvec3 l = glm::dvec3(radiance(glm::vec3(d)));
        double w = 0.5 * node.w * dphi;
        std::array<double, 9> b = basis(d);
        for (int i = 0; i < 9; ++i) sum[i] += l * (b[i] * w);
      }
    }
  }
  ShCoefficients out;
  for (int i = 0; i < 9; ++i) out[i] = glm::vec3(sum[i]);
  return out;
}

glm::vec3 sun_radiance(const SkySun& sun, const glm::vec3& d) {
  if (sun.cos_radius >= 1) return glm::vec3(0);
  const float radius = std::acos(sun.cos_radius);
  const float angle = std::acos(std::clamp(glm::dot(glm::normalize(d), sun.to_sun), -1.0f, 1.0f));
  const float edge = std::clamp((radius - angle) / (0.1f * radius), 0.0f, 1.0f);
  return sun.radiance * edge;
}

ShCoefficients sun_sh(const SkySun& sun) {
  const double solid_angle = 2 * kPi * (1 - double(sun.cos_radius));
  // light_sh's delta carries pi x colour: colour = radiance x solid angle / pi.
  return light_sh(sun.to_sun, sun.radiance * float(solid_angle / kPi));
}

UnitySh pack_unity_sh(const ShCoefficients& radiance) {
  // Irradiance / pi per band: pi / pi, (2 pi / 3) / pi, (pi / 4) / pi.
  const double band[9] = {1, 2.0 / 3, 2.0 / 3, 2.0 / 3, 0.25, 0.25, 0.25, 0.25, 0.25};
  UnitySh sh;
  for (int ch = 0; ch < 3; ++ch) {
    double c[9];
    for (int i = 0; i < 9; ++i) c[i] = double(radiance[i][ch]) * band[i];
    // Y(2,0)'s constant part (-kY20) joins the L0 term in A.w; its z^2 part is B.z.
    sh.a[ch] = glm::vec4(float(kY1 * c[3]), float(kY1 * c[1]), float(kY1 * c[2]), float(kY0 * c[0] - kY20 * c[6]));
    sh.b[ch] = glm::vec4(float(kY2 * c[4]), float(kY2 * c[5]), float(3 * kY20 * c[6]), float(kY2 * c[7]));
    sh.c[ch] = float(kY22 * c[8]);
  }
  return sh;
}

UnitySh flat_unity_sh(const glm::vec3& ambient) {
  UnitySh sh;
  for (int ch = 0; ch < 3; ++ch) sh.a[ch] = {0, 0, 0, ambient[ch]};
  return sh;
}

UnitySh operator+(const UnitySh& a, const UnitySh& b) {
  UnitySh sum;
  for (int ch = 0; ch < 3; ++ch) {
    sum.a[ch] = a.a[ch] + b.a[ch];
    sum.b[ch] = a.b[ch] + b.b[ch];
  }
  sum.c = a.c + b.c;
  return sum;
}

ShCoefficients light_sh(const glm::vec3& to_light, const glm::vec3& color) {
  // Radiance pi * color * delta(to_light): its irradiance / pi is
  // color * max(0, n.to_light), which pack_unity_sh divides back out.
  std::array<float, 9> y = sh_basis(glm::normalize(to_light));
  ShCoefficients c;
  for (int i = 0; i < 9; ++i) c[i] = std::numbers::pi_v<float> * color * y[i];
  return c;
}

glm::vec3 eval_unity_sh(const UnitySh& sh, const glm::vec3& n) {
  glm::vec4 n1(n, 1);
  glm::vec4 q(n.x * n.y, n.y * n.z, n.z * n.z, n.z * n.x);
  glm::vec3 out;
  for (int ch = 0; ch < 3; ++ch) out[ch] = glm::dot(sh.a[ch], n1) + glm::dot(sh.b[ch], q) + sh.c[ch] * (n.x * n.x - n.y * n.y);
  return glm::max(out, glm::vec3(0));
}

glm::vec3 cube_direction(int face, float s, float t) {
  float u = 2 * s - 1, v = 2 * t - 1;
  switch (face) {
    case 0: return glm::normalize(glm::vec3(1, -v, -u));
    case 1: return glm::normalize(glm::vec3(-1, -v, u));
    case 2: return glm::normalize(glm::vec3(u, 1, v));
    case 3: return glm::normalize(glm::vec3(u, -1, -v));
    case 4: return glm::normalize(glm::vec3(u, -v, 1));
    default: return glm::normalize(glm::vec3(-u, -v, -1));
  }
}

}  // namespace facet::runtime
