// The data of the four views: images (lit sphere, MERL slice) and curves
// (polar lobe, directional albedo), all from the model's BrdfFunction.
#include "facet/reference/hlsl_math.h"
#include "facet/runtime/brdf.h"

namespace facet::brdf {
namespace {

using glm::dvec3;
using reference::kPi;
constexpr double kDeg = kPi / 180.0;

Image blank(int w, int h) { return {w, h, std::vector<float>(size_t(w) * size_t(h) * 3, 0.0f)}; }
void set(Image& im, int x, int y, const dvec3& c) {
  size_t i = (size_t(y) * size_t(im.width) + size_t(x)) * 3;
  for (int k = 0; k < 3; ++k) im.rgb[i + k] = float(c[k]);
}

// The pixel's tangent frame: world +x made orthogonal to n (world +y where n
// is nearly +-x, which only the silhouette reaches).
void frame(const dvec3& n, dvec3& t, dvec3& b) {
  dvec3 seed = std::abs(n.x) < 0.999 ? dvec3(1, 0, 0) : dvec3(0, 1, 0);
  t = glm::normalize(seed - glm::dot(seed, n) * n);
  b = glm::cross(n, t);
}
dvec3 to_local(const dvec3& w, const dvec3& t, const dvec3& b, const dvec3& n) {
  return {glm::dot(w, t), glm::dot(w, b), glm::dot(w, n)};
}

}  // namespace

double channel_value(const dvec3& c, Channel ch) {
  switch (ch) {
    case Channel::red: return c.r;
    case Channel::green: return c.g;
    case Channel::blue: return c.b;
    case Channel::luminance: break;
  }
  return 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b;
}

dvec3 Image::at(int x, int y) const {
  size_t i = (size_t(y) * size_t(width) + size_t(x)) * 3;
  return {rgb[i], rgb[i + 1], rgb[i + 2]};
}

dvec3 directional_albedo(const BrdfFunction& f, const dvec3& v, int quadrature) {
  dvec3 sum(0.0);
  double ds = 1.0 / quadrature, dphi = 2.0 * kPi / quadrature;
  for (int i = 0; i < quadrature; ++i) {
    double s = (i + 0.5) * ds;
    double theta = 0.5 * kPi * s * s;
    double st = std::sin(theta), ct = std::cos(theta);
    // dl = 4 (v.h) dh; dh = sin(theta) dtheta dphi with dtheta = pi s ds.
    double weight = st * kPi * s * ds * dphi;
    for (int j = 0; j < quadrature; ++j) {
      double phi = (j + 0.5) * dphi;
      dvec3 h(st * std::cos(phi), st * std::sin(phi), ct);
      double VoH = glm::dot(v, h);
      if (VoH <= 0.0) continue;
      dvec3 l = 2.0 * VoH * h - v;
      if (l.z <= 0.0) continue;
      sum += f(v, l) * (l.z * 4.0 * VoH * weight);
    }
  }
  return sum;
}

bool lit_sphere_pixel(int x, int y, int size, dvec3& normal, dvec3& local_v) {
  double px = 2.0 * (x + 0.5) / size - 1.0;
  double py = 1.0 - 2.0 * (y + 0.5) / size;
  double r2 = px * px + py * py;
  if (r2 >= 1.0) return false;
  normal = dvec3(px, py, std::sqrt(1.0 - r2));
  dvec3 t, b;
  frame(normal, t, b);
  local_v = to_local(dvec3(0, 0, 1), t, b, normal);
  return true;
}

Image render_lit_sphere(const Model& m, const LitSphereOptions& o) {
  Image im = blank(o.size, o.size);
  const dvec3 light(-std::sin(o.incidence_deg * kDeg), 0.0, std::cos(o.incidence_deg * kDeg));
  for (int y = 0; y < o.size; ++y) {
    for (int x = 0; x < o.size; ++x) {
      dvec3 n, v;
      if (!lit_sphere_pixel(x, y, o.size, n, v)) continue;
      if (o.furnace) {
        set(im, x, y, directional_albedo(m.f, v, o.quadrature));
        continue;
      }
      dvec3 t, b;
      frame(n, t, b);
      dvec3 l = to_local(light, t, b, n);
      set(im, x, y, l.z > 0.0 ? m.f(v, l) * (kPi * l.z) : dvec3(0.0));
    }
  }
  return im;
}

Image render_slice(const Model& m, const SliceOptions& o) {
  Image im = blank(o.size, o.size);
  for (int j = 0; j < o.size; ++j) {
    for (int i = 0; i < o.size; ++i) {
      HalfDiff a{(i + 0.5) / o.size * 0.5 * kPi, (j + 0.5) / o.size * 0.5 * kPi, o.phi_d_deg * kDeg};
      dvec3 v, l;
      from_half_diff(a, v, l);
      set(im, i, o.size - 1 - j, kPi * m.f(v, l));
    }
  }
  return im;
}

std::vector<PolarPoint> polar_curve(const Model& m, double incidence_deg, Channel c, int samples) {
  const dvec3 l(-std::sin(incidence_deg * kDeg), 0.0, std::cos(incidence_deg * kDeg));
  std::vector<PolarPoint> points;
  samples = std::max(samples, 2);
  for (int i = 0; i < samples; ++i) {
    double theta = -90.0 + 180.0 * i / (samples - 1);
    double st = std::sin(theta * kDeg), ct = std::cos(theta * kDeg);
    double r = ct > 0.0 ? channel_value(m.f(dvec3(st, 0.0, ct), l), c) * ct : 0.0;
    points.push_back({theta, r, r * st, r * ct});
  }
  return points;
}

std::vector<AlbedoPoint> albedo_curve(const Model& m, int points, double max_theta_deg, int quadrature) {
  std::vector<AlbedoPoint> curve;
  for (int i = 0; i < points; ++i) {
    double theta = points == 1 ? 0.0 : max_theta_deg * i / (points - 1);
    dvec3 v(std::sin(theta * kDeg), 0.0, std::cos(theta * kDeg));
    curve.push_back({theta, directional_albedo(m.f, v, quadrature)});
  }
  return curve;
}

}  // namespace facet::brdf
