// Diagnostics as data. Stages append to a Diagnostics list and never print;
// a separate printer renders GCC/Clang-style text or JSON.
//
//   Diagnostics diags;
//   diags.add(DiagId::parse_unexpected_token, span, "expected '{'");
//   if (diags.has_errors()) ...
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "facet/source.h"

namespace facet {

enum class Severity : uint8_t { note, warning, error };

// Every diagnostic has a stable id. The tables live in facet/diag/*.def, one
// file per stage: FACET_DIAG(name, default severity, warning group).
enum class DiagId : uint16_t {
#define FACET_DIAG(name, severity, group) name,
#include "facet/diag/driver.def"
#include "facet/diag/shaderlab.def"
#include "facet/diag/sema.def"
#include "facet/diag/variants.def"
#include "facet/diag/backend.def"
#include "facet/diag/package.def"
#include "facet/diag/surface.def"
#include "facet/diag/runtime.def"
#undef FACET_DIAG
  count_
};

std::string_view diag_name(DiagId id);          // e.g. "parse_unexpected_token"
Severity diag_default_severity(DiagId id);
std::string_view diag_group(DiagId id);         // "" for errors without a group

struct DiagNote {
  SourceSpan span;  // may have no location
  std::string message;
};

// Replace `span` by `replacement`: an empty span inserts, an empty text removes.
struct FixIt {
  SourceSpan span;
  std::string replacement;
};

struct Diagnostic {
  DiagId id{};
  Severity severity = Severity::error;
  SourceSpan span;
  std::string message;
  std::vector<DiagNote> notes;
  std::vector<FixIt> fixits;
  // Files that included span.file, innermost first ("In file included from").
  std::vector<SourceSpan> include_stack;
  // When the same message came from several variants and was merged:
  // "in N of M variants". Both 0 when not merged.
  uint64_t variant_hits = 0;
  uint64_t variant_total = 0;
  // A warning that -Werror made an error: printed "[-Werror,-W<group>]".
  bool promoted = false;

  Diagnostic& note(SourceSpan s, std::string text) {
    notes.push_back({s, std::move(text)});
    return *this;
  }
  Diagnostic& fix(SourceSpan s, std::string replacement) {
    fixits.push_back({s, std::move(replacement)});
    return *this;
  }
};

// Append-only list of diagnostics that counts errors.
class Diagnostics {
 public:
  // Uses the id's default severity.
  Diagnostic& add(DiagId id, SourceSpan span, std::string message);
  Diagnostic& add(DiagId id, Severity severity, SourceSpan span, std::string message);
  void append(const Diagnostics& other);
  void push(Diagnostic d);

  const std::vector<Diagnostic>& all() const { return items_; }
  std::vector<Diagnostic>& mutable_all() { return items_; }
  size_t size() const { return items_.size(); }
  size_t error_count() const;
  size_t warning_count() const;
  bool has_errors() const { return error_count() > 0; }

 private:
  std::vector<Diagnostic> items_;
};

// The same diagnostics pointing into `to`: each file a span, note, fix-it
// or include-stack entry names in `from` is added to `to`, unless `to`
// already has it with the same path and text (SourceMap::add_file_version).
// For a caller that owns its SourceMap and receives diagnostics made against
// another one (a render's, a failed load's).
Diagnostics rebase_diagnostics(const Diagnostics& diags, const SourceMap& from, SourceMap& to);

// How warnings are treated, as the command line asks (-w, -Werror, -Wno-x).
struct WarningOptions {
  bool suppress_all = false;        // -w
  bool warnings_as_errors = false;  // -Werror
  std::vector<std::string> disabled_groups;  // -Wno-<group>
};

// Drops or promotes warnings as `options` asks, and drops the notes of a
// disabled group; returns the filtered list.
Diagnostics apply_warning_options(const Diagnostics& diags, const WarningOptions& options);

// Merges diagnostics that are identical but for the variant they came from
// into one with variant_hits/variant_total set. Order of first appearance.
Diagnostics merge_variant_duplicates(const std::vector<Diagnostics>& per_variant);

// A flood of diagnostics (a pragma naming thousands of undeclared keywords,
// the same warning from thousands of lines) would bury the one that matters
// and fill a CI log with megabytes. The printers collapse and cap what they
// show; the list itself, and so the exit status, keeps every error.
inline constexpr size_t kMaxShownDiagnostics = 100;  // per render_text / render_json call (facetc: per input)
inline constexpr size_t kMaxEchoedText = 64;         // characters of input text quoted in a message
// Diagnostics with the same id and message are shown this many times (a
// warning at two call sites shows both), the last with "(and N more like it)".
inline constexpr size_t kMaxRepeats = 3;
// A run of this many characters without a space in a message is input text
// echoed back whole (a 100 KB number); the printers shorten it.
inline constexpr size_t kMaxMessageWord = 256;

// `text` when it has at most `max` characters, else its first `max` and
// "..."; for quoting input text (a token, a keyword) in a message.
std::string shorten_echo(std::string_view text, size_t max = kMaxEchoedText);

// What a printer shows of a list.
struct ShownDiagnostics {
  // Of the diagnostics with the same id, severity and message the first
  // kMaxRepeats are shown, the last of them ending "(and N more like it)"
  // when there were more; then at most
  // `max_shown` of those, errors first kept, in their original order; words
  // longer than kMaxMessageWord shortened to kMaxEchoedText.
  Diagnostics shown;
  // What `shown` leaves out past `max_shown` ("and N more diagnostics").
  size_t hidden = 0;
  size_t hidden_errors = 0;
  size_t hidden_warnings = 0;
};
ShownDiagnostics cap_diagnostics(const Diagnostics& diags, size_t max_shown = kMaxShownDiagnostics);

// "and 812 more diagnostics (3 errors, 809 warnings)", the line printed
// after a capped list.
std::string hidden_summary(const ShownDiagnostics& shown);

struct RenderOptions {
  bool color = false;
  bool show_source_line = true;
};

// "file:line:col: error: message" + source line + caret + notes, like GCC;
// capped as cap_diagnostics says, then "facet: note: and N more diagnostics".
std::string render_text(const Diagnostics& diags, const SourceMap& sources, const RenderOptions& options = {});
// A JSON array of objects {id, severity, file, line, column, end_line,
// end_column, message, notes[], fixits[], group, variants}, capped as
// render_text is; a capped list ends with {id: "diagnostics_hidden", severity:
// "note", message: "and N more diagnostics (...)", hidden, hidden_errors,
// hidden_warnings}.
std::string render_json(const Diagnostics& diags, const SourceMap& sources);

}  // namespace facet
