// The diffuse rows of the model table.
#include "model_rows.h"

namespace facet::reference::models {

using glm::dvec3;

namespace {

// Functions, not constants: the table may be built during another file's
// static initialisation (a test's parameter list).
ModelParam albedo_param() { return colour("albedo", dvec3(1.0), "diffuse albedo"); }
ModelParam sigma_param() { return number("sigma", 0.25, 0.0, 1.5707963, "slope deviation in radians"); }

LightingModel lambert() {
  LightingModel m = facet_row("lambert", "Lambert", "c = FacetFd_Lambert() * a.NoL;",
                              [](const ModelPoint& in) { return dvec3(FacetFd_Lambert() * angles(in).NoL); });
  with_params(m, "FacetFd_Lambert", {albedo_param()}, [](const ModelParams& p) {
    return above_surface([c = p.col("albedo")](auto&, auto&, auto&) { return c * FacetFd_Lambert(); });
  });
  return m;
}

LightingModel burley() {
  LightingModel m = facet_row("burley", "Burley", "c = FacetFd_Burley(a.NoV, a.NoL, a.LoH, rough) * a.NoL;",
                              [](const ModelPoint& in) {
                                FacetAngles a = angles(in);
                                return dvec3(FacetFd_Burley(a.NoV, a.NoL, a.LoH, in.roughness) * a.NoL);
                              },
                              Energy::violator);
  with_params(m, "FacetFd_Burley", {roughness_param(), albedo_param()}, [](const ModelParams& p) {
    return above_surface([c = p.col("albedo"), r = p.num("roughness")](auto&, auto&, auto& a) {
      return c * FacetFd_Burley(a.NoV, a.NoL, a.LoH, r);
    });
  });
  return m;
}

LightingModel frostbite() {
  LightingModel m = facet_row("frostbite", "Frostbite", "c = FacetFd_Frostbite(a.NoV, a.NoL, a.LoH, rough * rough) * a.NoL;",
                              [](const ModelPoint& in) {
                                FacetAngles a = angles(in);
                                return dvec3(FacetFd_Frostbite(a.NoV, a.NoL, a.LoH, in.roughness * in.roughness) * a.NoL);
                              });
  with_params(m, "FacetFd_Frostbite (alpha = r^2)", {roughness_param(), albedo_param()}, [](const ModelParams& p) {
    return above_surface([c = p.col("albedo"), r = p.num("roughness")](auto&, auto&, auto& a) {
      return c * FacetFd_Frostbite(a.NoV, a.NoL, a.LoH, r * r);
    });
  });
  return m;
}

// The point form reads the roughness input as sigma.
LightingModel oren_nayar_qualitative() {
  LightingModel m = facet_row("oren-nayar-qualitative", "Oren-Nayar qualitative",
                              "c = FacetFd_OrenNayarQualitative(a.NoV, a.NoL, a.LoV, rough) * a.NoL;",
                              [](const ModelPoint& in) {
                                FacetAngles a = angles(in);
                                return dvec3(FacetFd_OrenNayarQualitative(a.NoV, a.NoL, a.LoV, in.roughness) * a.NoL);
                              },
                              Energy::violator);
  with_params(m, "FacetFd_OrenNayarQualitative", {sigma_param(), albedo_param()}, [](const ModelParams& p) {
    return above_surface([c = p.col("albedo"), s = p.num("sigma")](auto&, auto&, auto& a) {
      return c * FacetFd_OrenNayarQualitative(a.NoV, a.NoL, a.LoV, s);
    });
  });
  return m;
}

LightingModel oren_nayar() {
  LightingModel m = facet_row("oren-nayar", "Oren-Nayar full",
                              "c = FacetFd_OrenNayar(a.NoV, a.NoL, a.LoV, rough, 1.0) * a.NoL;",
                              [](const ModelPoint& in) {
                                FacetAngles a = angles(in);
                                return dvec3(FacetFd_OrenNayar(a.NoV, a.NoL, a.LoV, in.roughness, 1.0) * a.NoL);
                              });
  with_params(m, "FacetFd_OrenNayar (per channel: its interreflection term is quadratic in albedo)", {sigma_param(), albedo_param()},
              [](const ModelParams& p) {
                return above_surface([c = p.col("albedo"), s = p.num("sigma")](auto&, auto&, auto& a) {
                  return dvec3(FacetFd_OrenNayar(a.NoV, a.NoL, a.LoV, s, c.r), FacetFd_OrenNayar(a.NoV, a.NoL, a.LoV, s, c.g),
                               FacetFd_OrenNayar(a.NoV, a.NoL, a.LoV, s, c.b));
                });
              });
  return m;
}

// The point form only: `facet brdf` offers it with its specular lobe (the
// ashikhmin-shirley row).
LightingModel ashikhmin_shirley_diffuse() {
  LightingModel m = facet_row("ashikhmin-shirley-diffuse", "Ashikhmin-Shirley diffuse",
                              "c = FacetFd_AshikhminShirley(a.NoV, a.NoL, 1.0, f0) * a.NoL;", [](const ModelPoint& in) {
                                FacetAngles a = angles(in);
                                return dvec3(FacetFd_AshikhminShirley(a.NoV, a.NoL, 1.0, in.f0) * a.NoL);
                              });
  m.stdlib = "FacetFd_AshikhminShirley";
  return m;
}

}  // namespace

std::vector<LightingModel> diffuse_models() {
  return {lambert(), burley(), frostbite(), oren_nayar_qualitative(), oren_nayar(), ashikhmin_shirley_diffuse()};
}

}  // namespace facet::reference::models
