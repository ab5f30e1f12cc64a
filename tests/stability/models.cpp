// The model list of models.h. Each HLSL body and its twin are written side by
// side so that a difference between them shows in one screen.
#include "stability/models.h"

#include <stdexcept>

#include "facet/reference/lighting.h"
#include "facet/reference/unity_standard.h"

namespace facet::stability {
namespace {

using glm::dvec3;
using namespace facet::reference;
namespace u = facet::reference::unity;

// A tangent frame that stays finite for a zero normal (the HLSL twin is
// kHelpers' stability_frame).
void frame(const dvec3& n, dvec3& x, dvec3& y) {
  dvec3 nn = FacetSafeNormalize(n);
  x = FacetSafeNormalize(glm::cross(dvec3(0, 1, 0), nn) + dvec3(1e-3, 0, 0));
  y = glm::cross(nn, x);
}

const char* kIncludeFacet =
    "#include \"FacetBRDF.hlsl\"\n#include \"FacetDisney.hlsl\"\n#include \"FacetIBL.hlsl\"\n"
    "#ifndef FACET_STABILITY_HELPERS\n#define FACET_STABILITY_HELPERS\n"
    "void stability_frame(float3 n, out float3 t, out float3 b) {\n"
    "  float3 nn = FacetSafeNormalize(n);\n"
    "  t = FacetSafeNormalize(cross(float3(0, 1, 0), nn) + float3(1e-3, 0, 0));\n"
    "  b = cross(nn, t);\n"
    "}\n#endif\n";
const char* kIncludeUnityBRDF = "#include \"UnityStandardBRDF.cginc\"\n#include \"UnityStandardUtils.cginc\"\n";
const char* kIncludeUnityPBS =
    "#include \"UnityStandardBRDF.cginc\"\n#define UNITY_BRDF_PBS BRDF1_Unity_PBS\n#include \"UnityPBSLighting.cginc\"\n";
const char* kIncludeLighting = "#include \"Lighting.cginc\"\n";

FacetAngles angles(const Inputs& in) { return FacetComputeAngles(in.n, in.v, in.l); }
double clamped_alpha(const Inputs& in) { return FacetClampAlpha(in.roughness * in.roughness); }
dvec3 half_vector(const Inputs& in) { return FacetSafeNormalize(FacetSafeNormalize(in.v) + FacetSafeNormalize(in.l)); }

// Facet models: FacetComputeAngles first, as a caller would.
Model facet(std::string name, std::string body, std::function<dvec3(const Inputs&)> cpu, Energy energy = Energy::conserving,
            bool reciprocal = true) {
  return {std::move(name), kIncludeFacet,
          "FacetAngles a = FacetComputeAngles(n, v, l);\nfloat alpha = FacetClampAlpha(rough * rough);\n"
          "float3 F0 = float3(f0, f0, f0);\n" + body,
          std::move(cpu), energy, reciprocal, false};
}

std::vector<Model> diffuse_models() {
  return {
      facet("Lambert", "c = FacetFd_Lambert() * a.NoL;",
            [](const Inputs& in) { return dvec3(FacetFd_Lambert() * angles(in).NoL); }),
      facet("Burley", "c = FacetFd_Burley(a.NoV, a.NoL, a.LoH, rough) * a.NoL;",
            [](const Inputs& in) {
              FacetAngles a = angles(in);
              return dvec3(FacetFd_Burley(a.NoV, a.NoL, a.LoH, in.roughness) * a.NoL);
            },
            Energy::violator),
      facet("Frostbite", "c = FacetFd_Frostbite(a.NoV, a.NoL, a.LoH, rough * rough) * a.NoL;",
            [](const Inputs& in) {
              FacetAngles a = angles(in);
              return dvec3(FacetFd_Frostbite(a.NoV, a.NoL, a.LoH, in.roughness * in.roughness) * a.NoL);
            }),
      facet("Oren-Nayar qualitative", "c = FacetFd_OrenNayarQualitative(a.NoV, a.NoL, a.LoV, rough) * a.NoL;",
            [](const Inputs& in) {
              FacetAngles a = angles(in);
              return dvec3(FacetFd_OrenNayarQualitative(a.NoV, a.NoL, a.LoV, in.roughness) * a.NoL);
            },
            Energy::violator),
      facet("Oren-Nayar full", "c = FacetFd_OrenNayar(a.NoV, a.NoL, a.LoV, rough, 1.0) * a.NoL;",
            [](const Inputs& in) {
              FacetAngles a = angles(in);
              return dvec3(FacetFd_OrenNayar(a.NoV, a.NoL, a.LoV, in.roughness, 1.0) * a.NoL);
            }),
      facet("Ashikhmin-Shirley diffuse", "c = FacetFd_AshikhminShirley(a.NoV, a.NoL, 1.0, f0) * a.NoL;",
            [](const Inputs& in) {
              FacetAngles a = angles(in);
              return dvec3(FacetFd_AshikhminShirley(a.NoV, a.NoL, 1.0, in.f0) * a.NoL);
            }),
  };
}

std::vector<Model> phong_models() {
  return {
      facet("Phong normalized",
            "c = FacetPhongNormalized(2.0 * a.NoL * a.NoV - a.LoV, FacetAlphaToBlinnPhongExponent(alpha)) * a.NoL;",
            [](const Inputs& in) {
              FacetAngles a = angles(in);
              return dvec3(FacetPhongNormalized(2 * a.NoL * a.NoV - a.LoV,
                                                FacetAlphaToBlinnPhongExponent(clamped_alpha(in))) * a.NoL);
            }),
      facet("Blinn-Phong normalized", "c = FacetBlinnPhongNormalized(a.NoH, FacetAlphaToBlinnPhongExponent(alpha)) * a.NoL;",
            [](const Inputs& in) {
              FacetAngles a = angles(in);
              return dvec3(FacetBlinnPhongNormalized(a.NoH, FacetAlphaToBlinnPhongExponent(clamped_alpha(in))) * a.NoL);
            },
            Energy::violator),
  };
}

std::vector<Model> microfacet_models() {
  return {
      facet("Cook-Torrance GGX", "c = FacetBRDF_CookTorranceGGX(n, v, l, F0, rough) * a.NoL;",
            [](const Inputs& in) { return FacetBRDF_CookTorranceGGX(in.n, in.v, in.l, dvec3(in.f0), in.roughness) * angles(in).NoL; }),
      facet("Cook-Torrance Beckmann", "c = FacetBRDF_CookTorranceBeckmann(n, v, l, F0, rough) * a.NoL;",
            [](const Inputs& in) {
              return FacetBRDF_CookTorranceBeckmann(in.n, in.v, in.l, dvec3(in.f0), in.roughness) * angles(in).NoL;
            }),
      facet("GGX FP16-safe D + Hammon V",
            "float3 nn = FacetSafeNormalize(n);\n"
            "float3 h = FacetSafeNormalize(FacetSafeNormalize(v) + FacetSafeNormalize(l));\n"
            "float a16 = max(rough * rough, FACET_MIN_ALPHA_FP16);\n"
            "c = FacetD_GGX_FP16Safe(nn, h, a16) * FacetV_SmithGGXCorrelatedFast(a.NoV, a.NoL, a16) *"
            " FacetF_Schlick(F0, 1.0, a.LoH) * a.NoL;",
            [](const Inputs& in) {
              FacetAngles a = angles(in);
              double a16 = std::max(in.roughness * in.roughness, FACET_MIN_ALPHA_FP16);
              return FacetD_GGX_FP16Safe(FacetSafeNormalize(in.n), half_vector(in), a16) *
                     FacetV_SmithGGXCorrelatedFast(a.NoV, a.NoL, a16) * FacetF_Schlick(dvec3(in.f0), 1.0, a.LoH) * a.NoL;
            }),
      facet("GGX separable Smith",
            "c = FacetD_GGX(a.NoH, alpha) * FacetV_SmithGGXSeparable(a.NoV, a.NoL, alpha) * FacetF_Schlick(F0, 1.0, a.LoH) * a.NoL;",
            [](const Inputs& in) {
              FacetAngles a = angles(in);
              double al = clamped_alpha(in);
              return FacetD_GGX(a.NoH, al) * FacetV_SmithGGXSeparable(a.NoV, a.NoL, al) *
                     FacetF_Schlick(dvec3(in.f0), 1.0, a.LoH) * a.NoL;
            }),
      facet("GGX Schlick-GGX",
            "c = FacetD_GGX(a.NoH, alpha) * FacetV_SchlickGGX(a.NoV, a.NoL, alpha) * FacetF_Schlick(F0, 1.0, a.LoH) * a.NoL;",
            [](const Inputs& in) {
              FacetAngles a = angles(in);
              double al = clamped_alpha(in);
              return FacetD_GGX(a.NoH, al) * FacetV_SchlickGGX(a.NoV, a.NoL, al) *
                     FacetF_Schlick(dvec3(in.f0), 1.0, a.LoH) * a.NoL;
            }),
      facet("GGX Schlick-GGX Karis",
            "c = FacetD_GGX(a.NoH, alpha) * FacetV_SchlickGGXKaris(a.NoV, a.NoL, rough) * FacetF_Schlick(F0, 1.0, a.LoH) * a.NoL;",
            [](const Inputs& in) {
              FacetAngles a = angles(in);
              return FacetD_GGX(a.NoH, clamped_alpha(in)) * FacetV_SchlickGGXKaris(a.NoV, a.NoL, in.roughness) *
                     FacetF_Schlick(dvec3(in.f0), 1.0, a.LoH) * a.NoL;
            }),
      facet("GGX + energy compensation",
            "float2 ab = FacetEnvBRDFApproxAB(rough, a.NoV);\n"
            "float e = E > 0.0 ? E : max(ab.x + ab.y, 0.05);\n"
            "c = FacetBRDF_CookTorranceGGX(n, v, l, F0, rough) * FacetEnergyCompensation(F0, e) * a.NoL;",
            [](const Inputs& in) {
              FacetAngles a = angles(in);
              glm::dvec2 ab = FacetEnvBRDFApproxAB(in.roughness, a.NoV);
              double e = in.energy > 0 ? in.energy : std::max(ab.x + ab.y, 0.05);
              return FacetBRDF_CookTorranceGGX(in.n, in.v, in.l, dvec3(in.f0), in.roughness) *
                     FacetEnergyCompensation(dvec3(in.f0), e) * a.NoL;
            },
            Energy::conserving, false),
      facet("Ward",
            "float3 t, b; stability_frame(n, t, b);\n"
            "float3 h = FacetSafeNormalize(FacetSafeNormalize(v) + FacetSafeNormalize(l));\n"
            "c = FacetSpecular_Ward(a.NoV, a.NoL, a.NoH, dot(h, t), dot(h, b), alpha, alpha) * a.NoL;",
            [](const Inputs& in) {
              FacetAngles a = angles(in);
              dvec3 x, y;
              frame(in.n, x, y);
              dvec3 h = half_vector(in);
              double al = clamped_alpha(in);
              return dvec3(FacetSpecular_Ward(a.NoV, a.NoL, a.NoH, glm::dot(h, x), glm::dot(h, y), al, al) * a.NoL);
            }),
      facet("Ashikhmin-Shirley specular",
            "float3 t, b; stability_frame(n, t, b);\n"
            "float3 h = FacetSafeNormalize(FacetSafeNormalize(v) + FacetSafeNormalize(l));\n"
            "float e = FacetAlphaToBlinnPhongExponent(alpha);\n"
            "c = FacetSpecular_AshikhminShirley(a.NoV, a.NoL, a.NoH, a.LoH, dot(h, t), dot(h, b), e, e, f0) * a.NoL;",
            [](const Inputs& in) {
              FacetAngles a = angles(in);
              dvec3 x, y;
              frame(in.n, x, y);
              dvec3 h = half_vector(in);
              double e = FacetAlphaToBlinnPhongExponent(clamped_alpha(in));
              return dvec3(FacetSpecular_AshikhminShirley(a.NoV, a.NoL, a.NoH, a.LoH, glm::dot(h, x), glm::dot(h, y), e, e,
                                                          in.f0) * a.NoL);
            }),
  };
}

// Disney with every lobe on: white base (the furnace), metallic = f0.
FacetDisneyMaterial disney_material(const Inputs& in) {
  FacetDisneyMaterial m;
  m.baseColor = dvec3(1.0);
  m.roughness = in.roughness, m.metallic = in.f0, m.clearcoat = 1, m.sheen = 1, m.subsurface = 0.5, m.anisotropic = 0.5;
  return m;
}

std::vector<Model> other_models() {
  return {
      // A normal shorter than FacetSafeNormalize's floor gives no frame:
      // such a pixel shades black, as every other model makes it.
      facet("Disney",
            "float3 nn = FacetSafeNormalize(n);\n"
            "if (dot(nn, nn) >= 0.25) {\n"
            "  float3 t, b; stability_frame(n, t, b);\n"
            "  FacetDisneyMaterial m;\n"
            "  m.baseColor = float3(1, 1, 1); m.subsurface = 0.5; m.metallic = f0; m.specular = 0.5;\n"
            "  m.specularTint = 0; m.roughness = rough; m.anisotropic = 0.5; m.sheen = 1; m.sheenTint = 0.5;\n"
            "  m.clearcoat = 1; m.clearcoatGloss = 1;\n"
            "  float3 ln = FacetSafeNormalize(l);\n"
            "  c = FacetBRDF_Disney(m, ln, FacetSafeNormalize(v), nn, t, b) * saturate(dot(nn, ln));\n"
            "}",
            [](const Inputs& in) {
              dvec3 nn = FacetSafeNormalize(in.n);
              if (glm::dot(nn, nn) < 0.25) return dvec3(0.0);
              dvec3 x, y;
              frame(in.n, x, y);
              dvec3 ln = FacetSafeNormalize(in.l);
              return FacetBRDF_Disney(disney_material(in), ln, FacetSafeNormalize(in.v), nn, x, y) *
                     saturate(glm::dot(nn, ln));
            },
            Energy::violator),
      facet("Translucency",
            "c = FacetTranslucency(FacetSafeNormalize(n), FacetSafeNormalize(v), FacetSafeNormalize(l), 0.3, 4.0 * rough,"
            " 1.0, 0.0, 1.0);",
            [](const Inputs& in) {
              return dvec3(FacetTranslucency(FacetSafeNormalize(in.n), FacetSafeNormalize(in.v), FacetSafeNormalize(in.l),
                                             0.3, 4.0 * in.roughness, 1.0, 0.0, 1.0));
            },
            Energy::none, false),
  };
}

// Unity's tiers: white albedo, metallic = f0, smoothness = 1 - roughness, a
// white light and no indirect light.
Model unity_tier(int tier) {
  std::string name = "BRDF" + std::to_string(tier) + "_Unity_PBS";
  std::string hlsl =
      "half3 spec; half omr;\n"
      "half3 diff = DiffuseAndSpecularFromMetallic(float3(1, 1, 1), f0, spec, omr);\n"
      "UnityLight li; li.color = float3(1, 1, 1); li.dir = l; li.ndotl = 0;\n"
      "UnityIndirect ind; ind.diffuse = 0; ind.specular = 0;\n"
      "c = " + name + "(diff, spec, omr, 1.0 - rough, n, v, li, ind).xyz;";
  auto cpu = [tier](const Inputs& in) {
    dvec3 spec;
    double omr;
    dvec3 diff = u::DiffuseAndSpecularFromMetallic(dvec3(1.0), in.f0, spec, omr);
    return dvec3(u::UNITY_BRDF_PBS(tier, diff, spec, omr, 1.0 - in.roughness, in.n, in.v, {dvec3(1.0), in.l, 0}, {}));
  };
  Energy energy = tier == 2 ? Energy::violator : Energy::conserving;
  return {name, kIncludeUnityBRDF, hlsl, cpu, energy, true, true};
}

std::vector<Model> unity_models() {
  std::vector<Model> m = {unity_tier(1), unity_tier(2), unity_tier(3)};
  m.push_back({"LightingStandard", kIncludeUnityPBS,
               "UnityGI gi; gi.light.color = float3(1, 1, 1); gi.light.dir = l; gi.light.ndotl = 0;"
               " gi.indirect.diffuse = 0; gi.indirect.specular = 0;\n"
               "SurfaceOutputStandard s = (SurfaceOutputStandard)0; s.Albedo = float3(1, 1, 1); s.Normal = n;"
               " s.Metallic = f0; s.Smoothness = 1.0 - rough; s.Occlusion = 1; s.Alpha = 1;\n"
               "c = LightingStandard(s, v, gi).xyz;",
               [](const Inputs& in) {
                 u::SurfaceOutputStandard s;
                 s.Albedo = dvec3(1.0), s.Normal = in.n, s.Metallic = in.f0, s.Smoothness = 1.0 - in.roughness;
                 u::UnityGI gi;
                 gi.light = {dvec3(1.0), in.l, 0};
                 return dvec3(u::LightingStandard(s, in.v, gi));
               },
               Energy::conserving, true, true});
  m.push_back({"LightingLambert", kIncludeLighting,
               "SurfaceOutput s = (SurfaceOutput)0; s.Albedo = float3(1, 1, 1); s.Normal = n; s.Alpha = 1;\n"
               "UnityGI gi = (UnityGI)0; gi.light.dir = l; gi.light.color = float3(1, 1, 1);\n"
               "c = LightingLambert(s, gi).xyz;",
               [](const Inputs& in) {
                 u::SurfaceOutput s;
                 s.Albedo = dvec3(1.0), s.Normal = in.n;
                 u::UnityGI gi;
                 gi.light = {dvec3(1.0), in.l, 0};
                 return dvec3(u::LightingLambert(s, gi, false));
               },
               Energy::conserving, true, true});
  return m;
}

// Per unit intensity, from each formula's clamps (derivations in
// docs/stability.md): diffuse f <= 6.25/pi; Phong (n+2)/(2 pi) at
// n = 2/alpha_min^2 - 2 = 4.9e5; GGX family D <= 1/(pi alpha_min^2) = 77 625
// times V NoL <= 1/alpha_min, times 20 for the compensation (E >= 0.05);
// Disney's D <= 1/(pi 0.001^2) times V NoL <= 1/NoV_min = 1e4; Unity's
// tiers from their own epsilons.
double bound_of(const std::string& name) {
  static const std::pair<const char*, double> bounds[] = {
      {"Lambert", 2.0}, {"Burley", 2.0}, {"Frostbite", 2.0}, {"Oren-Nayar qualitative", 2.0}, {"Oren-Nayar full", 2.0},
      {"Ashikhmin-Shirley diffuse", 2.0}, {"Phong normalized", 1e5}, {"Blinn-Phong normalized", 1e5},
      {"Translucency", 1.0}, {"Disney", 1e10}, {"BRDF1_Unity_PBS", 1e5}, {"BRDF2_Unity_PBS", 1e6},
      {"BRDF3_Unity_PBS", 20.0}, {"LightingStandard", 1e5}, {"LightingLambert", 1.1}};
  for (auto [n, b] : bounds)
    if (name == n) return b;
  return 1e9;  // the microfacet specular lobes
}

// |l + v|^2 below FacetSafeNormalize's 2^-14 floor: h comes out shorter than
// unit (both directions grazing near the mirror configuration).
bool short_half_vector(const float* x) {
  dvec3 v = FacetSafeNormalize(dvec3(x[3], x[4], x[5])), l = FacetSafeNormalize(dvec3(x[6], x[7], x[8]));
  double len2 = glm::dot(v + l, v + l);
  return len2 < FACET_HALF_MIN;
}
bool degenerate_normal(const float* x) {
  float n2 = x[0] * x[0] + x[1] * x[1] + x[2] * x[2];  // in fp32, as the shader's normalize()
  return n2 < 1e-30f;
}

std::vector<Model> all_models() {
  std::vector<Model> all;
  for (auto group : {diffuse_models(), phong_models(), microfacet_models(), other_models(), unity_models()})
    for (Model& m : group) all.push_back(std::move(m));
  for (Model& m : all) {
    m.bound = bound_of(m.name);
    if (m.name == "Disney") {
      m.known_issue = short_half_vector;
      m.known_issue_text =
          "FacetBRDF_Disney: h = FacetSafeNormalize(l + v) is not unit when |l + v|^2 < 2^-14 (v, l grazing near the "
          "mirror direction), and FacetD_GGXAnisotropic of a short h grows as 1/|h|^4: far above the lobe's bound";
    }
    if (m.name == "LightingStandard") {
      m.known_issue = degenerate_normal;
      m.known_issue_text =
          "LightingStandard: s.Normal = normalize(s.Normal) (as Unity) is NaN for a zero (or, in fp32, denormal) normal";
    }
  }
  return all;
}

}  // namespace

const std::vector<Model>& models() {
  static const std::vector<Model> list = all_models();
  return list;
}

const Model& model(const std::string& name) {
  for (const Model& m : models())
    if (m.name == name) return m;
  throw std::out_of_range("no stability model named " + name);
}

std::string evaluator_hlsl(const Model& m) {
  return "float3 n = float3(x[0], x[1], x[2]);\nfloat3 v = float3(x[3], x[4], x[5]);\n"
         "float3 l = float3(x[6], x[7], x[8]);\nfloat rough = x[9];\nfloat f0 = x[10];\nfloat E = x[12];\n"
         "float3 c = 0;\n{\n" + m.hlsl + "\n}\nr.xyz = c * x[11];";
}

std::array<float, kInputs> pack(const Inputs& in) {
  return {float(in.n.x), float(in.n.y), float(in.n.z), float(in.v.x), float(in.v.y), float(in.v.z),
          float(in.l.x), float(in.l.y), float(in.l.z), float(in.roughness), float(in.f0), float(in.intensity),
          float(in.energy)};
}

Inputs unpack(const float* x) {
  Inputs in;
  in.n = {x[0], x[1], x[2]};
  in.v = {x[3], x[4], x[5]};
  in.l = {x[6], x[7], x[8]};
  in.roughness = x[9], in.f0 = x[10], in.intensity = x[11], in.energy = x[12];
  return in;
}

}  // namespace facet::stability
