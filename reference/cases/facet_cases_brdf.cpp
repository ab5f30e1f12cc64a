// Cases for the diffuse terms, the Phong family, NDFs, masking functions and
// the helpers of stdlib/FacetBRDF.hlsl.
#include "case_helpers.h"

#include "facet/reference/brdf.h"

namespace facet::reference::cases {
namespace {

// Cosines of a (v, l) pair drawn around n = +z. L = -V is excluded
// (|v + l| >= 0.1): there H is undefined and every term using it is
// ill-conditioned in any precision.
struct Pair {
  double NoV, NoL, NoH, LoH, LoV, HoX, HoY;
};
Pair draw_pair(Rng& rng, double minNoV, double minNoL) {
  const glm::dvec3 n(0, 0, 1);
  for (;;) {
    glm::dvec3 v = rng.direction(n, minNoV, 1.0);
    glm::dvec3 l = rng.direction(n, minNoL, 1.0);
    glm::dvec3 s = v + l;
    if (glm::dot(s, s) < 0.01) continue;
    glm::dvec3 h = glm::normalize(s);
    return {v.z, l.z, h.z, glm::dot(l, h), glm::dot(l, v), h.x, h.y};
  }
}

// cos(theta) with theta dense near 0, for NDF peaks, without libm:
// 1 - cos = (1 - lo) t^4 keeps a quarter of the points within
// 1 - cos < (1 - lo)/256 of the peak.
double peaked_cos(Rng& rng, double lo) {
  double t = rng.uniform();
  return 1.0 - (1.0 - lo) * t * t * t * t;
}

void add_helpers(std::vector<FunctionCase>& out) {
  out.push_back(make_case("FacetPow5", "x in [-0.1, 1]", 1, 1, kIncludeBRDF, "r.x = FacetPow5(x[0]);",
                          [](const double* x, double* r) { r[0] = FacetPow5(x[0]); },
                          [](Rng& g, float* x) { x[0] = float(g.uniform(-0.1, 1.0)); }));
  out.push_back(make_case("FacetAcos", "x in [-1, 1]", 1, 1, kIncludeBRDF, "r.x = FacetAcos(x[0]);",
                          [](const double* x, double* r) { r[0] = FacetAcos(x[0]); },
                          [](Rng& g, float* x) { x[0] = float(g.uniform(-1.0, 1.0)); }));
  out.push_back(make_case("FacetClampNoV", "NoV in [-1, 1]", 1, 1, kIncludeBRDF, "r.x = FacetClampNoV(x[0]);",
                          [](const double* x, double* r) { r[0] = FacetClampNoV(x[0]); },
                          [](Rng& g, float* x) { x[0] = float(g.uniform(-1.0, 1.0)); }));
  out.push_back(make_case("FacetClampAlpha", "alpha in [0, 0.05]", 1, 1, kIncludeBRDF, "r.x = FacetClampAlpha(x[0]);",
                          [](const double* x, double* r) { r[0] = FacetClampAlpha(x[0]); },
                          [](Rng& g, float* x) { x[0] = float(g.uniform(0.0, 0.05)); }));
  out.push_back(make_case("FacetPerceptualRoughnessToAlpha", "r in [0, 1]", 1, 1, kIncludeBRDF,
                          "r.x = FacetPerceptualRoughnessToAlpha(x[0]);",
                          [](const double* x, double* r) { r[0] = FacetPerceptualRoughnessToAlpha(x[0]); },
                          [](Rng& g, float* x) { x[0] = float(g.uniform()); }));
  out.push_back(make_case("FacetSafeNormalize", "|v| in [0, 2], zero included", 3, 3, kIncludeBRDF,
                          "r.xyz = FacetSafeNormalize(" + xv(0) + ");",
                          [](const double* x, double* r) {
                            glm::dvec3 v = FacetSafeNormalize(v3(x, 0));
                            r[0] = v.x, r[1] = v.y, r[2] = v.z;
                          },
                          [](Rng& g, float* x) {
                            double len = g.uniform() < 0.05 ? 0.0 : g.log_uniform(1e-4, 2.0);
                            put(x, 0, len * g.unit_vector());
                          }));
  for (int part = 0; part < 2; ++part) {
    std::string hlsl = "FacetAngles a = FacetComputeAngles(" + xv(0) + ", " + xv(3) + ", " + xv(6) + ");\n" +
                       (part == 0 ? "r = float4(a.NoV, a.NoL, a.NoH, a.LoH);" : "r.x = a.LoV;");
    out.push_back(make_case(
        "FacetComputeAngles", part == 0 ? "NoV NoL NoH LoH" : "LoV", 9, part == 0 ? 4 : 1, kIncludeBRDF, hlsl,
        [part](const double* x, double* r) {
          FacetAngles a = FacetComputeAngles(v3(x, 0), v3(x, 3), v3(x, 6));
          if (part == 0) r[0] = a.NoV, r[1] = a.NoL, r[2] = a.NoH, r[3] = a.LoH;
          else r[0] = a.LoV;
        },
        [](Rng& g, float* x) {
          // Unnormalised inputs (length 0.5..2) and back-facing v and l are
          // part of the range; L = -V is not (see draw_pair).
          Frame f = random_frame(g);
          glm::dvec3 v, l;
          do {
            v = g.direction(f.n, -0.5, 1.0);
            l = g.direction(f.n, -0.5, 1.0);
          } while (glm::dot(v + l, v + l) < 0.01);
          put(x, 0, g.uniform(0.5, 2.0) * f.n);
          put(x, 3, g.uniform(0.5, 2.0) * v);
          put(x, 6, g.uniform(0.5, 2.0) * l);
        }));
  }
}

void add_diffuse(std::vector<FunctionCase>& out) {
  out.push_back(make_case("FacetFd_Lambert", "constant", 1, 1, kIncludeBRDF, "r.x = FacetFd_Lambert();",
                          [](const double*, double* r) { r[0] = FacetFd_Lambert(); }, [](Rng&, float*) {}));
  for (double rough : {0.0, 0.5, 1.0}) {
    out.push_back(make_case(
        "FacetFd_Burley", "r=" + lit(rough), 3, 1, kIncludeBRDF,
        "r.x = FacetFd_Burley(x[0], x[1], x[2], " + lit(rough) + ");",
        [rough](const double* x, double* r) { r[0] = FacetFd_Burley(x[0], x[1], x[2], fp(rough)); },
        [](Rng& g, float* x) {
          Pair p = draw_pair(g, FACET_MIN_NOV, 0.0);
          x[0] = float(p.NoV), x[1] = float(p.NoL), x[2] = float(p.LoH);
        }));
  }
  for (double alpha : {FACET_MIN_ALPHA, 0.25, 1.0}) {
    out.push_back(make_case(
        "FacetFd_Frostbite", "alpha=" + lit(alpha), 3, 1, kIncludeBRDF,
        "r.x = FacetFd_Frostbite(x[0], x[1], x[2], " + lit(alpha) + ");",
        [alpha](const double* x, double* r) { r[0] = FacetFd_Frostbite(x[0], x[1], x[2], fp(alpha)); },
        [](Rng& g, float* x) {
          Pair p = draw_pair(g, FACET_MIN_NOV, 0.0);
          x[0] = float(p.NoV), x[1] = float(p.NoL), x[2] = float(p.LoH);
        }));
  }
  for (double sigma : {0.25, 0.5, 1.0}) {
    // Both cosines >= 0.02: s = LoV - NoL NoV cancels in fp32 (absolute
    // error ~1e-7) and is divided by max(NoL, NoV), so with both directions
    // grazing the fp32 error exceeds 1e-4 relative by construction.
    out.push_back(make_case(
        "FacetFd_OrenNayarQualitative", "sigma=" + lit(sigma), 3, 1, kIncludeBRDF,
        "r.x = FacetFd_OrenNayarQualitative(x[0], x[1], x[2], " + lit(sigma) + ");",
        [sigma](const double* x, double* r) { r[0] = FacetFd_OrenNayarQualitative(x[0], x[1], x[2], fp(sigma)); },
        [](Rng& g, float* x) {
          Pair p = draw_pair(g, 0.02, 0.02);
          x[0] = float(p.NoV), x[1] = float(p.NoL), x[2] = float(p.LoV);
        }));
    // Cosines >= 0.01: tan(beta) = sin/cos grows as 1/cos at grazing angles,
    // and with it the fp32 error of the cos(phi) it multiplies.
    out.push_back(make_case(
        "FacetFd_OrenNayar", "sigma=" + lit(sigma), 4, 1, kIncludeBRDF,
        "r.x = FacetFd_OrenNayar(x[0], x[1], x[2], " + lit(sigma) + ", x[3]);",
        [sigma](const double* x, double* r) { r[0] = FacetFd_OrenNayar(x[0], x[1], x[2], fp(sigma), x[3]); },
        [](Rng& g, float* x) {
          Pair p = draw_pair(g, 0.01, 0.01);
          x[0] = float(p.NoV), x[1] = float(p.NoL), x[2] = float(p.LoV), x[3] = float(g.uniform());
        }));
  }
  for (double rs : {0.0, 0.5}) {
    out.push_back(make_case(
        "FacetFd_AshikhminShirley", "rs=" + lit(rs), 3, 1, kIncludeBRDF,
        "r.x = FacetFd_AshikhminShirley(x[0], x[1], x[2], " + lit(rs) + ");",
        [rs](const double* x, double* r) { r[0] = FacetFd_AshikhminShirley(x[0], x[1], x[2], fp(rs)); },
        [](Rng& g, float* x) {
          Pair p = draw_pair(g, FACET_MIN_NOV, 0.0);
          x[0] = float(p.NoV), x[1] = float(p.NoL), x[2] = float(g.uniform());
        }));
  }
}

void add_phong(std::vector<FunctionCase>& out) {
  using Fn = double (*)(double, double);
  struct Entry {
    const char* name;
    Fn fn;
  };
  const Entry entries[] = {{"FacetPhong", FacetPhong},
                           {"FacetPhongNormalized", FacetPhongNormalized},
                           {"FacetBlinnPhong", FacetBlinnPhong},
                           {"FacetBlinnPhongNormalized", FacetBlinnPhongNormalized},
                           {"FacetD_BlinnPhong", FacetD_BlinnPhong}};
  for (const Entry& e : entries) {
    for (double n : {5.0, 50.0, 500.0}) {
      Fn fn = e.fn;
      out.push_back(make_case(
          e.name, "n=" + lit(n), 1, 1, kIncludeBRDF, std::string("r.x = ") + e.name + "(x[0], " + lit(n) + ");",
          [fn, n](const double* x, double* r) { r[0] = fn(x[0], fp(n)); },
          [](Rng& g, float* x) { x[0] = float(g.uniform() < 0.1 ? g.uniform(-0.3, 0.0) : peaked_cos(g, 0.0)); }));
    }
  }
  out.push_back(make_case("FacetAlphaToBlinnPhongExponent", "alpha in [0, 1]", 1, 1, kIncludeBRDF,
                          "r.x = FacetAlphaToBlinnPhongExponent(x[0]);",
                          [](const double* x, double* r) { r[0] = FacetAlphaToBlinnPhongExponent(x[0]); },
                          [](Rng& g, float* x) { x[0] = float(g.uniform()); }));
}

void add_ndfs(std::vector<FunctionCase>& out) {
  // Plain GGX: 1 - NoH^2 (1 - a^2) has an fp32 absolute error of ~2e-7, so
  // its relative error is ~2e-7/d and D's twice that. At alpha = 0.02 the
  // points with d < 7e-3 (theta_h < 4.8 degrees, the peak) are left out:
  // that is the documented reason for FacetD_GGX_FP16Safe.
  for (double alpha : {0.02, 0.1, 0.5, 1.0}) {
    double lo = alpha < 0.05 ? 0.9965 : 1.0;
    out.push_back(make_case(
        "FacetD_GGX", "alpha=" + lit(alpha) + (lo < 1 ? ", NoH <= 0.9965" : ""), 1, 1, kIncludeBRDF,
        "r.x = FacetD_GGX(x[0], " + lit(alpha) + ");",
        [alpha](const double* x, double* r) { r[0] = FacetD_GGX(x[0], fp(alpha)); },
        [lo](Rng& g, float* x) { x[0] = float(lo * peaked_cos(g, 0.0)); }));
  }
  // The |n x h|^2 form has a relative error ~1e-7/sin(theta_h), so it keeps
  // 1e-4 down to the fp32 clamp alpha = 0.002025 (where k <= 453.5 is active).
  for (double alpha : {FACET_MIN_ALPHA, FACET_MIN_ALPHA_FP16, 0.1, 0.5}) {
    out.push_back(make_case(
        "FacetD_GGX_FP16Safe", "alpha=" + lit(alpha), 6, 1, kIncludeBRDF,
        "r.x = FacetD_GGX_FP16Safe(" + xv(0) + ", " + xv(3) + ", " + lit(alpha) + ");",
        [alpha](const double* x, double* r) { r[0] = FacetD_GGX_FP16Safe(v3(x, 0), v3(x, 3), fp(alpha)); },
        [alpha](Rng& g, float* x) {
          Frame f = random_frame(g);
          put(x, 0, f.n);
          put(x, 3, g.near(f.n, 8.0 * alpha + 0.02));
        }));
  }
  const glm::dvec2 aniso[] = {{0.05, 0.2}, {0.3, 0.3}, {0.5, 1.0}};
  for (glm::dvec2 a : aniso) {
    out.push_back(make_case(
        "FacetD_GGXAnisotropic", "alphaX=" + lit(a.x) + " alphaY=" + lit(a.y), 3, 1, kIncludeBRDF,
        "r.x = FacetD_GGXAnisotropic(x[0], x[1], x[2], " + lit(a.x) + ", " + lit(a.y) + ");",
        [a](const double* x, double* r) { r[0] = FacetD_GGXAnisotropic(x[0], x[1], x[2], fp(a.x), fp(a.y)); },
        [a](Rng& g, float* x) {
          glm::dvec3 h = g.near({0, 0, 1}, 4.0 * a.y + 0.05);
          x[0] = float(h.z), x[1] = float(h.x), x[2] = float(h.y);
        }));
  }
  // Beckmann: exp(-tan^2/alpha^2) turns the ~6e-8 absolute error of the
  // argument into 6e-8/alpha^2 relative, so alpha >= 0.05.
  for (double alpha : {0.05, 0.3, 0.7}) {
    out.push_back(make_case(
        "FacetD_Beckmann", "alpha=" + lit(alpha), 1, 1, kIncludeBRDF,
        "r.x = FacetD_Beckmann(x[0], " + lit(alpha) + ");",
        [alpha](const double* x, double* r) { r[0] = FacetD_Beckmann(x[0], fp(alpha)); },
        [](Rng& g, float* x) { x[0] = float(peaked_cos(g, 0.0)); }));
  }
}

void add_masking(std::vector<FunctionCase>& out) {
  using Fn3 = double (*)(double, double, double);
  struct Entry {
    const char* name;
    Fn3 fn;
    const char* param;
    std::vector<double> values;
  };
  const std::vector<Entry> entries = {
      {"FacetV_SmithGGXSeparable", FacetV_SmithGGXSeparable, "alpha", {FACET_MIN_ALPHA, 0.25, 1.0}},
      {"FacetV_SmithGGXCorrelated", FacetV_SmithGGXCorrelated, "alpha", {FACET_MIN_ALPHA, 0.25, 1.0}},
      {"FacetV_SmithGGXCorrelatedFast", FacetV_SmithGGXCorrelatedFast, "alpha", {FACET_MIN_ALPHA, 0.25, 1.0}},
      {"FacetV_SmithSchlick", FacetV_SmithSchlick, "k", {0.05, 0.25, 0.5}},
      {"FacetV_SchlickGGX", FacetV_SchlickGGX, "alpha", {FACET_MIN_ALPHA, 0.25, 1.0}},
      {"FacetV_SchlickGGXKaris", FacetV_SchlickGGXKaris, "r", {0.0, 0.5, 1.0}},
  };
  for (const Entry& e : entries) {
    for (double p : e.values) {
      Fn3 fn = e.fn;
      out.push_back(make_case(
          e.name, std::string(e.param) + "=" + lit(p), 2, 1, kIncludeBRDF,
          std::string("r.x = ") + e.name + "(x[0], x[1], " + lit(p) + ");",
          [fn, p](const double* x, double* r) { r[0] = fn(x[0], x[1], fp(p)); },
          [](Rng& g, float* x) {
            x[0] = float(g.uniform() < 0.2 ? g.log_uniform(FACET_MIN_NOV, 0.05) : g.uniform(FACET_MIN_NOV, 1.0));
            x[1] = float(g.uniform() < 0.05 ? 0.0 : g.uniform());
          }));
    }
  }
  using Fn2 = double (*)(double, double);
  const std::pair<const char*, Fn2> singles[] = {{"FacetLambda_SmithGGX", FacetLambda_SmithGGX},
                                                 {"FacetG1_SmithGGX", FacetG1_SmithGGX},
                                                 {"FacetG1_SmithBeckmann", FacetG1_SmithBeckmann}};
  for (auto [name, fn] : singles) {
    for (double alpha : {0.05, 0.3, 1.0}) {
      out.push_back(make_case(
          name, "alpha=" + lit(alpha), 1, 1, kIncludeBRDF,
          std::string("r.x = ") + name + "(x[0], " + lit(alpha) + ");",
          [fn, alpha](const double* x, double* r) { r[0] = fn(x[0], fp(alpha)); },
          [](Rng& g, float* x) { x[0] = float(g.uniform(0.01, 1.0)); }));
    }
  }
  out.push_back(make_case("FacetG_CookTorrance", "v, l around n", 4, 1, kIncludeBRDF,
                          "r.x = FacetG_CookTorrance(x[0], x[1], x[2], x[3]);",
                          [](const double* x, double* r) { r[0] = FacetG_CookTorrance(x[0], x[1], x[2], x[3]); },
                          [](Rng& g, float* x) {
                            Pair p = draw_pair(g, FACET_MIN_NOV, 0.0);
                            x[0] = float(p.NoV), x[1] = float(p.NoL), x[2] = float(p.NoH), x[3] = float(p.LoH);
                          }));
}

}  // namespace

void add_diffuse_cases(std::vector<FunctionCase>& out) {
  add_helpers(out);
  add_diffuse(out);
  add_phong(out);
}

void add_specular_cases(std::vector<FunctionCase>& out) {
  add_ndfs(out);
  add_masking(out);
}

}  // namespace facet::reference::cases
