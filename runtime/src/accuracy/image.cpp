#include "accuracy/image.h"

#include <algorithm>
#include <cmath>
#include <map>

#include "accuracy/lobe.h"
#include "facet/reference/brdf.h"
#include "facet/reference/color.h"
#include "facet/reference/fp16/brdf_fp16.h"
#include "facet/reference/ibl.h"
#include "facet/reference/tonemap.h"
#include "facet/reference/unity_standard.h"

namespace facet::runtime::accuracy {
namespace {

namespace ref = facet::reference;
namespace u = facet::reference::unity;
using glm::dvec3;

// A silver-like conductor (f0 = 0.958) for the metallic spheres.
const dvec3 kConductorEta(0.15), kConductorK(3.6);
constexpr double kDielectricEta = 1.5;
const std::vector<std::string> kAllScenes{"directional", "uniform", "sky"};

double alpha_of(const mc::Material& m) { return m.roughness * m.roughness; }

double exact_fresnel(double LoH, const mc::Material& m) {
  double dielectric = ref::FacetF_Dielectric(kDielectricEta, LoH);
  double conductor = ref::FacetF_Conductor(kConductorEta, kConductorK, LoH).x;
  return ref::lerp(dielectric, conductor, m.metallic);
}

// The exact terms with the Fresnel term Schlick's: what the F weight rows
// (the spherical Gaussian, pow4) and the IBL fits approximate.
Terms schlick_terms() {
  Terms t = exact_terms();
  t.f = [](double LoH, const mc::Material& m) { return ref::FacetF_Schlick(exact_f0(m), 1.0, LoH); };
  return t;
}

// The specular lobe alone, F Schlick's: what the DFG integral integrates.
mc::Model schlick_specular_model() {
  Terms t = schlick_terms();
  t.diffuse = [](const dvec3&, const dvec3&, const mc::Material&) { return 0.0; };
  return material_model(t);
}

ImageProbe term_probe(Terms approx, std::string what, Terms reference = exact_terms()) {
  return {.scenes = kAllScenes,
          .approx = material_model(approx),
          .reference = material_model(reference),
          .what = std::move(what)};
}

ImageProbe visibility_probe(std::function<double(double, double, double)> v, bool perceptual) {
  Terms t = exact_terms();
  t.v = [v, perceptual](double NoV, double NoL, double alpha) { return v(NoV, NoL, perceptual ? std::sqrt(alpha) : alpha); };
  return term_probe(t, "the V term replaced in the exact model");
}

ImageProbe fp16_d_probe(bool safe) {
  using half = ref::fp16::half;
  Terms t = exact_terms();
  t.d = [safe](double NoH, double alpha) {
    if (!safe) return double(ref::fp16::D_GGX<half>(half(NoH), half(alpha)));
    ref::fp16::Vec3<half> n{half(0), half(0), half(1)};
    ref::fp16::Vec3<half> h{half(std::sqrt(std::max(0.0, 1.0 - NoH * NoH))), half(0), half(NoH)};
    return double(ref::fp16::D_GGX_FP16Safe<half>(n, h, half(alpha)));
  };
  return term_probe(t, "the D term evaluated in IEEE half (_Float16)");
}

// A white-furnace probe: the row's lobe (white, F = 1) under the uniform
// environment, against the 1 an energy-conserving lobe reflects.
ImageProbe furnace_probe(std::function<Lobe(const mc::Material&, const mc::ShadingPoint&)> lobe) {
  return {.scenes = {"uniform"},
          .approx = [lobe](const mc::ShadingPoint& p) { return lobe(p.material, p); },
          .reference_closed = [](const mc::ShadingPoint&) { return 1.0; },
          .what = "the white lobe in the white furnace, against 1"};
}

// A Blinn-Phong exponent with the width of GGX at alpha (Walter et al. 2007).
double exponent_of(const mc::Material& m) { return std::max(2.0 / (alpha_of(m) * alpha_of(m)) - 2.0, 1.0); }

ImageProbe parameter_furnace(std::string id, std::function<std::map<std::string, dvec3>(const mc::Material&)> params) {
  return furnace_probe([id, params](const mc::Material& m, const mc::ShadingPoint&) { return model_lobe(id, params(m)); });
}

ImageProbe diffuse_probe(std::function<double(const dvec3&, const dvec3&, const mc::Material&)> approx,
                         std::function<double(const dvec3&, const dvec3&, const mc::Material&)> reference) {
  Terms a = exact_terms(), r = exact_terms();
  a.diffuse = std::move(approx);
  r.diffuse = std::move(reference);
  return term_probe(a, "the diffuse term replaced, against the full Oren-Nayar model", r);
}

std::function<double(const dvec3&, const dvec3&, const mc::Material&)> oren_nayar(std::string id) {
  return [id](const dvec3& v, const dvec3& l, const mc::Material& m) {
    return model_lobe(id, {{"sigma", dvec3(m.roughness)}})(v, l);
  };
}

// Unity's tier against D_GGX * V_correlated, both F = 1, specular only.
ImageProbe unity_probe(int tier) {
  return {.scenes = kAllScenes,
          .approx = [tier](const mc::ShadingPoint& p) { return unity_lobe(tier, 1.0 - p.material.roughness); },
          .reference = [](const mc::ShadingPoint& p) {
            double alpha = std::max(alpha_of(p.material), 0.002);
            return Lobe([alpha](const dvec3& v, const dvec3& l) {
              if (l.z <= 0) return 0.0;
              dvec3 h = glm::normalize(v + l);
              return ref::FacetD_GGX(h.z, alpha) * ref::FacetV_SmithGGXCorrelated(v.z, l.z, alpha);
            });
          },
          .what = "the tier's specular lobe (white, metallic) against D_GGX V_correlated"};
}

// The IBL fits: the closed form under the uniform environment against the
// integral it stands for, the GGX specular lobe with Schlick's F.
ImageProbe ibl_probe(std::function<double(const mc::ShadingPoint&)> closed) {
  return {.scenes = {"uniform"},
          .reference = schlick_specular_model(),
          .approx_closed = std::move(closed),
          .what = "the closed form under the uniform environment against the integrated GGX lobe"};
}

double grazing_of(const mc::Material& m) { return std::clamp(1.0 - m.roughness + exact_f0(m), 0.0, 1.0); }

double clamped_hill(double x) { return std::clamp(ref::FacetTonemapACESHill(dvec3(x)).x, 0.0, 1.0); }

ImageProbe display_probe(std::function<double(double)> approx, std::function<double(double)> reference,
                         std::string what) {
  return {.scenes = {"directional", "sky"},
          .display_approx = std::move(approx),
          .display_reference = std::move(reference),
          .what = std::move(what)};
}

std::map<std::string, std::function<ImageProbe()>> probes() {
  return {
      {"D_GGX_fp16", [] { return fp16_d_probe(false); }},
      {"D_GGX_FP16Safe", [] { return fp16_d_probe(true); }},
      {"V_SmithGGXCorrelatedFast", [] { return visibility_probe(ref::FacetV_SmithGGXCorrelatedFast, false); }},
      {"V_SmithGGXSeparable", [] { return visibility_probe(ref::FacetV_SmithGGXSeparable, false); }},
      {"V_SchlickGGX", [] { return visibility_probe(ref::FacetV_SchlickGGX, false); }},
      {"V_SchlickGGXKaris", [] { return visibility_probe(ref::FacetV_SchlickGGXKaris, true); }},
      {"F_Schlick", [] { return term_probe(schlick_terms(), "Schlick's F with the exact f0, against the exact F"); }},
      {"F_SchlickSG",
       [] {
         Terms t = schlick_terms();
         t.f = [](double LoH, const mc::Material& m) { return ref::FacetF_SchlickSG(dvec3(exact_f0(m)), 1.0, LoH).x; };
         return term_probe(t, "the F weight replaced, against Schlick's (1 - c)^5", schlick_terms());
       }},
      {"F_Pow4",
       [] {
         Terms t = schlick_terms();
         t.f = [](double LoH, const mc::Material& m) { return u::FresnelLerpFast(dvec3(exact_f0(m)), dvec3(1.0), LoH).x; };
         return term_probe(t, "the F weight replaced, against Schlick's (1 - c)^5", schlick_terms());
       }},
      {"Fd_Lambert", [] { return parameter_furnace("lambert", [](const mc::Material&) { return std::map<std::string, dvec3>{}; }); }},
      {"Fd_Burley",
       [] { return parameter_furnace("burley", [](const mc::Material& m) { return std::map<std::string, dvec3>{{"roughness", dvec3(m.roughness)}}; }); }},
      {"Fd_Frostbite",
       [] { return parameter_furnace("frostbite", [](const mc::Material& m) { return std::map<std::string, dvec3>{{"roughness", dvec3(m.roughness)}}; }); }},
      {"Fd_OrenNayarQualitative", [] { return diffuse_probe(oren_nayar("oren-nayar-qualitative"), oren_nayar("oren-nayar")); }},
      {"PhongNormalized",
       [] { return parameter_furnace("phong", [](const mc::Material& m) { return std::map<std::string, dvec3>{{"exponent", dvec3(exponent_of(m))}}; }); }},
      {"BlinnPhongNormalized",
       [] { return parameter_furnace("blinn-phong", [](const mc::Material& m) { return std::map<std::string, dvec3>{{"exponent", dvec3(exponent_of(m))}}; }); }},
      {"Specular_Ward",
       [] {
         return parameter_furnace("ward", [](const mc::Material& m) {
           return std::map<std::string, dvec3>{{"alpha_x", dvec3(alpha_of(m))}, {"alpha_y", dvec3(alpha_of(m))}};
         });
       }},
      {"Specular_AshikhminShirley",
       [] {
         return parameter_furnace("ashikhmin-shirley", [](const mc::Material& m) {
           double n = exponent_of(m);
           return std::map<std::string, dvec3>{{"nu", dvec3(n)}, {"nv", dvec3(n)}, {"rs", dvec3(1.0)}, {"rd", dvec3(0.0)}};
         });
       }},
      {"CookTorranceGGX",
       [] { return furnace_probe([](const mc::Material& m, const mc::ShadingPoint&) { return ggx_model_lobe(alpha_of(m)); }); }},
      {"CookTorranceGGX_Compensated",
       [] {
         return furnace_probe([](const mc::Material& m, const mc::ShadingPoint& p) {
           double alpha = alpha_of(m), E = ref::FacetDFG_Integrate(p.n.z, alpha, 4096).y;
           double k = ref::FacetEnergyCompensation(dvec3(1), E).x;
           Lobe lobe = ggx_model_lobe(alpha);
           return Lobe([lobe, k](const dvec3& v, const dvec3& l) { return k * lobe(v, l); });
         });
       }},
      {"BRDF1_Unity_PBS", [] { return unity_probe(1); }},
      {"BRDF2_Unity_PBS", [] { return unity_probe(2); }},
      {"BRDF3_Unity_PBS", [] { return unity_probe(3); }},
      {"EnvBRDFApprox",
       [] {
         return ibl_probe([](const mc::ShadingPoint& p) {
           return ref::FacetEnvBRDFApprox(dvec3(exact_f0(p.material)), p.material.roughness, p.n.z).x;
         });
       }},
      {"Unity_SurfaceReduction",
       [] {
         return ibl_probe([](const mc::ShadingPoint& p) {
           const mc::Material& m = p.material;
           return u::FresnelLerp(dvec3(exact_f0(m)), dvec3(grazing_of(m)), p.n.z).x / (alpha_of(m) * alpha_of(m) + 1.0);
         });
       }},
      {"Unity_BRDF2_SurfaceReduction",
       [] {
         auto lerp_fast = [](const mc::Material& m, double NoV) {
           return u::FresnelLerpFast(dvec3(exact_f0(m)), dvec3(grazing_of(m)), NoV).x;
         };
         return ImageProbe{.scenes = {"uniform"},
                           .approx_closed = [lerp_fast](const mc::ShadingPoint& p) {
                             double r = p.material.roughness;
                             return (1.0 - r * r * r * (0.6 - 0.08 * r)) * lerp_fast(p.material, p.n.z);
                           },
                           .reference_closed = [lerp_fast](const mc::ShadingPoint& p) {
                             double r = p.material.roughness;
                             return lerp_fast(p.material, p.n.z) / (r * r * r * r + 1.0);
                           },
                           .what = "Unity BRDF2's IBL term under the uniform environment, the reduction replaced"};
       }},
      {"Tonemap_ACESNarkowicz",
       [] {
         return display_probe([](double x) { return std::clamp(ref::FacetTonemapACESNarkowicz(dvec3(x)).x, 0.0, 1.0); },
                              clamped_hill, "the exact image tone-mapped, against Hill's ACES fit");
       }},
      {"SRGBPow22",
       [] {
         return display_probe([](double x) { return std::pow(clamped_hill(x), 1.0 / 2.2); },
                              [](double x) { return ref::FacetLinearToSRGB(clamped_hill(x)); },
                              "the exact image after Hill's ACES fit, encoded, against the exact sRGB encode");
       }},
  };
}

// What one probe needs from a scene's rendering, and what it found.
struct ProbeSlots {
  size_t row = 0;
  const ImageProbe* probe = nullptr;
  std::optional<size_t> approx, reference, contrast;  // model and contrast indices
};

double rms(double sum_squares, size_t n) { return n ? std::sqrt(sum_squares / double(n)) : 0.0; }

ImageError error_of(const mc::Scene& scene, const ProbeSlots& s, const mc::Rendering& r) {
  ImageError e{.scene = scene.name};
  double sq = 0, noise_sq = 0;
  const size_t n = r.points.size();
  for (size_t p = 0; p < n; ++p) {
    const mc::ShadingPoint& point = r.points[p];
    double diff = 0, noise = 0;
    if (s.contrast) {
      diff = r.contrasts[*s.contrast][p].value;
      noise = r.contrasts[*s.contrast][p].std_error;
    } else if (s.probe->display_approx) {
      const mc::Estimate& x = r.models[0][p];  // the exact model
      diff = s.probe->display_approx(x.value) - s.probe->display_reference(x.value);
      noise = std::abs(s.probe->display_reference(x.value + x.std_error) - s.probe->display_reference(x.value));
    } else {
      mc::Estimate a = s.approx ? r.models[*s.approx][p] : mc::Estimate{s.probe->approx_closed(point), 0.0};
      mc::Estimate b = s.reference ? r.models[*s.reference][p] : mc::Estimate{s.probe->reference_closed(point), 0.0};
      diff = a.value - b.value;
      noise = std::hypot(a.std_error, b.std_error);
    }
    if (!std::isfinite(diff)) diff = INFINITY;
    sq += diff * diff;
    noise_sq += noise * noise;
    e.max_error = std::max(e.max_error, std::abs(diff));
  }
  e.rmse = rms(sq, n);
  e.noise = rms(noise_sq, n);
  return e;
}

void measure_scene(const mc::Scene& scene, std::vector<StudyRow>& rows, const std::vector<std::optional<ImageProbe>>& row_probes,
                   const mc::RenderOptions& options) {
  std::vector<mc::Model> models{material_model(exact_terms())};
  std::vector<mc::Contrast> contrasts;
  std::vector<ProbeSlots> slots;
  for (size_t i = 0; i < rows.size(); ++i) {
    const std::optional<ImageProbe>& probe = row_probes[i];
    if (!probe || std::find(probe->scenes.begin(), probe->scenes.end(), scene.name) == probe->scenes.end()) continue;
    ProbeSlots s{.row = i, .probe = &*probe};
    if (!probe->display_approx) {
      if (!probe->approx_closed) {
        s.approx = models.size();
        models.push_back(probe->approx);
      }
      if (!probe->reference_closed) {
        s.reference = probe->reference ? models.size() : 0;  // 0: the exact model
        if (probe->reference) models.push_back(probe->reference);
      }
      if (s.approx && s.reference) {
        s.contrast = contrasts.size();
        contrasts.push_back({*s.approx, *s.reference});
      }
    }
    slots.push_back(s);
  }
  if (slots.empty()) return;
  const mc::Rendering rendering = mc::render(scene, models, contrasts, options);
  for (const ProbeSlots& s : slots) rows[s.row].image.push_back(error_of(scene, s, rendering));
}

}  // namespace

Terms exact_terms() {
  return {.d = [](double NoH, double alpha) { return ref::FacetD_GGX(NoH, alpha); },
          .v = [](double NoV, double NoL, double alpha) { return ref::FacetV_SmithGGXCorrelated(NoV, NoL, alpha); },
          .f = exact_fresnel,
          .diffuse = [](const dvec3&, const dvec3&, const mc::Material&) { return ref::kInvPi; }};
}

double exact_f0(const mc::Material& m) { return exact_fresnel(1.0, m); }

mc::Model material_model(const Terms& terms) {
  return [terms](const mc::ShadingPoint& point) {
    const mc::Material m = point.material;
    const double alpha = std::max(alpha_of(m), 1e-4);
    return mc::Brdf([terms, m, alpha](const dvec3& v, const dvec3& l) {
      if (l.z <= 0 || v.z <= 0) return 0.0;
      dvec3 h = glm::normalize(v + l);
      double specular = terms.d(h.z, alpha) * terms.v(v.z, l.z, alpha) * terms.f(glm::dot(l, h), m);
      return (1.0 - m.metallic) * kBaseColour * terms.diffuse(v, l, m) + specular;
    });
  };
}

std::optional<ImageProbe> image_probe(std::string_view row_id) {
  const std::map<std::string, std::function<ImageProbe()>> all = probes();
  auto it = all.find(std::string(row_id));
  if (it == all.end()) return std::nullopt;
  return it->second();
}

void compute_image_errors(std::vector<StudyRow>& rows, uint32_t samples) {
  const mc::RenderOptions options{.samples = samples};
  std::vector<std::optional<ImageProbe>> row_probes;
  for (StudyRow& row : rows) {
    row.image.clear();
    row_probes.push_back(image_probe(row.id));
    row.image_how = row_probes.back() ? row_probes.back()->what : std::string();
  }
  for (const mc::Scene& scene : mc::study_scenes()) measure_scene(scene, rows, row_probes, options);
}

}  // namespace facet::runtime::accuracy
