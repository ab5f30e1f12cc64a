// The registry of facet brdf: each stdlib lighting model family, its
// parameters, and how a parsed spec becomes a call of the CPU twins.
#include <fmt/format.h>

#include <charconv>
#include <map>
#include <memory>
#include <mutex>

#include "facet/reference/disney.h"
#include "facet/reference/ibl.h"
#include "facet/reference/unity_standard.h"
#include "facet/runtime/brdf.h"

namespace facet::brdf {
namespace {

namespace ref = facet::reference;
using glm::dvec3;
using glm::dvec4;

struct Params {
  std::map<std::string, dvec3> values;
  double num(const std::string& name) const { return values.at(name).x; }
  dvec3 col(const std::string& name) const { return values.at(name); }
};

struct Family {
  FamilyInfo info;
  std::function<BrdfFunction(const Params&)> make;
};

ParamInfo number(std::string name, double def, double min, double max, std::string help) {
  return {std::move(name), 1, min, max, dvec3(def), std::move(help)};
}
ParamInfo colour(std::string name, dvec3 def, std::string help) {
  return {std::move(name), 3, 0.0, 1.0, def, std::move(help)};
}
ParamInfo roughness_param() { return number("roughness", 0.5, 0.0, 1.0, "perceptual roughness r (alpha = r^2)"); }
ParamInfo f0_param() { return colour("f0", dvec3(0.04), "reflectance at normal incidence"); }

// Wraps a lobe written against FacetComputeAngles (n = +z): zero below the surface.
using AngleLobe = std::function<dvec3(const dvec3& v, const dvec3& l, const ref::FacetAngles& a)>;
BrdfFunction above_surface(AngleLobe lobe) {
  return [lobe = std::move(lobe)](const dvec3& v, const dvec3& l) {
    if (v.z <= 0.0 || l.z <= 0.0) return dvec3(0.0);
    return lobe(v, l, ref::FacetComputeAngles(dvec3(0, 0, 1), v, l));
  };
}
dvec3 half_vector(const dvec3& v, const dvec3& l) { return ref::FacetSafeNormalize(v + l); }
double clamped_alpha(double r) { return ref::FacetClampAlpha(r * r); }

// ---- diffuse ----
std::vector<Family> diffuse_families() {
  std::vector<Family> f;
  const ParamInfo albedo = colour("albedo", dvec3(1.0), "diffuse albedo");
  f.push_back({{"lambert", "FacetFd_Lambert", {albedo}}, [](const Params& p) {
                 return above_surface([c = p.col("albedo")](auto&, auto&, auto&) { return c * ref::FacetFd_Lambert(); });
               }});
  f.push_back({{"burley", "FacetFd_Burley", {roughness_param(), albedo}}, [](const Params& p) {
                 return above_surface([c = p.col("albedo"), r = p.num("roughness")](auto&, auto&, auto& a) {
                   return c * ref::FacetFd_Burley(a.NoV, a.NoL, a.LoH, r);
                 });
               }});
  f.push_back({{"frostbite", "FacetFd_Frostbite (alpha = r^2)", {roughness_param(), albedo}}, [](const Params& p) {
                 return above_surface([c = p.col("albedo"), r = p.num("roughness")](auto&, auto&, auto& a) {
                   return c * ref::FacetFd_Frostbite(a.NoV, a.NoL, a.LoH, r * r);
                 });
               }});
  const ParamInfo sigma = number("sigma", 0.25, 0.0, 1.5707963, "slope deviation in radians");
  f.push_back({{"oren-nayar-qualitative", "FacetFd_OrenNayarQualitative", {sigma, albedo}}, [](const Params& p) {
                 return above_surface([c = p.col("albedo"), s = p.num("sigma")](auto&, auto&, auto& a) {
                   return c * ref::FacetFd_OrenNayarQualitative(a.NoV, a.NoL, a.LoV, s);
                 });
               }});
  f.push_back({{"oren-nayar", "FacetFd_OrenNayar (per channel: its interreflection term is quadratic in albedo)",
                {sigma, albedo}},
               [](const Params& p) {
                 return above_surface([c = p.col("albedo"), s = p.num("sigma")](auto&, auto&, auto& a) {
                   return dvec3(ref::FacetFd_OrenNayar(a.NoV, a.NoL, a.LoV, s, c.r),
                                ref::FacetFd_OrenNayar(a.NoV, a.NoL, a.LoV, s, c.g),
                                ref::FacetFd_OrenNayar(a.NoV, a.NoL, a.LoV, s, c.b));
                 });
               }});
  return f;
}

// ---- Phong family, Ward, Ashikhmin-Shirley ----
std::vector<Family> classic_families() {
  std::vector<Family> f;
  const ParamInfo exponent = number("exponent", 50.0, 1e-4, 1e5, "specular exponent n");
  f.push_back({{"phong", "FacetPhongNormalized", {exponent}}, [](const Params& p) {
                 return above_surface([n = p.num("exponent")](auto&, auto&, auto& a) {
                   return dvec3(ref::FacetPhongNormalized(2.0 * a.NoL * a.NoV - a.LoV, n));
                 });
               }});
  f.push_back({{"blinn-phong", "FacetBlinnPhongNormalized", {exponent}}, [](const Params& p) {
                 return above_surface([n = p.num("exponent")](auto&, auto&, auto& a) {
                   return dvec3(ref::FacetBlinnPhongNormalized(a.NoH, n));
                 });
               }});
  f.push_back({{"ward", "FacetSpecular_Ward",
                {number("alpha_x", 0.3, 1e-3, 1.0, "slope deviation along the tangent"),
                 number("alpha_y", 0.3, 1e-3, 1.0, "slope deviation along the bitangent"),
                 colour("ks", dvec3(1.0), "specular weight")}},
               [](const Params& p) {
                 return above_surface([ax = p.num("alpha_x"), ay = p.num("alpha_y"), ks = p.col("ks")](
                                          auto& v, auto& l, auto& a) {
                   dvec3 h = half_vector(v, l);
                   return ks * ref::FacetSpecular_Ward(a.NoV, a.NoL, a.NoH, h.x, h.y, ax, ay);
                 });
               }});
  f.push_back({{"ashikhmin-shirley", "FacetSpecular_AshikhminShirley + FacetFd_AshikhminShirley",
                {number("nu", 100.0, 1.0, 1e5, "exponent along the tangent"),
                 number("nv", 100.0, 1.0, 1e5, "exponent along the bitangent"),
                 number("rs", 0.05, 0.0, 1.0, "specular reflectance at normal incidence"),
                 colour("rd", dvec3(0.5), "diffuse reflectance")}},
               [](const Params& p) {
                 return above_surface([nu = p.num("nu"), nv = p.num("nv"), rs = p.num("rs"), rd = p.col("rd")](
                                          auto& v, auto& l, auto& a) {
                   dvec3 h = half_vector(v, l);
                   double spec = ref::FacetSpecular_AshikhminShirley(a.NoV, a.NoL, a.NoH, a.LoH, h.x, h.y, nu, nv, rs);
                   dvec3 diffuse(ref::FacetFd_AshikhminShirley(a.NoV, a.NoL, rd.r, rs),
                                 ref::FacetFd_AshikhminShirley(a.NoV, a.NoL, rd.g, rs),
                                 ref::FacetFd_AshikhminShirley(a.NoV, a.NoL, rd.b, rs));
                   return dvec3(spec) + diffuse;
                 });
               }});
  return f;
}

// ---- microfacet specular ----
// D_GGX * V * F_Schlick(f0, 1, LoH) with the visibility term picked by `v`.
using Visibility = double (*)(double NoV, double NoL, double alpha, double r);
Family ggx_with(const char* name, const char* twins, Visibility v) {
  return {{name, twins, {roughness_param(), f0_param()}}, [v](const Params& p) {
            return above_surface([v, r = p.num("roughness"), f0 = p.col("f0")](auto&, auto&, auto& a) {
              double alpha = clamped_alpha(r);
              return ref::FacetD_GGX(a.NoH, alpha) * v(a.NoV, a.NoL, alpha, r) * ref::FacetF_Schlick(f0, 1.0, a.LoH);
            });
          }};
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
      (*t)[i] = ref::FacetDFG_Integrate(std::max(i / double(kEntries - 1), 1.0 / 256.0), alpha, kSamples).y;
    }
    slot = t;
  }
  return slot;
}
double table_at(const std::vector<double>& t, double NoV) {
  double x = std::clamp(NoV * double(t.size() - 1), 0.0, double(t.size() - 1));
  size_t i = std::min(size_t(x), t.size() - 2);
  return ref::lerp(t[i], t[i + 1], x - double(i));
}

std::vector<Family> microfacet_families() {
  std::vector<Family> f;
  f.push_back({{"ggx", "FacetBRDF_CookTorranceGGX", {roughness_param(), f0_param()}}, [](const Params& p) {
                 return above_surface([r = p.num("roughness"), f0 = p.col("f0")](auto& v, auto& l, auto&) {
                   return ref::FacetBRDF_CookTorranceGGX(dvec3(0, 0, 1), v, l, f0, r);
                 });
               }});
  f.push_back({{"ggx-ms", "FacetBRDF_CookTorranceGGX * FacetEnergyCompensation(f0, FacetDFG_Integrate(NoV).y)",
                {roughness_param(), f0_param()}},
               [](const Params& p) {
                 double r = p.num("roughness");
                 return above_surface([r, f0 = p.col("f0"), table = ggx_albedo_table(clamped_alpha(r))](
                                          auto& v, auto& l, auto& a) {
                   return ref::FacetBRDF_CookTorranceGGX(dvec3(0, 0, 1), v, l, f0, r) *
                          ref::FacetEnergyCompensation(f0, table_at(*table, a.NoV));
                 });
               }});
  f.push_back(ggx_with("ggx-fast", "FacetD_GGX * FacetV_SmithGGXCorrelatedFast * FacetF_Schlick",
                       [](double NoV, double NoL, double alpha, double) {
                         return ref::FacetV_SmithGGXCorrelatedFast(NoV, NoL, alpha);
                       }));
  f.push_back(ggx_with("ggx-separable", "FacetD_GGX * FacetV_SmithGGXSeparable * FacetF_Schlick",
                       [](double NoV, double NoL, double alpha, double) {
                         return ref::FacetV_SmithGGXSeparable(NoV, NoL, alpha);
                       }));
  f.push_back(ggx_with("ggx-schlick", "FacetD_GGX * FacetV_SchlickGGX (k = alpha/2) * FacetF_Schlick",
                       [](double NoV, double NoL, double alpha, double) {
                         return ref::FacetV_SchlickGGX(NoV, NoL, alpha);
                       }));
  f.push_back(ggx_with("ggx-karis", "FacetD_GGX * FacetV_SchlickGGXKaris (k = (r+1)^2/8) * FacetF_Schlick",
                       [](double NoV, double NoL, double, double r) {
                         return ref::FacetV_SchlickGGXKaris(NoV, NoL, r);
                       }));
  f.push_back({{"beckmann", "FacetBRDF_CookTorranceBeckmann", {roughness_param(), f0_param()}}, [](const Params& p) {
                 return above_surface([r = p.num("roughness"), f0 = p.col("f0")](auto& v, auto& l, auto&) {
                   return ref::FacetBRDF_CookTorranceBeckmann(dvec3(0, 0, 1), v, l, f0, r);
                 });
               }});
  f.push_back({{"cook-torrance-1982", "FacetD_Beckmann * FacetG_CookTorrance / (4 NoL NoV) * FacetF_Schlick",
                {roughness_param(), f0_param()}},
               [](const Params& p) {
                 return above_surface([r = p.num("roughness"), f0 = p.col("f0")](auto&, auto&, auto& a) {
                   double g = ref::FacetG_CookTorrance(a.NoV, a.NoL, a.NoH, a.LoH);
                   return ref::FacetD_Beckmann(a.NoH, clamped_alpha(r)) * g / std::max(4.0 * a.NoL * a.NoV, 1e-12) *
                          ref::FacetF_Schlick(f0, 1.0, a.LoH);
                 });
               }});
  return f;
}

// ---- Disney and the Unity Standard tiers ----
Family disney_family() {
  ref::FacetDisneyMaterial d;
  FamilyInfo info{"disney", "FacetBRDF_Disney",
                  {colour("baseColor", d.baseColor, "base colour (linear)"),
                   number("subsurface", d.subsurface, 0, 1, ""), number("metallic", d.metallic, 0, 1, ""),
                   number("specular", d.specular, 0, 1, "0.5 is f0 = 0.04"),
                   number("specularTint", d.specularTint, 0, 1, ""), number("roughness", d.roughness, 0, 1, ""),
                   number("anisotropic", d.anisotropic, 0, 1, ""), number("sheen", d.sheen, 0, 1, ""),
                   number("sheenTint", d.sheenTint, 0, 1, ""), number("clearcoat", d.clearcoat, 0, 1, ""),
                   number("clearcoatGloss", d.clearcoatGloss, 0, 1, "")}};
  return {std::move(info), [](const Params& p) {
            ref::FacetDisneyMaterial m;
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
            return BrdfFunction([m](const dvec3& v, const dvec3& l) {
              if (v.z <= 0.0 || l.z <= 0.0) return dvec3(0.0);
              return ref::FacetBRDF_Disney(m, l, v, dvec3(0, 0, 1), dvec3(1, 0, 0), dvec3(0, 1, 0));
            });
          }};
}

// UNITY_BRDF_PBS returns colour * NoL in Unity's units (light colours carry
// the pi), so the BRDF is that over pi * NoL; no indirect light.
Family unity_family(int tier) {
  FamilyInfo info{fmt::format("unity-brdf{}", tier), fmt::format("BRDF{}_Unity_PBS (metallic workflow)", tier),
                  {colour("albedo", dvec3(0.8), "albedo"), number("metallic", 0.0, 0, 1, ""),
                   number("smoothness", 0.5, 0, 1, "1 - perceptual roughness")}};
  return {std::move(info), [tier](const Params& p) {
            namespace u = ref::unity;
            dvec3 spec;
            double oneMinusReflectivity = 0;
            dvec3 diff = u::DiffuseAndSpecularFromMetallic(p.col("albedo"), p.num("metallic"), spec, oneMinusReflectivity);
            double smoothness = p.num("smoothness");
            return BrdfFunction([=](const dvec3& v, const dvec3& l) {
              if (v.z <= 0.0 || l.z <= 0.0) return dvec3(0.0);
              u::UnityLight light{dvec3(1.0), l, l.z};
              dvec4 c = u::UNITY_BRDF_PBS(tier, diff, spec, oneMinusReflectivity, smoothness, dvec3(0, 0, 1), v, light,
                                          u::UnityIndirect{});
              return dvec3(c) / (ref::kPi * l.z);
            });
          }};
}

const std::vector<Family>& families() {
  static const std::vector<Family> all = [] {
    std::vector<Family> f = diffuse_families();
    for (auto* group : {&classic_families, &microfacet_families})
      for (Family& x : group()) f.push_back(std::move(x));
    f.push_back(disney_family());
    for (int tier : {1, 2, 3}) f.push_back(unity_family(tier));
    return f;
  }();
  return all;
}

std::string known_names() {
  std::string s;
  for (const Family& f : families()) s += (s.empty() ? "" : ", ") + f.info.name;
  return s + ", merl:PATH";
}

std::string format_value(const ParamInfo& p, const dvec3& v) {
  if (p.components == 1 || (v.r == v.g && v.g == v.b)) return fmt::format("{}", v.r);
  return fmt::format("{}/{}/{}", v.r, v.g, v.b);
}

Result<double> parse_number(const std::string& text) {
  double d = 0;
  auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), d);
  if (ec != std::errc() || end != text.data() + text.size() || !std::isfinite(d)) return failure();
  return d;
}

Result<dvec3> parse_value(const std::string& family, const ParamInfo& p, const std::string& text) {
  std::vector<std::string> parts;
  for (size_t start = 0;;) {
    size_t slash = text.find('/', start);
    parts.push_back(text.substr(start, slash - start));
    if (slash == std::string::npos) break;
    start = slash + 1;
  }
  if (parts.size() != 1 && !(p.components == 3 && parts.size() == 3)) {
    return failure(p.components == 1
                       ? fmt::format("model '{}': {} takes one number, not '{}'", family, p.name, text)
                       : fmt::format("model '{}': {} takes one number or r/g/b, not '{}'", family, p.name, text));
  }
  dvec3 v;
  for (size_t i = 0; i < 3; ++i) {
    Result<double> d = parse_number(parts[std::min(i, parts.size() - 1)]);
    if (!d) return failure(fmt::format("model '{}': {}: '{}' is not a number", family, p.name, text));
    if (*d < p.min || *d > p.max) {
      return failure(fmt::format("model '{}': {} = {} is outside [{}, {}]", family, p.name, *d, p.min, p.max));
    }
    v[int(i)] = *d;
  }
  return v;
}

Result<Params> parse_params(const Family& family, const std::string& list) {
  const std::string& name = family.info.name;
  Params p;
  for (const ParamInfo& info : family.info.params) p.values[info.name] = info.default_value;
  std::map<std::string, bool> seen;
  for (size_t start = 0;;) {
    size_t comma = list.find(',', start);
    std::string item = list.substr(start, comma - start);
    size_t eq = item.find('=');
    if (eq == std::string::npos || eq == 0) {
      return failure(fmt::format("model '{}': '{}' is not name=value", name, item));
    }
    std::string key = item.substr(0, eq);
    auto info = std::find_if(family.info.params.begin(), family.info.params.end(),
                             [&](const ParamInfo& i) { return i.name == key; });
    if (info == family.info.params.end()) {
      std::string names;
      for (const ParamInfo& i : family.info.params) names += (names.empty() ? "" : ", ") + i.name;
      return failure(fmt::format("model '{}': unknown parameter '{}' (parameters: {})", name, key, names));
    }
    if (seen[key]) return failure(fmt::format("model '{}': {} is given twice", name, key));
    seen[key] = true;
    Result<dvec3> v = parse_value(name, *info, item.substr(eq + 1));
    if (!v) return unexpected(v.error());
    p.values[key] = *v;
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  return p;
}

std::string label_of(const Family& family, const Params& p) {
  std::string s = family.info.name;
  char sep = ':';
  for (const ParamInfo& info : family.info.params) {
    s += fmt::format("{}{}={}", sep, info.name, format_value(info, p.values.at(info.name)));
    sep = ',';
  }
  return s;
}

Result<Model> parse_merl_model(const std::string& path) {
  if (path.empty()) return failure("model 'merl' needs a file: merl:PATH");
  Result<MerlData> data = load_merl(path);
  if (!data) return unexpected(data.error());
  auto shared = std::make_shared<MerlData>(std::move(*data));
  return Model{"merl:" + path, [shared](const dvec3& v, const dvec3& l) {
                 if (v.z <= 0.0 || l.z <= 0.0) return dvec3(0.0);
                 return merl_lookup(*shared, v, l);
               }};
}

}  // namespace

const std::vector<FamilyInfo>& model_families() {
  static const std::vector<FamilyInfo> infos = [] {
    std::vector<FamilyInfo> v;
    for (const Family& f : families()) v.push_back(f.info);
    v.push_back({"merl", "merl_lookup (nearest bin of a MERL binary file; spec merl:PATH)", {}});
    return v;
  }();
  return infos;
}

Result<Model> parse_model(const std::string& spec) {
  size_t colon = spec.find(':');
  std::string name = spec.substr(0, colon);
  std::string rest = colon == std::string::npos ? "" : spec.substr(colon + 1);
  if (name == "merl") return parse_merl_model(rest);
  auto family = std::find_if(families().begin(), families().end(), [&](const Family& f) { return f.info.name == name; });
  if (family == families().end()) {
    return failure(fmt::format("unknown model '{}' (models: {})", name, known_names()));
  }
  Params p;
  for (const ParamInfo& info : family->info.params) p.values[info.name] = info.default_value;
  if (colon != std::string::npos) {
    Result<Params> parsed = parse_params(*family, rest);
    if (!parsed) return unexpected(parsed.error());
    p = std::move(*parsed);
  }
  return Model{label_of(*family, p), family->make(p)};
}

}  // namespace facet::brdf
