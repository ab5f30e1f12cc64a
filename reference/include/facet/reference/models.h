// The table of the stdlib's lighting models: one row per model, read by every
// tool that needs to know which models exist. The stability suite evaluates a
// row's HLSL and its CPU twin on hard inputs; `facet brdf` plots a row's BRDF
// at the parameters a user gives; the accuracy study measures the rows'
// lobes; the reference case table compares each row's HLSL with its twin.
//
// A row has up to two forms of the same model:
//  - the point form (hlsl + twin): the light reflected towards v for a unit
//    light from l, f(v, l) <n.l> (Unity's rows in their own convention:
//    specular times pi, diffuse not divided by pi), at an arbitrary point
//    (n, v, l, perceptual roughness, f0) including degenerate ones;
//  - the parameter form (params + bind): the BRDF without the cosine in the
//    local frame n = +z, tangent +x, bitangent +y, at named parameters.
// A row without HLSL has no stdlib entry point of its own (a composition
// only the CPU plots); a row without params is not offered by `facet brdf`.
#pragma once

#include <glm/glm.hpp>

#include <array>
#include <functional>
#include <map>
#include <string>
#include <string_view>
#include <vector>

namespace facet::reference {

// Evaluator point layout (13 floats): x[0..2] n, x[3..5] v, x[6..8] l,
// x[9] perceptual roughness, x[10] f0 (metallic for Unity's rows),
// x[11] intensity, x[12] E for the energy-compensated model (0: its own
// estimate from EnvBRDFApprox).
inline constexpr int kModelInputs = 13;

struct ModelPoint {
  glm::dvec3 n{0, 0, 1}, v{0, 0, 1}, l{0, 0, 1};
  double roughness = 0.5, f0 = 0.04, intensity = 1.0, energy = 0.0;
};

// What a model promises about energy (the white furnace).
enum class Energy {
  conserving,  // E(v) <= 1 for every v
  violator,    // exceeds 1 by a documented amount
  none,        // not a BRDF (translucency) or not meant to be bounded
};

struct ModelParam {
  std::string name;
  int components = 1;  // 1 (a number) or 3 (a colour)
  double min = 0, max = 1;
  glm::dvec3 default_value{0.0};
  std::string help;
};

struct ModelParams {
  std::map<std::string, glm::dvec3> values;
  double num(const std::string& name) const { return values.at(name).x; }
  glm::dvec3 col(const std::string& name) const { return values.at(name); }
};

// f(v, l) in the local frame, without the cosine; zero below the surface.
using LocalBrdf = std::function<glm::dvec3(const glm::dvec3& v, const glm::dvec3& l)>;

struct LightingModel {
  std::string name;      // "Cook-Torrance GGX": what reports and test names show
  std::string includes;  // HLSL include lines of the point form
  std::string hlsl;      // statements reading n, v, l, rough, f0, E and assigning float3 c
  std::function<glm::dvec3(const ModelPoint&)> cpu;  // the point form's twin, unit intensity
  Energy energy = Energy::conserving;
  bool reciprocal = true;  // f(v, l) = f(l, v) claimed
  bool unity = false;      // Unity's convention: E = (1/pi) integral of the output
  // The largest value a correct implementation can return per unit
  // intensity on any input, derived from the formula's clamps (docs/stability.md).
  double bound = 3.4e38;
  // Points where the stdlib is known to misbehave: the stability suite
  // reports them apart and asserts that they still misbehave.
  std::function<bool(const ModelPoint&)> known_issue;
  std::string known_issue_text;
  std::string id;      // "ggx": facet brdf's spelling, unique
  std::string stdlib;  // the stdlib functions (and twins) the model calls
  std::vector<ModelParam> params;
  std::function<LocalBrdf(const ModelParams&)> bind;  // empty: no parameter form
};

const std::vector<LightingModel>& lighting_models();
const LightingModel* find_lighting_model(std::string_view id);  // nullptr when no row has that id

// The parameters' defaults, overridden by `values` (names must be the row's).
ModelParams model_params(const LightingModel& m, const std::map<std::string, glm::dvec3>& values = {});
// The row's BRDF at those parameters; throws std::out_of_range for an
// unknown id or a row without a parameter form.
LocalBrdf model_brdf(std::string_view id, const std::map<std::string, glm::dvec3>& values = {});

// The full evaluator statements of a point form: unpacks x[] and scales by x[11].
std::string evaluator_hlsl(const LightingModel& m);
// A point as the evaluator reads it (rounded to float), and back in double
// (what the CPU twin sees: the float inputs).
std::array<float, kModelInputs> pack(const ModelPoint& in);
ModelPoint unpack(const float* x);

}  // namespace facet::reference
