#include "facet/diagnostics.h"

#include <algorithm>
#include <array>
#include <map>
#include <tuple>

#include <fmt/format.h>

#include "facet/result.h"

namespace facet {
namespace {

struct DiagInfo {
  std::string_view name;
  Severity severity;
  std::string_view group;
};

constexpr std::array<DiagInfo, size_t(DiagId::count_)> kDiagTable = {{
#define FACET_DIAG(name, severity, group) {#name, Severity::severity, group},
#include "facet/diag/driver.def"
#include "facet/diag/shaderlab.def"
#include "facet/diag/sema.def"
#include "facet/diag/variants.def"
#include "facet/diag/backend.def"
#include "facet/diag/package.def"
#include "facet/diag/surface.def"
#include "facet/diag/runtime.def"
#undef FACET_DIAG
}};

const DiagInfo& info(DiagId id) {
  size_t index = size_t(id);
  if (index >= kDiagTable.size()) FACET_ICE("diagnostic id out of range");
  return kDiagTable[std::min(index, kDiagTable.size() - 1)];
}

}  // namespace

std::string_view diag_name(DiagId id) { return info(id).name; }
Severity diag_default_severity(DiagId id) { return info(id).severity; }
std::string_view diag_group(DiagId id) { return info(id).group; }

Diagnostic& Diagnostics::add(DiagId id, SourceSpan span, std::string message) {
  return add(id, diag_default_severity(id), span, std::move(message));
}

Diagnostic& Diagnostics::add(DiagId id, Severity severity, SourceSpan span, std::string message) {
  Diagnostic d;
  d.id = id;
  d.severity = severity;
  d.span = span;
  d.message = std::move(message);
  items_.push_back(std::move(d));
  return items_.back();
}

void Diagnostics::append(const Diagnostics& other) {
  items_.insert(items_.end(), other.items_.begin(), other.items_.end());
}

void Diagnostics::push(Diagnostic d) { items_.push_back(std::move(d)); }

Diagnostics rebase_diagnostics(const Diagnostics& diags, const SourceMap& from, SourceMap& to) {
  std::map<FileId, FileId> moved;
  auto rebase = [&](SourceSpan& span) {
    if (!span.has_location()) return;
    if (span.file >= from.file_count()) {
      span = {};
      return;
    }
    auto [it, added] = moved.try_emplace(span.file, kNoFile);
    if (added) it->second = to.add_file_version(from.path(span.file), from.text(span.file));
    span.file = it->second;
  };
  Diagnostics out;
  for (Diagnostic d : diags.all()) {
    rebase(d.span);
    for (DiagNote& note : d.notes) rebase(note.span);
    for (FixIt& fix : d.fixits) rebase(fix.span);
    for (SourceSpan& include : d.include_stack) rebase(include);
    out.push(std::move(d));
  }
  return out;
}

size_t Diagnostics::error_count() const {
  return size_t(std::count_if(items_.begin(), items_.end(),
                              [](const Diagnostic& d) { return d.severity == Severity::error; }));
}

size_t Diagnostics::warning_count() const {
  return size_t(std::count_if(items_.begin(), items_.end(),
                              [](const Diagnostic& d) { return d.severity == Severity::warning; }));
}

Diagnostics apply_warning_options(const Diagnostics& diags, const WarningOptions& options) {
  Diagnostics out;
  for (Diagnostic d : diags.all()) {
    std::string_view group = diag_group(d.id);
    bool disabled = !group.empty() && std::find(options.disabled_groups.begin(), options.disabled_groups.end(),
                                                group) != options.disabled_groups.end();
    // -Wno-<group> silences the group's notes too (a note standing alone,
    // like the legacy-command one); a note attached to a message stays with it.
    if (d.severity == Severity::note && disabled) continue;
    if (d.severity == Severity::warning) {
      if (options.suppress_all || disabled) continue;
      if (options.warnings_as_errors) {
        d.severity = Severity::error;
        d.promoted = true;
      }
    }
    out.push(std::move(d));
  }
  return out;
}

namespace {

// Two diagnostics from different variants are "the same" when everything a
// reader sees is the same.
auto identity(const Diagnostic& d) {
  return std::make_tuple(d.id, d.severity, d.span.file, d.span.begin, d.span.end, d.message);
}

}  // namespace

Diagnostics merge_variant_duplicates(const std::vector<Diagnostics>& per_variant) {
  Diagnostics out;
  std::map<decltype(identity(Diagnostic{})), size_t> seen;
  std::vector<uint64_t> hits;
  for (const Diagnostics& list : per_variant) {
    std::map<size_t, bool> counted_here;
    for (const Diagnostic& d : list.all()) {
      auto key = identity(d);
      auto it = seen.find(key);
      if (it == seen.end()) {
        seen.emplace(key, out.size());
        counted_here[out.size()] = true;
        out.push(d);
        hits.push_back(1);
      } else if (!counted_here[it->second]) {
        counted_here[it->second] = true;
        ++hits[it->second];
      }
    }
  }
  auto& items = out.mutable_all();
  for (size_t i = 0; i < items.size(); ++i) {
    if (per_variant.size() > 1) {
      items[i].variant_hits = hits[i];
      items[i].variant_total = per_variant.size();
    }
  }
  return out;
}

std::string shorten_echo(std::string_view text, size_t max) {
  if (text.size() <= max) return std::string(text);
  return std::string(text.substr(0, max)) + "...";
}

namespace {

// `message` with every run of more than kMaxMessageWord non-space
// characters shortened: input text that a stage quoted whole.
std::string shorten_long_words(const std::string& message) {
  std::string out;
  size_t i = 0;
  while (i < message.size()) {
    size_t end = message.find(' ', i);
    if (end == std::string::npos) end = message.size();
    std::string_view word = std::string_view(message).substr(i, end - i);
    out += word.size() > kMaxMessageWord ? shorten_echo(word) : std::string(word);
    if (end < message.size()) out += ' ';
    i = end + 1;
  }
  return out;
}

// The first kMaxRepeats of each (id, severity, message), the last of them
// with how many more there were.
std::vector<std::pair<Diagnostic, size_t>> collapse_repeats(const Diagnostics& diags) {
  std::vector<std::pair<Diagnostic, size_t>> out;
  struct Seen {
    size_t count = 0;
    size_t last_shown = 0;  // index into `out`
  };
  std::map<std::tuple<DiagId, Severity, std::string_view>, Seen> seen;
  for (const Diagnostic& d : diags.all()) {
    Seen& s = seen[std::make_tuple(d.id, d.severity, std::string_view(d.message))];
    if (s.count++ < kMaxRepeats) {
      s.last_shown = out.size();
      out.push_back({d, 0});
    } else {
      ++out[s.last_shown].second;
    }
  }
  return out;
}

}  // namespace

ShownDiagnostics cap_diagnostics(const Diagnostics& diags, size_t max_shown) {
  std::vector<std::pair<Diagnostic, size_t>> unique = collapse_repeats(diags);
  // Errors are kept first, so that a flood of warnings never hides one.
  std::vector<bool> keep(unique.size(), false);
  size_t kept = 0;
  for (bool errors : {true, false}) {
    for (size_t i = 0; i < unique.size() && kept < max_shown; ++i) {
      if (!keep[i] && (unique[i].first.severity == Severity::error) == errors) {
        keep[i] = true;
        ++kept;
      }
    }
  }
  ShownDiagnostics out;
  for (size_t i = 0; i < unique.size(); ++i) {
    auto& [d, more] = unique[i];
    if (!keep[i]) {
      ++out.hidden;
      out.hidden_errors += d.severity == Severity::error;
      out.hidden_warnings += d.severity == Severity::warning;
      continue;
    }
    d.message = shorten_long_words(d.message);
    if (more > 0) d.message += fmt::format(" (and {} more like it)", more);
    out.shown.push(std::move(d));
  }
  return out;
}

std::string hidden_summary(const ShownDiagnostics& shown) {
  return fmt::format("and {} more diagnostic{} ({} error{}, {} warning{})", shown.hidden,
                     shown.hidden == 1 ? "" : "s", shown.hidden_errors, shown.hidden_errors == 1 ? "" : "s",
                     shown.hidden_warnings, shown.hidden_warnings == 1 ? "" : "s");
}

}  // namespace facet
