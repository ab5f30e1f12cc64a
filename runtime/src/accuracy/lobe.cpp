#include "accuracy/lobe.h"

#include <cmath>

#include "facet/reference/models.h"

namespace facet::runtime::accuracy {
namespace {

// Midpoint rule over the half vector h in (mu = n.h, phi), mapped to the
// light l = reflect(-v, h) with d omega_l = 4 (v.h) d omega_h. Microfacet and
// Phong-like lobes peak at h = n for every view, so the mu cells are squeezed
// towards mu = 1 (mu = 1 - t^2): sharp lobes get many samples even at
// grazing views, where a grid over l would miss them.
constexpr int kMuCells = 512;
constexpr int kPhiCells = 256;

template <class F>
void for_each_direction(const glm::dvec3& v, F&& visit) {
  const double dphi = 2.0 * M_PI / kPhiCells;
  for (int i = 0; i < kMuCells; ++i) {
    double t0 = double(i) / kMuCells, t1 = double(i + 1) / kMuCells, t = (i + 0.5) / kMuCells;
    double mu = 1.0 - t * t;
    double dmu = (1.0 - t0 * t0) - (1.0 - t1 * t1);
    double s = std::sqrt(std::max(0.0, 1.0 - mu * mu));
    for (int j = 0; j < kPhiCells; ++j) {
      double phi = (j + 0.5) * dphi;
      glm::dvec3 h(s * std::cos(phi), s * std::sin(phi), mu);
      double vh = glm::dot(v, h);
      if (vh <= 0) continue;
      glm::dvec3 l = 2.0 * vh * h - v;
      if (l.z <= 0) continue;
      visit(l, l.z * 4.0 * vh * dmu * dphi);
    }
  }
}

}  // namespace

glm::dvec3 view_at(double NoV) { return {std::sqrt(std::max(0.0, 1.0 - NoV * NoV)), 0.0, NoV}; }

double albedo(const Lobe& f, const glm::dvec3& v) {
  double sum = 0;
  for_each_direction(v, [&](const glm::dvec3& l, double weight) { sum += f(v, l) * weight; });
  return sum;
}

LobeComparison compare_lobes(const Lobe& approx, const Lobe& reference, const glm::dvec3& v) {
  double diff = 0, ref = 0, app = 0;
  for_each_direction(v, [&](const glm::dvec3& l, double weight) {
    double a = approx(v, l), r = reference(v, l);
    diff += std::abs(a - r) * weight;
    ref += r * weight;
    app += a * weight;
  });
  return {ref > 0 ? diff / ref : 0.0, ref > 0 ? app / ref : 1.0};
}

Lobe model_lobe(std::string_view id, const std::map<std::string, glm::dvec3>& params) {
  facet::reference::LocalBrdf f = facet::reference::model_brdf(id, params);
  return [f](const glm::dvec3& v, const glm::dvec3& l) { return f(v, l).x; };
}

Lobe ggx_model_lobe(double alpha) {
  return model_lobe("ggx", {{"roughness", glm::dvec3(std::sqrt(alpha))}, {"f0", glm::dvec3(1.0)}});
}

Lobe unity_lobe(int tier, double smoothness) {
  return model_lobe("unity-brdf" + std::to_string(tier), {{"albedo", glm::dvec3(1.0)},
                                                         {"metallic", glm::dvec3(1.0)},
                                                         {"smoothness", glm::dvec3(smoothness)}});
}

}  // namespace facet::runtime::accuracy
