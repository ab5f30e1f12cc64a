// The lighting models of the stability suite: every assembled model of the
// stdlib, each as HLSL statements for the GPU evaluator and as its CPU twin,
// both computing the light reflected towards v for a light of intensity
// `intensity` from l: f(v, l) <n.l> intensity (Unity's tiers in their own
// convention, specular times pi, diffuse not divided by pi).
//
// Evaluator point layout (16 floats): x[0..2] n, x[3..5] v, x[6..8] l,
// x[9] perceptual roughness, x[10] f0 (metallic for the Unity tiers),
// x[11] intensity, x[12] E for the energy-compensated model (0: its own
// estimate from EnvBRDFApprox). The result is r.xyz.
#pragma once

#include <glm/glm.hpp>

#include <array>
#include <functional>
#include <string>
#include <vector>

namespace facet::stability {

inline constexpr int kInputs = 13;

struct Inputs {
  glm::dvec3 n{0, 0, 1}, v{0, 0, 1}, l{0, 0, 1};
  double roughness = 0.5, f0 = 0.04, intensity = 1.0, energy = 0.0;
};

// What a model promises about energy (the white furnace, T6).
enum class Energy {
  conserving,  // E(v) <= 1 for every v
  violator,    // exceeds 1 by a documented amount
  none,        // not a BRDF (translucency) or not meant to be bounded (raw Blinn-Phong)
};

struct Model {
  std::string name;
  std::string includes;  // HLSL include lines
  std::string hlsl;      // statements reading n, v, l, rough, f0, E and assigning float3 c (unit intensity)
  std::function<glm::dvec3(const Inputs&)> cpu;  // the twin, unit intensity
  Energy energy = Energy::conserving;
  bool reciprocal = true;  // f(v, l) = f(l, v) claimed (T5)
  bool unity = false;      // Unity convention: E = (1/pi) integral of the output
  // The largest value a correct implementation can return per unit
  // intensity on any input, derived from the formula's clamps (docs/stability.md).
  double bound = 3.4e38;
  // Points where the stdlib is known to misbehave (reported, not fixed here):
  // the hard-case checks leave them out and KnownIssuesTest asserts them.
  std::function<bool(const float* x)> known_issue;
  std::string known_issue_text;
};

const std::vector<Model>& models();
const Model& model(const std::string& name);  // throws std::out_of_range

// The full evaluator statements for a model: unpacks x[] and scales by x[11].
std::string evaluator_hlsl(const Model& m);

// Packs an input point as the evaluator reads it (rounded to float).
std::array<float, kInputs> pack(const Inputs& in);
// The same point back in double (what the CPU twin sees: the float inputs).
Inputs unpack(const float* x);

}  // namespace facet::stability
