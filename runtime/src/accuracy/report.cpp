// The study as JSON (written and read back), and as one HTML page with the
// Pareto chart (pareto_chart.cpp) and the table; what the chart needs to
// know about a study: its error kinds and whether it was timed on a CPU.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <nlohmann/json.hpp>

#include "accuracy/driver_statistics.h"
#include "facet/markup.h"
#include "facet/runtime/accuracy.h"

namespace facet::runtime::accuracy {
namespace {

std::string cell(const std::optional<double>& v, const char* format) {
  return v ? fmt::format(fmt::runtime(format), *v) : std::string("-");
}

double number(const nlohmann::json& j, const char* key, double fallback = 0) {
  auto it = j.find(key);
  return it != j.end() && it->is_number() ? it->get<double>() : fallback;
}
std::string string_of(const nlohmann::json& j, const char* key) {
  auto it = j.find(key);
  return it != j.end() && it->is_string() ? it->get<std::string>() : std::string();
}

// JSON has no infinity: an image error that overflowed is written "inf".
nlohmann::ordered_json finite_or_inf(double v) {
  return std::isfinite(v) ? nlohmann::ordered_json(v) : nlohmann::ordered_json("inf");
}
double number_or_inf(const nlohmann::json& j, const char* key) {
  auto it = j.find(key);
  if (it != j.end() && it->is_string() && it->get<std::string>() == "inf") return std::numeric_limits<double>::infinity();
  return number(j, key);
}

nlohmann::ordered_json image_json(const StudyRow& r) {
  nlohmann::ordered_json out = nlohmann::ordered_json::array();
  for (const ImageError& e : r.image) {
    out.push_back({{"scene", e.scene}, {"rmse", finite_or_inf(e.rmse)}, {"max_error", finite_or_inf(e.max_error)},
                   {"noise", finite_or_inf(e.noise)}});
  }
  return out;
}
std::vector<ImageError> image_from_json(const nlohmann::json& j) {
  std::vector<ImageError> out;
  auto it = j.find("image");
  if (it == j.end() || !it->is_array()) return out;
  for (const nlohmann::json& e : *it) {
    if (!e.is_object()) continue;
    out.push_back({.scene = string_of(e, "scene"), .rmse = number_or_inf(e, "rmse"),
                   .max_error = number_or_inf(e, "max_error"), .noise = number_or_inf(e, "noise")});
  }
  return out;
}

// "0.0123 (sky)": the figure of the scene where it is largest, or "-" for a
// row without image errors.
std::string image_cell(const StudyRow& r, double ImageError::*figure) {
  const ImageError* worst = nullptr;
  for (const ImageError& e : r.image) {
    if (!worst || !(e.*figure <= worst->*figure)) worst = &e;
  }
  if (!worst) return "-";
  double v = worst->*figure;
  return fmt::format("{} ({})", std::isfinite(v) ? fmt::format("{:.3g}", v) : std::string("inf"), worst->scene);
}
// ---- the fp16 columns (StudyRow::fp16_*): absent from a row without them ----
void fp16_to_json(const StudyRow& r, nlohmann::ordered_json& j) {
  if (r.fp16_error) {
    bool finite = std::isfinite(*r.fp16_error);
    j["fp16_error"] = finite ? nlohmann::ordered_json(*r.fp16_error) : nlohmann::ordered_json(nullptr);
    if (!finite) j["fp16_error_is_infinite"] = true;
  }
  if (r.fp16_ns_per_eval) j["fp16_ns_per_eval"] = *r.fp16_ns_per_eval;
  if (!r.fp16_domain.empty()) j["fp16_domain"] = r.fp16_domain;
}
void fp16_from_json(const nlohmann::json& j, StudyRow& r) {
  if (j.contains("fp16_error") && j["fp16_error"].is_number()) r.fp16_error = j["fp16_error"].get<double>();
  if (j.contains("fp16_error_is_infinite") && j["fp16_error_is_infinite"].is_boolean() &&
      j["fp16_error_is_infinite"].get<bool>()) {
    r.fp16_error = std::numeric_limits<double>::infinity();
  }
  if (j.contains("fp16_ns_per_eval") && j["fp16_ns_per_eval"].is_number()) r.fp16_ns_per_eval = j["fp16_ns_per_eval"].get<double>();
  r.fp16_domain = string_of(j, "fp16_domain");
}
std::string fp16_error_cell(const std::optional<double>& e) {
  if (!e) return "-";
  return std::isfinite(*e) ? fmt::format("{:.3g}", *e) : std::string("inf (overflow)");
}
// The two table cells, the domain as the error cell's tooltip.
std::string fp16_html_cells(const StudyRow& r) {
  return fmt::format("<td class=\"n\" title=\"{}\">{}</td><td class=\"n\">{}</td>", xml_escape(r.fp16_domain),
                     fp16_error_cell(r.fp16_error), cell(r.fp16_ns_per_eval, "{:.3g}"));
}
std::string fp16_html_note(const Study& study) {
  if (!study.shader_float16) return "";
  return *study.shader_float16
             ? "<p>fp16 columns: the row's HLSL and the stdlib with half for float, run with shaderFloat16 (real 16-bit "
               "arithmetic); error: max relative error against the fp64 twin over the domain in the cell's tooltip.</p>\n"
             : "<p>fp16 columns: not measured, the device has no shaderFloat16.</p>\n";
}
// ---- end of the fp16 columns ----

Result<StudyRow> row_from_json(const nlohmann::json& j) {
  if (!j.is_object() || !j.contains("id") || !j["id"].is_string()) return failure("a row without an 'id'");
  StudyRow r{.id = string_of(j, "id"), .group = string_of(j, "group"), .name = string_of(j, "name"),
             .reference = string_of(j, "reference"), .metric = string_of(j, "metric"), .error = number(j, "error"),
             .detail = string_of(j, "detail"), .anchor = string_of(j, "anchor"),
             .spirv_instructions = uint32_t(number(j, "spirv_instructions"))};
  if (j.contains("error_is_infinite") && j["error_is_infinite"].is_boolean() && j["error_is_infinite"].get<bool>()) r.error = std::numeric_limits<double>::infinity();
  if (j.contains("ns_per_eval") && j["ns_per_eval"].is_number()) r.ns_per_eval = j["ns_per_eval"].get<double>();
  r.image = image_from_json(j);
  r.image_how = string_of(j, "image_how");
  read_driver_fields(j, r);
  fp16_from_json(j, r);
  return r;
}

}  // namespace

bool timed_on_cpu(const Study& study) {
  if (!study.device_type.empty()) return study.device_type == "cpu";
  for (const char* cpu : {"llvmpipe", "lavapipe", "SwiftShader"}) {
    if (study.device.find(cpu) != std::string::npos) return true;
  }
  return false;
}

ErrorKind error_kind(const StudyRow& row) {
  const std::string& m = row.metric;
  if (m.empty() || m == "-") return ErrorKind::none;
  if (m.starts_with("fp16")) return ErrorKind::fp16;
  if (m.find("relL1") != std::string::npos) return ErrorKind::lobe;
  for (const char* energy : {"albedo", "energy", "|E - 1|"}) {
    if (m.find(energy) != std::string::npos) return ErrorKind::energy;
  }
  return ErrorKind::pointwise;
}

Result<Study> study_from_json(const std::string& text) {
  nlohmann::json j = nlohmann::json::parse(text, nullptr, false);
  if (j.is_discarded() || !j.is_object()) return failure("not a JSON object");
  if (!j.contains("rows") || !j["rows"].is_array()) return failure("no 'rows' array: not a study written by facet bench accuracy");
  Study study{.device = string_of(j, "device"), .device_type = string_of(j, "device_type")};
  if (j.contains("grid") && j["grid"].is_array() && j["grid"].size() == 2 && j["grid"][0].is_number() && j["grid"][1].is_number()) {
    study.options.width = j["grid"][0].get<uint32_t>(), study.options.height = j["grid"][1].get<uint32_t>();
  }
  study.options.evaluations = uint32_t(number(j, "evaluations_per_invocation", study.options.evaluations));
  study.options.frames = uint32_t(number(j, "frames", study.options.frames));
  study.options.image_samples = uint32_t(number(j, "image_samples", 0));
  if (j.contains("driver_statistics_offered") && j["driver_statistics_offered"].is_boolean()) {
    study.driver_statistics_offered = j["driver_statistics_offered"].get<bool>();
  }
  if (j.contains("shader_float16") && j["shader_float16"].is_boolean()) study.shader_float16 = j["shader_float16"].get<bool>();
  for (const nlohmann::json& r : j["rows"]) {
    Result<StudyRow> row = row_from_json(r);
    if (!row) return failure(fmt::format("row {}: {}", study.rows.size() + 1, row.error().reason));
    study.rows.push_back(std::move(*row));
  }
  return study;
}

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
    if (!r.image.empty()) {
      j["image"] = image_json(r);
      j["image_how"] = r.image_how;
    }
    write_driver_fields(r, j);
    fp16_to_json(r, j);
    rows.push_back(std::move(j));
  }
  nlohmann::ordered_json out{{"device", study.device},
                             {"device_type", study.device_type},
                             {"grid", {study.options.width, study.options.height}},
                             {"evaluations_per_invocation", study.options.evaluations},
                             {"frames", study.options.frames},
                             {"image_samples", study.options.image_samples}};
  if (study.driver_statistics_offered) out["driver_statistics_offered"] = *study.driver_statistics_offered;
  if (study.shader_float16) out["shader_float16"] = *study.shader_float16;
  out["rows"] = rows;
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
  if (study.options.image_samples > 0) {
    html += fmt::format("<p>Image errors: the test scenes rendered by the Monte Carlo reference, {} samples per pixel; "
                        "RMSE and largest error of the worst scene, in linear radiance (white furnace = 1).</p>\n",
                        study.options.image_samples);
  }
  html += fp16_html_note(study);
  html += driver_statistics_html(study);
  html += study_chart_svg(study);
  html += "<table><tr><th>group</th><th>row</th><th>what</th><th>against</th><th>metric</th><th>error</th>"
          "<th>image RMSE</th><th>image max</th><th>detail</th><th>published anchor</th><th>SPIR-V instr.</th><th>ns/eval</th>"
          "<th>fp16 GPU error</th><th>fp16 ns/eval</th>" +
          driver_header_cells(study) + "</tr>\n";
  for (const StudyRow& r : study.rows) {
    html += fmt::format("<tr><td>{}</td><td>{}</td><td>{}</td><td>{}</td><td>{}</td><td class=\"n\">{}</td>"
                        "<td class=\"n\">{}</td><td class=\"n\">{}</td><td>{}</td>"
                        "<td>{}</td><td class=\"n\">{}</td><td class=\"n\">{}</td>{}{}</tr>\n",
                        xml_escape(r.group), xml_escape(r.id), xml_escape(r.name), xml_escape(r.reference), xml_escape(r.metric),
                        r.metric == "-" ? std::string("-") : std::isfinite(r.error) ? fmt::format("{:.4g}", r.error) : std::string("inf (overflow)"),
                        image_cell(r, &ImageError::rmse), image_cell(r, &ImageError::max_error), xml_escape(r.detail),
                        xml_escape(r.anchor), r.spirv_instructions, cell(r.ns_per_eval, "{:.3g}"), fp16_html_cells(r),
                        driver_row_cells(study, r));
  }
  return html + "</table>\n" + driver_raw_statistics_html(study) + "</body></html>\n";
}

}  // namespace facet::runtime::accuracy
