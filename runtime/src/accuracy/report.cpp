// The study as JSON, and as one HTML page with the table and a log-log
// Pareto chart (error against ns per evaluation) in inline SVG.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>

#include "facet/markup.h"
#include "facet/runtime/accuracy.h"

namespace facet::runtime::accuracy {
namespace {

bool on_chart(const StudyRow& r) { return r.error > 0 && std::isfinite(r.error) && r.ns_per_eval && *r.ns_per_eval > 0; }

// Pareto-optimal rows within a group: no other row of the group is both
// cheaper and more accurate.
bool pareto(const StudyRow& r, const std::vector<StudyRow>& rows) {
  for (const StudyRow& o : rows) {
    if (&o == &r || o.group != r.group || !on_chart(o)) continue;
    if (*o.ns_per_eval <= *r.ns_per_eval && o.error <= r.error && (*o.ns_per_eval < *r.ns_per_eval || o.error < r.error)) {
      return false;
    }
  }
  return true;
}

std::string chart(const Study& study) {
  std::vector<const StudyRow*> points;
  for (const StudyRow& r : study.rows) {
    if (on_chart(r)) points.push_back(&r);
  }
  if (points.empty()) return "<p>No row has both an error and a GPU time (run with a GPU to draw the chart).</p>\n";
  double x0 = 1e30, x1 = 0, y0 = 1e30, y1 = 0;
  for (const StudyRow* r : points) {
    x0 = std::min(x0, *r->ns_per_eval), x1 = std::max(x1, *r->ns_per_eval);
    y0 = std::min(y0, r->error), y1 = std::max(y1, r->error);
  }
  double lx0 = std::floor(std::log10(x0)), lx1 = std::ceil(std::log10(x1) + 1e-9);
  double ly0 = std::floor(std::log10(y0)), ly1 = std::ceil(std::log10(y1) + 1e-9);
  if (lx1 == lx0) lx1 += 1;
  if (ly1 == ly0) ly1 += 1;
  const double W = 760, H = 440, L = 70, R = 20, T = 20, B = 50;
  auto px = [&](double x) { return L + (std::log10(x) - lx0) / (lx1 - lx0) * (W - L - R); };
  auto py = [&](double y) { return H - B - (std::log10(y) - ly0) / (ly1 - ly0) * (H - T - B); };
  std::string svg = fmt::format(R"svg(<svg xmlns="http://www.w3.org/2000/svg" width="{}" height="{}" class="pareto">)svg", W, H);
  svg += fmt::format(R"svg(<rect x="{}" y="{}" width="{}" height="{}" fill="#fafafa" stroke="#999"/>)svg", L, T, W - L - R,
                     H - T - B);
  for (double e = lx0; e <= lx1; ++e) {
    svg += fmt::format(R"svg(<line x1="{0}" x2="{0}" y1="{1}" y2="{2}" stroke="#ddd"/><text x="{0}" y="{3}" font-size="11" text-anchor="middle">1e{4}</text>)svg",
                       px(std::pow(10, e)), T, H - B, H - B + 16, int(e));
  }
  for (double e = ly0; e <= ly1; ++e) {
    svg += fmt::format(R"svg(<line x1="{0}" x2="{1}" y1="{2}" y2="{2}" stroke="#ddd"/><text x="{3}" y="{4}" font-size="11" text-anchor="end">1e{5}</text>)svg",
                       L, W - R, py(std::pow(10, e)), L - 6, py(std::pow(10, e)) + 4, int(e));
  }
  svg += fmt::format(R"svg(<text x="{}" y="{}" font-size="12" text-anchor="middle">GPU ns per evaluation (minus the null pass)</text>)svg",
                     (L + W - R) / 2, H - 12);
  svg += fmt::format(R"svg(<text x="16" y="{}" font-size="12" transform="rotate(-90 16 {})" text-anchor="middle">error (row metric)</text>)svg",
                     (T + H - B) / 2, (T + H - B) / 2);
  for (const StudyRow* r : points) {
    bool best = pareto(*r, study.rows);
    svg += fmt::format(R"svg(<circle cx="{:.1f}" cy="{:.1f}" r="4" fill="{}" class="point"><title>{}: error {:.3g}, {:.3g} ns</title></circle>)svg",
                       px(*r->ns_per_eval), py(r->error), best ? "#d62728" : "#1f77b4", xml_escape(r->id), r->error,
                       *r->ns_per_eval);
    svg += fmt::format(R"svg(<text x="{:.1f}" y="{:.1f}" font-size="9">{}</text>)svg", px(*r->ns_per_eval) + 6,
                       py(r->error) - 4, xml_escape(r->id));
  }
  return svg + "</svg>\n<p>Red: Pareto-optimal within its group (nothing in the group is both cheaper and more accurate).</p>\n";
}

std::string cell(const std::optional<double>& v, const char* format) {
  return v ? fmt::format(fmt::runtime(format), *v) : std::string("-");
}

}  // namespace

std::string study_json(const Study& study) {
  nlohmann::ordered_json rows = nlohmann::ordered_json::array();
  for (const StudyRow& r : study.rows) {
    nlohmann::ordered_json j{{"id", r.id},           {"group", r.group},   {"name", r.name},
                             {"reference", r.reference}, {"metric", r.metric}, {"error", r.error},
                             {"detail", r.detail},   {"anchor", r.anchor}, {"spirv_instructions", r.spirv_instructions}};
    if (!std::isfinite(r.error)) {  // an fp16 form that overflows: JSON has no infinity
      j["error"] = nullptr;
      j["error_is_infinite"] = true;
    }
    j["ns_per_eval"] = r.ns_per_eval ? nlohmann::ordered_json(*r.ns_per_eval) : nlohmann::ordered_json(nullptr);
    rows.push_back(std::move(j));
  }
  nlohmann::ordered_json out{{"device", study.device},
                             {"grid", {study.options.width, study.options.height}},
                             {"evaluations_per_invocation", study.options.evaluations},
                             {"frames", study.options.frames},
                             {"rows", rows}};
  return out.dump(2) + "\n";
}

std::string study_html(const Study& study) {
  std::string html = "<!DOCTYPE html>\n<html><head><meta charset=\"utf-8\"><title>facet accuracy vs cost</title><style>"
                     "body{font-family:sans-serif;margin:24px}table{border-collapse:collapse;font-size:12px}"
                     "td,th{border:1px solid #ccc;padding:3px 6px;vertical-align:top}th{background:#eee}"
                     "td.n{text-align:right;font-variant-numeric:tabular-nums}</style></head><body>\n";
  html += "<h1>Accuracy versus cost</h1>\n";
  html += fmt::format("<p>Device: {}. Timed pass: {}x{} invocations, {} evaluations each, median of {} dispatches, "
                      "minus a null pass.</p>\n",
                      xml_escape(study.device.empty() ? std::string("none (no GPU timing)") : study.device),
                      study.options.width, study.options.height, study.options.evaluations, study.options.frames);
  html += chart(study);
  html += "<table><tr><th>group</th><th>row</th><th>what</th><th>against</th><th>metric</th><th>error</th>"
          "<th>detail</th><th>published anchor</th><th>SPIR-V instr.</th><th>ns/eval</th></tr>\n";
  for (const StudyRow& r : study.rows) {
    html += fmt::format("<tr><td>{}</td><td>{}</td><td>{}</td><td>{}</td><td>{}</td><td class=\"n\">{}</td><td>{}</td>"
                        "<td>{}</td><td class=\"n\">{}</td><td class=\"n\">{}</td></tr>\n",
                        xml_escape(r.group), xml_escape(r.id), xml_escape(r.name), xml_escape(r.reference), xml_escape(r.metric),
                        r.metric == "-" ? std::string("-") : std::isfinite(r.error) ? fmt::format("{:.4g}", r.error) : std::string("inf (overflow)"), xml_escape(r.detail),
                        xml_escape(r.anchor), r.spirv_instructions, cell(r.ns_per_eval, "{:.3g}"));
  }
  return html + "</table>\n</body></html>\n";
}

}  // namespace facet::runtime::accuracy
