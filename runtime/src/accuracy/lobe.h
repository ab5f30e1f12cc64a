// Hemisphere integrals of BRDF lobes on the CPU twins (double precision),
// in the frame n = +z, tangent +x, bitangent +y.
#pragma once

#include <glm/glm.hpp>

#include <functional>

namespace facet::runtime::accuracy {

// A BRDF value (without the cosine) for view v and light l, both unit.
using Lobe = std::function<double(const glm::dvec3& v, const glm::dvec3& l)>;

// The unit view vector at cos(theta) = NoV in the xz plane.
glm::dvec3 view_at(double NoV);

// Directional albedo E(v) = integral of f(v, l) (n.l) over the hemisphere.
double albedo(const Lobe& f, const glm::dvec3& v);

// relL1 = integral |a - r| (n.l) / integral r (n.l), and the energy ratio
// albedo(a) / albedo(r), for one view.
struct LobeComparison {
  double rel_l1 = 0;
  double energy_ratio = 1;
};
LobeComparison compare_lobes(const Lobe& approx, const Lobe& reference, const glm::dvec3& v);

}  // namespace facet::runtime::accuracy
