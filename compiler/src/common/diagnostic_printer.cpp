// GCC/Clang-style text and JSON renderings of Diagnostics.
#include <fmt/format.h>

#include <nlohmann/json.hpp>

#include "facet/diagnostics.h"

namespace facet {
namespace {

std::string_view severity_word(Severity s) {
  switch (s) {
    case Severity::note: return "note";
    case Severity::warning: return "warning";
    case Severity::error: return "error";
  }
  return "error";
}

std::string_view severity_color(Severity s) {
  switch (s) {
    case Severity::note: return "\x1b[1;36m";
    case Severity::warning: return "\x1b[1;35m";
    case Severity::error: return "\x1b[1;31m";
  }
  return "";
}

std::string location_prefix(const SourceSpan& span, const SourceMap& sources) {
  if (!span.has_location() || span.file >= sources.file_count()) return "facet: ";
  LineColumn lc = sources.line_column(span.file, span.begin);
  return fmt::format("{}:{}:{}: ", sources.path(span.file), lc.line, lc.column);
}

// Length of the valid UTF-8 sequence at `i`, or 0 when the bytes are not one.
size_t utf8_length(std::string_view s, size_t i) {
  unsigned char c = static_cast<unsigned char>(s[i]);
  size_t n = c < 0x80 ? 1 : (c >> 5) == 0x6 ? 2 : (c >> 4) == 0xe ? 3 : (c >> 3) == 0x1e ? 4 : 0;
  if (n == 0 || i + n > s.size()) return 0;
  for (size_t k = 1; k < n; ++k) {
    if ((static_cast<unsigned char>(s[i + k]) & 0xc0) != 0x80) return 0;
  }
  return n;
}

// The line as a terminal can show it: control bytes and invalid UTF-8 become
// '?', one byte each, so byte columns still line the caret up.
std::string printable(std::string_view line) {
  std::string out;
  for (size_t i = 0; i < line.size();) {
    size_t n = utf8_length(line, i);
    unsigned char c = static_cast<unsigned char>(line[i]);
    if (n == 0 || (n == 1 && ((c < 0x20 && c != '\t') || c == 0x7f))) {
      out += '?';
      ++i;
    } else {
      out.append(line.substr(i, n));
      i += n;
    }
  }
  return out;
}

// At most this many bytes of a source line are shown, around the caret, so a
// 10 MB one-line file gives a short message.
constexpr size_t kExcerptWidth = 240;

// "   12 |     foo bar\n      |     ^~~\n". Tabs are kept so the caret lines up.
std::string source_excerpt(const SourceSpan& span, const SourceMap& sources, const RenderOptions& options) {
  if (!span.has_location() || span.file >= sources.file_count()) return {};
  LineColumn begin = sources.line_column(span.file, span.begin);
  std::string_view line = sources.line_text(span.file, begin.line);
  if (line.empty() && sources.text(span.file).empty()) return {};
  std::string gutter = fmt::format("{:>5}", begin.line);
  size_t caret_at = std::min<size_t>(begin.column - 1, line.size());
  if (line.size() > kExcerptWidth) {
    size_t start = caret_at > kExcerptWidth / 2 ? caret_at - kExcerptWidth / 2 : 0;
    line = line.substr(start, kExcerptWidth);
    caret_at -= start;
  }
  std::string marker;
  for (size_t i = 0; i < caret_at; ++i) marker += line[i] == '\t' ? '\t' : ' ';
  size_t length = span.end > span.begin ? span.end - span.begin : 1;
  length = std::max<size_t>(1, std::min(length, line.size() > caret_at ? line.size() - caret_at : 1));
  marker += options.color ? "\x1b[1;32m^" : "^";
  marker += std::string(length - 1, '~');
  if (options.color) marker += "\x1b[0m";
  return fmt::format("{} | {}\n{} | {}\n", gutter, printable(line), std::string(gutter.size(), ' '), marker);
}

std::string headline(Severity severity, const SourceSpan& span, const std::string& message,
                     const SourceMap& sources, const RenderOptions& options, std::string_view suffix) {
  std::string where = location_prefix(span, sources);
  if (options.color) {
    return fmt::format("\x1b[1m{}\x1b[0m{}{}:\x1b[0m \x1b[1m{}\x1b[0m{}\n", where, severity_color(severity),
                       severity_word(severity), message, suffix);
  }
  return fmt::format("{}{}: {}{}\n", where, severity_word(severity), message, suffix);
}

}  // namespace

std::string render_text(const Diagnostics& diags, const SourceMap& sources, const RenderOptions& options) {
  std::string out;
  ShownDiagnostics capped = cap_diagnostics(diags);
  for (const Diagnostic& d : capped.shown.all()) {
    for (auto it = d.include_stack.rbegin(); it != d.include_stack.rend(); ++it) {
      if (!it->has_location()) continue;
      LineColumn lc = sources.line_column(it->file, it->begin);
      out += fmt::format("In file included from {}:{}:\n", sources.path(it->file), lc.line);
    }
    std::string suffix;
    std::string_view group = diag_group(d.id);
    if (d.severity == Severity::warning && !group.empty()) suffix += fmt::format(" [-W{}]", group);
    if (d.promoted) suffix += group.empty() ? std::string(" [-Werror]") : fmt::format(" [-Werror,-W{}]", group);
    if (d.variant_total > 1) suffix += fmt::format(" [in {} of {} variants]", d.variant_hits, d.variant_total);
    out += headline(d.severity, d.span, d.message, sources, options, suffix);
    if (options.show_source_line) out += source_excerpt(d.span, sources, options);
    for (const FixIt& fix : d.fixits) {
      if (!fix.replacement.empty()) out += fmt::format("      | fix: replace with '{}'\n", fix.replacement);
    }
    for (const DiagNote& note : d.notes) {
      out += headline(Severity::note, note.span, note.message, sources, options, "");
      if (options.show_source_line && note.span.has_location()) out += source_excerpt(note.span, sources, options);
    }
  }
  if (capped.hidden > 0) out += headline(Severity::note, {}, hidden_summary(capped), sources, options, "");
  return out;
}

namespace {

nlohmann::json location_json(const SourceSpan& span, const SourceMap& sources) {
  nlohmann::json j = nlohmann::json::object();
  if (!span.has_location() || span.file >= sources.file_count()) return j;
  LineColumn b = sources.line_column(span.file, span.begin);
  LineColumn e = sources.line_column(span.file, span.end);
  j["file"] = sources.path(span.file);
  j["line"] = b.line;
  j["column"] = b.column;
  j["end_line"] = e.line;
  j["end_column"] = e.column;
  return j;
}

}  // namespace

std::string render_json(const Diagnostics& diags, const SourceMap& sources) {
  nlohmann::json list = nlohmann::json::array();
  ShownDiagnostics capped = cap_diagnostics(diags);
  for (const Diagnostic& d : capped.shown.all()) {
    nlohmann::json j = location_json(d.span, sources);
    j["id"] = std::string(diag_name(d.id));
    j["severity"] = std::string(severity_word(d.severity));
    j["message"] = d.message;
    j["group"] = std::string(diag_group(d.id));
    if (d.variant_total > 1) j["variants"] = {{"hits", d.variant_hits}, {"total", d.variant_total}};
    nlohmann::json notes = nlohmann::json::array();
    for (const DiagNote& n : d.notes) {
      nlohmann::json nj = location_json(n.span, sources);
      nj["message"] = n.message;
      notes.push_back(std::move(nj));
    }
    j["notes"] = std::move(notes);
    nlohmann::json fixits = nlohmann::json::array();
    for (const FixIt& f : d.fixits) {
      nlohmann::json fj = location_json(f.span, sources);
      fj["replacement"] = f.replacement;
      fixits.push_back(std::move(fj));
    }
    j["fixits"] = std::move(fixits);
    nlohmann::json includes = nlohmann::json::array();
    for (const SourceSpan& s : d.include_stack) includes.push_back(location_json(s, sources));
    j["include_stack"] = std::move(includes);
    list.push_back(std::move(j));
  }
  if (capped.hidden > 0) {
    list.push_back({{"id", "diagnostics_hidden"},
                    {"severity", "note"},
                    {"message", hidden_summary(capped)},
                    {"group", ""},
                    {"hidden", capped.hidden},
                    {"hidden_errors", capped.hidden_errors},
                    {"hidden_warnings", capped.hidden_warnings},
                    {"notes", nlohmann::json::array()},
                    {"fixits", nlohmann::json::array()},
                    {"include_stack", nlohmann::json::array()}});
  }
  return list.dump(2) + "\n";
}

}  // namespace facet
