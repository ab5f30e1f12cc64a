// facetc --check's JUnit XML and SARIF 2.1.0 reports, built from the checked
// shaders (which no longer hold their SourceMaps).
#include "check_reports.h"

#include <fmt/format.h>

#include <cctype>
#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>

#include "facet/markup.h"

namespace facet::tools {
namespace {
namespace fs = std::filesystem;

// The code point of the valid UTF-8 sequence at `i` and its length, or
// length 0 for bytes that are not one (overlong forms and surrogates too).
std::pair<uint32_t, size_t> decode_utf8(std::string_view s, size_t i) {
  unsigned char c = static_cast<unsigned char>(s[i]);
  size_t n = c < 0x80 ? 1 : (c >> 5) == 0x6 ? 2 : (c >> 4) == 0xe ? 3 : (c >> 3) == 0x1e ? 4 : 0;
  if (n == 0 || i + n > s.size()) return {0, 0};
  uint32_t cp = n == 1 ? c : n == 2 ? c & 0x1f : n == 3 ? c & 0x0f : c & 0x07;
  for (size_t k = 1; k < n; ++k) {
    unsigned char b = static_cast<unsigned char>(s[i + k]);
    if ((b & 0xc0) != 0x80) return {0, 0};
    cp = (cp << 6) | (b & 0x3f);
  }
  static constexpr uint32_t kMin[] = {0, 0, 0x80, 0x800, 0x10000};
  if (cp < kMin[n] || cp > 0x10ffff || (cp >= 0xd800 && cp <= 0xdfff)) return {0, 0};
  return {cp, n};
}

// XML 1.0 cannot hold control characters (not even as references), U+FFFE,
// U+FFFF or invalid UTF-8, and a shader's messages may quote any bytes:
// those become '?' before markup is escaped, so that the report stays
// well-formed.
std::string xml_text(std::string_view s) {
  std::string clean;
  clean.reserve(s.size());
  for (size_t i = 0; i < s.size();) {
    auto [cp, n] = decode_utf8(s, i);
    bool allowed = n > 0 && (cp >= 0x20 || cp == '\t' || cp == '\n' || cp == '\r') && cp != 0xfffe && cp != 0xffff;
    if (!allowed) {
      clean += '?';
      ++i;
      continue;
    }
    clean.append(s.substr(i, n));
    i += n;
  }
  return xml_escape(clean);
}

// An attribute value: a line break in one is read back as a space, so it is
// written as a character reference to survive.
std::string xml_attribute(std::string_view s) {
  std::string out;
  for (char c : xml_text(s)) {
    if (c == '\n') {
      out += "&#10;";
    } else if (c == '\r') {
      out += "&#13;";
    } else if (c == '\t') {
      out += "&#9;";
    } else {
      out += c;
    }
  }
  return out;
}

const char* sarif_level(Severity s) {
  switch (s) {
    case Severity::note: return "note";
    case Severity::warning: return "warning";
    case Severity::error: return "error";
  }
  return "error";
}

// RFC 3986: unreserved characters and '/' as they are, every other byte as %XX.
std::string uri_escape(std::string_view path) {
  std::string out;
  for (char ch : path) {
    unsigned char c = static_cast<unsigned char>(ch);
    if (std::isalnum(c) || c == '-' || c == '.' || c == '_' || c == '~' || c == '/') {
      out += ch;
    } else {
      out += fmt::format("%{:02X}", c);
    }
  }
  return out;
}

nlohmann::json artifact_location(const std::string& file, const fs::path& base) {
  fs::path absolute = fs::absolute(file).lexically_normal();
  fs::path relative = absolute.lexically_relative(base);
  if (!relative.empty() && *relative.begin() != "..") {
    return {{"uri", uri_escape(relative.generic_string())}, {"uriBaseId", "SRCROOT"}};
  }
  return {{"uri", "file://" + uri_escape(absolute.generic_string())}};
}

// "0.1.0" of version_string()'s "facet 0.1.0 (glslang 12, ...)".
std::string facet_version() {
  std::string text = version_string();
  size_t begin = text.find(' ');
  size_t end = text.find(' ', begin + 1);
  return begin == std::string::npos ? text : text.substr(begin + 1, end - begin - 1);
}

}  // namespace

std::string junit_xml(const std::vector<ShaderCheck>& checks, double seconds, const std::string& timestamp) {
  size_t failures = 0;
  for (const ShaderCheck& c : checks) failures += c.ok ? 0 : 1;
  std::string out = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  out += fmt::format("<testsuites name=\"facetc --check\" tests=\"{}\" failures=\"{}\" errors=\"0\" time=\"{:.3f}\">\n",
                     checks.size(), failures, seconds);
  out += fmt::format("  <testsuite name=\"facetc --check\" tests=\"{}\" failures=\"{}\" errors=\"0\" skipped=\"0\" "
                     "time=\"{:.3f}\" timestamp=\"{}\">\n",
                     checks.size(), failures, seconds, timestamp);
  for (const ShaderCheck& c : checks) {
    fs::path path(c.path);
    std::string folder = path.parent_path().generic_string();
    out += fmt::format("    <testcase classname=\"{}\" name=\"{}\" time=\"{:.3f}\"",
                       xml_attribute(folder.empty() ? "." : folder), xml_attribute(path.filename().string()),
                       c.seconds);
    if (c.ok && c.text.empty()) {
      out += "/>\n";
      continue;
    }
    out += ">\n";
    if (!c.ok) {
      std::string type = "error";
      for (const CheckDiagnostic& d : c.diagnostics) {
        if (d.severity == Severity::error) {
          type = diag_name(d.id);
          break;
        }
      }
      std::string message = first_error(c);
      out += fmt::format("      <failure message=\"{}\" type=\"{}\">{}</failure>\n",
                         xml_attribute(message.empty() ? "error: the shader does not compile" : message),
                         xml_attribute(type), xml_text(c.text));
    } else {
      out += fmt::format("      <system-out>{}</system-out>\n", xml_text(c.text));
    }
    out += "    </testcase>\n";
  }
  out += "  </testsuite>\n</testsuites>\n";
  return out;
}

std::string sarif_json(const std::vector<ShaderCheck>& checks, const std::string& base_dir) {
  fs::path base = fs::path(base_dir).lexically_normal();
  // Rules sorted by id, so that their indices do not depend on which shader
  // showed one first.
  std::map<std::string, DiagId> used;
  for (const ShaderCheck& c : checks) {
    for (const CheckDiagnostic& d : c.diagnostics) used.emplace(std::string(diag_name(d.id)), d.id);
  }
  nlohmann::json rules = nlohmann::json::array();
  std::map<std::string, size_t> rule_index;
  for (const auto& [name, id] : used) {
    rule_index[name] = rules.size();
    rules.push_back({{"id", name}, {"defaultConfiguration", {{"level", sarif_level(diag_default_severity(id))}}}});
  }
  nlohmann::json results = nlohmann::json::array();
  for (const ShaderCheck& c : checks) {
    for (const CheckDiagnostic& d : c.diagnostics) {
      std::string text = d.message;
      for (const std::string& note : d.notes) text += "\nnote: " + note;
      // A diagnostic without a location (an unreadable file) is the shader's.
      nlohmann::json physical = {{"artifactLocation", artifact_location(d.file.empty() ? c.path : d.file, base)}};
      if (!d.file.empty() && d.line >= 1 && d.column >= 1) {
        nlohmann::json region = {{"startLine", d.line}, {"startColumn", d.column}};
        if (d.end_line >= d.line && d.end_column >= 1) {
          region["endLine"] = d.end_line;
          region["endColumn"] = d.end_column;
        }
        physical["region"] = std::move(region);
      }
      std::string name(diag_name(d.id));
      results.push_back({{"ruleId", name},
                         {"ruleIndex", rule_index.at(name)},
                         {"level", sarif_level(d.severity)},
                         {"message", {{"text", text}}},
                         {"locations", nlohmann::json::array({{{"physicalLocation", physical}}})}});
    }
  }
  std::string base_uri = "file://" + uri_escape(base.generic_string());
  if (!base_uri.ends_with('/')) base_uri += '/';  // SARIF: a base URI ends with a slash
  nlohmann::json run = {
      {"tool", {{"driver", {{"name", "facetc"}, {"version", facet_version()}, {"rules", rules}}}}},
      {"originalUriBaseIds", {{"SRCROOT", {{"uri", base_uri}}}}},
      {"invocations", nlohmann::json::array({{{"executionSuccessful", true}}})},
      {"results", results}};
  nlohmann::json log = {{"$schema", "https://json.schemastore.org/sarif-2.1.0.json"},
                        {"version", "2.1.0"},
                        {"runs", nlohmann::json::array({run})}};
  // Messages may quote invalid UTF-8 from a shader: replaced, never thrown on.
  return log.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n";
}

}  // namespace facet::tools
