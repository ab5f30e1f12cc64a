#include "accuracy/catalogue.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <string_view>

#include "accuracy/lobe.h"
#include "facet/reference/brdf.h"
#include "facet/reference/color.h"
#include "facet/reference/ibl.h"
#include "facet/reference/models.h"
#include "facet/reference/tonemap.h"
#include "facet/reference/unity_standard.h"

namespace facet::runtime::accuracy {
namespace {

namespace ref = facet::reference;
namespace u = facet::reference::unity;
using glm::dvec3;
using glm::dvec4;

constexpr const char* kFacet = "#include \"FacetBRDF.hlsl\"\n";
constexpr const char* kFacetIbl = "#include \"FacetBRDF.hlsl\"\n#include \"FacetIBL.hlsl\"\n";
constexpr const char* kFacetTonemap = "#include \"FacetTonemap.hlsl\"\n";
constexpr const char* kFacetColor = "#include \"FacetColor.hlsl\"\n";
constexpr const char* kUnityBrdf = "#include \"UnityStandardBRDF.cginc\"\n#include \"UnityStandardUtils.cginc\"\n";

const dvec3 kN(0, 0, 1);

RowSpec spec(std::string id, std::string group, std::string name, std::string reference, std::string metric,
             std::string anchor, std::string includes, std::string hlsl, std::function<void(StudyRow&)> measure) {
  RowSpec s;
  s.row = {.id = std::move(id), .group = std::move(group), .name = std::move(name), .reference = std::move(reference),
           .metric = std::move(metric), .anchor = std::move(anchor)};
  s.includes = std::move(includes);
  s.hlsl = std::move(hlsl);
  s.measure = std::move(measure);
  return s;
}

RowSpec reference_row(std::string id, std::string group, std::string name, std::string includes, std::string hlsl) {
  return spec(std::move(id), std::move(group), std::move(name), "itself (the reference)", "-", "",
              std::move(includes), std::move(hlsl), nullptr);
}

// ---- lobes -----------------------------------------------------------------

struct Angles {
  double NoV, NoL, NoH, LoH;
};
Angles angles(const dvec3& v, const dvec3& l) {
  dvec3 h = glm::normalize(v + l);
  return {v.z, l.z, h.z, glm::dot(l, h)};
}

Lobe ggx_lobe(double alpha, std::function<double(double, double, double)> vis) {
  return [alpha, vis](const dvec3& v, const dvec3& l) {
    if (l.z <= 0) return 0.0;
    Angles a = angles(v, l);
    return ref::FacetD_GGX(a.NoH, alpha) * vis(a.NoV, a.NoL, alpha);
  };
}

// Max relL1 and the range of energy ratios over NoV in {1, .5, .2}.
void lobe_metrics(StudyRow& row, const std::vector<std::pair<std::string, std::pair<Lobe, Lobe>>>& settings) {
  double worst = 0, lo = 1e30, hi = 0;
  std::string detail;
  for (const auto& [label, lobes] : settings) {
    double setting_worst = 0;
    for (double NoV : {1.0, 0.5, 0.2}) {
      LobeComparison c = compare_lobes(lobes.first, lobes.second, view_at(NoV));
      setting_worst = std::max(setting_worst, c.rel_l1);
      lo = std::min(lo, c.energy_ratio);
      hi = std::max(hi, c.energy_ratio);
    }
    worst = std::max(worst, setting_worst);
    detail += fmt::format("{}{}: relL1 {:.3f}", detail.empty() ? "" : "; ", label, setting_worst);
  }
  row.error = worst;
  row.detail = fmt::format("{}; energy ratio {:.2f}-{:.2f}x (NoV 1, .5, .2)", detail, lo, hi);
}

void visibility_row(StudyRow& row, std::function<double(double, double, double)> approx, bool perceptual_param) {
  std::vector<std::pair<std::string, std::pair<Lobe, Lobe>>> settings;
  for (double alpha : {0.05, 0.2, 0.5, 1.0}) {
    auto corrected = [approx, perceptual_param](double NoV, double NoL, double a) {
      return approx(NoV, NoL, perceptual_param ? std::sqrt(a) : a);
    };
    settings.push_back({fmt::format("a={}", alpha),
                        {ggx_lobe(alpha, corrected), ggx_lobe(alpha, ref::FacetV_SmithGGXCorrelated)}});
  }
  lobe_metrics(row, settings);
  // The pointwise error, as docs/accuracy.md states it (NoV, NoL >= 0.2).
  std::string pointwise;
  for (double alpha : {0.05, 0.2, 0.5}) {
    double worst = 0;
    for (int i = 0; i <= 40; ++i) {
      for (int j = 0; j <= 40; ++j) {
        double NoV = 0.2 + 0.02 * i, NoL = 0.2 + 0.02 * j;
        double r = ref::FacetV_SmithGGXCorrelated(NoV, NoL, alpha);
        double a = approx(NoV, NoL, perceptual_param ? std::sqrt(alpha) : alpha);
        if (std::abs(a / r - 1) > std::abs(worst)) worst = a / r - 1;
      }
    }
    pointwise += fmt::format("{}{:+.1f} % (a={})", pointwise.empty() ? "" : " / ", 100 * worst, alpha);
  }
  row.detail += "; max rel V error " + pointwise + " for NoV, NoL >= 0.2";
}

// Max albedo over NoV (and the minimum), with the bound 1.
void albedo_row(StudyRow& row, const std::vector<std::pair<std::string, Lobe>>& settings, bool headline_loss = false) {
  double max_all = 0, min_all = 1e30;
  std::string detail;
  for (const auto& [label, f] : settings) {
    double hi = 0, lo = 1e30;
    for (double NoV : {1.0, 0.9, 0.7, 0.5, 0.3, 0.1, 0.02}) {
      double e = albedo(f, view_at(NoV));
      hi = std::max(hi, e);
      lo = std::min(lo, e);
    }
    max_all = std::max(max_all, hi);
    min_all = std::min(min_all, lo);
    detail += fmt::format("{}{}: {:.3f}-{:.3f}", detail.empty() ? "" : "; ", label, lo, hi);
  }
  row.error = headline_loss ? 1.0 - min_all : std::max(0.0, max_all - 1.0);
  row.detail = "albedo " + detail;
}

// ---- pointwise -------------------------------------------------------------

template <class F>
std::pair<double, double> max_abs_over(double lo, double hi, int steps, F&& diff) {
  double worst = 0, at = lo;
  for (int i = 0; i <= steps; ++i) {
    double x = lo + (hi - lo) * i / steps;
    double d = std::abs(diff(x));
    if (d > worst) worst = d, at = x;
  }
  return {worst, at};
}

double degrees_of(double cos_theta) { return std::acos(std::clamp(cos_theta, -1.0, 1.0)) * 180.0 / M_PI; }

// fp16 GGX D: the naive form and the cross-product form in _Float16.
double ggx_naive_half(double NoH, double alpha) {
  _Float16 a = _Float16(alpha), n = _Float16(NoH);
  _Float16 a2 = a * a;
  _Float16 d = (n * a2 - n) * n + _Float16(1);
  return double(a2 / (_Float16(M_PI) * d * d));
}
double ggx_cross_half(double NoH, double alpha) {
  // n = z, h in the xz plane: |n x h|^2 = h.x^2, from the half-precision h.
  double s = std::sqrt(std::max(0.0, 1.0 - NoH * NoH));
  _Float16 hx = _Float16(s), hz = _Float16(NoH), a = _Float16(alpha);
  _Float16 one_minus = hx * hx;
  _Float16 an = hz * a;
  _Float16 k = a / (one_minus + an * an);
  k = std::min(k, _Float16(453.5));
  return double(k * (k * _Float16(1.0 / M_PI)));
}

void fp16_d_row(StudyRow& row, double (*half_form)(double, double)) {
  double worst_all = 0;
  std::string detail;
  for (double alpha : {0.0079, 0.02, 0.0625, 0.25}) {
    double peak = ref::FacetD_GGX(1.0, alpha), worst = 0;
    for (int i = 0; i <= 3000; ++i) {
      double theta = (30.0 * i / 3000) * M_PI / 180.0;
      double NoH = std::cos(theta), exact = ref::FacetD_GGX(NoH, alpha);
      if (exact < 1e-3 * peak) continue;
      double h = half_form(NoH, alpha);
      double rel = std::isfinite(h) ? std::abs(h / exact - 1) : INFINITY;
      worst = std::max(worst, rel);
    }
    worst_all = std::max(worst_all, worst);
    detail += fmt::format("{}a={}: {}", detail.empty() ? "" : "; ", alpha,
                          std::isfinite(worst) ? fmt::format("{:.3g}", worst) : std::string("inf"));
  }
  row.error = worst_all;
  row.detail = "fp16 max rel error where D > 1e-3 peak, theta_h <= 30 deg: " + detail;
}

// ---- rows ------------------------------------------------------------------

void add_visibility(std::vector<RowSpec>& out) {
  out.push_back(reference_row("V_SmithGGXCorrelated", "V", "Smith GGX height-correlated V (exact)", kFacet,
                              "value = FacetV_SmithGGXCorrelated(p0, p1, p4);"));
  out.push_back(spec("V_SmithGGXCorrelatedFast", "V", "Hammon fast V 0.5/lerp(2LV, L+V, a)", "height-correlated V",
                     "max lobe relL1 (D_GGX * V, a = .05/.2/.5/1)",
                     "max rel -27.5 % (a=.05) / -22.5 % (a=.2) / -13.4 % (a=.5); lobe relL1 <= 0.19, energy 0.81-1.00x",
                     kFacet, "value = FacetV_SmithGGXCorrelatedFast(p0, p1, p4);",
                     [](StudyRow& r) { visibility_row(r, ref::FacetV_SmithGGXCorrelatedFast, false); }));
  out.push_back(spec("V_SmithGGXSeparable", "V", "Smith GGX separable V (exact G1 product)", "height-correlated V",
                     "max lobe relL1", "<= 2.8 % (a=.2) / 20 % (a=.5) for NoV, NoL >= .2", kFacet,
                     "value = FacetV_SmithGGXSeparable(p0, p1, p4);",
                     [](StudyRow& r) { visibility_row(r, ref::FacetV_SmithGGXSeparable, false); }));
  out.push_back(spec("V_SchlickGGX", "V", "Schlick-GGX V, k = a/2", "height-correlated V", "max lobe relL1",
                     "G1 max abs 0.16, rel 20 %; -72 % at a=.05 grazing", kFacet,
                     "value = FacetV_SchlickGGX(p0, p1, p4);",
                     [](StudyRow& r) { visibility_row(r, ref::FacetV_SchlickGGX, false); }));
  out.push_back(spec("V_SchlickGGXKaris", "V", "Schlick-GGX V, Karis k = (r+1)^2/8", "height-correlated V",
                     "max lobe relL1", "lobe energy 0.34-0.99x (r=.2), 0.42-0.94x (r=.5)", kFacet,
                     "value = FacetV_SchlickGGXKaris(p0, p1, p4);",
                     [](StudyRow& r) { visibility_row(r, ref::FacetV_SchlickGGXKaris, true); }));
}

void add_ndf(std::vector<RowSpec>& out) {
  out.push_back(reference_row("D_GGX", "D", "GGX D, 1 - NoH^2 form (fp32)", kFacet, "value = FacetD_GGX(p2, p4);"));
  out.push_back(spec("D_GGX_fp16", "D", "GGX D naive form in fp16", "fp64 GGX D", "fp16 max rel error (highlight)",
                     "a=0.0079: up to 76x; a=0.02: 3.9x; a=0.0625: 26 %; a=0.25: 1.5 %", kFacet,
                     "value = FacetD_GGX(p2, p4);", [](StudyRow& r) { fp16_d_row(r, ggx_naive_half); }));
  out.push_back(spec("D_GGX_FP16Safe", "D", "GGX D |n x h|^2 form, k <= 453.5, in fp16", "fp64 GGX D",
                     "fp16 max rel error (highlight)", "<= 0.4 % wherever finite", kFacet,
                     "value = FacetD_GGX_FP16Safe(float3(0.0, 0.0, 1.0), normalize(float3(sqrt(1.0 - p2 * p2), 0.0, p2)), p4);",
                     [](StudyRow& r) { fp16_d_row(r, ggx_cross_half); }));
}

void add_fresnel(std::vector<RowSpec>& out) {
  out.push_back(reference_row("F_Dielectric", "F", "exact unpolarised dielectric Fresnel", kFacet,
                              "value = FacetF_Dielectric(1.0 + p5, p3);"));
  out.push_back(reference_row("F_Conductor", "F", "exact conductor Fresnel (complex IOR)", kFacet,
                              "value = FacetF_Conductor(float3(p5, p6, p7), float3(p6, p7, p5) * 4, p3).x;"));
  out.push_back(spec(
      "F_Schlick", "F", "Schlick F, pow5 by multiplies", "exact dielectric Fresnel", "max |dF| over angle, eta = 1.5",
      "eta=1.5: 0.036 @85 deg (cos-weighted mean 0.0087); eta=1.33: 0.060 @83.8 deg", kFacet,
      "value = FacetF_Schlick(p5, 1.0, p3);", [](StudyRow& r) {
        std::string detail;
        for (double eta : {1.5, 1.33, 1.8, 2.4}) {
          double f0 = ref::FacetF0FromIOR(eta);
          auto [worst, at] = max_abs_over(0.0, 1.0, 20000, [&](double c) {
            return ref::FacetF_Schlick(f0, 1.0, c) - ref::FacetF_Dielectric(eta, c);
          });
          if (eta == 1.5) r.error = worst;
          detail += fmt::format("{}eta={}: {:.3f} @{:.1f} deg", detail.empty() ? "" : "; ", eta, worst, degrees_of(at));
        }
        r.detail = detail;
      }));
  out.push_back(spec("F_SchlickSG", "F", "spherical-Gaussian Fresnel weight 2^((-5.55473c-6.98316)c)", "(1-c)^5",
                     "max |dw|", "max |dw| 0.0038 @86.8 deg", kFacet,
                     "value = FacetF_SchlickSG(float3(p5, p5, p5), 1.0, p3).x;", [](StudyRow& r) {
                       auto [worst, at] = max_abs_over(0.0, 1.0, 20000, [](double c) {
                         return ref::FacetF_SchlickSG(dvec3(0), 1.0, c).x - ref::FacetPow5(1 - c);
                       });
                       r.error = worst;
                       r.detail = fmt::format("@{:.1f} deg", degrees_of(at));
                     }));
  out.push_back(spec("F_Pow4", "F", "(1-c)^4 weight (Unity FresnelLerpFast)", "(1-c)^5", "max |dw|", "max |dw| 0.082",
                     kUnityBrdf, "value = FresnelLerpFast(half3(p5, p5, p5), half3(1, 1, 1), p3).x;", [](StudyRow& r) {
                       auto [worst, at] =
                           max_abs_over(0.0, 1.0, 20000, [](double c) { return u::Pow4(1 - c) - ref::FacetPow5(1 - c); });
                       r.error = worst;
                       r.detail = fmt::format("@{:.1f} deg", degrees_of(at));
                     }));
}

void add_diffuse(std::vector<RowSpec>& out) {
  out.push_back(spec("Fd_Lambert", "diffuse", "Lambert 1/pi", "albedo <= 1", "albedo excess over 1", "exactly 1",
                     kFacet, "value = FacetFd_Lambert() * p0;", [](StudyRow& r) {
                       albedo_row(r, {{"", model_lobe("lambert")}});
                     }));
  out.push_back(spec("Fd_Burley", "diffuse", "Disney/Burley diffuse", "albedo <= 1", "albedo excess over 1",
                     "max albedo 1.519 (r=1, NoV=.02); r=.5: 1.005-1.026", kFacet,
                     "value = FacetFd_Burley(p0, p1, p3, p4);", [](StudyRow& r) {
                       std::vector<std::pair<std::string, Lobe>> s;
                       for (double rough : {0.5, 1.0}) {
                         s.push_back({fmt::format("r={}", rough), model_lobe("burley", {{"roughness", dvec3(rough)}})});
                       }
                       albedo_row(r, s);
                     }));
  out.push_back(spec("Fd_Frostbite", "diffuse", "Frostbite renormalised Burley", "albedo <= 1", "albedo excess over 1",
                     "<= 1.006 (a=1), 0.826 (a=.5), 0.952 (a=0)", kFacet, "value = FacetFd_Frostbite(p0, p1, p3, p4);",
                     [](StudyRow& r) {
                       std::vector<std::pair<std::string, Lobe>> s;
                       for (double alpha : {0.0, 0.5, 1.0}) {
                         // The model's parameter is r, alpha = r^2.
                         s.push_back({fmt::format("a={}", alpha),
                                      model_lobe("frostbite", {{"roughness", dvec3(std::sqrt(alpha))}})});
                       }
                       albedo_row(r, s);
                     }));
  out.push_back(reference_row("Fd_OrenNayar", "diffuse", "Oren-Nayar full model (trigonometric)", kFacet,
                              "value = FacetFd_OrenNayar(p0, p1, p3 * 2 - 1, p4, 0.8);"));
  out.push_back(spec("Fd_OrenNayarQualitative", "diffuse", "Oren-Nayar qualitative (A, B vector form)",
                     "Oren-Nayar full model", "max lobe relL1 (sigma = .25/.5/1)",
                     "albedo 0.92-1.010 (sigma=.25), 0.78-0.95 (.5), 0.62-0.83 (1)", kFacet,
                     "value = FacetFd_OrenNayarQualitative(p0, p1, p3 * 2 - 1, p4);", [](StudyRow& r) {
                       std::vector<std::pair<std::string, std::pair<Lobe, Lobe>>> s;
                       for (double sigma : {0.25, 0.5, 1.0}) {
                         s.push_back({fmt::format("sigma={}", sigma),
                                      {model_lobe("oren-nayar-qualitative", {{"sigma", dvec3(sigma)}}),
                                       model_lobe("oren-nayar", {{"sigma", dvec3(sigma)}})}});
                       }
                       lobe_metrics(r, s);
                     }));
}

void add_specular(std::vector<RowSpec>& out) {
  out.push_back(spec("PhongNormalized", "specular", "Phong (n+2)/2pi (R.V)^n", "albedo <= 1", "albedo excess over 1",
                     "max 1.0000 (n=10, 100), 0.9975 (n=1000)", kFacet, "value = FacetPhongNormalized(p2, p4 * 100);",
                     [](StudyRow& r) {
                       std::vector<std::pair<std::string, Lobe>> s;
                       for (double n : {10.0, 100.0}) {
                         s.push_back({fmt::format("n={}", n), model_lobe("phong", {{"exponent", dvec3(n)}})});
                       }
                       albedo_row(r, s);
                     }));
  out.push_back(spec("BlinnPhongNormalized", "specular", "Blinn-Phong (n+8)/8pi NoH^n", "albedo <= 1",
                     "albedo excess over 1", "max 1.075 (n=10), 1.018 (100), 1.002 (1000)", kFacet,
                     "value = FacetBlinnPhongNormalized(p2, p4 * 100);", [](StudyRow& r) {
                       std::vector<std::pair<std::string, Lobe>> s;
                       for (double n : {10.0, 100.0}) {
                         s.push_back({fmt::format("n={}", n), model_lobe("blinn-phong", {{"exponent", dvec3(n)}})});
                       }
                       albedo_row(r, s);
                     }));
  out.push_back(spec("Specular_Ward", "specular", "Ward (Walter 2005 form)", "albedo <= 1", "energy lost (1 - min albedo)",
                     "max 0.971 / 0.794 / 0.586 (a=.1/.3/.5) at NoV=1", kFacet,
                     "value = FacetSpecular_Ward(p0, p1, p2, p6 * 0.5, p7 * 0.5, p4 * 0.5, p4 * 0.5);", [](StudyRow& r) {
                       std::vector<std::pair<std::string, Lobe>> s;
                       for (double a : {0.1, 0.3, 0.5}) {
                         s.push_back({fmt::format("a={}", a),
                                      model_lobe("ward", {{"alpha_x", dvec3(a)}, {"alpha_y", dvec3(a)}})});
                       }
                       albedo_row(r, s, true);
                     }));
  out.push_back(spec("Specular_AshikhminShirley", "specular", "Ashikhmin-Shirley specular (Rs = 1)", "albedo <= 1",
                     "energy lost (1 - min albedo)", "max 0.697 / 0.961 / 0.996 (n=10/100/1000)", kFacet,
                     "value = FacetSpecular_AshikhminShirley(p0, p1, p2, p3, p6 * 0.5, p7 * 0.5, 100, 100, 1);",
                     [](StudyRow& r) {
                       std::vector<std::pair<std::string, Lobe>> s;
                       for (double n : {10.0, 100.0}) {
                         // Rs = 1 leaves no diffuse lobe (its weight is 1 - Rs).
                         s.push_back({fmt::format("n={}", n),
                                      model_lobe("ashikhmin-shirley", {{"nu", dvec3(n)}, {"nv", dvec3(n)},
                                                                       {"rs", dvec3(1.0)}, {"rd", dvec3(0.0)}})});
                       }
                       albedo_row(r, s, true);
                     }));
  out.push_back(spec("CookTorranceGGX", "specular", "Cook-Torrance GGX single scatter (F = 1)", "albedo = 1",
                     "energy lost at a = 1 (1 - E_avg)",
                     "E_avg 0.991 (a=.05), 0.882 (.25), 0.700 (.5), 0.536 (.75), 0.409 (a=1)", kFacet,
                     "value = FacetBRDF_CookTorranceGGX(float3(0, 0, 1), normalize(float3(sqrt(1 - p0 * p0), 0, p0)), "
                     "normalize(float3(-p6, p7, p1)), float3(1, 1, 1), p4).x;",
                     [](StudyRow& r) {
                       std::string detail;
                       for (double alpha : {0.25, 0.5, 1.0}) {
                         Lobe f = ggx_model_lobe(alpha);
                         double e_avg = 0;
                         const int n = 16;
                         for (int i = 0; i < n; ++i) {  // E_avg = 2 int E(mu) mu dmu, midpoint rule
                           double mu = (i + 0.5) / n;
                           e_avg += 2.0 * albedo(f, view_at(mu)) * mu / n;
                         }
                         if (alpha == 1.0) r.error = 1.0 - e_avg;
                         detail += fmt::format("{}E_avg {:.3f} (a={})", detail.empty() ? "" : ", ", e_avg, alpha);
                       }
                       r.detail = detail;
                     }));
  out.push_back(spec("CookTorranceGGX_Compensated", "specular", "GGX + multiscatter compensation 1 + f0(1/E - 1), f0 = 1",
                     "albedo = 1", "max |E - 1| for NoV >= 0.05", "E(v) = 1 +- 0.01 for all r, NoV >= 0.05 (T7)",
                     kFacet, "value = FacetEnergyCompensation(float3(1, 1, 1), max(p5, 0.3)).x * FacetD_GGX(p2, p4) * "
                     "FacetV_SmithGGXCorrelated(p0, p1, p4);",
                     [](StudyRow& r) {
                       double worst = 0;
                       for (double alpha : {0.1, 0.5, 1.0}) {
                         for (double NoV : {1.0, 0.5, 0.2, 0.05}) {
                           Lobe f = ggx_model_lobe(alpha);
                           double e = albedo(f, view_at(NoV));
                           double E = ref::FacetDFG_Integrate(NoV, alpha, 4096).y;
                           double compensated = e * ref::FacetEnergyCompensation(dvec3(1), E).x;
                           worst = std::max(worst, std::abs(compensated - 1));
                         }
                       }
                       r.error = worst;
                       r.detail = "E from the DFG integral (4,096 samples), a = .1/.5/1";
                     }));
}

void add_standard(std::vector<RowSpec>& out) {
  const char* hlsl =
      "UnityLight l; l.color = float3(1, 1, 1); l.dir = normalize(float3(-p6, p7, p1)); l.ndotl = 0;\n"
      "UnityIndirect ind; ind.diffuse = 0; ind.specular = 0;\n"
      "value = BRDF{}_Unity_PBS(float3(0, 0, 0), float3(p5, p5, p5), 1 - p5, p4, float3(0, 0, 1), "
      "normalize(float3(sqrt(1 - p0 * p0), 0, p0)), l, ind).x;";
  const char* anchors[] = {"(V: Smith joint approximation of height-correlated V)",
                           "energy ratio 0.10-1.82x, relL1 0.14-0.90", ""};
  for (int tier = 1; tier <= 3; ++tier) {
    out.push_back(spec(fmt::format("BRDF{}_Unity_PBS", tier), "Standard", fmt::format("Unity Standard BRDF{} specular", tier),
                       "D_GGX * V_correlated (F = 1)", "max lobe relL1 (smoothness .2/.5/.8)", anchors[tier - 1],
                       kUnityBrdf, fmt::format(fmt::runtime(hlsl), tier), [tier](StudyRow& r) {
                         std::vector<std::pair<std::string, std::pair<Lobe, Lobe>>> s;
                         for (double smoothness : {0.2, 0.5, 0.8}) {
                           double rough = 1 - smoothness, alpha = std::max(rough * rough, 0.002);
                           s.push_back({fmt::format("s={}", smoothness),
                                        {unity_lobe(tier, smoothness), ggx_lobe(alpha, ref::FacetV_SmithGGXCorrelated)}});
                         }
                         lobe_metrics(r, s);
                       }));
  }
}

void add_ibl(std::vector<RowSpec>& out) {
  out.push_back(reference_row("EnvBRDF_DFG", "IBL", "DFG integral (split-sum BRDF term), f0*A + B", kFacetIbl,
                              "value = FacetEnvBRDF_DFG(float3(p5, p5, p5), 1.0, float2(p6, p7)).x;"));
  out.push_back(spec("EnvBRDFApprox", "IBL", "EnvBRDFApprox analytic fit (Karis mobile)", "DFG integral",
                     "max |dA| over NoV, r", "|dA| <= 0.40, |dB| <= 0.085; +47 % at r=1, NoV=1", kFacetIbl,
                     "value = FacetEnvBRDFApprox(float3(p5, p5, p5), p4, p0).x;", [](StudyRow& r) {
                       double worst_a = 0, worst_b = 0;
                       for (double rough : {0.0, 0.25, 0.5, 0.75, 1.0}) {
                         for (double NoV : {0.05, 0.25, 0.5, 0.75, 1.0}) {
                           glm::dvec2 dfg = ref::FacetDFG_Integrate(NoV, ref::FacetClampAlpha(rough * rough), 4096);
                           glm::dvec2 ab = ref::FacetEnvBRDFApproxAB(rough, NoV);
                           worst_a = std::max(worst_a, std::abs(ab.x - (dfg.y - dfg.x)));
                           worst_b = std::max(worst_b, std::abs(ab.y - dfg.x));
                         }
                       }
                       r.error = worst_a;
                       r.detail = fmt::format("|dB| {:.3f}", worst_b);
                     }));
  out.push_back(spec("Unity_SurfaceReduction", "IBL", "Unity BRDF1 IBL: FresnelLerp(f0, grazing, NoV)/(a^2+1)",
                     "DFG integral f0*A + B", "max abs error (f0 = .04 and 1)", "<= 0.25 (f0=.04), <= 0.39 (f0=1)",
                     kUnityBrdf,
                     "value = FresnelLerp(half3(p5, p5, p5), half3(1, 1, 1), p0).x / (p4 * p4 * p4 * p4 + 1);",
                     [](StudyRow& r) {
                       std::string detail;
                       double worst_all = 0;
                       for (double f0 : {0.04, 1.0}) {
                         double worst = 0;
                         for (double smoothness : {0.0, 0.25, 0.5, 0.75, 1.0}) {
                           double rough = 1 - smoothness, alpha = rough * rough;
                           double grazing = std::clamp(smoothness + f0, 0.0, 1.0);  // 1 - oneMinusReflectivity = f0
                           for (double NoV : {0.05, 0.25, 0.5, 0.75, 1.0}) {
                             double unity = u::FresnelLerp(dvec3(f0), dvec3(grazing), NoV).x / (alpha * alpha + 1);
                             glm::dvec2 dfg = ref::FacetDFG_Integrate(NoV, ref::FacetClampAlpha(alpha), 4096);
                             worst = std::max(worst, std::abs(unity - ref::FacetEnvBRDF_DFG(dvec3(f0), 1.0, dfg).x));
                           }
                         }
                         worst_all = std::max(worst_all, worst);
                         detail += fmt::format("{}f0={}: {:.3f}", detail.empty() ? "" : "; ", f0, worst);
                       }
                       r.error = worst_all;
                       r.detail = detail;
                     }));
  out.push_back(spec("Unity_BRDF2_SurfaceReduction", "IBL", "Unity BRDF2 1 - r^3 (0.6 - 0.08 r)", "1/(r^4 + 1)",
                     "max abs error", "max abs 0.020", kFacet, "value = 1 - p4 * p4 * p4 * (0.6 - 0.08 * p4);",
                     [](StudyRow& r) {
                       auto [worst, at] = max_abs_over(0.0, 1.0, 10000, [](double x) {
                         return (1 - x * x * x * (0.6 - 0.08 * x)) - 1 / (x * x * x * x + 1);
                       });
                       r.error = worst;
                       r.detail = fmt::format("@r={:.2f}", at);
                     }));
}

void add_tonemap_and_color(std::vector<RowSpec>& out) {
  auto tonemap = [&](const char* id, const char* name, const char* call) {
    out.push_back(reference_row(id, "tonemap", name, kFacetTonemap, fmt::format("value = {}(float3(p0, p1, p2) * 8).x;", call)));
  };
  tonemap("Tonemap_ACESHill", "ACES fitted (Hill RRT+ODT)", "FacetTonemapACESHill");
  tonemap("Tonemap_Reinhard", "Reinhard x/(1+x)", "FacetTonemapReinhard");
  tonemap("Tonemap_Hable", "Hable (Uncharted 2) filmic", "FacetTonemapHable");
  tonemap("Tonemap_PBRNeutral", "Khronos PBR Neutral", "FacetTonemapPBRNeutral");
  tonemap("Tonemap_AgX", "AgX (minimal)", "FacetTonemapAgX");
  out.push_back(spec("Tonemap_ACESNarkowicz", "tonemap", "ACES fitted (Narkowicz curve)", "ACES Hill RRT+ODT fit",
                     "max abs error on grey, x in [0, 16]", "", kFacetTonemap,
                     "value = FacetTonemapACESNarkowicz(float3(p0, p1, p2) * 8).x;", [](StudyRow& r) {
                       auto [worst, at] = max_abs_over(0.0, 16.0, 16000, [](double x) {
                         return std::clamp(ref::FacetTonemapACESNarkowicz(dvec3(x)).x, 0.0, 1.0) -
                                std::clamp(ref::FacetTonemapACESHill(dvec3(x)).x, 0.0, 1.0);
                       });
                       r.error = worst;
                       r.detail = fmt::format("@x={:.2f} (both clamped to [0, 1])", at);
                     }));
  out.push_back(reference_row("LinearToSRGB", "sRGB", "exact sRGB encode (IEC 61966-2-1)", kFacetColor,
                              "value = FacetLinearToSRGB(p0);"));
  out.push_back(spec("SRGBPow22", "sRGB", "sRGB encode as x^(1/2.2)", "exact sRGB encode", "max abs error",
                     "max abs 0.0335 (8.5 codes) at linear 0.0022", kFacetColor, "value = pow(p0, 1.0 / 2.2);",
                     [](StudyRow& r) {
                       auto [worst, at] = max_abs_over(0.0, 1.0, 200000, [](double x) {
                         return std::pow(x, 1 / 2.2) - ref::FacetLinearToSRGB(x);
                       });
                       r.error = worst;
                       r.detail = fmt::format("@linear {:.4f} ({:.1f} 8-bit codes)", at, worst * 255);
                     }));
  out.push_back(reference_row("Translucency", "translucency", "Barre-Brisebois fast translucency", kFacet,
                              "value = FacetTranslucency(float3(0, 0, 1), normalize(float3(p6, 0, p0)), "
                              "normalize(float3(-p7, 0, -p1)), 0.2, 4, 1, 0.1, 1);"));
}

}  // namespace

std::vector<RowSpec> catalogue() {
  std::vector<RowSpec> out;
  add_ndf(out);
  add_visibility(out);
  add_fresnel(out);
  add_diffuse(out);
  add_specular(out);
  add_standard(out);
  add_ibl(out);
  add_tonemap_and_color(out);
  return out;
}

}  // namespace facet::runtime::accuracy
