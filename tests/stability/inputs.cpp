#include "stability/inputs.h"

#include <cmath>
#include <utility>

#include "facet/reference/ibl.h"

namespace facet::stability {
namespace {

std::vector<glm::dvec3> normals() {
  return {{0, 0, 1}, {0, 0, 0.98}, {0, 0, 1.02}, {0, 0, 0}, {0, 0, 1e-40}, {1e-39, 0, 1}, {0.6, 0, 0.8}};
}

std::vector<std::pair<glm::dvec3, glm::dvec3>> view_light_pairs() {
  const double cosines[] = {-0.3, -1e-6, 0.0, 1e-7, 1e-4, 0.5, 1.0};
  std::vector<std::pair<glm::dvec3, glm::dvec3>> pairs;
  for (double cv : cosines)
    for (double cl : cosines) pairs.push_back({direction(cv, 0.0), direction(cl, 2.0)});
  for (double c : cosines) {
    glm::dvec3 v = direction(c, 0.7);
    pairs.push_back({v, -v});                                   // L = -V: H = 0
    pairs.push_back({v, 2.0 * v.z * glm::dvec3(0, 0, 1) - v});  // mirror: NoH = 1
    pairs.push_back({v, v});                                    // L = V
  }
  pairs.push_back({{0, 0, 1}, {0, 0, 1}});           // L = V = N
  pairs.push_back({{1e-40, 0, 1}, {0, 1e-39, 1}});   // denormal components (fp32 denormals)
  return pairs;
}

}  // namespace

glm::dvec3 direction(double c, double phi) {
  double s = std::sqrt(std::max(0.0, 1.0 - c * c));
  return {s * std::cos(phi), s * std::sin(phi), c};
}

std::vector<Point> hard_case_grid() {
  std::vector<Point> points;
  for (const glm::dvec3& n : normals())
    for (const auto& [v, l] : view_light_pairs())
      for (double r : {0.0, 0.045, 0.5, 1.0})
        for (double f0 : {0.0, 0.04, 1.0})
          for (double intensity : kIntensities) {
            Inputs in;
            in.n = n, in.v = v, in.l = l, in.roughness = r, in.f0 = f0, in.intensity = intensity;
            points.push_back(pack(in));
          }
  return points;
}

std::vector<Point> full_input_set() {
  constexpr uint32_t kPairs = 4096;
  std::vector<Point> points;
  for (double r : {0.0, 0.01, 0.045, 0.089, 0.1, 0.25, 0.5, 0.75, 1.0})
    for (double f0 : {0.02, 0.04, 0.16, 1.0})
      for (uint32_t i = 0; i < kPairs; ++i) {
        // Hammersley in 2D for v, a scrambled radical inverse pair for l.
        double u1 = (i + 0.5) / kPairs, u2 = reference::FacetRadicalInverse(i);
        double u3 = reference::FacetRadicalInverse(i * 2654435761u), u4 = reference::FacetRadicalInverse(i ^ 0x5bd1e995u);
        Inputs in;
        in.v = direction(u1, 2.0 * reference::kPi * u2);
        in.l = direction(u3, 2.0 * reference::kPi * u4);
        in.roughness = r, in.f0 = f0;
        points.push_back(pack(in));
      }
  return points;
}

}  // namespace facet::stability
