// `facet bench accuracy --budget E`: every combination of the stdlib's D, V,
// F and diffuse terms rendered in the test scenes by the Monte Carlo
// reference against the exact model, costed from the study's rows, and the
// cheapest one under each budget; Unity's Standard tiers measured the same way.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>

#include "accuracy/image.h"
#include "accuracy/lobe.h"
#include "facet/reference/brdf.h"
#include "facet/reference/unity_standard.h"

namespace facet::runtime::accuracy {
namespace {

namespace ref = facet::reference;
namespace u = facet::reference::unity;
using glm::dvec3;

template <class F>
struct Option {
  std::string id;
  std::vector<std::string> cost_rows;  // the study rows that evaluate it
  F term;
};
using DOption = Option<std::function<double(double, double)>>;
using VOption = Option<std::function<double(double, double, double)>>;
using FOption = Option<std::function<double(double, const mc::Material&)>>;
using DiffuseOption = Option<std::function<double(const dvec3&, const dvec3&, const mc::Material&)>>;

std::vector<DOption> d_options() {
  return {{"D_GGX", {"D_GGX"}, exact_terms().d},
          {"D_GGX_FP16Safe", {"D_GGX_FP16Safe"}, [](double NoH, double alpha) {
             dvec3 h(std::sqrt(std::max(0.0, 1.0 - NoH * NoH)), 0.0, NoH);
             return ref::FacetD_GGX_FP16Safe(dvec3(0, 0, 1), h, alpha);
           }}};
}

std::vector<VOption> v_options() {
  return {{"V_SmithGGXCorrelated", {"V_SmithGGXCorrelated"}, exact_terms().v},
          {"V_SmithGGXCorrelatedFast", {"V_SmithGGXCorrelatedFast"}, ref::FacetV_SmithGGXCorrelatedFast},
          {"V_SmithGGXSeparable", {"V_SmithGGXSeparable"}, ref::FacetV_SmithGGXSeparable},
          {"V_SchlickGGX", {"V_SchlickGGX"}, ref::FacetV_SchlickGGX},
          {"V_SchlickGGXKaris", {"V_SchlickGGXKaris"},
           [](double NoV, double NoL, double alpha) { return ref::FacetV_SchlickGGXKaris(NoV, NoL, std::sqrt(alpha)); }}};
}

std::vector<FOption> f_options() {
  return {{"F_exact", {"F_Dielectric", "F_Conductor"}, exact_terms().f},
          {"F_Schlick", {"F_Schlick"},
           [](double LoH, const mc::Material& m) { return ref::FacetF_Schlick(exact_f0(m), 1.0, LoH); }},
          {"F_SchlickSG", {"F_SchlickSG"},
           [](double LoH, const mc::Material& m) { return ref::FacetF_SchlickSG(dvec3(exact_f0(m)), 1.0, LoH).x; }},
          {"F_Pow4", {"F_Pow4"},
           [](double LoH, const mc::Material& m) { return u::FresnelLerpFast(dvec3(exact_f0(m)), dvec3(1.0), LoH).x; }}};
}

std::vector<DiffuseOption> diffuse_options() {
  auto angles = [](const dvec3& v, const dvec3& l) { return glm::dot(l, glm::normalize(v + l)); };
  return {{"Fd_Lambert", {"Fd_Lambert"}, exact_terms().diffuse},
          {"Fd_Burley", {"Fd_Burley"},
           [angles](const dvec3& v, const dvec3& l, const mc::Material& m) {
             return ref::FacetFd_Burley(v.z, l.z, angles(v, l), m.roughness);
           }},
          {"Fd_Frostbite", {"Fd_Frostbite"}, [angles](const dvec3& v, const dvec3& l, const mc::Material& m) {
             return ref::FacetFd_Frostbite(v.z, l.z, angles(v, l), m.roughness * m.roughness);
           }}};
}

// Unity's tier as the whole material: albedo the exact model's (the base
// colour, or for a metal its f0, which Unity takes from the albedo).
mc::Model unity_model(int tier) {
  return [tier](const mc::ShadingPoint& p) {
    double albedo = p.material.metallic > 0.5 ? exact_f0(p.material) : kBaseColour;
    return model_lobe("unity-brdf" + std::to_string(tier), {{"albedo", dvec3(albedo)},
                                                           {"metallic", dvec3(p.material.metallic)},
                                                           {"smoothness", dvec3(1.0 - p.material.roughness)}});
  };
}

// The cost of a set of rows: GPU times where every row has one, else SPIR-V
// instruction counts (the unit says which).
struct Costs {
  std::map<std::string, const StudyRow*> rows;
  bool timed = true;
  double of(const std::vector<std::string>& ids) const {
    double sum = 0;
    for (const std::string& id : ids) {
      auto it = rows.find(id);
      if (it == rows.end()) continue;
      sum += timed ? *it->second->ns_per_eval * 1000.0 : double(it->second->spirv_instructions);
    }
    return sum;
  }
};

Costs costs_of(const Study& study) {
  Costs c;
  for (const StudyRow& r : study.rows) {
    c.rows[r.id] = &r;
    c.timed = c.timed && r.ns_per_eval.has_value();
  }
  c.timed = c.timed && !study.rows.empty();
  return c;
}

}  // namespace

BudgetSearch search_term_combinations(const Study& study, uint32_t samples) {
  const Costs costs = costs_of(study);
  BudgetSearch search{.device = costs.timed ? study.device : std::string(),
                      .device_type = costs.timed ? study.device_type : std::string(),
                      .cost_unit = costs.timed ? "ps/eval" : "SPIR-V instr.",
                      .samples = samples};
  std::vector<mc::Model> models{material_model(exact_terms())};
  std::vector<TermCombination*> entries;
  for (const DOption& d : d_options()) {
    for (const VOption& v : v_options()) {
      for (const FOption& f : f_options()) {
        for (const DiffuseOption& diffuse : diffuse_options()) {
          Terms t{.d = d.term, .v = v.term, .f = f.term, .diffuse = diffuse.term};
          models.push_back(material_model(t));
          TermCombination c{.name = fmt::format("{} + {} + {} + {}", d.id, v.id, f.id, diffuse.id)};
          for (const auto* rows : {&d.cost_rows, &v.cost_rows, &f.cost_rows, &diffuse.cost_rows}) {
            c.rows.insert(c.rows.end(), rows->begin(), rows->end());
          }
          c.cost = costs.of(c.rows);
          search.combinations.push_back(std::move(c));
        }
      }
    }
  }
  for (int tier = 1; tier <= 3; ++tier) {
    models.push_back(unity_model(tier));
    std::string id = fmt::format("BRDF{}_Unity_PBS", tier);
    search.unity_tiers.push_back({.name = id, .rows = {id}, .cost = costs.of({id})});
  }
  for (TermCombination& c : search.combinations) entries.push_back(&c);
  for (TermCombination& c : search.unity_tiers) entries.push_back(&c);

  std::vector<mc::Contrast> contrasts;
  for (size_t i = 1; i < models.size(); ++i) contrasts.push_back({i, 0});
  for (const mc::Scene& scene : mc::study_scenes()) {
    const mc::Rendering r = mc::render(scene, models, contrasts, {.samples = samples});
    for (size_t c = 0; c < contrasts.size(); ++c) {
      double sq = 0;
      for (const mc::Estimate& e : r.contrasts[c]) sq += e.value * e.value;
      double rmse = r.points.empty() ? 0.0 : std::sqrt(sq / double(r.points.size()));
      if (!std::isfinite(rmse)) rmse = INFINITY;
      if (entries[c]->worst_scene.empty() || !(rmse <= entries[c]->image_rmse)) {
        entries[c]->image_rmse = rmse;
        entries[c]->worst_scene = scene.name;
      }
    }
  }
  std::stable_sort(search.combinations.begin(), search.combinations.end(),
                   [](const TermCombination& a, const TermCombination& b) {
                     return a.cost != b.cost ? a.cost < b.cost : a.image_rmse < b.image_rmse;
                   });
  return search;
}

const TermCombination* cheapest_within(const BudgetSearch& search, double budget) {
  for (const TermCombination& c : search.combinations) {  // cheapest first
    if (c.image_rmse <= budget) return &c;
  }
  return nullptr;
}

}  // namespace facet::runtime::accuracy
