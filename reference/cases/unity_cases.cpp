// Cases for the Unity-named lighting functions of stdlib/ (UnityStandardBRDF,
// UnityStandardUtils, UnityPBSLighting, Lighting, UnityCG) against their
// twins in facet/reference/unity_standard.h. Each parameter (roughness,
// metallic, tier) gets its own setting.
#include "case_helpers.h"

#include "facet/reference/unity_standard.h"

#include <cmath>
#include <cstdio>

namespace facet::reference {
namespace {

using namespace cases;
namespace u = unity;

const char* kIncludeUnityBRDF = "#include \"UnityStandardBRDF.cginc\"\n#include \"UnityStandardUtils.cginc\"\n";
// The tier is pinned: the evaluator's shader model would otherwise pick it.
const char* kIncludeUnityPBS =
    "#include \"UnityStandardBRDF.cginc\"\n#define UNITY_BRDF_PBS BRDF1_Unity_PBS\n#include \"UnityPBSLighting.cginc\"\n";
const char* kIncludeLighting = "#include \"Lighting.cginc\"\n";

glm::dvec3 put3(double* r, const glm::dvec3& v) {
  r[0] = v.x, r[1] = v.y, r[2] = v.z;
  return v;
}
glm::dvec3 fp3(const glm::dvec3& v) { return {fp(v.x), fp(v.y), fp(v.z)}; }
void put4(double* r, const glm::dvec4& v) { r[0] = v.x, r[1] = v.y, r[2] = v.z, r[3] = v.w; }
glm::dvec3 v3d(const float* x, int i) { return {x[i], x[i + 1], x[i + 2]}; }

// Unit n, v, l with v in front (NdotV >= 0.05), l from slightly below the
// horizon, and l != -v (there H is undefined).
void draw_nvl(Rng& g, float* x) {
  Frame f = random_frame(g);
  glm::dvec3 v, l;
  do {
    v = g.direction(f.n, 0.05, 1.0);
    l = g.direction(f.n, -0.3, 1.0);
  } while (glm::dot(v + l, v + l) < 0.01);
  put(x, 0, f.n);
  put(x, 3, v);
  put(x, 6, l);
}

// GGX's denominator d = 1 - NdotH^2 (1 - a^2) cancels near NdotH = 1 down to
// about a^2, so an fp32 absolute error e in d (or e / 2 in NdotH) becomes a
// relative error 2 e / d in D. With a budget of half the 1e-4 tolerance (the
// rest is left to the other factors), 1e-4 holds where d >= 4 e / 1e-4; the
// largest NdotH that keeps it, or 1 where a^2 alone is large enough.
double ggx_max_nh(double roughness, double e) {
  double a2 = fp(roughness) * fp(roughness), d_min = 4.0 * e / 1e-4;
  return a2 >= d_min ? 1.0 : std::sqrt((1.0 - d_min) / (1.0 - a2));
}
// e for GGXTerm on a float NdotH: the rounding of (NdotH a^2 - NdotH) NdotH
// (~1, so up to 6e-8) and of the sum and d itself, about three half-ulps of 1.
constexpr double kGgxErrorScalar = 1.8e-7;
// e for the BRDFs, whose NdotH the shader computes from float n, v, l:
// normalize(l + v) and the dot add about 2.4e-7 to NdotH, twice that to d.
constexpr double kGgxErrorVectors = 4.8e-7;

std::string nh_bound_text(double max_nh) {
  char buf[48];
  std::snprintf(buf, sizeof buf, ", NdotH <= %.5f", max_nh);
  return max_nh < 1.0 ? buf : "";
}

// Dense towards hi: hi (1 - t^4), so the ill-conditioned edge is sampled.
double toward(Rng& g, double hi) {
  double t = g.uniform();
  return hi * (1.0 - t * t * t * t);
}

void add_terms(std::vector<FunctionCase>& out) {
  out.push_back(make_case("Pow5", "x in [-0.1, 1]", 1, 1, kIncludeUnityBRDF, "r.x = Pow5(x[0]);",
                          [](const double* x, double* r) { r[0] = u::Pow5(x[0]); },
                          [](Rng& g, float* x) { x[0] = float(g.uniform(-0.1, 1.0)); }));
  out.push_back(make_case("Unity_SafeNormalize", "|v| in [0, 2], zero included", 3, 3, kIncludeUnityBRDF,
                          "r.xyz = Unity_SafeNormalize(" + xv(0) + ");",
                          [](const double* x, double* r) { put3(r, u::Unity_SafeNormalize(v3(x, 0))); },
                          [](Rng& g, float* x) {
                            double len = g.uniform() < 0.05 ? 0.0 : g.log_uniform(1e-3, 2.0);
                            put(x, 0, len * g.unit_vector());
                          }));
  for (double f0 : {0.04, 0.5, 1.0}) {
    std::string set = "F0=" + lit(f0);
    out.push_back(make_case("FresnelTerm", set, 1, 3, kIncludeUnityBRDF,
                            "r.xyz = FresnelTerm(float3(" + lit(f0) + ", 0.5, 0.9), x[0]);",
                            [f0](const double* x, double* r) { put3(r, u::FresnelTerm({fp(f0), 0.5, 0.9}, x[0])); },
                            [](Rng& g, float* x) { x[0] = float(g.uniform()); }));
    out.push_back(make_case("FresnelLerp", set, 2, 3, kIncludeUnityBRDF,
                            "r.xyz = FresnelLerp(float3(" + lit(f0) + ", 0.5, 0.9), x[1], x[0]);",
                            [f0](const double* x, double* r) {
                              put3(r, u::FresnelLerp({fp(f0), 0.5, 0.9}, glm::dvec3(x[1]), x[0]));
                            },
                            [](Rng& g, float* x) { x[0] = float(g.uniform()), x[1] = float(g.uniform()); }));
    out.push_back(make_case("FresnelLerpFast", set, 2, 3, kIncludeUnityBRDF,
                            "r.xyz = FresnelLerpFast(float3(" + lit(f0) + ", 0.5, 0.9), x[1], x[0]);",
                            [f0](const double* x, double* r) {
                              put3(r, u::FresnelLerpFast({fp(f0), 0.5, 0.9}, glm::dvec3(x[1]), x[0]));
                            },
                            [](Rng& g, float* x) { x[0] = float(g.uniform()), x[1] = float(g.uniform()); }));
  }
  for (double pr : {0.1, 0.5, 0.9}) {
    std::string set = "perceptualRoughness=" + lit(pr);
    out.push_back(make_case("DisneyDiffuse", set, 3, 1, kIncludeUnityBRDF,
                            "r.x = DisneyDiffuse(x[0], x[1], x[2], " + lit(pr) + ");",
                            [pr](const double* x, double* r) { r[0] = u::DisneyDiffuse(x[0], x[1], x[2], fp(pr)); },
                            [](Rng& g, float* x) {
                              for (int k = 0; k < 3; ++k) x[k] = float(g.uniform());
                            }));
    double a = pr * pr;
    std::string aset = "roughness=" + lit(a);
    out.push_back(make_case("SmithJointGGXVisibilityTerm", aset, 2, 1, kIncludeUnityBRDF,
                            "r.x = SmithJointGGXVisibilityTerm(x[0], x[1], " + lit(a) + ");",
                            [a](const double* x, double* r) { r[0] = u::SmithJointGGXVisibilityTerm(x[0], x[1], fp(a)); },
                            [](Rng& g, float* x) { x[0] = float(g.uniform()), x[1] = float(g.uniform()); }));
    out.push_back(make_case("SmithBeckmannVisibilityTerm", aset, 2, 1, kIncludeUnityBRDF,
                            "r.x = SmithBeckmannVisibilityTerm(x[0], x[1], " + lit(a) + ");",
                            [a](const double* x, double* r) { r[0] = u::SmithBeckmannVisibilityTerm(x[0], x[1], fp(a)); },
                            [](Rng& g, float* x) { x[0] = float(g.uniform()), x[1] = float(g.uniform()); }));
    // At roughness 0.01 the peak (NdotH > 0.99644, where D is ill-conditioned)
    // is left out; half the points are drawn densely towards the bound.
    double max_nh = ggx_max_nh(a, kGgxErrorScalar);
    out.push_back(make_case("GGXTerm", aset + nh_bound_text(max_nh), 1, 1, kIncludeUnityBRDF,
                            "r.x = GGXTerm(x[0], " + lit(a) + ");",
                            [a](const double* x, double* r) { r[0] = u::GGXTerm(x[0], fp(a)); },
                            [max_nh](Rng& g, float* x) {
                              x[0] = float(g.uniform() < 0.5 ? max_nh * g.uniform() : toward(g, max_nh));
                              if (x[0] > max_nh) x[0] = std::nextafter(float(max_nh), 0.0f);
                            }));
  }
  // pow(x, n) = exp2(n log2 x): the GPU's log2 is off by an absolute e ~1.5e-7
  // just below x = 1 (lavapipe: what the n = 510 case's 5.4e-5 implies;
  // Vulkan allows 2^-21), which becomes
  // a relative error of ln 2 * n * e ~ n * 1e-7 wherever x^n is not tiny, i.e.
  // on the whole lobe: no input range avoids it. So perceptual roughness 0.1
  // (n = 19998: ~2e-3) is not checked; 0.25 (n = 510: ~5e-5) is the
  // narrowest lobe that is.
  for (double pr : {0.25, 0.5, 0.9}) {
    double n = u::PerceptualRoughnessToSpecPower(fp(pr));
    out.push_back(make_case("NDFBlinnPhongNormalizedTerm", "n=" + lit(n), 1, 1, kIncludeUnityBRDF,
                            "r.x = NDFBlinnPhongNormalizedTerm(x[0], " + lit(n) + ");",
                            [n](const double* x, double* r) { r[0] = u::NDFBlinnPhongNormalizedTerm(x[0], fp(n)); },
                            [](Rng& g, float* x) { x[0] = float(g.uniform() < 0.5 ? g.uniform() : toward(g, 1.0)); }));
  }
  out.push_back(make_case("PerceptualRoughnessToSpecPower", "r in [0.1, 1]", 1, 1, kIncludeUnityBRDF,
                          "r.x = PerceptualRoughnessToSpecPower(x[0]);",
                          [](const double* x, double* r) { r[0] = u::PerceptualRoughnessToSpecPower(x[0]); },
                          [](Rng& g, float* x) { x[0] = float(g.uniform(0.1, 1.0)); }));
}

void add_setups(std::vector<FunctionCase>& out) {
  out.push_back(make_case("EnergyConservationBetweenDiffuseAndSpecular", "albedo, specColor in [0, 1]^3", 6, 4,
                          kIncludeUnityBRDF,
                          "half omr; r.xyz = EnergyConservationBetweenDiffuseAndSpecular(" + xv(0) + ", " + xv(3) +
                              ", omr); r.w = omr;",
                          [](const double* x, double* r) {
                            double omr;
                            put3(r, u::EnergyConservationBetweenDiffuseAndSpecular(v3(x, 0), v3(x, 3), omr));
                            r[3] = omr;
                          },
                          [](Rng& g, float* x) {
                            for (int k = 0; k < 6; ++k) x[k] = float(g.uniform());
                          }));
  for (double m : {0.0, 0.5, 1.0}) {
    out.push_back(make_case("DiffuseAndSpecularFromMetallic", "metallic=" + lit(m), 3, 4, kIncludeUnityBRDF,
                            "half3 spec; half omr; r.xyz = DiffuseAndSpecularFromMetallic(" + xv(0) + ", " + lit(m) +
                                ", spec, omr); r.w = omr + spec.g;",
                            [m](const double* x, double* r) {
                              glm::dvec3 spec;
                              double omr;
                              put3(r, u::DiffuseAndSpecularFromMetallic(v3(x, 0), fp(m), spec, omr));
                              r[3] = omr + spec.y;
                            },
                            [](Rng& g, float* x) {
                              for (int k = 0; k < 3; ++k) x[k] = float(g.uniform());
                            }));
  }
  out.push_back(make_case("PreMultiplyAlpha", "without _ALPHAPREMULTIPLY_ON", 5, 4, kIncludeUnityBRDF,
                          "half a; r.xyz = PreMultiplyAlpha(" + xv(0) + ", x[3], x[4], a); r.w = a;",
                          [](const double* x, double* r) {
                            double a;
                            put3(r, u::PreMultiplyAlpha(v3(x, 0), x[3], x[4], a));
                            r[3] = a;
                          },
                          [](Rng& g, float* x) {
                            for (int k = 0; k < 5; ++k) x[k] = float(g.uniform());
                          }));
}

// BRDF inputs: x[0..8] n, v, l; x[9..11] albedo; x[12] indirect diffuse;
// x[13] indirect specular. Light colour (1, 0.9, 0.8).
const glm::dvec3 kLightColor(1.0, 0.9, 0.8);
void draw_brdf(Rng& g, float* x) {
  draw_nvl(g, x);
  for (int k = 9; k < 12; ++k) x[k] = float(g.uniform());
  x[12] = float(g.uniform());
  x[13] = float(g.uniform(0.0, 2.0));
}
// As draw_nvl, with n.normalize(v + l) <= max_nh on the float vectors the
// shader and the twin see. Half the points reflect v about an h just inside
// the bound, so the edge of the allowed part of the lobe is well covered.
void draw_nvl_below(Rng& g, float* x, double max_nh) {
  for (;;) {
    Frame f = random_frame(g);
    glm::dvec3 v = g.direction(f.n, 0.05, 1.0), l;
    if (g.uniform() < 0.5) {
      l = g.direction(f.n, -0.3, 1.0);
    } else {
      glm::dvec3 h = g.direction(f.n, max_nh - 0.02, max_nh);
      l = 2.0 * glm::dot(v, h) * h - v;
    }
    if (glm::dot(v + l, v + l) < 0.01 || glm::dot(l, f.n) < -0.3) continue;
    put(x, 0, f.n);
    put(x, 3, v);
    put(x, 6, l);
    glm::dvec3 sum = v3d(x, 3) + v3d(x, 6);
    if (glm::dot(v3d(x, 0), sum) <= max_nh * std::sqrt(glm::dot(sum, sum))) return;
  }
}
Draw brdf_draw(double max_nh) {
  if (max_nh >= 1.0) return draw_brdf;
  return [max_nh](Rng& g, float* x) {
    draw_nvl_below(g, x, max_nh);
    for (int k = 9; k < 12; ++k) x[k] = float(g.uniform());
    x[12] = float(g.uniform());
    x[13] = float(g.uniform(0.0, 2.0));
  };
}
const char* kBrdfPrelude =
    "UnityLight l; l.color = float3(1.0, 0.9, 0.8); l.dir = float3(x[6], x[7], x[8]); l.ndotl = 0;\n"
    "UnityIndirect ind; ind.diffuse = x[12]; ind.specular = x[13];\n";
u::UnityLight twin_light(const double* x) { return {fp3(kLightColor), v3(x, 6), 0}; }
u::UnityIndirect twin_indirect(const double* x) { return {glm::dvec3(x[12]), glm::dvec3(x[13])}; }

// BRDF1/2 at smoothness s have GGX roughness (1 - s)^2 and keep NdotH below
// ggx_max_nh with the error of an NdotH made from vectors: 0.9904 at s = 0.9,
// so there the tail of the lobe (D <= 0.09) is checked, not its peak (3183),
// which fp32 can only resolve in FacetD_GGX_FP16Safe's form.
// BRDF3 has a Phong lobe (R.L)^m, m = PerceptualRoughnessToSpecPower(1 - s) / 4,
// whose relative error is about m times the fp32 error of R.L plus that of
// log2 (together ~1.5e-7) wherever it is neither capped at 16 nor tiny: the
// whole lobe, so no input range helps. At s = 0.9 (m = 5000) that is up to
// 7.5e-4; s = 0.8 (m = 312: ~5e-5) is the narrowest BRDF3 lobe checked.
double brdf_max_nh(int tier, double smoothness) {
  return tier == 3 ? 1.0 : ggx_max_nh((1.0 - smoothness) * (1.0 - smoothness), kGgxErrorVectors);
}
std::vector<double> brdf_smoothnesses(int tier) {
  if (tier == 3) return {0.1, 0.5, 0.8};
  return {0.1, 0.5, 0.9};
}

void add_brdfs(std::vector<FunctionCase>& out) {
  for (int tier = 1; tier <= 3; ++tier) {
    std::string name = "BRDF" + std::to_string(tier) + "_Unity_PBS";
    for (double smoothness : brdf_smoothnesses(tier)) {
      double max_nh = brdf_max_nh(tier, smoothness);
      for (double metallic : {0.0, 1.0}) {
        std::string set = "smoothness=" + lit(smoothness) + " metallic=" + lit(metallic) + nh_bound_text(max_nh);
        std::string hlsl = std::string(kBrdfPrelude) + "half3 spec; half omr;\n" +
                           "half3 diff = DiffuseAndSpecularFromMetallic(" + xv(9) + ", " + lit(metallic) +
                           ", spec, omr);\n" + "r = " + name + "(diff, spec, omr, " + lit(smoothness) + ", " + xv(0) +
                           ", " + xv(3) + ", l, ind);";
        out.push_back(make_case(
            name, set, 14, 4, kIncludeUnityBRDF, hlsl,
            [tier, smoothness, metallic](const double* x, double* r) {
              glm::dvec3 spec;
              double omr;
              glm::dvec3 diff = u::DiffuseAndSpecularFromMetallic(v3(x, 9), fp(metallic), spec, omr);
              put4(r, u::UNITY_BRDF_PBS(tier, diff, spec, omr, fp(smoothness), v3(x, 0), v3(x, 3), twin_light(x),
                                        twin_indirect(x)));
            },
            brdf_draw(max_nh)));
      }
    }
  }
}

void add_lighting_models(std::vector<FunctionCase>& out) {
  // Lighting.cginc without UNITY_PASS_FORWARDBASE: no indirect term.
  out.push_back(make_case("LightingLambert", "no indirect (not ForwardBase)", 14, 4, kIncludeLighting,
                          "SurfaceOutput s = (SurfaceOutput)0; s.Albedo = " + xv(9) + "; s.Normal = " + xv(0) +
                              "; s.Alpha = 0.5;\nUnityGI gi = (UnityGI)0; gi.light.dir = " + xv(6) +
                              "; gi.light.color = float3(1.0, 0.9, 0.8);\nr = LightingLambert(s, gi);",
                          [](const double* x, double* r) {
                            u::SurfaceOutput s;
                            s.Albedo = v3(x, 9), s.Normal = v3(x, 0), s.Alpha = 0.5;
                            u::UnityGI gi;
                            gi.light = twin_light(x);
                            put4(r, u::LightingLambert(s, gi, false));
                          },
                          draw_brdf));
  for (double smoothness : {0.1, 0.5, 0.9}) {
    for (double metallic : {0.0, 1.0}) {
      double max_nh = brdf_max_nh(1, smoothness);
      std::string set = "BRDF1 smoothness=" + lit(smoothness) + " metallic=" + lit(metallic) + nh_bound_text(max_nh);
      out.push_back(make_case(
          "LightingStandard", set, 14, 4, kIncludeUnityPBS,
          std::string("UnityGI gi; gi.light.color = float3(1.0, 0.9, 0.8); gi.light.dir = float3(x[6], x[7], x[8]);"
                      " gi.light.ndotl = 0; gi.indirect.diffuse = x[12]; gi.indirect.specular = x[13];\n") +
              "SurfaceOutputStandard s = (SurfaceOutputStandard)0; s.Albedo = " + xv(9) + "; s.Normal = " + xv(0) +
              "; s.Metallic = " + lit(metallic) + "; s.Smoothness = " + lit(smoothness) +
              "; s.Occlusion = 1; s.Alpha = 0.5;\nr = LightingStandard(s, " + xv(3) + ", gi);",
          [smoothness, metallic](const double* x, double* r) {
            u::SurfaceOutputStandard s;
            s.Albedo = v3(x, 9), s.Normal = v3(x, 0), s.Metallic = fp(metallic), s.Smoothness = fp(smoothness);
            s.Alpha = 0.5;
            u::UnityGI gi{twin_light(x), twin_indirect(x)};
            put4(r, u::LightingStandard(s, v3(x, 3), gi));
          },
          brdf_draw(max_nh)));
      out.push_back(make_case(
          "LightingStandardSpecular",
          "BRDF1 smoothness=" + lit(smoothness) + " specular=" + lit(metallic ? 0.9 : 0.04) + nh_bound_text(max_nh),
          14, 4, kIncludeUnityPBS,
          std::string("UnityGI gi; gi.light.color = float3(1.0, 0.9, 0.8); gi.light.dir = float3(x[6], x[7], x[8]);"
                      " gi.light.ndotl = 0; gi.indirect.diffuse = x[12]; gi.indirect.specular = x[13];\n") +
              "SurfaceOutputStandardSpecular s = (SurfaceOutputStandardSpecular)0; s.Albedo = " + xv(9) +
              "; s.Specular = " + lit(metallic ? 0.9 : 0.04) + "; s.Normal = " + xv(0) + "; s.Smoothness = " +
              lit(smoothness) + "; s.Occlusion = 1; s.Alpha = 0.5;\nr = LightingStandardSpecular(s, " + xv(3) +
              ", gi);",
          [smoothness, metallic](const double* x, double* r) {
            u::SurfaceOutputStandardSpecular s;
            s.Albedo = v3(x, 9), s.Specular = glm::dvec3(fp(metallic ? 0.9 : 0.04)), s.Normal = v3(x, 0);
            s.Smoothness = fp(smoothness), s.Alpha = 0.5;
            u::UnityGI gi{twin_light(x), twin_indirect(x)};
            put4(r, u::LightingStandardSpecular(s, v3(x, 3), gi));
          },
          brdf_draw(max_nh)));
    }
  }
}

void add_color_and_sh(std::vector<FunctionCase>& out) {
  out.push_back(make_case("Luminance", "linear", 3, 1, kIncludeUnityBRDF, "r.x = Luminance(" + xv(0) + ");",
                          [](const double* x, double* r) { r[0] = u::Luminance(v3(x, 0)); },
                          [](Rng& g, float* x) { put(x, 0, {g.uniform(0, 4), g.uniform(0, 4), g.uniform(0, 4)}); }));
  out.push_back(make_case("LinearToGammaSpace", "c in [0, 2]", 3, 3, kIncludeUnityBRDF,
                          "r.xyz = LinearToGammaSpace(" + xv(0) + ");",
                          [](const double* x, double* r) { put3(r, u::LinearToGammaSpace(v3(x, 0))); },
                          [](Rng& g, float* x) { put(x, 0, {g.uniform(0, 2), g.log_uniform(1e-4, 1), g.uniform()}); }));
  out.push_back(make_case("GammaToLinearSpace", "c in [0, 1]", 3, 3, kIncludeUnityBRDF,
                          "r.xyz = GammaToLinearSpace(" + xv(0) + ");",
                          [](const double* x, double* r) { put3(r, u::GammaToLinearSpace(v3(x, 0))); },
                          [](Rng& g, float* x) { put(x, 0, {g.uniform(), g.log_uniform(1e-4, 1), g.uniform()}); }));
  // ShadeSH9's evaluation (FacetSHEval, which ShadeSH9 calls with the
  // unity_SH* uniforms) for two fixed environments.
  const u::SHCoefficients envs[] = {
      {{0.1, 0.2, 0.3, 0.6}, {0.05, 0.25, -0.1, 0.5}, {-0.1, 0.3, 0.2, 0.7},
       {0.02, -0.03, 0.04, 0.05}, {0.01, 0.02, -0.03, 0.04}, {-0.02, 0.01, 0.03, -0.01}, {0.03, -0.02, 0.01, 0}},
      {{0, 0.8, 0, 0.9}, {0, 0.7, 0, 0.85}, {0, 0.5, 0, 0.8}, {0, 0, 0, 0}, {0, 0, 0, 0}, {0, 0, 0, 0}, {0.1, 0.1, 0.1, 0}},
  };
  for (int e = 0; e < 2; ++e) {
    const u::SHCoefficients& sh = envs[e];
    auto f4 = [](const glm::dvec4& v) {
      return "float4(" + lit(v.x) + ", " + lit(v.y) + ", " + lit(v.z) + ", " + lit(v.w) + ")";
    };
    std::string args = f4(sh.SHAr) + ", " + f4(sh.SHAg) + ", " + f4(sh.SHAb) + ", " + f4(sh.SHBr) + ", " +
                       f4(sh.SHBg) + ", " + f4(sh.SHBb) + ", " + f4(sh.SHC);
    out.push_back(make_case("FacetSHEval", e == 0 ? "environment A" : "sky from above", 3, 3,
                            "#include \"FacetCore.hlsl\"\n",
                            "r.xyz = FacetSHEval(float4(" + xv(0) + ", 1), " + args + ");",
                            [sh](const double* x, double* r) {
                              auto f = [](const glm::dvec4& v) {
                                return glm::dvec4(fp(v.x), fp(v.y), fp(v.z), fp(v.w));
                              };
                              u::SHCoefficients s{f(sh.SHAr), f(sh.SHAg), f(sh.SHAb), f(sh.SHBr),
                                                  f(sh.SHBg), f(sh.SHBb), f(sh.SHC)};
                              put3(r, u::ShadeSH9(glm::dvec4(v3(x, 0), 1.0), s));
                            },
                            [](Rng& g, float* x) { put(x, 0, g.unit_vector()); }));
  }
}

}  // namespace

std::vector<FunctionCase> unity_standard_cases() {
  std::vector<FunctionCase> out;
  add_terms(out);
  add_setups(out);
  add_brdfs(out);
  add_lighting_models(out);
  add_color_and_sh(out);
  return out;
}

}  // namespace facet::reference
