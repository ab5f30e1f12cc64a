// Internal to the model table: the builders the rows share and the groups of
// rows, one file each (diffuse_models.cpp, specular_models.cpp,
// other_models.cpp). Each row's HLSL, its twin and its parameter form are
// written side by side so that a difference between them shows in one screen.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "facet/reference/lighting.h"
#include "facet/reference/models.h"

namespace facet::reference::models {

// The stdlib headers a facet row includes, and the frame helper whose twin is frame().
extern const char* const kIncludeFacet;
extern const char* const kIncludeUnityBRDF;
extern const char* const kIncludeUnityPBS;
extern const char* const kIncludeLighting;

// A tangent frame that stays finite for a zero normal (the HLSL twin is
// kIncludeFacet's stability_frame).
void frame(const glm::dvec3& n, glm::dvec3& x, glm::dvec3& y);
inline FacetAngles angles(const ModelPoint& in) { return FacetComputeAngles(in.n, in.v, in.l); }
inline double clamped_alpha(const ModelPoint& in) { return FacetClampAlpha(in.roughness * in.roughness); }
glm::dvec3 half_vector(const ModelPoint& in);

// A facet row: FacetComputeAngles first, as a caller would; `body` reads a,
// alpha and F0 too.
LightingModel facet_row(std::string id, std::string name, std::string body, std::function<glm::dvec3(const ModelPoint&)> cpu,
                        Energy energy = Energy::conserving, bool reciprocal = true);
// The parameter form of a row.
void with_params(LightingModel& m, std::string stdlib, std::vector<ModelParam> params,
                 std::function<LocalBrdf(const ModelParams&)> bind);

ModelParam number(std::string name, double def, double min, double max, std::string help);
ModelParam colour(std::string name, glm::dvec3 def, std::string help);
ModelParam roughness_param();  // perceptual roughness r (alpha = r^2)
ModelParam f0_param();

// A lobe written against FacetComputeAngles in the local frame: zero below the surface.
using AngleLobe = std::function<glm::dvec3(const glm::dvec3& v, const glm::dvec3& l, const FacetAngles& a)>;
LocalBrdf above_surface(AngleLobe lobe);
inline double clamped_alpha_of(double r) { return FacetClampAlpha(r * r); }

std::vector<LightingModel> diffuse_models();
std::vector<LightingModel> phong_models();
std::vector<LightingModel> microfacet_models();
std::vector<LightingModel> other_models();
std::vector<LightingModel> unity_models();

}  // namespace facet::reference::models
