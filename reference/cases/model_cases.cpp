// The cases of the model table's point forms (facet/reference/models.h): each
// row's evaluator statements on the GPU against its twin, so that the HLSL a
// row holds is the formula its twin computes, at ordinary inputs (the
// stability suite takes the same rows to the hard ones).
#include "case_helpers.h"
#include "facet/reference/lighting.h"
#include "facet/reference/models.h"

namespace facet::reference {
namespace {

// An ordinary point: unit n, v and l in front within 84 degrees of n (fp32
// cosines near 0 lose the relative precision the comparison asks for), l
// half the time near v's mirror direction so that specular peaks are
// sampled, |v + l| >= 0.1; roughness >= 0.5, where the plain GGX D of an fp32
// NoH stays within the tolerance; h at least `min_half_angle` radians from n.
void draw_point(cases::Rng& g, float* x, double min_half_angle) {
  cases::Frame f = cases::random_frame(g);
  glm::dvec3 v = g.direction(f.n, 0.1, 1.0), l;
  double roughness = g.uniform(0.5, 1.0);
  bool near_mirror = g.uniform() < 0.5;
  const double max_noh = 1.0 - 0.5 * min_half_angle * min_half_angle;  // cos, to second order
  do {
    if (near_mirror) {
      glm::dvec3 h = g.near(f.n, roughness * roughness);
      l = 2.0 * glm::dot(v, h) * h - v;
    } else {
      l = g.direction(f.n, 0.1, 1.0);
    }
  } while (glm::dot(l, f.n) < 0.1 || glm::dot(v + l, v + l) < 0.01 ||
           glm::dot(glm::normalize(v + l), f.n) > max_noh);
  ModelPoint p;
  p.n = f.n, p.v = v, p.l = glm::normalize(l);
  p.roughness = roughness;
  p.f0 = g.uniform(0.02, 1.0);
  std::array<float, kModelInputs> packed = pack(p);
  std::copy(packed.begin(), packed.end(), x);
}

// Disney's clearcoat lobe at clearcoatGloss = 1 is GTR1 with alpha = 0.001:
// its denominator sin^2(theta_h) + 1e-6 cancels in fp32 near the peak (a
// NoH rounded by 6e-8 moves it by 1.2e-7: 1e-4 relative at 2 degrees, and
// 9.3e-5 was measured with 3 degrees left out), so its case leaves the 5
// degrees around n out (1.2e-5). The stability suite takes the
// peak itself (bounds, finiteness) where no comparison at 1e-4 is possible.
double min_half_angle(const LightingModel& m) { return m.id == "disney" ? 5.0 * kPi / 180.0 : 0.0; }

}  // namespace

std::vector<FunctionCase> lighting_model_cases() {
  std::vector<FunctionCase> out;
  for (const LightingModel& m : lighting_models()) {
    if (m.hlsl.empty()) continue;
    out.push_back(cases::make_case("model " + m.id, "r in [0.5, 1], f0 in [0.02, 1]", kModelInputs, 3, m.includes,
                                   evaluator_hlsl(m),
                                   [&m](const double* x, double* r) {
                                     float xf[kModelInputs];
                                     for (int i = 0; i < kModelInputs; ++i) xf[i] = float(x[i]);
                                     ModelPoint p = unpack(xf);
                                     glm::dvec3 c = m.cpu(p) * p.intensity;
                                     r[0] = c.x, r[1] = c.y, r[2] = c.z;
                                   },
                                   [limit = min_half_angle(m)](cases::Rng& g, float* x) { draw_point(g, x, limit); }));
  }
  return out;
}

}  // namespace facet::reference
