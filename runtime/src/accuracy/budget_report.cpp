// The budget search's answers: a markdown table, JSON, and the chart of the
// combinations' Pareto front with Unity's tiers, drawn by the study's chart
// (pareto_chart.cpp) from one row per point.
#include <fmt/format.h>

#include <cmath>
#include <nlohmann/json.hpp>

#include "accuracy/pareto_chart.h"
#include "facet/markup.h"
#include "facet/runtime/accuracy.h"

namespace facet::runtime::accuracy {
namespace {

std::string figure(double v) { return std::isfinite(v) ? fmt::format("{:.3g}", v) : std::string("inf"); }

std::string cost_text(const BudgetSearch& s, double cost) {
  return s.cost_unit == "ps/eval" ? fmt::format("{:.3g} ps", cost) : fmt::format("{:.0f} instr.", cost);
}

// Combinations that nothing is both cheaper and more accurate than.
std::vector<const TermCombination*> pareto_front(const BudgetSearch& s) {
  std::vector<const TermCombination*> front;
  double best = INFINITY;
  for (const TermCombination& c : s.combinations) {  // cheapest first, the more accurate first among equals
    if (c.image_rmse < best) {
      front.push_back(&c);
      best = c.image_rmse;
    }
  }
  return front;
}

nlohmann::ordered_json combination_json(const TermCombination& c) {
  return {{"name", c.name},
          {"rows", c.rows},
          {"image_rmse", std::isfinite(c.image_rmse) ? nlohmann::ordered_json(c.image_rmse) : nlohmann::ordered_json("inf")},
          {"worst_scene", c.worst_scene},
          {"cost", c.cost}};
}

// A chart point as a study row: the image panel draws it (metric "-" keeps
// it out of the other panels), coloured by its family.
StudyRow point_row(const TermCombination& c, const std::string& group) {
  StudyRow r{.id = c.name, .group = group, .name = c.name, .reference = "exact model", .metric = "-"};
  r.ns_per_eval = c.cost / 1000.0;
  r.image.push_back({.scene = c.worst_scene, .rmse = c.image_rmse});
  return r;
}

}  // namespace

std::string budget_answers(const BudgetSearch& s, const std::vector<double>& budgets) {
  std::string out = fmt::format("| image RMSE budget | cheapest combination | image RMSE (worst scene) | cost ({}) |\n"
                                "|---:|---|---:|---:|\n",
                                s.cost_unit);
  for (double budget : budgets) {
    const TermCombination* c = cheapest_within(s, budget);
    out += c ? fmt::format("| {} | {} | {} ({}) | {} |\n", figure(budget), c->name, figure(c->image_rmse), c->worst_scene,
                           cost_text(s, c->cost))
             : fmt::format("| {} | none of the {} combinations | - | - |\n", figure(budget), s.combinations.size());
  }
  out += "\n| Unity tier | image RMSE (worst scene) | cost | within |\n|---|---:|---:|---|\n";
  for (const TermCombination& t : s.unity_tiers) {
    std::string within;
    for (double budget : budgets) {
      if (t.image_rmse <= budget) within += (within.empty() ? "" : ", ") + figure(budget);
    }
    out += fmt::format("| {} | {} ({}) | {} | {} |\n", t.name, figure(t.image_rmse), t.worst_scene, cost_text(s, t.cost),
                       within.empty() ? std::string("none of the budgets") : within);
  }
  return out;
}

std::string budget_chart_svg(const BudgetSearch& s, const std::vector<double>& budgets) {
  if (s.cost_unit != "ps/eval") {
    return R"(<svg xmlns="http://www.w3.org/2000/svg" width="560" height="24" font-family="DejaVu Sans, sans-serif">)"
           R"(<text x="4" y="16" font-size="12">No GPU times: the budget chart needs a study timed on a GPU.</text></svg>)"
           "\n";
  }
  Study chart{.device = s.device, .device_type = s.device_type};
  std::vector<const TermCombination*> points = pareto_front(s);
  for (double budget : budgets) {
    const TermCombination* c = cheapest_within(s, budget);
    if (c && std::find(points.begin(), points.end(), c) == points.end()) points.push_back(c);
  }
  for (const TermCombination* c : points) chart.rows.push_back(point_row(*c, "combination"));
  for (const TermCombination& t : s.unity_tiers) chart.rows.push_back(point_row(t, "Standard"));
  return pareto_chart_svg(
      chart, {.title = "Choosing by budget: image error of each combination of terms against its cost",
              .subtitle = fmt::format("Pareto front of {} term combinations, and Unity's tiers. Monte Carlo reference, "
                                      "{} samples per pixel. Costs: {}.",
                                      s.combinations.size(), s.samples, s.device),
              .time_axis = "GPU time per evaluation, ps (the sum of the terms' times, each minus the null pass; log scale)"});
}

std::string budget_json(const BudgetSearch& s, const std::vector<double>& budgets) {
  nlohmann::ordered_json answers = nlohmann::ordered_json::array();
  for (double budget : budgets) {
    const TermCombination* c = cheapest_within(s, budget);
    answers.push_back({{"budget", budget}, {"cheapest", c ? combination_json(*c) : nlohmann::ordered_json(nullptr)}});
  }
  nlohmann::ordered_json all = nlohmann::ordered_json::array(), tiers = nlohmann::ordered_json::array();
  for (const TermCombination& c : s.combinations) all.push_back(combination_json(c));
  for (const TermCombination& t : s.unity_tiers) tiers.push_back(combination_json(t));
  nlohmann::ordered_json out{{"device", s.device}, {"cost_unit", s.cost_unit}, {"samples", s.samples},
                             {"answers", answers}, {"unity_tiers", tiers},   {"combinations", all}};
  return out.dump(2) + "\n";
}

std::string budget_html(const BudgetSearch& s, const std::vector<double>& budgets) {
  std::string html = "<!DOCTYPE html>\n<html><head><meta charset=\"utf-8\"><title>facet: choosing by error budget</title>"
                     "<style>body{font-family:sans-serif;margin:24px}pre{font-size:12px}</style></head><body>\n"
                     "<h1>Choosing by error budget</h1>\n";
  html += fmt::format("<p>{} combinations of D, V, F and diffuse terms, rendered in the three test scenes by the Monte "
                      "Carlo reference ({} samples per pixel) against the exact model; cost: the sum of the terms' {} "
                      "({}).</p>\n",
                      s.combinations.size(), s.samples, s.cost_unit,
                      xml_escape(s.device.empty() ? std::string("no GPU") : s.device));
  html += budget_chart_svg(s, budgets);
  html += "<pre>" + xml_escape(budget_answers(s, budgets)) + "</pre>\n</body></html>\n";
  return html;
}

}  // namespace facet::runtime::accuracy
