#include "case_helpers.h"

#include <cstdio>

namespace facet::reference::cases {

double Rng::log_uniform(double lo, double hi) {
  // x = hi * 2^-k * (1 - u/2) with k uniform over the octaves covers
  // [lo, hi] roughly log-uniformly; values under lo are redrawn.
  int octaves = 0;
  for (double v = hi; v > lo; v *= 0.5) ++octaves;
  for (;;) {
    double v = hi;
    int k = int(uniform() * octaves);
    for (int i = 0; i < k; ++i) v *= 0.5;
    v *= 1.0 - 0.5 * uniform();
    if (v >= lo) return v;
  }
}

glm::dvec3 Rng::unit_vector() {
  for (;;) {
    glm::dvec3 p(uniform(-1, 1), uniform(-1, 1), uniform(-1, 1));
    double r2 = glm::dot(p, p);
    if (r2 <= 1.0 && r2 >= 1e-4) return p / std::sqrt(r2);
  }
}

glm::dvec3 Rng::direction(const glm::dvec3& n, double lo, double hi) {
  for (;;) {
    glm::dvec3 d = unit_vector();
    double c = glm::dot(d, n);
    if (c < 0 && lo >= 0) {
      d = -d;
      c = -c;
    }
    if (c >= lo && c <= hi) return d;
  }
}

glm::dvec3 Rng::near(const glm::dvec3& n, double spread) {
  for (;;) {
    double t = uniform();
    glm::dvec3 d = n + spread * t * t * unit_vector();
    double r2 = glm::dot(d, d);
    if (r2 > 1e-8 && glm::dot(d, n) > 0) return d / std::sqrt(r2);
  }
}

Frame random_frame(Rng& rng) {
  glm::dvec3 n = rng.unit_vector();
  for (;;) {
    glm::dvec3 t = glm::cross(n, rng.unit_vector());
    double r2 = glm::dot(t, t);
    if (r2 > 1e-2) {
      glm::dvec3 x = t / std::sqrt(r2);
      return {n, x, glm::cross(n, x)};
    }
  }
}

uint64_t case_seed(const std::string& function, const std::string& setting) {
  uint64_t h = 1469598103934665603ull;  // FNV-1a
  for (char c : function + "/" + setting) {
    h ^= uint8_t(c);
    h *= 1099511628211ull;
  }
  return h;
}

std::string lit(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.9g", double(float(v)));
  std::string s = buf;
  if (s.find_first_of(".eEn") == std::string::npos) s += ".0";
  return s;
}

std::string lit3(const glm::dvec3& v) { return "float3(" + lit(v.x) + ", " + lit(v.y) + ", " + lit(v.z) + ")"; }

std::string xv(int i) {
  return "float3(x[" + std::to_string(i) + "], x[" + std::to_string(i + 1) + "], x[" + std::to_string(i + 2) + "])";
}

FunctionCase make_case(std::string function, std::string setting, int inputs, int outputs, std::string includes,
                       std::string hlsl, std::function<void(const double*, double*)> reference, Draw draw) {
  FunctionCase c;
  uint64_t seed = case_seed(function, setting);
  c.function = std::move(function);
  c.setting = std::move(setting);
  c.input_count = inputs;
  c.output_count = outputs;
  c.includes = std::move(includes);
  c.hlsl = std::move(hlsl);
  c.reference = std::move(reference);
  c.sample = [seed, inputs, draw = std::move(draw)](uint32_t i, uint32_t, float* x) {
    for (int k = 0; k < inputs; ++k) x[k] = 0.0f;
    Rng rng(seed, i);
    draw(rng, x);
  };
  return c;
}

}  // namespace facet::reference::cases
