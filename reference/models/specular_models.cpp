// The Phong-family and microfacet rows of the model table.
#include <map>
#include <memory>
#include <mutex>

#include "model_rows.h"

namespace facet::reference::models {

using glm::dvec3;

namespace {

// A function, not a constant: the table may be built during another file's
// static initialisation.
ModelParam exponent_param() { return number("exponent", 50.0, 1e-4, 1e5, "specular exponent n"); }

LightingModel phong() {
  LightingModel m = facet_row(
      "phong", "Phong normalized",
      "c = FacetPhongNormalized(2.0 * a.NoL * a.NoV - a.LoV, FacetAlphaToBlinnPhongExponent(alpha)) * a.NoL;",
      [](const ModelPoint& in) {
        FacetAngles a = angles(in);
        return dvec3(FacetPhongNormalized(2 * a.NoL * a.NoV - a.LoV, FacetAlphaToBlinnPhongExponent(clamped_alpha(in))) *
                     a.NoL);
      });
  with_params(m, "FacetPhongNormalized", {exponent_param()}, [](const ModelParams& p) {
    return above_surface([n = p.num("exponent")](auto&, auto&, auto& a) {
      return dvec3(FacetPhongNormalized(2.0 * a.NoL * a.NoV - a.LoV, n));
    });
  });
  return m;
}

LightingModel blinn_phong() {
  LightingModel m = facet_row(
      "blinn-phong", "Blinn-Phong normalized",
      "c = FacetBlinnPhongNormalized(a.NoH, FacetAlphaToBlinnPhongExponent(alpha)) * a.NoL;",
      [](const ModelPoint& in) {
        FacetAngles a = angles(in);
        return dvec3(FacetBlinnPhongNormalized(a.NoH, FacetAlphaToBlinnPhongExponent(clamped_alpha(in))) * a.NoL);
      },
      Energy::violator);
  with_params(m, "FacetBlinnPhongNormalized", {exponent_param()}, [](const ModelParams& p) {
    return above_surface([n = p.num("exponent")](auto&, auto&, auto& a) { return dvec3(FacetBlinnPhongNormalized(a.NoH, n)); });
  });
  return m;
}

// ---- D_GGX * V * F_Schlick with the visibility term picked by `vis` ----
using Visibility = double (*)(double NoV, double NoL, double alpha, double r);

LocalBrdf ggx_with(Visibility vis, const ModelParams& p) {
  return above_surface([vis, r = p.num("roughness"), f0 = p.col("f0")](auto&, auto&, auto& a) {
    double alpha = clamped_alpha_of(r);
    return FacetD_GGX(a.NoH, alpha) * vis(a.NoV, a.NoL, alpha, r) * FacetF_Schlick(f0, 1.0, a.LoH);
  });
}

// `hlsl_v` is the HLSL visibility call, reading a, alpha and rough.
LightingModel ggx_variant(std::string id, std::string name, std::string stdlib, const std::string& hlsl_v, Visibility vis) {
  LightingModel m = facet_row(std::move(id), std::move(name),
                              "c = FacetD_GGX(a.NoH, alpha) * " + hlsl_v + " * FacetF_Schlick(F0, 1.0, a.LoH) * a.NoL;",
                              [vis](const ModelPoint& in) {
                                FacetAngles a = angles(in);
                                double al = clamped_alpha(in);
                                return FacetD_GGX(a.NoH, al) * vis(a.NoV, a.NoL, al, in.roughness) *
                                       FacetF_Schlick(dvec3(in.f0), 1.0, a.LoH) * a.NoL;
                              });
  with_params(m, std::move(stdlib), {roughness_param(), f0_param()},
              [vis](const ModelParams& p) { return ggx_with(vis, p); });
  return m;
}

LightingModel ggx() {
  LightingModel m = facet_row("ggx", "Cook-Torrance GGX", "c = FacetBRDF_CookTorranceGGX(n, v, l, F0, rough) * a.NoL;",
                              [](const ModelPoint& in) {
                                return FacetBRDF_CookTorranceGGX(in.n, in.v, in.l, dvec3(in.f0), in.roughness) * angles(in).NoL;
                              });
  with_params(m, "FacetBRDF_CookTorranceGGX", {roughness_param(), f0_param()}, [](const ModelParams& p) {
    return above_surface([r = p.num("roughness"), f0 = p.col("f0")](auto& v, auto& l, auto&) {
      return FacetBRDF_CookTorranceGGX(dvec3(0, 0, 1), v, l, f0, r);
    });
  });
  return m;
}

LightingModel beckmann() {
  LightingModel m = facet_row("beckmann", "Cook-Torrance Beckmann",
                              "c = FacetBRDF_CookTorranceBeckmann(n, v, l, F0, rough) * a.NoL;", [](const ModelPoint& in) {
                                return FacetBRDF_CookTorranceBeckmann(in.n, in.v, in.l, dvec3(in.f0), in.roughness) *
                                       angles(in).NoL;
                              });
  with_params(m, "FacetBRDF_CookTorranceBeckmann", {roughness_param(), f0_param()}, [](const ModelParams& p) {
    return above_surface([r = p.num("roughness"), f0 = p.col("f0")](auto& v, auto& l, auto&) {
      return FacetBRDF_CookTorranceBeckmann(dvec3(0, 0, 1), v, l, f0, r);
    });
  });
  return m;
}

LightingModel ggx_fp16() {
  LightingModel m = facet_row(
      "ggx-fp16", "GGX FP16-safe D + Hammon V",
      "float3 nn = FacetSafeNormalize(n);\n"
      "float3 h = FacetSafeNormalize(FacetSafeNormalize(v) + FacetSafeNormalize(l));\n"
      "float a16 = max(rough * rough, FACET_MIN_ALPHA_FP16);\n"
      "c = FacetD_GGX_FP16Safe(nn, h, a16) * FacetV_SmithGGXCorrelatedFast(a.NoV, a.NoL, a16) *"
      " FacetF_Schlick(F0, 1.0, a.LoH) * a.NoL;",
      [](const ModelPoint& in) {
        FacetAngles a = angles(in);
        double a16 = std::max(in.roughness * in.roughness, FACET_MIN_ALPHA_FP16);
        return FacetD_GGX_FP16Safe(FacetSafeNormalize(in.n), half_vector(in), a16) *
               FacetV_SmithGGXCorrelatedFast(a.NoV, a.NoL, a16) * FacetF_Schlick(dvec3(in.f0), 1.0, a.LoH) * a.NoL;
      });
  m.stdlib = "FacetD_GGX_FP16Safe * FacetV_SmithGGXCorrelatedFast * FacetF_Schlick";
  return m;
}

// The CPU composition with Hammon's V and the exact D (no stdlib entry point).
LightingModel ggx_fast() {
  LightingModel m;
  m.id = "ggx-fast";
  m.name = "GGX + Hammon fast V";
  with_params(m, "FacetD_GGX * FacetV_SmithGGXCorrelatedFast * FacetF_Schlick", {roughness_param(), f0_param()},
              [](const ModelParams& p) {
                return ggx_with([](double NoV, double NoL, double alpha, double) {
                  return FacetV_SmithGGXCorrelatedFast(NoV, NoL, alpha);
                }, p);
              });
  return m;
}

// E(NoV) of the GGX lobe with F = 1 (dfg.y), the compensation's input as the
// stdlib reads it from the DFG table; tabulated once per alpha per process
// (a million samples each).
std::shared_ptr<const std::vector<double>> ggx_albedo_table(double alpha) {
  static std::mutex mutex;
  static std::map<double, std::shared_ptr<const std::vector<double>>> cache;
  std::lock_guard<std::mutex> lock(mutex);
  auto& slot = cache[alpha];
  if (!slot) {
    // Nodes at NoV = i/64 so that normal incidence is exact; the first at
    // 1/256, as NoV = 0 leaves no reflected directions.
    constexpr int kEntries = 65;
    constexpr uint32_t kSamples = 16384;  // the DFG doc's advice: grazing rows need >= 16k
    auto t = std::make_shared<std::vector<double>>(kEntries);
    for (int i = 0; i < kEntries; ++i) {
      (*t)[i] = FacetDFG_Integrate(std::max(i / double(kEntries - 1), 1.0 / 256.0), alpha, kSamples).y;
    }
    slot = t;
  }
  return slot;
}
double table_at(const std::vector<double>& t, double NoV) {
  double x = std::clamp(NoV * double(t.size() - 1), 0.0, double(t.size() - 1));
  size_t i = std::min(size_t(x), t.size() - 2);
  return lerp(t[i], t[i + 1], x - double(i));
}

// The point form estimates E from EnvBRDFApprox unless the point brings it
// (x[12]); the parameter form integrates it (the stdlib's DFG table).
LightingModel ggx_ms() {
  LightingModel m = facet_row(
      "ggx-ms", "GGX + energy compensation",
      "float2 ab = FacetEnvBRDFApproxAB(rough, a.NoV);\n"
      "float e = E > 0.0 ? E : max(ab.x + ab.y, 0.05);\n"
      "c = FacetBRDF_CookTorranceGGX(n, v, l, F0, rough) * FacetEnergyCompensation(F0, e) * a.NoL;",
      [](const ModelPoint& in) {
        FacetAngles a = angles(in);
        glm::dvec2 ab = FacetEnvBRDFApproxAB(in.roughness, a.NoV);
        double e = in.energy > 0 ? in.energy : std::max(ab.x + ab.y, 0.05);
        return FacetBRDF_CookTorranceGGX(in.n, in.v, in.l, dvec3(in.f0), in.roughness) *
               FacetEnergyCompensation(dvec3(in.f0), e) * a.NoL;
      },
      Energy::conserving, false);
  with_params(m, "FacetBRDF_CookTorranceGGX * FacetEnergyCompensation(f0, FacetDFG_Integrate(NoV).y)",
              {roughness_param(), f0_param()}, [](const ModelParams& p) {
                double r = p.num("roughness");
                return above_surface([r, f0 = p.col("f0"), table = ggx_albedo_table(clamped_alpha_of(r))](
                                         auto& v, auto& l, auto& a) {
                  return FacetBRDF_CookTorranceGGX(dvec3(0, 0, 1), v, l, f0, r) *
                         FacetEnergyCompensation(f0, table_at(*table, a.NoV));
                });
              });
  return m;
}

// Cook and Torrance's own geometry term with Beckmann's D (no stdlib entry point).
LightingModel cook_torrance_1982() {
  LightingModel m;
  m.id = "cook-torrance-1982";
  m.name = "Cook-Torrance 1982";
  with_params(m, "FacetD_Beckmann * FacetG_CookTorrance / (4 NoL NoV) * FacetF_Schlick", {roughness_param(), f0_param()},
              [](const ModelParams& p) {
                return above_surface([r = p.num("roughness"), f0 = p.col("f0")](auto&, auto&, auto& a) {
                  double g = FacetG_CookTorrance(a.NoV, a.NoL, a.NoH, a.LoH);
                  return FacetD_Beckmann(a.NoH, clamped_alpha_of(r)) * g / std::max(4.0 * a.NoL * a.NoV, 1e-12) *
                         FacetF_Schlick(f0, 1.0, a.LoH);
                });
              });
  return m;
}

// The point form is isotropic at alpha; the parameter form takes both slopes.
LightingModel ward() {
  LightingModel m = facet_row("ward", "Ward",
                              "float3 t, b; stability_frame(n, t, b);\n"
                              "float3 h = FacetSafeNormalize(FacetSafeNormalize(v) + FacetSafeNormalize(l));\n"
                              "c = FacetSpecular_Ward(a.NoV, a.NoL, a.NoH, dot(h, t), dot(h, b), alpha, alpha) * a.NoL;",
                              [](const ModelPoint& in) {
                                FacetAngles a = angles(in);
                                dvec3 x, y;
                                frame(in.n, x, y);
                                dvec3 h = half_vector(in);
                                double al = clamped_alpha(in);
                                return dvec3(FacetSpecular_Ward(a.NoV, a.NoL, a.NoH, glm::dot(h, x), glm::dot(h, y), al, al) *
                                             a.NoL);
                              });
  with_params(m, "FacetSpecular_Ward",
              {number("alpha_x", 0.3, 1e-3, 1.0, "slope deviation along the tangent"),
               number("alpha_y", 0.3, 1e-3, 1.0, "slope deviation along the bitangent"),
               colour("ks", dvec3(1.0), "specular weight")},
              [](const ModelParams& p) {
                return above_surface([ax = p.num("alpha_x"), ay = p.num("alpha_y"), ks = p.col("ks")](auto& v, auto& l,
                                                                                                      auto& a) {
                  dvec3 h = FacetSafeNormalize(v + l);
                  return ks * FacetSpecular_Ward(a.NoV, a.NoL, a.NoH, h.x, h.y, ax, ay);
                });
              });
  return m;
}

LightingModel ashikhmin_shirley_specular() {
  LightingModel m = facet_row(
      "ashikhmin-shirley-specular", "Ashikhmin-Shirley specular",
      "float3 t, b; stability_frame(n, t, b);\n"
      "float3 h = FacetSafeNormalize(FacetSafeNormalize(v) + FacetSafeNormalize(l));\n"
      "float e = FacetAlphaToBlinnPhongExponent(alpha);\n"
      "c = FacetSpecular_AshikhminShirley(a.NoV, a.NoL, a.NoH, a.LoH, dot(h, t), dot(h, b), e, e, f0) * a.NoL;",
      [](const ModelPoint& in) {
        FacetAngles a = angles(in);
        dvec3 x, y;
        frame(in.n, x, y);
        dvec3 h = half_vector(in);
        double e = FacetAlphaToBlinnPhongExponent(clamped_alpha(in));
        return dvec3(
            FacetSpecular_AshikhminShirley(a.NoV, a.NoL, a.NoH, a.LoH, glm::dot(h, x), glm::dot(h, y), e, e, in.f0) * a.NoL);
      });
  m.stdlib = "FacetSpecular_AshikhminShirley";
  return m;
}

// Both lobes of the model, as its paper pairs them (CPU only).
LightingModel ashikhmin_shirley() {
  LightingModel m;
  m.id = "ashikhmin-shirley";
  m.name = "Ashikhmin-Shirley";
  with_params(m, "FacetSpecular_AshikhminShirley + FacetFd_AshikhminShirley",
              {number("nu", 100.0, 1.0, 1e5, "exponent along the tangent"),
               number("nv", 100.0, 1.0, 1e5, "exponent along the bitangent"),
               number("rs", 0.05, 0.0, 1.0, "specular reflectance at normal incidence"),
               colour("rd", dvec3(0.5), "diffuse reflectance")},
              [](const ModelParams& p) {
                return above_surface([nu = p.num("nu"), nv = p.num("nv"), rs = p.num("rs"), rd = p.col("rd")](
                                         auto& v, auto& l, auto& a) {
                  dvec3 h = FacetSafeNormalize(v + l);
                  double spec = FacetSpecular_AshikhminShirley(a.NoV, a.NoL, a.NoH, a.LoH, h.x, h.y, nu, nv, rs);
                  dvec3 diffuse(FacetFd_AshikhminShirley(a.NoV, a.NoL, rd.r, rs), FacetFd_AshikhminShirley(a.NoV, a.NoL, rd.g, rs),
                                FacetFd_AshikhminShirley(a.NoV, a.NoL, rd.b, rs));
                  return dvec3(spec) + diffuse;
                });
              });
  return m;
}

}  // namespace

std::vector<LightingModel> phong_models() { return {phong(), blinn_phong()}; }

std::vector<LightingModel> microfacet_models() {
  std::vector<LightingModel> m = {ggx(), beckmann(), ggx_fp16(), ggx_fast()};
  m.push_back(ggx_variant("ggx-separable", "GGX separable Smith", "FacetD_GGX * FacetV_SmithGGXSeparable * FacetF_Schlick",
                          "FacetV_SmithGGXSeparable(a.NoV, a.NoL, alpha)",
                          [](double NoV, double NoL, double alpha, double) { return FacetV_SmithGGXSeparable(NoV, NoL, alpha); }));
  m.push_back(ggx_variant("ggx-schlick", "GGX Schlick-GGX", "FacetD_GGX * FacetV_SchlickGGX (k = alpha/2) * FacetF_Schlick",
                          "FacetV_SchlickGGX(a.NoV, a.NoL, alpha)",
                          [](double NoV, double NoL, double alpha, double) { return FacetV_SchlickGGX(NoV, NoL, alpha); }));
  m.push_back(ggx_variant("ggx-karis", "GGX Schlick-GGX Karis",
                          "FacetD_GGX * FacetV_SchlickGGXKaris (k = (r+1)^2/8) * FacetF_Schlick",
                          "FacetV_SchlickGGXKaris(a.NoV, a.NoL, rough)",
                          [](double NoV, double NoL, double, double r) { return FacetV_SchlickGGXKaris(NoV, NoL, r); }));
  m.push_back(ggx_ms());
  m.push_back(cook_torrance_1982());
  m.push_back(ward());
  m.push_back(ashikhmin_shirley_specular());
  m.push_back(ashikhmin_shirley());
  return m;
}

}  // namespace facet::reference::models
