// Cases for the Fresnel terms, the assembled specular lobes (Cook-Torrance,
// Ashikhmin-Shirley, Ward), energy compensation and translucency.
#include "case_helpers.h"

#include "facet/reference/brdf.h"

namespace facet::reference::cases {
namespace {

// Approximate complex IORs (n, k) at 650/550/450 nm, illustrative only: the
// case checks the formula, not the optics.
struct Metal {
  const char* name;
  glm::dvec3 eta, k;
};
const Metal kMetals[] = {
    {"Au", {0.18, 0.42, 1.37}, {3.42, 2.35, 1.77}},
    {"Ag", {0.15, 0.12, 0.14}, {4.83, 3.12, 2.15}},
    {"Cu", {0.27, 0.68, 1.32}, {3.61, 2.63, 2.29}},
    {"Al", {1.66, 0.88, 0.52}, {8.07, 6.35, 4.93}},
};

void put_out3(double* r, const glm::dvec3& v) { r[0] = v.x, r[1] = v.y, r[2] = v.z; }

void add_fresnel(std::vector<FunctionCase>& out) {
  out.push_back(make_case("FacetF_Schlick", "scalar, f0 f90 VoH in [0, 1]", 3, 1, kIncludeBRDF,
                          "r.x = FacetF_Schlick(x[0], x[1], x[2]);",
                          [](const double* x, double* r) { r[0] = FacetF_Schlick(x[0], x[1], x[2]); },
                          [](Rng& g, float* x) {
                            x[0] = float(g.uniform()), x[1] = float(g.uniform()), x[2] = float(g.uniform());
                          }));
  out.push_back(make_case("FacetF_Schlick", "float3 f0", 5, 3, kIncludeBRDF,
                          "r.xyz = FacetF_Schlick(" + xv(0) + ", x[3], x[4]);",
                          [](const double* x, double* r) { put_out3(r, FacetF_Schlick(v3(x, 0), x[3], x[4])); },
                          [](Rng& g, float* x) {
                            for (int i = 0; i < 5; ++i) x[i] = float(g.uniform());
                          }));
  out.push_back(make_case("FacetF_SchlickSG", "float3 f0", 5, 3, kIncludeBRDF,
                          "r.xyz = FacetF_SchlickSG(" + xv(0) + ", x[3], x[4]);",
                          [](const double* x, double* r) { put_out3(r, FacetF_SchlickSG(v3(x, 0), x[3], x[4])); },
                          [](Rng& g, float* x) {
                            for (int i = 0; i < 5; ++i) x[i] = float(g.uniform());
                          }));
  out.push_back(make_case("FacetF90FromF0", "f0 in [0, 0.1]^3", 3, 1, kIncludeBRDF,
                          "r.x = FacetF90FromF0(" + xv(0) + ");",
                          [](const double* x, double* r) { r[0] = FacetF90FromF0(v3(x, 0)); },
                          [](Rng& g, float* x) {
                            for (int i = 0; i < 3; ++i) x[i] = float(g.uniform(0.0, 0.1));
                          }));
  out.push_back(make_case("FacetF0FromIOR", "eta in [1, 3]", 1, 1, kIncludeBRDF, "r.x = FacetF0FromIOR(x[0]);",
                          [](const double* x, double* r) { r[0] = FacetF0FromIOR(x[0]); },
                          [](Rng& g, float* x) { x[0] = float(g.uniform(1.0, 3.0)); }));
  for (double eta : {1.33, 1.5, 2.4, 1.0 / 1.5}) {
    // Inside a denser medium (eta < 1) F rises to 1 with an infinite slope at
    // the critical angle; points within 0.01 of cos^2 = 1 - eta^2 are left out.
    double crit2 = 1.0 - fp(eta) * fp(eta);
    out.push_back(make_case(
        "FacetF_Dielectric", "eta=" + lit(eta), 1, 1, kIncludeBRDF, "r.x = FacetF_Dielectric(" + lit(eta) + ", x[0]);",
        [eta](const double* x, double* r) { r[0] = FacetF_Dielectric(fp(eta), x[0]); },
        [crit2](Rng& g, float* x) {
          double c2;
          do c2 = g.uniform(); while (crit2 > 0 && std::abs(c2 - crit2) < 0.01);
          x[0] = float(std::sqrt(c2));
        }));
  }
  for (const Metal& m : kMetals) {
    out.push_back(make_case(
        "FacetF_Conductor", m.name, 1, 3, kIncludeBRDF,
        "r.xyz = FacetF_Conductor(" + lit3(m.eta) + ", " + lit3(m.k) + ", x[0]);",
        [m](const double* x, double* r) {
          glm::dvec3 eta(fp(m.eta.x), fp(m.eta.y), fp(m.eta.z)), k(fp(m.k.x), fp(m.k.y), fp(m.k.z));
          put_out3(r, FacetF_Conductor(eta, k, x[0]));
        },
        [](Rng& g, float* x) { x[0] = float(g.uniform()); }));
  }
  out.push_back(make_case("FacetF_Conductor", "eta in [0.05, 3], k in [0, 8]", 7, 3, kIncludeBRDF,
                          "r.xyz = FacetF_Conductor(" + xv(0) + ", " + xv(3) + ", x[6]);",
                          [](const double* x, double* r) { put_out3(r, FacetF_Conductor(v3(x, 0), v3(x, 3), x[6])); },
                          [](Rng& g, float* x) {
                            for (int i = 0; i < 3; ++i) x[i] = float(g.uniform(0.05, 3.0));
                            for (int i = 3; i < 6; ++i) x[i] = float(g.uniform(0.0, 8.0));
                            x[6] = float(g.uniform());
                          }));
}

// (v, l, h) in the z frame with h's tangent-frame coordinates, L = -V left out.
struct Geometry {
  double NoV, NoL, NoH, LoH, HoX, HoY;
};
Geometry draw_geometry(Rng& g, double spread) {
  const glm::dvec3 n(0, 0, 1);
  for (;;) {
    // Draw h near n and v, reflect: concentrates points on the lobe.
    glm::dvec3 v = g.direction(n, FACET_MIN_NOV, 1.0);
    glm::dvec3 h = g.uniform() < 0.7 ? g.near(n, spread) : g.direction(n, 0.0, 1.0);
    glm::dvec3 l = 2.0 * glm::dot(v, h) * h - v;
    if (l.z < 0.0 || glm::dot(v + l, v + l) < 0.01) continue;
    h = glm::normalize(v + l);
    return {v.z, l.z, h.z, glm::dot(l, h), h.x, h.y};
  }
}

void add_specular_lobes(std::vector<FunctionCase>& out) {
  // alpha >= 0.1 for the same reason as FacetD_GGX (fp32 cancellation at the peak).
  for (double alpha : {0.1, 0.5, 1.0}) {
    out.push_back(make_case(
        "FacetSpecular_GGX", "alpha=" + lit(alpha), 8, 3, kIncludeBRDF,
        "r.xyz = FacetSpecular_GGX(x[0], x[1], x[2], x[3], " + lit(alpha) + ", " + xv(4) + ", x[7]);",
        [alpha](const double* x, double* r) {
          put_out3(r, FacetSpecular_GGX(x[0], x[1], x[2], x[3], fp(alpha), v3(x, 4), x[7]));
        },
        [alpha](Rng& g, float* x) {
          Geometry q = draw_geometry(g, 3.0 * alpha);
          x[0] = float(q.NoV), x[1] = float(q.NoL), x[2] = float(q.NoH), x[3] = float(q.LoH);
          for (int i = 4; i < 8; ++i) x[i] = float(g.uniform());
        }));
  }
  for (double alpha : {0.1, 0.3, 0.7}) {
    out.push_back(make_case(
        "FacetSpecular_Beckmann", "alpha=" + lit(alpha), 8, 3, kIncludeBRDF,
        "r.xyz = FacetSpecular_Beckmann(x[0], x[1], x[2], x[3], " + lit(alpha) + ", " + xv(4) + ", x[7]);",
        [alpha](const double* x, double* r) {
          put_out3(r, FacetSpecular_Beckmann(x[0], x[1], x[2], x[3], fp(alpha), v3(x, 4), x[7]));
        },
        [alpha](Rng& g, float* x) {
          Geometry q = draw_geometry(g, 3.0 * alpha);
          x[0] = float(q.NoV), x[1] = float(q.NoL), x[2] = float(q.NoH), x[3] = float(q.LoH);
          for (int i = 4; i < 8; ++i) x[i] = float(g.uniform());
        }));
  }
  const glm::dvec3 as[] = {{10, 10, 0.05}, {100, 1000, 0.5}, {5, 50, 1.0}};
  for (glm::dvec3 p : as) {
    out.push_back(make_case(
        "FacetSpecular_AshikhminShirley", "nu=" + lit(p.x) + " nv=" + lit(p.y) + " rs=" + lit(p.z), 6, 1,
        kIncludeBRDF,
        "r.x = FacetSpecular_AshikhminShirley(x[0], x[1], x[2], x[3], x[4], x[5], " + lit(p.x) + ", " + lit(p.y) +
            ", " + lit(p.z) + ");",
        [p](const double* x, double* r) {
          r[0] = FacetSpecular_AshikhminShirley(x[0], x[1], x[2], x[3], x[4], x[5], fp(p.x), fp(p.y), fp(p.z));
        },
        [p](Rng& g, float* x) {
          Geometry q = draw_geometry(g, 3.0 / std::sqrt(std::min(p.x, p.y)));
          x[0] = float(q.NoV), x[1] = float(q.NoL), x[2] = float(q.NoH), x[3] = float(q.LoH);
          x[4] = float(q.HoX), x[5] = float(q.HoY);
        }));
  }
  const glm::dvec2 ward[] = {{0.1, 0.1}, {0.3, 0.3}, {0.15, 0.5}};
  for (glm::dvec2 a : ward) {
    out.push_back(make_case(
        "FacetSpecular_Ward", "alphaX=" + lit(a.x) + " alphaY=" + lit(a.y), 5, 1, kIncludeBRDF,
        "r.x = FacetSpecular_Ward(x[0], x[1], x[2], x[3], x[4], " + lit(a.x) + ", " + lit(a.y) + ");",
        [a](const double* x, double* r) { r[0] = FacetSpecular_Ward(x[0], x[1], x[2], x[3], x[4], fp(a.x), fp(a.y)); },
        [a](Rng& g, float* x) {
          Geometry q = draw_geometry(g, 3.0 * a.y);
          x[0] = float(q.NoV), x[1] = float(q.NoL), x[2] = float(q.NoH), x[3] = float(q.HoX), x[4] = float(q.HoY);
        }));
  }
}

void add_assembled(std::vector<FunctionCase>& out) {
  out.push_back(make_case("FacetEnergyCompensation", "E in [0.3, 1]", 4, 3, kIncludeBRDF,
                          "r.xyz = FacetEnergyCompensation(" + xv(0) + ", x[3]);",
                          [](const double* x, double* r) { put_out3(r, FacetEnergyCompensation(v3(x, 0), x[3])); },
                          [](Rng& g, float* x) {
                            for (int i = 0; i < 3; ++i) x[i] = float(g.uniform());
                            x[3] = float(g.uniform(0.3, 1.0));
                          }));
  struct Translucent {
    double distortion, power, scale, ambient, thickness;
  };
  const Translucent ts[] = {{0.2, 4, 1, 0, 1}, {0.5, 12, 2, 0.1, 0.5}, {0.0, 1, 1, 0.05, 1}};
  for (const Translucent& t : ts) {
    std::string args = lit(t.distortion) + ", " + lit(t.power) + ", " + lit(t.scale) + ", " + lit(t.ambient) + ", " +
                       lit(t.thickness);
    out.push_back(make_case(
        "FacetTranslucency", "distortion power scale ambient thickness = " + args, 9, 1, kIncludeBRDF,
        "r.x = FacetTranslucency(" + xv(0) + ", " + xv(3) + ", " + xv(6) + ", " + args + ");",
        [t](const double* x, double* r) {
          r[0] = FacetTranslucency(v3(x, 0), v3(x, 3), v3(x, 6), fp(t.distortion), fp(t.power), fp(t.scale),
                                   fp(t.ambient), fp(t.thickness));
        },
        [](Rng& g, float* x) {
          // Light from behind the surface, view from the front: where it shows.
          Frame f = random_frame(g);
          put(x, 0, f.n);
          put(x, 3, g.direction(f.n, 0.0, 1.0));
          put(x, 6, g.direction(-f.n, -0.3, 1.0));
        }));
  }
  using Lobe = glm::dvec3 (*)(const glm::dvec3&, const glm::dvec3&, const glm::dvec3&, const glm::dvec3&, double);
  const std::pair<const char*, Lobe> lobes[] = {{"FacetBRDF_CookTorranceGGX", FacetBRDF_CookTorranceGGX},
                                                {"FacetBRDF_CookTorranceBeckmann", FacetBRDF_CookTorranceBeckmann}};
  for (auto [name, fn] : lobes) {
    // r >= 0.4 (alpha >= 0.16): NoH comes from an fp32 dot product, whose
    // ~1e-7 absolute error the plain D form turns into 2e-7/alpha^2 relative.
    for (double rough : {0.4, 0.7, 1.0}) {
      out.push_back(make_case(
          name, "r=" + lit(rough), 12, 3, kIncludeBRDF,
          std::string("r.xyz = ") + name + "(" + xv(0) + ", " + xv(3) + ", " + xv(6) + ", " + xv(9) + ", " +
              lit(rough) + ");",
          [fn, rough](const double* x, double* r) {
            put_out3(r, fn(v3(x, 0), v3(x, 3), v3(x, 6), v3(x, 9), fp(rough)));
          },
          [rough](Rng& g, float* x) {
            Frame f = random_frame(g);
            glm::dvec3 v = g.direction(f.n, 0.0, 1.0), l;
            do {
              glm::dvec3 h = g.near(f.n, 3.0 * rough * rough);
              l = 2.0 * glm::dot(v, h) * h - v;
            } while (glm::dot(l, f.n) < 0.0 || glm::dot(v + l, v + l) < 0.01);
            put(x, 0, f.n), put(x, 3, v), put(x, 6, glm::normalize(l));
            for (int i = 9; i < 12; ++i) x[i] = float(g.uniform());
          }));
    }
  }
}

}  // namespace

void add_fresnel_cases(std::vector<FunctionCase>& out) { add_fresnel(out); }

void add_lobe_cases(std::vector<FunctionCase>& out) {
  add_specular_lobes(out);
  add_assembled(out);
}

}  // namespace facet::reference::cases
