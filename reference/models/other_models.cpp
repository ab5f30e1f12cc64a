// The Disney, translucency and Unity rows of the model table.
#include "facet/reference/unity_standard.h"
#include "model_rows.h"

namespace facet::reference::models {

using glm::dvec3;
using glm::dvec4;
namespace u = facet::reference::unity;

namespace {

// The point form: every lobe on, white base (the furnace), metallic = f0.
FacetDisneyMaterial disney_material(const ModelPoint& in) {
  FacetDisneyMaterial m;
  m.baseColor = dvec3(1.0);
  m.roughness = in.roughness, m.metallic = in.f0, m.clearcoat = 1, m.sheen = 1, m.subsurface = 0.5, m.anisotropic = 0.5;
  return m;
}

LocalBrdf disney_brdf(const ModelParams& p) {
  FacetDisneyMaterial m;
  m.baseColor = p.col("baseColor");
  m.subsurface = p.num("subsurface");
  m.metallic = p.num("metallic");
  m.specular = p.num("specular");
  m.specularTint = p.num("specularTint");
  m.roughness = p.num("roughness");
  m.anisotropic = p.num("anisotropic");
  m.sheen = p.num("sheen");
  m.sheenTint = p.num("sheenTint");
  m.clearcoat = p.num("clearcoat");
  m.clearcoatGloss = p.num("clearcoatGloss");
  return [m](const dvec3& v, const dvec3& l) {
    if (v.z <= 0.0 || l.z <= 0.0) return dvec3(0.0);
    return FacetBRDF_Disney(m, l, v, dvec3(0, 0, 1), dvec3(1, 0, 0), dvec3(0, 1, 0));
  };
}

// |l + v|^2 below FacetSafeNormalize's 2^-14 floor: h comes out shorter than
// unit (both directions grazing near the mirror configuration).
bool short_half_vector(const ModelPoint& in) {
  dvec3 v = FacetSafeNormalize(in.v), l = FacetSafeNormalize(in.l);
  return glm::dot(v + l, v + l) < FACET_HALF_MIN;
}

// A normal shorter than FacetSafeNormalize's floor gives no frame: such a
// pixel shades black, as every other model makes it.
LightingModel disney() {
  LightingModel m = facet_row("disney", "Disney",
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
                              [](const ModelPoint& in) {
                                dvec3 nn = FacetSafeNormalize(in.n);
                                if (glm::dot(nn, nn) < 0.25) return dvec3(0.0);
                                dvec3 x, y;
                                frame(in.n, x, y);
                                dvec3 ln = FacetSafeNormalize(in.l);
                                return FacetBRDF_Disney(disney_material(in), ln, FacetSafeNormalize(in.v), nn, x, y) *
                                       saturate(glm::dot(nn, ln));
                              },
                              Energy::violator);
  m.known_issue = short_half_vector;
  m.known_issue_text =
      "FacetBRDF_Disney: h = FacetSafeNormalize(l + v) is not unit when |l + v|^2 < 2^-14 (v, l grazing near the "
      "mirror direction), and FacetD_GGXAnisotropic of a short h grows as 1/|h|^4: far above the lobe's bound";
  FacetDisneyMaterial d;
  with_params(m, "FacetBRDF_Disney",
              {colour("baseColor", d.baseColor, "base colour (linear)"), number("subsurface", d.subsurface, 0, 1, ""),
               number("metallic", d.metallic, 0, 1, ""), number("specular", d.specular, 0, 1, "0.5 is f0 = 0.04"),
               number("specularTint", d.specularTint, 0, 1, ""), number("roughness", d.roughness, 0, 1, ""),
               number("anisotropic", d.anisotropic, 0, 1, ""), number("sheen", d.sheen, 0, 1, ""),
               number("sheenTint", d.sheenTint, 0, 1, ""), number("clearcoat", d.clearcoat, 0, 1, ""),
               number("clearcoatGloss", d.clearcoatGloss, 0, 1, "")},
              disney_brdf);
  return m;
}

LightingModel translucency() {
  LightingModel m = facet_row(
      "translucency", "Translucency",
      "c = FacetTranslucency(FacetSafeNormalize(n), FacetSafeNormalize(v), FacetSafeNormalize(l), 0.3, 4.0 * rough,"
      " 1.0, 0.0, 1.0);",
      [](const ModelPoint& in) {
        return dvec3(FacetTranslucency(FacetSafeNormalize(in.n), FacetSafeNormalize(in.v), FacetSafeNormalize(in.l), 0.3,
                                       4.0 * in.roughness, 1.0, 0.0, 1.0));
      },
      Energy::none, false);
  m.stdlib = "FacetTranslucency";
  return m;
}

// Unity's tiers. The point form: white albedo, metallic = f0, smoothness =
// 1 - roughness, a white light and no indirect light. The parameter form:
// UNITY_BRDF_PBS returns colour * NoL in Unity's units (light colours carry
// the pi), so the BRDF is that over pi * NoL.
LightingModel unity_tier(int tier) {
  std::string function = "BRDF" + std::to_string(tier) + "_Unity_PBS";
  LightingModel m;
  m.id = "unity-brdf" + std::to_string(tier);
  m.name = function;
  m.includes = kIncludeUnityBRDF;
  m.hlsl = "half3 spec; half omr;\n"
           "half3 diff = DiffuseAndSpecularFromMetallic(float3(1, 1, 1), f0, spec, omr);\n"
           "UnityLight li; li.color = float3(1, 1, 1); li.dir = l; li.ndotl = 0;\n"
           "UnityIndirect ind; ind.diffuse = 0; ind.specular = 0;\n"
           "c = " + function + "(diff, spec, omr, 1.0 - rough, n, v, li, ind).xyz;";
  m.cpu = [tier](const ModelPoint& in) {
    dvec3 spec;
    double omr;
    dvec3 diff = u::DiffuseAndSpecularFromMetallic(dvec3(1.0), in.f0, spec, omr);
    return dvec3(u::UNITY_BRDF_PBS(tier, diff, spec, omr, 1.0 - in.roughness, in.n, in.v, {dvec3(1.0), in.l, 0}, {}));
  };
  m.energy = tier == 2 ? Energy::violator : Energy::conserving;
  m.unity = true;
  with_params(m, function + " (metallic workflow)",
              {colour("albedo", dvec3(0.8), "albedo"), number("metallic", 0.0, 0, 1, ""),
               number("smoothness", 0.5, 0, 1, "1 - perceptual roughness")},
              [tier](const ModelParams& p) -> LocalBrdf {
                dvec3 spec;
                double oneMinusReflectivity = 0;
                dvec3 diff = u::DiffuseAndSpecularFromMetallic(p.col("albedo"), p.num("metallic"), spec, oneMinusReflectivity);
                double smoothness = p.num("smoothness");
                return [=](const dvec3& v, const dvec3& l) {
                  if (v.z <= 0.0 || l.z <= 0.0) return dvec3(0.0);
                  u::UnityLight light{dvec3(1.0), l, l.z};
                  dvec4 c = u::UNITY_BRDF_PBS(tier, diff, spec, oneMinusReflectivity, smoothness, dvec3(0, 0, 1), v, light,
                                              u::UnityIndirect{});
                  return dvec3(c) / (kPi * l.z);
                };
              });
  return m;
}

// s.Normal = normalize(s.Normal), as Unity, is NaN for a zero (or, in fp32,
// denormal) normal: the squared length is taken in fp32, as the shader's normalize().
bool degenerate_normal(const ModelPoint& in) {
  float x = float(in.n.x), y = float(in.n.y), z = float(in.n.z);
  return x * x + y * y + z * z < 1e-30f;
}

LightingModel lighting_standard() {
  LightingModel m;
  m.id = "unity-lighting-standard";
  m.name = "LightingStandard";
  m.stdlib = "LightingStandard (UnityPBSLighting.cginc)";
  m.includes = kIncludeUnityPBS;
  m.hlsl = "UnityGI gi; gi.light.color = float3(1, 1, 1); gi.light.dir = l; gi.light.ndotl = 0;"
           " gi.indirect.diffuse = 0; gi.indirect.specular = 0;\n"
           "SurfaceOutputStandard s = (SurfaceOutputStandard)0; s.Albedo = float3(1, 1, 1); s.Normal = n;"
           " s.Metallic = f0; s.Smoothness = 1.0 - rough; s.Occlusion = 1; s.Alpha = 1;\n"
           "c = LightingStandard(s, v, gi).xyz;";
  m.cpu = [](const ModelPoint& in) {
    u::SurfaceOutputStandard s;
    s.Albedo = dvec3(1.0), s.Normal = in.n, s.Metallic = in.f0, s.Smoothness = 1.0 - in.roughness;
    u::UnityGI gi;
    gi.light = {dvec3(1.0), in.l, 0};
    return dvec3(u::LightingStandard(s, in.v, gi));
  };
  m.unity = true;
  m.known_issue = degenerate_normal;
  m.known_issue_text =
      "LightingStandard: s.Normal = normalize(s.Normal) (as Unity) is NaN for a zero (or, in fp32, denormal) normal";
  return m;
}

LightingModel lighting_lambert() {
  LightingModel m;
  m.id = "unity-lighting-lambert";
  m.name = "LightingLambert";
  m.stdlib = "LightingLambert (Lighting.cginc)";
  m.includes = kIncludeLighting;
  m.hlsl = "SurfaceOutput s = (SurfaceOutput)0; s.Albedo = float3(1, 1, 1); s.Normal = n; s.Alpha = 1;\n"
           "UnityGI gi = (UnityGI)0; gi.light.dir = l; gi.light.color = float3(1, 1, 1);\n"
           "c = LightingLambert(s, gi).xyz;";
  m.cpu = [](const ModelPoint& in) {
    u::SurfaceOutput s;
    s.Albedo = dvec3(1.0), s.Normal = in.n;
    u::UnityGI gi;
    gi.light = {dvec3(1.0), in.l, 0};
    return dvec3(u::LightingLambert(s, gi, false));
  };
  m.unity = true;
  return m;
}

}  // namespace

std::vector<LightingModel> other_models() { return {disney(), translucency()}; }

std::vector<LightingModel> unity_models() {
  return {unity_tier(1), unity_tier(2), unity_tier(3), lighting_standard(), lighting_lambert()};
}

}  // namespace facet::reference::models
