// The table's assembly and lookups, and the builders of model_rows.h.
#include <algorithm>
#include <stdexcept>

#include "model_rows.h"

namespace facet::reference {
namespace models {

using glm::dvec3;

const char* const kIncludeFacet =
    "#include \"FacetBRDF.hlsl\"\n#include \"FacetDisney.hlsl\"\n#include \"FacetIBL.hlsl\"\n"
    "#ifndef FACET_STABILITY_HELPERS\n#define FACET_STABILITY_HELPERS\n"
    "void stability_frame(float3 n, out float3 t, out float3 b) {\n"
    "  float3 nn = FacetSafeNormalize(n);\n"
    "  t = FacetSafeNormalize(cross(float3(0, 1, 0), nn) + float3(1e-3, 0, 0));\n"
    "  b = cross(nn, t);\n"
    "}\n#endif\n";
const char* const kIncludeUnityBRDF = "#include \"UnityStandardBRDF.cginc\"\n#include \"UnityStandardUtils.cginc\"\n";
const char* const kIncludeUnityPBS =
    "#include \"UnityStandardBRDF.cginc\"\n#define UNITY_BRDF_PBS BRDF1_Unity_PBS\n#include \"UnityPBSLighting.cginc\"\n";
const char* const kIncludeLighting = "#include \"Lighting.cginc\"\n";

void frame(const dvec3& n, dvec3& x, dvec3& y) {
  dvec3 nn = FacetSafeNormalize(n);
  x = FacetSafeNormalize(glm::cross(dvec3(0, 1, 0), nn) + dvec3(1e-3, 0, 0));
  y = glm::cross(nn, x);
}

dvec3 half_vector(const ModelPoint& in) { return FacetSafeNormalize(FacetSafeNormalize(in.v) + FacetSafeNormalize(in.l)); }

LightingModel facet_row(std::string id, std::string name, std::string body, std::function<dvec3(const ModelPoint&)> cpu,
                        Energy energy, bool reciprocal) {
  LightingModel m;
  m.id = std::move(id);
  m.name = std::move(name);
  m.includes = kIncludeFacet;
  m.hlsl = "FacetAngles a = FacetComputeAngles(n, v, l);\nfloat alpha = FacetClampAlpha(rough * rough);\n"
           "float3 F0 = float3(f0, f0, f0);\n" + body;
  m.cpu = std::move(cpu);
  m.energy = energy;
  m.reciprocal = reciprocal;
  return m;
}

void with_params(LightingModel& m, std::string stdlib, std::vector<ModelParam> params,
                 std::function<LocalBrdf(const ModelParams&)> bind) {
  m.stdlib = std::move(stdlib);
  m.params = std::move(params);
  m.bind = std::move(bind);
}

ModelParam number(std::string name, double def, double min, double max, std::string help) {
  return {std::move(name), 1, min, max, dvec3(def), std::move(help)};
}
ModelParam colour(std::string name, dvec3 def, std::string help) { return {std::move(name), 3, 0.0, 1.0, def, std::move(help)}; }
ModelParam roughness_param() { return number("roughness", 0.5, 0.0, 1.0, "perceptual roughness r (alpha = r^2)"); }
ModelParam f0_param() { return colour("f0", dvec3(0.04), "reflectance at normal incidence"); }

LocalBrdf above_surface(AngleLobe lobe) {
  return [lobe = std::move(lobe)](const dvec3& v, const dvec3& l) {
    if (v.z <= 0.0 || l.z <= 0.0) return dvec3(0.0);
    return lobe(v, l, FacetComputeAngles(dvec3(0, 0, 1), v, l));
  };
}

namespace {

// Per unit intensity, from each formula's clamps (derivations in
// docs/stability.md): diffuse f <= 6.25/pi; Phong (n+2)/(2 pi) at
// n = 2/alpha_min^2 - 2 = 4.9e5; GGX family D <= 1/(pi alpha_min^2) = 77 625
// times V NoL <= 1/alpha_min, times 20 for the compensation (E >= 0.05);
// Disney's D <= 1/(pi 0.001^2) times V NoL <= 1/NoV_min = 1e4; Unity's
// rows from their own epsilons. A row with no HLSL has no bound.
double bound_of(const LightingModel& m) {
  static const std::pair<const char*, double> bounds[] = {
      {"lambert", 2.0},        {"burley", 2.0},        {"frostbite", 2.0},       {"oren-nayar-qualitative", 2.0},
      {"oren-nayar", 2.0},     {"ashikhmin-shirley-diffuse", 2.0},                 {"phong", 1e5},
      {"blinn-phong", 1e5},    {"translucency", 1.0},  {"disney", 1e10},         {"unity-brdf1", 1e5},
      {"unity-brdf2", 1e6},    {"unity-brdf3", 20.0},  {"unity-lighting-standard", 1e5},
      {"unity-lighting-lambert", 1.1}};
  for (auto [id, b] : bounds)
    if (m.id == id) return b;
  return m.hlsl.empty() ? 3.4e38 : 1e9;  // the microfacet specular lobes
}

std::vector<LightingModel> all_rows() {
  std::vector<LightingModel> all;
  for (auto group : {models::diffuse_models(), models::phong_models(), models::microfacet_models(),
                     models::other_models(), models::unity_models()})
    for (LightingModel& m : group) all.push_back(std::move(m));
  for (LightingModel& m : all) m.bound = bound_of(m);
  return all;
}

}  // namespace
}  // namespace models

const std::vector<LightingModel>& lighting_models() {
  static const std::vector<LightingModel> table = models::all_rows();
  return table;
}

const LightingModel* find_lighting_model(std::string_view id) {
  for (const LightingModel& m : lighting_models())
    if (m.id == id) return &m;
  return nullptr;
}

ModelParams model_params(const LightingModel& m, const std::map<std::string, glm::dvec3>& values) {
  ModelParams p;
  for (const ModelParam& info : m.params) p.values[info.name] = info.default_value;
  for (const auto& [name, value] : values) {
    if (!p.values.count(name)) throw std::out_of_range("model " + m.id + " has no parameter " + name);
    p.values[name] = value;
  }
  return p;
}

LocalBrdf model_brdf(std::string_view id, const std::map<std::string, glm::dvec3>& values) {
  const LightingModel* m = find_lighting_model(id);
  if (!m || !m->bind) throw std::out_of_range("no lighting model with a parameter form named " + std::string(id));
  return m->bind(model_params(*m, values));
}

std::string evaluator_hlsl(const LightingModel& m) {
  return "float3 n = float3(x[0], x[1], x[2]);\nfloat3 v = float3(x[3], x[4], x[5]);\n"
         "float3 l = float3(x[6], x[7], x[8]);\nfloat rough = x[9];\nfloat f0 = x[10];\nfloat E = x[12];\n"
         "float3 c = 0;\n{\n" + m.hlsl + "\n}\nr.xyz = c * x[11];";
}

std::array<float, kModelInputs> pack(const ModelPoint& in) {
  return {float(in.n.x), float(in.n.y), float(in.n.z), float(in.v.x), float(in.v.y), float(in.v.z),
          float(in.l.x), float(in.l.y), float(in.l.z), float(in.roughness), float(in.f0), float(in.intensity),
          float(in.energy)};
}

ModelPoint unpack(const float* x) {
  ModelPoint in;
  in.n = {x[0], x[1], x[2]};
  in.v = {x[3], x[4], x[5]};
  in.l = {x[6], x[7], x[8]};
  in.roughness = x[9], in.f0 = x[10], in.intensity = x[11], in.energy = x[12];
  return in;
}

}  // namespace facet::reference
