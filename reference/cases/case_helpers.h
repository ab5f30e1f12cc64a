// Internal to the case table: the deterministic point generator and small
// builders shared by the facet_cases_*.cpp files.
#pragma once

#include "facet/reference/cases.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <string>

namespace facet::reference::cases {

// splitmix64, seeded per (case, point) so a point does not depend on which
// other points were drawn. Samplers use only + - * / sqrt (all correctly
// rounded in IEEE 754), never libm, so every platform draws identical points.
class Rng {
 public:
  Rng(uint64_t seed, uint32_t point) : state_(seed ^ (uint64_t(point) + 1) * 0x9E3779B97F4A7C15ull) {}
  uint64_t next() {
    uint64_t z = (state_ += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  }
  double uniform() { return double(next() >> 11) * 0x1.0p-53; }  // [0, 1)
  double uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }
  // Log-uniform in [lo, hi], lo > 0, by repeated halving (no log/exp).
  double log_uniform(double lo, double hi);
  glm::dvec3 unit_vector();
  // A direction with lo <= dot(d, n) <= hi (n unit), by rejection.
  glm::dvec3 direction(const glm::dvec3& n, double lo, double hi);
  // Rotated away from n by at most about atan(spread): dense near n.
  glm::dvec3 near(const glm::dvec3& n, double spread);

 private:
  uint64_t state_;
};

struct Frame {
  glm::dvec3 n, x, y;  // orthonormal: normal, tangent, bitangent
};
Frame random_frame(Rng& rng);
inline Frame z_frame() { return {{0, 0, 1}, {1, 0, 0}, {0, 1, 0}}; }

uint64_t case_seed(const std::string& function, const std::string& setting);

// A parameter as the shader sees it: rounded to float.
inline double fp(double v) { return double(float(v)); }
// The HLSL literal of fp(v).
std::string lit(double v);
std::string lit3(const glm::dvec3& v);
// "float3(x[i], x[i+1], x[i+2])"
std::string xv(int i);
inline glm::dvec3 v3(const double* x, int i) { return {x[i], x[i + 1], x[i + 2]}; }
inline void put(float* x, int i, const glm::dvec3& v) {
  x[i] = float(v.x);
  x[i + 1] = float(v.y);
  x[i + 2] = float(v.z);
}

using Draw = std::function<void(Rng&, float*)>;
// Builds a case whose sampler seeds an Rng per point and calls draw.
FunctionCase make_case(std::string function, std::string setting, int inputs, int outputs, std::string includes,
                       std::string hlsl, std::function<void(const double*, double*)> reference, Draw draw);

inline const char* kIncludeBRDF = "#include \"FacetBRDF.hlsl\"\n";
inline const char* kIncludeDisney = "#include \"FacetDisney.hlsl\"\n";
inline const char* kIncludeIBL = "#include \"FacetIBL.hlsl\"\n";
inline const char* kIncludeTonemap = "#include \"FacetTonemap.hlsl\"\n";
inline const char* kIncludeColor = "#include \"FacetColor.hlsl\"\n";

void add_diffuse_cases(std::vector<FunctionCase>& out);
void add_specular_cases(std::vector<FunctionCase>& out);
void add_fresnel_cases(std::vector<FunctionCase>& out);
void add_lobe_cases(std::vector<FunctionCase>& out);
void add_disney_cases(std::vector<FunctionCase>& out);
void add_ibl_cases(std::vector<FunctionCase>& out);
void add_tonemap_cases(std::vector<FunctionCase>& out);

}  // namespace facet::reference::cases
