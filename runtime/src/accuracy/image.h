// Image-level errors: how each approximation changes the study's test scenes
// (facet/reference/monte_carlo.h) against its exact form, rendered by the
// Monte Carlo reference from the same samples.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "facet/reference/monte_carlo.h"
#include "facet/runtime/accuracy.h"

namespace facet::runtime::accuracy {

namespace mc = facet::reference::monte_carlo;

// The scenes' material, term by term (scalar, grey): f = (1 - metallic)
// kBaseColour diffuse + D V F. Each term can be replaced by an approximation.
struct Terms {
  std::function<double(double NoH, double alpha)> d;
  std::function<double(double NoV, double NoL, double alpha)> v;
  std::function<double(double LoH, const mc::Material& m)> f;
  // The diffuse lobe for a white albedo.
  std::function<double(const glm::dvec3& v, const glm::dvec3& l, const mc::Material& m)> diffuse;
};

inline constexpr double kBaseColour = 0.8;
// The exact model: GGX D, height-correlated Smith V, exact Fresnel (a
// dielectric of index 1.5 blended by metallic with a silver-like conductor),
// Lambert diffuse.
Terms exact_terms();
// f0 of the exact Fresnel at a material: its value at normal incidence.
double exact_f0(const mc::Material& m);
mc::Model material_model(const Terms& terms);

// How a row enters the scenes. Each side is either a model integrated by the
// renderer or a closed form of the pixel's value (the IBL fits, and the white
// furnace's 1); a row that acts on the finished image (tone mapping, the
// sRGB encode) maps the exact model's image through `display`.
struct ImageProbe {
  std::vector<std::string> scenes;  // names of study_scenes()
  mc::Model approx, reference;      // the reference defaults to the exact model
  std::function<double(const mc::ShadingPoint&)> approx_closed, reference_closed;
  std::function<double(double)> display_approx, display_reference;
  std::string what;  // how the row enters the image, in words
};
std::optional<ImageProbe> image_probe(std::string_view row_id);

}  // namespace facet::runtime::accuracy
