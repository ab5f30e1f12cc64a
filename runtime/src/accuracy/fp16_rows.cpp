// The fp16 rows: domains and fp64 twins (fp16_rows.h).
#include "accuracy/fp16_rows.h"

#include <glm/glm.hpp>

#include <cmath>
#include <limits>

#include "facet/reference/brdf.h"

namespace facet::runtime::accuracy {
namespace {

namespace ref = facet::reference;

double as_float(double x) { return double(float(x)); }

// n values from lo to hi, ends included.
std::vector<double> steps(double lo, double hi, int n) {
  std::vector<double> out;
  for (int i = 0; i < n; ++i) out.push_back(lo + (hi - lo) * i / (n - 1));
  return out;
}

// The GGX D domain of the CPU fp16 rows (catalogue.cpp): alpha in {0.0079,
// 0.02, 0.0625, 0.25}, theta_h in [0, 30 deg] where D > 1e-3 of the peak;
// p0 = sin theta_h, p2 = cos theta_h (h = (p0, 0, p2)), p4 = alpha.
std::vector<Inputs> ggx_points() {
  std::vector<Inputs> out;
  for (double alpha : {0.0079, 0.02, 0.0625, 0.25}) {
    double peak = ref::FacetD_GGX(1.0, alpha);
    for (int i = 0; i <= 3000; ++i) {
      double theta = (30.0 * i / 3000) * M_PI / 180.0;
      if (ref::FacetD_GGX(std::cos(theta), alpha) < 1e-3 * peak) continue;
      out.push_back({as_float(std::sin(theta)), 0, as_float(std::cos(theta)), 0, as_float(alpha), 0, 0, 0});
    }
  }
  return out;
}

// NoV = p0, NoL = p1 on a 41 x 41 grid over [0.01, 1], p4 in `params`.
std::vector<Inputs> visibility_points(std::initializer_list<double> params) {
  std::vector<Inputs> out;
  for (double p : params)
    for (double nv : steps(0.01, 1.0, 41))
      for (double nl : steps(0.01, 1.0, 41)) out.push_back({as_float(nv), as_float(nl), 0, 0, as_float(p), 0, 0, 0});
  return out;
}

// VoH = p3 over [0, 1] (1001 values), f0 = p5 in {0.02, 0.04, 0.5, 1}.
std::vector<Inputs> fresnel_points() {
  std::vector<Inputs> out;
  for (double f0 : {0.02, 0.04, 0.5, 1.0})
    for (double c : steps(0.0, 1.0, 1001)) out.push_back({0, 0, 0, as_float(c), 0, as_float(f0), 0, 0});
  return out;
}

// NoV = p0, NoL = p1, LoH = p3 on 21^3 points over [0.01, 1], roughness p4 in {0.1, 0.5, 1}.
std::vector<Inputs> diffuse_points() {
  std::vector<Inputs> out;
  for (double r : {0.1, 0.5, 1.0})
    for (double nv : steps(0.01, 1.0, 21))
      for (double nl : steps(0.01, 1.0, 21))
        for (double lh : steps(0.01, 1.0, 21)) out.push_back({as_float(nv), as_float(nl), 0, as_float(lh), as_float(r), 0, 0, 0});
  return out;
}

constexpr const char* kGgxDomain = "a = 0.0079/0.02/0.0625/0.25, theta_h <= 30 deg where D > 1e-3 peak";
constexpr const char* kVisibilityDomain = "NoV, NoL in [0.01, 1] (41 x 41), a = 0.0079/0.0625/0.25/1";

}  // namespace

std::vector<Fp16Row> fp16_rows() {
  auto v = [](const char* id, double (*twin)(double, double, double), const char* domain,
              std::initializer_list<double> params) {
    return Fp16Row{id, domain, visibility_points(params), [twin](const Inputs& p) { return twin(p[0], p[1], p[4]); }};
  };
  return {
      {"D_GGX_fp16", kGgxDomain, ggx_points(), [](const Inputs& p) { return ref::FacetD_GGX(p[2], p[4]); }},
      // h = (sin, 0, cos) as given, rounded to half (the CPU row's h), not
      // rebuilt from NoH in half as the timed kernel does.
      {"D_GGX_FP16Safe", kGgxDomain, ggx_points(), [](const Inputs& p) { return ref::FacetD_GGX(p[2], p[4]); },
       "value = FacetD_GGX_FP16Safe(float3(0.0, 0.0, 1.0), float3(p0, 0.0, p2), p4);"},
      v("V_SmithGGXCorrelated", ref::FacetV_SmithGGXCorrelated, kVisibilityDomain, {0.0079, 0.0625, 0.25, 1.0}),
      v("V_SmithGGXCorrelatedFast", ref::FacetV_SmithGGXCorrelatedFast, kVisibilityDomain, {0.0079, 0.0625, 0.25, 1.0}),
      v("V_SmithGGXSeparable", ref::FacetV_SmithGGXSeparable, kVisibilityDomain, {0.0079, 0.0625, 0.25, 1.0}),
      v("V_SchlickGGX", ref::FacetV_SchlickGGX, kVisibilityDomain, {0.0079, 0.0625, 0.25, 1.0}),
      v("V_SchlickGGXKaris", ref::FacetV_SchlickGGXKaris,
        "NoV, NoL in [0.01, 1] (41 x 41), perceptual roughness 0.089/0.25/0.5/1", {0.089, 0.25, 0.5, 1.0}),
      {"F_Schlick", "VoH in [0, 1] (1001 values), f0 = 0.02/0.04/0.5/1, f90 = 1", fresnel_points(),
       [](const Inputs& p) { return ref::FacetF_Schlick(p[5], 1.0, p[3]); }},
      {"F_SchlickSG", "VoH in [0, 1] (1001 values), f0 = 0.02/0.04/0.5/1, f90 = 1", fresnel_points(),
       [](const Inputs& p) { return ref::FacetF_SchlickSG(glm::dvec3(p[5]), 1.0, p[3]).x; }},
      {"Fd_Burley", "NoV, NoL, LoH in [0.01, 1] (21^3), roughness 0.1/0.5/1", diffuse_points(),
       [](const Inputs& p) { return ref::FacetFd_Burley(p[0], p[1], p[3], p[4]); }},
  };
}

double max_relative_error(const std::vector<float>& gpu, const Fp16Row& row) {
  double worst = 0;
  for (size_t i = 0; i < row.points.size() && i < gpu.size(); ++i) {
    if (!std::isfinite(gpu[i])) return std::numeric_limits<double>::infinity();
    worst = std::max(worst, std::abs(double(gpu[i]) / row.twin(row.points[i]) - 1.0));
  }
  return worst;
}

}  // namespace facet::runtime::accuracy
