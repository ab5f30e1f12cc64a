// Hemisphere integrals of BRDF lobes on the CPU twins (double precision),
// in the frame n = +z, tangent +x, bitangent +y.
#pragma once

#include <glm/glm.hpp>

#include <functional>
#include <map>
#include <string>
#include <string_view>

namespace facet::runtime::accuracy {

// A BRDF value (without the cosine) for view v and light l, both unit.
using Lobe = std::function<double(const glm::dvec3& v, const glm::dvec3& l)>;

// A model of the lighting-model table (facet/reference/models.h) at the
// given parameters, as a scalar lobe (its red channel: the study uses white
// albedos and f0 = 1).
Lobe model_lobe(std::string_view id, const std::map<std::string, glm::dvec3>& params = {});
// Cook-Torrance GGX with F = 1 at alpha (the model's parameter is r = sqrt(alpha)).
Lobe ggx_model_lobe(double alpha);
// Unity's Standard tier (1, 2 or 3) for a white light with no indirect light
// and spec colour 1 (metallic 1, white albedo).
Lobe unity_lobe(int tier, double smoothness);

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
