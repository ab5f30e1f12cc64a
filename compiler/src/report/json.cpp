// The report as JSON (keys in a fixed order; docs/reports.md).
#include <cmath>
#include <nlohmann/json.hpp>

#include "facet/report.h"

namespace facet::report {
namespace {

using Json = nlohmann::ordered_json;

double micro(double seconds) { return std::round(seconds * 1e6) / 1e6; }

// Exact counts: a number when it fits in 64 bits, else a decimal string.
Json count(const BigCount& n) {
  if (auto v = n.to_u64()) return *v;
  return n.to_string();
}

Json ladder_json(const Ladder& l, bool enumerated) {
  auto compiled = [&](uint64_t value) { return enumerated ? Json(value) : Json(nullptr); };
  Json j = {{"scope", l.scope}, {"full", count(l.full)}, {"after_skip_variants", count(l.after_skip)}};
  j["after_materials"] = l.has_materials ? count(l.after_materials) : Json(nullptr);
  j["reachable"] = count(l.reachable);
  j["after_keyword_rules_and_strip"] = compiled(l.after_strip);
  j["after_scene_needs"] = nullptr;  // scenes are the runtime's (facet render --explain)
  j["programs"] = compiled(l.programs);
  j["unique_after_preprocessing"] = compiled(l.unique_tokens);
  j["unique_spirv"] = compiled(l.unique_spirv);
  return j;
}

Json pass_json(const PassReport& p) {
  Json j = {{"index", p.index}, {"name", p.name}, {"light_mode", p.light_mode}, {"enumerated", p.enumerated}};
  j["ladder"] = Json::array();
  for (const Ladder& l : p.ladders) j["ladder"].push_back(ladder_json(l, p.enumerated));
  j["unreachable_keywords"] = p.unreachable_keywords;
  j["keyword_sets"] = Json::array();
  for (const KeywordSetRow& s : p.sets) {
    Json keywords = Json::array();
    for (const std::string& k : s.keywords) keywords.push_back(k.empty() ? "_" : k);
    j["keyword_sets"].push_back(
        {{"pragma", s.pragma}, {"keywords", keywords}, {"stages", s.stages}, {"factor", s.factor}});
  }
  j["findings"] = Json::array();
  for (const Finding& f : p.findings) {
    j["findings"].push_back({{"kind", finding_name(f.kind)}, {"keyword", f.keyword}, {"stage", f.stage},
                             {"detail", f.detail}});
  }
  j["what_if"] = Json::array();
  for (const WhatIf& w : p.what_ifs) {
    j["what_if"].push_back(
        {{"change", w.change}, {"programs_saved", count(w.programs_saved)}, {"seconds_saved", micro(w.seconds_saved)}});
  }
  j["compile_seconds"] = micro(p.compile_seconds);
  j["spirv_bytes"] = p.spirv_bytes;
  j["variants"] = Json::array();
  for (const VariantRow& v : p.variants) {
    j["variants"].push_back({{"keywords", v.keywords}, {"seconds", micro(v.seconds)}, {"spirv_bytes", v.spirv_bytes}});
  }
  return j;
}

Json summary_json(const StripPlan& plan) {
  Json j = {{"programs_now", plan.programs_now}, {"programs_after", plan.programs_after},
            {"seconds_saved", micro(plan.seconds_saved)}, {"steps", Json::array()}};
  for (const PlannedStep& s : plan.steps) {
    j["steps"].push_back({{"pass", s.pass}, {"pass_name", s.pass_name}, {"change", s.step.change},
                          {"always_off", s.step.always_off}, {"programs_saved", s.step.programs_saved},
                          {"seconds_saved", micro(s.step.seconds_saved)}});
  }
  j["passes_not_enumerated"] = plan.passes_not_enumerated;
  return j;
}

}  // namespace

std::string_view finding_name(FindingKind kind) {
  switch (kind) {
    case FindingKind::dead: return "dead";
    case FindingKind::undeclared: return "undeclared";
    case FindingKind::free_in_stage: return "free";
  }
  return "dead";
}

std::string to_json(const std::vector<ShaderReport>& reports) {
  Json doc = {{"format", "facet-variant-report"}, {"version", 1}, {"shaders", Json::array()}};
  for (const ShaderReport& r : reports) {
    Json s = {{"path", r.path}, {"name", r.name}, {"programs", r.programs}, {"compiled", r.compiled},
              {"compile_seconds", micro(r.compile_seconds)}, {"summary", summary_json(strip_plan(r))},
              {"passes", Json::array()}};
    if (r.estimate) {
      const BuildEstimate& e = *r.estimate;
      s["estimate"] = {{"programs", e.programs}, {"to_compile", e.unique}, {"sampled", e.sampled},
                       {"preprocess_seconds", micro(e.preprocess_seconds)},
                       {"seconds_per_program", micro(e.seconds_per_program)},
                       {"estimated_seconds", micro(e.estimated_seconds)}, {"threads", e.jobs}};
    }
    for (const PassReport& p : r.passes) s["passes"].push_back(pass_json(p));
    doc["shaders"].push_back(std::move(s));
  }
  return doc.dump(2, ' ', false, Json::error_handler_t::replace) + "\n";
}

}  // namespace facet::report
