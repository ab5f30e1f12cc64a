// The driver-statistics columns in the study's JSON and page: keys written
// only where a row has them, columns only where some row has data, and a
// paragraph that says where the numbers come from or why there are none.
#include <fmt/format.h>

#include <algorithm>
#include <nlohmann/json.hpp>
#include <span>

#include "accuracy/driver_statistics.h"
#include "facet/markup.h"
#include "facet/runtime/pipeline_statistics.h"

namespace facet::runtime::accuracy {
namespace {

// One derived column: its heading and how a row gives its value.
struct DriverColumn {
  const char* json_key;
  const char* heading;
  std::optional<uint32_t> StudyRow::*field;
};
constexpr DriverColumn kColumns[] = {
    {"driver_instructions", "driver instr.", &StudyRow::driver_instructions},
    {"driver_registers", "driver regs", &StudyRow::driver_registers},
    {"driver_code_bytes", "driver code bytes", &StudyRow::driver_code_bytes},
};

bool column_has_data(const Study& study, const DriverColumn& column) {
  for (const StudyRow& r : study.rows) {
    if (r.*column.field) return true;
  }
  return false;
}

std::string quoted_names(std::span<const std::string_view> names) {
  std::string out;
  for (std::string_view n : names) out += (out.empty() ? "'" : ", '") + std::string(n) + "'";
  return out;
}

// Every raw statistic name, in first-seen order.
std::vector<std::string> statistic_names(const Study& study) {
  std::vector<std::string> names;
  for (const StudyRow& r : study.rows) {
    for (const auto& [name, value] : r.driver_statistics) {
      if (std::find(names.begin(), names.end(), name) == names.end()) names.push_back(name);
    }
  }
  return names;
}

}  // namespace

std::string driver_raw_statistics_html(const Study& study) {
  std::vector<std::string> names = statistic_names(study);
  if (names.empty()) return "";
  std::string html = "<details><summary>Driver statistics as the driver reports them (not minus the null kernel)"
                     "</summary>\n<table><tr><th>row</th>";
  for (const std::string& n : names) html += "<th>" + xml_escape(n) + "</th>";
  html += "</tr>\n";
  for (const StudyRow& r : study.rows) {
    html += "<tr><td>" + xml_escape(r.id) + "</td>";
    for (const std::string& n : names) {
      auto it = std::find_if(r.driver_statistics.begin(), r.driver_statistics.end(),
                             [&](const auto& s) { return s.first == n; });
      html += "<td class=\"n\">" + (it == r.driver_statistics.end() ? std::string("—") : fmt::format("{:.6g}", it->second)) +
              "</td>";
    }
    html += "</tr>\n";
  }
  return html + "</table></details>\n";
}

void write_driver_fields(const StudyRow& row, nlohmann::ordered_json& j) {
  for (const DriverColumn& c : kColumns) {
    if (row.*c.field) j[c.json_key] = *(row.*c.field);
  }
  if (row.driver_statistics.empty()) return;
  nlohmann::ordered_json statistics = nlohmann::ordered_json::array();
  for (const auto& [name, value] : row.driver_statistics) statistics.push_back({{"name", name}, {"value", value}});
  j["driver_statistics"] = std::move(statistics);
}

void read_driver_fields(const nlohmann::json& j, StudyRow& row) {
  for (const DriverColumn& c : kColumns) {
    auto it = j.find(c.json_key);
    if (it != j.end() && it->is_number_unsigned()) row.*c.field = it->get<uint32_t>();
  }
  auto statistics = j.find("driver_statistics");
  if (statistics == j.end() || !statistics->is_array()) return;
  for (const nlohmann::json& s : *statistics) {
    if (!s.is_object() || !s.contains("name") || !s["name"].is_string() || !s.contains("value") || !s["value"].is_number()) {
      continue;
    }
    row.driver_statistics.emplace_back(s["name"].get<std::string>(), s["value"].get<double>());
  }
}

std::string driver_header_cells(const Study& study) {
  std::string html;
  for (const DriverColumn& c : kColumns) {
    if (column_has_data(study, c)) html += fmt::format("<th>{}</th>", c.heading);
  }
  return html;
}

std::string driver_row_cells(const Study& study, const StudyRow& row) {
  std::string html;
  for (const DriverColumn& c : kColumns) {
    if (!column_has_data(study, c)) continue;
    const std::optional<uint32_t>& value = row.*c.field;
    html += "<td class=\"n\">" + (value ? std::to_string(*value) : std::string("—")) + "</td>";
  }
  return html;
}

std::string driver_statistics_html(const Study& study) {
  const std::string device = xml_escape(study.device);
  if (!study.driver_statistics_offered) {
    return study.device.empty() ? "" : "<p>Driver statistics: not recorded in this study.</p>\n";
  }
  if (!*study.driver_statistics_offered) {
    return fmt::format("<p>Driver statistics: not available on {} (the device does not offer "
                       "VK_KHR_pipeline_executable_properties).</p>\n",
                       device);
  }
  std::string html = fmt::format(
      "<p>Driver statistics (VK_KHR_pipeline_executable_properties on {}) of the same one-evaluation kernel as the "
      "SPIR-V count: instructions from {}; registers (per thread) from {}; code bytes from {}; names compared without "
      "case. Instructions and code bytes are minus the null kernel's, registers are the kernel's own.",
      device, quoted_names(instruction_statistic_names()), quoted_names(register_statistic_names()),
      quoted_names(code_size_statistic_names()));
  bool any_column = false;
  for (const DriverColumn& c : kColumns) any_column = any_column || column_has_data(study, c);
  if (!any_column) html += " The driver reports none of these names; what it reports is listed under the table.";
  return html + "</p>\n";
}

}  // namespace facet::runtime::accuracy
