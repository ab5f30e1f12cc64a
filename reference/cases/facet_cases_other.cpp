// Cases for the Disney BRDF, the IBL math, the tone mappers and sRGB.
#include "case_helpers.h"

#include "facet/reference/color.h"
#include "facet/reference/disney.h"
#include "facet/reference/ibl.h"
#include "facet/reference/tonemap.h"

namespace facet::reference::cases {
namespace {

void put_out3(double* r, const glm::dvec3& v) { r[0] = v.x, r[1] = v.y, r[2] = v.z; }

FacetDisneyMaterial rounded(FacetDisneyMaterial m) {
  m.baseColor = {fp(m.baseColor.x), fp(m.baseColor.y), fp(m.baseColor.z)};
  for (double* p : {&m.subsurface, &m.metallic, &m.specular, &m.specularTint, &m.roughness, &m.anisotropic,
                    &m.sheen, &m.sheenTint, &m.clearcoat, &m.clearcoatGloss})
    *p = fp(*p);
  return m;
}

std::string disney_hlsl(const FacetDisneyMaterial& m) {
  return "FacetDisneyMaterial m;\nm.baseColor = " + lit3(m.baseColor) + ";\nm.subsurface = " + lit(m.subsurface) +
         ";\nm.metallic = " + lit(m.metallic) + ";\nm.specular = " + lit(m.specular) +
         ";\nm.specularTint = " + lit(m.specularTint) + ";\nm.roughness = " + lit(m.roughness) +
         ";\nm.anisotropic = " + lit(m.anisotropic) + ";\nm.sheen = " + lit(m.sheen) +
         ";\nm.sheenTint = " + lit(m.sheenTint) + ";\nm.clearcoat = " + lit(m.clearcoat) +
         ";\nm.clearcoatGloss = " + lit(m.clearcoatGloss) + ";\nr.xyz = FacetBRDF_Disney(m, " + xv(0) + ", " +
         xv(3) + ", " + xv(6) + ", " + xv(9) + ", " + xv(12) + ");";
}

void add_disney(std::vector<FunctionCase>& out) {
  // roughness >= 0.4 and clearcoatGloss 0 (GTR1 alpha 0.1): the GTR2 peak
  // needs h . x to 1e-4 of alpha and GTR1's 1 + (a^2 - 1) NoH^2 cancels like
  // plain GGX, so glossier settings exceed 1e-4 in fp32 by construction.
  FacetDisneyMaterial base;  // the BRDF Explorer defaults
  FacetDisneyMaterial metal;
  metal.baseColor = {0.95, 0.64, 0.54};
  metal.metallic = 1.0, metal.roughness = 0.4, metal.anisotropic = 0.8;
  FacetDisneyMaterial layered;
  layered.baseColor = {0.2, 0.5, 0.8};
  layered.subsurface = 1.0, layered.sheen = 1.0, layered.sheenTint = 0.5, layered.clearcoat = 1.0;
  layered.clearcoatGloss = 0.0, layered.roughness = 0.7, layered.specularTint = 0.5;
  const std::pair<const char*, FacetDisneyMaterial> materials[] = {
      {"defaults", base}, {"anisotropic metal r=0.4", metal}, {"subsurface sheen clearcoat r=0.7", layered}};
  for (auto [name, material] : materials) {
    FacetDisneyMaterial m = rounded(material);
    out.push_back(make_case(
        "FacetBRDF_Disney", name, 15, 3, kIncludeDisney, disney_hlsl(m),
        [m](const double* x, double* r) {
          put_out3(r, FacetBRDF_Disney(m, v3(x, 0), v3(x, 3), v3(x, 6), v3(x, 9), v3(x, 12)));
        },
        [](Rng& g, float* x) {
          Frame f = random_frame(g);
          glm::dvec3 v = g.direction(f.n, 0.01, 1.0), l;
          do l = g.direction(f.n, 0.01, 1.0);
          while (glm::dot(v + l, v + l) < 0.01);
          put(x, 0, l), put(x, 3, v), put(x, 6, f.n), put(x, 9, f.x), put(x, 12, f.y);
        }));
  }
  for (double a : {0.1, 0.5, 1.0}) {
    out.push_back(make_case("FacetD_GTR1", "a=" + lit(a), 1, 1, kIncludeDisney,
                            "r.x = FacetD_GTR1(x[0], " + lit(a) + ");",
                            [a](const double* x, double* r) { r[0] = FacetD_GTR1(x[0], fp(a)); },
                            [](Rng& g, float* x) { x[0] = float(g.uniform()); }));
  }
  out.push_back(make_case("FacetDisneySchlickWeight", "u in [-0.1, 1.1]", 1, 1, kIncludeDisney,
                          "r.x = FacetDisneySchlickWeight(x[0]);",
                          [](const double* x, double* r) { r[0] = FacetDisneySchlickWeight(x[0]); },
                          [](Rng& g, float* x) { x[0] = float(g.uniform(-0.1, 1.1)); }));
  for (double a : {0.05, 0.25, 1.0}) {
    out.push_back(make_case("FacetDisneySmithGGX", "alphaG=" + lit(a), 1, 1, kIncludeDisney,
                            "r.x = FacetDisneySmithGGX(x[0], " + lit(a) + ");",
                            [a](const double* x, double* r) { r[0] = FacetDisneySmithGGX(x[0], fp(a)); },
                            [](Rng& g, float* x) { x[0] = float(g.uniform()); }));
  }
  out.push_back(make_case("FacetDisneySmithGGXAnisotropic", "alphaX=0.1 alphaY=0.4", 3, 1, kIncludeDisney,
                          "r.x = FacetDisneySmithGGXAnisotropic(x[0], x[1], x[2], 0.1, 0.4);",
                          [](const double* x, double* r) {
                            r[0] = FacetDisneySmithGGXAnisotropic(x[0], x[1], x[2], fp(0.1), fp(0.4));
                          },
                          [](Rng& g, float* x) {
                            glm::dvec3 v = g.direction({0, 0, 1}, 0.0, 1.0);
                            x[0] = float(v.z), x[1] = float(v.x), x[2] = float(v.y);
                          }));
}

void add_ibl(std::vector<FunctionCase>& out) {
  out.push_back(make_case("FacetPerceptualRoughnessToMipLevel", "maxMip=7", 1, 1, kIncludeIBL,
                          "r.x = FacetPerceptualRoughnessToMipLevel(x[0], 7.0);",
                          [](const double* x, double* r) { r[0] = FacetPerceptualRoughnessToMipLevel(x[0], 7.0); },
                          [](Rng& g, float* x) { x[0] = float(g.uniform(-0.1, 1.1)); }));
  out.push_back(make_case("FacetPerceptualRoughnessToMipLevelUnity", "steps=6", 1, 1, kIncludeIBL,
                          "r.x = FacetPerceptualRoughnessToMipLevelUnity(x[0], 6.0);",
                          [](const double* x, double* r) { r[0] = FacetPerceptualRoughnessToMipLevelUnity(x[0], 6.0); },
                          [](Rng& g, float* x) { x[0] = float(g.uniform(-0.1, 1.1)); }));
  out.push_back(make_case("FacetEnvBRDFApproxAB", "r, NoV in [0, 1]", 2, 2, kIncludeIBL,
                          "r.xy = FacetEnvBRDFApproxAB(x[0], x[1]);",
                          [](const double* x, double* r) {
                            glm::dvec2 ab = FacetEnvBRDFApproxAB(x[0], x[1]);
                            r[0] = ab.x, r[1] = ab.y;
                          },
                          [](Rng& g, float* x) { x[0] = float(g.uniform()), x[1] = float(g.uniform()); }));
  out.push_back(make_case("FacetEnvBRDFApprox", "f0, r, NoV in [0, 1]", 5, 3, kIncludeIBL,
                          "r.xyz = FacetEnvBRDFApprox(" + xv(0) + ", x[3], x[4]);",
                          [](const double* x, double* r) { put_out3(r, FacetEnvBRDFApprox(v3(x, 0), x[3], x[4])); },
                          [](Rng& g, float* x) {
                            for (int i = 0; i < 5; ++i) x[i] = float(g.uniform());
                          }));
  out.push_back(make_case("FacetEnvBRDF_DFG", "f0, f90, dfg", 6, 3, kIncludeIBL,
                          "r.xyz = FacetEnvBRDF_DFG(" + xv(0) + ", x[3], float2(x[4], x[5]));",
                          [](const double* x, double* r) {
                            put_out3(r, FacetEnvBRDF_DFG(v3(x, 0), x[3], glm::dvec2(x[4], x[5])));
                          },
                          [](Rng& g, float* x) {
                            for (int i = 0; i < 4; ++i) x[i] = float(g.uniform());
                            double y = g.uniform(0.3, 1.0);
                            x[5] = float(y), x[4] = float(g.uniform(0.0, 0.5 * y));
                          }));
  out.push_back(make_case("FacetRadicalInverse", "i < 2^24", 1, 1, kIncludeIBL,
                          "r.x = FacetRadicalInverse(uint(x[0]));",
                          [](const double* x, double* r) { r[0] = FacetRadicalInverse(uint32_t(x[0])); },
                          [](Rng& g, float* x) { x[0] = float(g.next() >> 40); }));
  // 64 samples per point; the sum is the same Hammersley set on both sides,
  // so the comparison checks the integrand, not the quadrature.
  for (double alpha : {0.1, 0.5, 1.0}) {
    out.push_back(make_case("FacetDFG_Integrate", "alpha=" + lit(alpha) + " N=64", 1, 2, kIncludeIBL,
                            "r.xy = FacetDFG_Integrate(x[0], " + lit(alpha) + ", 64u);",
                            [alpha](const double* x, double* r) {
                              glm::dvec2 d = FacetDFG_Integrate(x[0], fp(alpha), 64);
                              r[0] = d.x, r[1] = d.y;
                            },
                            [](Rng& g, float* x) { x[0] = float(g.uniform(0.02, 1.0)); }));
  }
  // L00 in [0.5, 1] and the other coefficients within +-0.08 keep E above
  // 0.15, away from the max(., 0) floor where the relative error is undefined.
  auto draw_sh = [](Rng& g, float* x) {
    put(x, 0, g.unit_vector());
    x[3] = float(g.uniform(0.5, 1.0));
    for (int i = 4; i < 12; ++i) x[i] = float(g.uniform(-0.08, 0.08));
  };
  out.push_back(make_case("FacetSH9Irradiance", "scalar", 12, 1, kIncludeIBL,
                          "float sh[9];\nfor (int i = 0; i < 9; ++i) sh[i] = x[3 + i];\nr.x = FacetSH9Irradiance(" +
                              xv(0) + ", sh);",
                          [](const double* x, double* r) { r[0] = FacetSH9Irradiance(v3(x, 0), x + 3); }, draw_sh));
  out.push_back(make_case(
      "FacetSH9Irradiance", "float3 (g = r/2, b = r/4)", 12, 3, kIncludeIBL,
      "float3 sh[9];\nfor (int i = 0; i < 9; ++i) sh[i] = float3(x[3 + i], 0.5 * x[3 + i], 0.25 * x[3 + i]);\n"
      "r.xyz = FacetSH9Irradiance(" +
          xv(0) + ", sh);",
      [](const double* x, double* r) {
        glm::dvec3 sh[9];
        for (int i = 0; i < 9; ++i) sh[i] = glm::dvec3(x[3 + i], 0.5 * x[3 + i], 0.25 * x[3 + i]);
        put_out3(r, FacetSH9Irradiance(v3(x, 0), sh));
      },
      draw_sh));
}

void add_color_case(std::vector<FunctionCase>& out, const char* name, const char* include, double lo, double hi,
                    glm::dvec3 (*fn)(const glm::dvec3&)) {
  out.push_back(make_case(name, "rgb in [0, " + lit(hi) + "], 5% zeros", 3, 3, include,
                          std::string("r.xyz = ") + name + "(" + xv(0) + ");",
                          [fn](const double* x, double* r) { put_out3(r, fn(v3(x, 0))); },
                          [lo, hi](Rng& g, float* x) {
                            for (int i = 0; i < 3; ++i) x[i] = float(g.uniform() < 0.05 ? 0.0 : g.log_uniform(lo, hi));
                          }));
}

glm::dvec3 reinhard(const glm::dvec3& c) { return FacetTonemapReinhard(c); }
glm::dvec3 hable(const glm::dvec3& c) { return FacetTonemapHable(c); }
glm::dvec3 narkowicz(const glm::dvec3& c) { return FacetTonemapACESNarkowicz(c); }
glm::dvec3 pbr_neutral(const glm::dvec3& c) { return FacetTonemapPBRNeutral(c); }
glm::dvec3 to_srgb(const glm::dvec3& c) { return FacetLinearToSRGB(c); }
glm::dvec3 from_srgb(const glm::dvec3& c) { return FacetSRGBToLinear(c); }

void add_tonemap(std::vector<FunctionCase>& out) {
  add_color_case(out, "FacetTonemapReinhard", kIncludeTonemap, 1e-4, 64.0, reinhard);
  add_color_case(out, "FacetTonemapHable", kIncludeTonemap, 1e-4, 64.0, hable);
  add_color_case(out, "FacetTonemapACESNarkowicz", kIncludeTonemap, 1e-4, 64.0, narkowicz);
  add_color_case(out, "FacetTonemapACESHill", kIncludeTonemap, 1e-4, 64.0, FacetTonemapACESHill);
  add_color_case(out, "FacetACESHillRRTODTFit", kIncludeTonemap, 1e-4, 64.0, FacetACESHillRRTODTFit);
  add_color_case(out, "FacetTonemapPBRNeutral", kIncludeTonemap, 1e-4, 8.0, pbr_neutral);
  add_color_case(out, "FacetTonemapAgX", kIncludeTonemap, 1e-4, 64.0, FacetTonemapAgX);
  add_color_case(out, "FacetHableCurve", kIncludeTonemap, 1e-4, 64.0, FacetHableCurve);
  add_color_case(out, "FacetAgXContrast", kIncludeTonemap, 1e-3, 1.0, FacetAgXContrast);
  for (double white : {2.0, 4.0, 11.2}) {
    out.push_back(make_case("FacetTonemapReinhardExtended", "white=" + lit(white), 3, 3, kIncludeTonemap,
                            "r.xyz = FacetTonemapReinhardExtended(" + xv(0) + ", " + lit(white) + ");",
                            [white](const double* x, double* r) {
                              put_out3(r, FacetTonemapReinhardExtended(v3(x, 0), fp(white)));
                            },
                            [](Rng& g, float* x) {
                              for (int i = 0; i < 3; ++i) x[i] = float(g.log_uniform(1e-4, 16.0));
                            }));
  }
  add_color_case(out, "FacetLinearToSRGB", kIncludeColor, 1e-5, 1.0, to_srgb);
  add_color_case(out, "FacetSRGBToLinear", kIncludeColor, 1e-4, 1.0, from_srgb);
  using Fn = double (*)(double);
  const std::pair<const char*, Fn> scalars[] = {{"FacetLinearToSRGB", FacetLinearToSRGB},
                                                {"FacetSRGBToLinear", FacetSRGBToLinear}};
  for (auto [name, fn] : scalars) {
    out.push_back(make_case(name, "scalar, [-0.1, 1.1]", 1, 1, kIncludeColor,
                            std::string("r.x = ") + name + "(x[0]);",
                            [fn](const double* x, double* r) { r[0] = fn(x[0]); },
                            [](Rng& g, float* x) { x[0] = float(g.uniform(-0.1, 1.1)); }));
  }
}

}  // namespace

void add_disney_cases(std::vector<FunctionCase>& out) { add_disney(out); }
void add_ibl_cases(std::vector<FunctionCase>& out) { add_ibl(out); }
void add_tonemap_cases(std::vector<FunctionCase>& out) { add_tonemap(out); }

}  // namespace facet::reference::cases
