#include "info_log.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <optional>
#include <string_view>

#include "names_in_scope.h"
#include "facet/support/text.h"

namespace facet::backend {
namespace {

constexpr std::string_view kIncludeFailure = "Could not process include directive for header name:";

bool is_ident_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

// Splits "'tok' : message" into token and message.
void split_token(std::string_view body, LogMessage& m) {
  body = trim(body);
  if (body.size() >= 2 && body.front() == '\'') {
    size_t close = body.find("' :", 1);
    if (close != std::string_view::npos) {
      m.token = std::string(body.substr(1, close - 1));
      m.text = std::string(trim(body.substr(close + 3)));
      return;
    }
  }
  m.text = std::string(body);
}

bool is_digit(char c) { return c >= '0' && c <= '9'; }

// Length of the run of digits at `pos`.
size_t digits_at(std::string_view s, size_t pos) {
  size_t n = 0;
  while (pos + n < s.size() && is_digit(s[pos + n])) ++n;
  return n;
}

// "2 compilation errors.  No code generated."
bool is_noise(std::string_view rest) {
  size_t n = digits_at(rest, 0);
  if (n == 0) return false;
  std::string_view after = rest.substr(n);
  return after.starts_with(" compilation error.") || after.starts_with(" compilation errors.");
}

// Hand-written matchers for glslang's two located line forms (std::regex
// recurses per character and can exhaust the stack on long lines).
struct Located {
  std::string file;
  uint32_t line = 0;
  uint32_t column = 0;
  std::string text;
};

// "FILE:LINE: TEXT", FILE being the shortest prefix that makes it match.
// A line glslang's int counter wrapped ("FILE:-2: ") or one of nine digits
// and more is no position: the message keeps its text, without a location.
std::optional<Located> match_located(std::string_view s) {
  for (size_t colon = s.find(':'); colon != std::string_view::npos; colon = s.find(':', colon + 1)) {
    if (colon + 1 < s.size() && s[colon + 1] == '-') {
      size_t wrapped = digits_at(s, colon + 2);
      if (wrapped > 0 && s.substr(colon + 2 + wrapped).starts_with(": ")) {
        return Located{"", 0, 0, std::string(s.substr(colon + 2 + wrapped + 2))};
      }
    }
    size_t n = digits_at(s, colon + 1);
    if (n == 0 || n >= 9) continue;
    size_t end = colon + 1 + n;
    if (s.substr(end).starts_with(": ")) {
      return Located{std::string(s.substr(0, colon)), uint32_t(std::stoul(std::string(s.substr(colon + 1, n)))), 0,
                     std::string(s.substr(end + 2))};
    }
  }
  return std::nullopt;
}

// "FILE(LINE): error at column COL, TEXT"
std::optional<Located> match_parse_failed(std::string_view s) {
  constexpr std::string_view marker = "): error at column ";
  size_t at = s.rfind(marker);
  if (at == std::string_view::npos) return std::nullopt;
  size_t open = s.rfind('(', at);
  if (open == std::string_view::npos || digits_at(s, open + 1) != at - open - 1 || at == open + 1) return std::nullopt;
  size_t col_begin = at + marker.size();
  size_t n = digits_at(s, col_begin);
  if (n == 0 || n >= 9 || !s.substr(col_begin + n).starts_with(", ") || at - open - 1 >= 9) return std::nullopt;
  return Located{std::string(s.substr(0, open)), uint32_t(std::stoul(std::string(s.substr(open + 1, at - open - 1)))),
                 uint32_t(std::stoul(std::string(s.substr(col_begin, n)))),
                 std::string(s.substr(col_begin + n + 2))};
}

// Byte position of `token` in `line`, whole words only for identifiers.
std::optional<size_t> find_token(std::string_view line, std::string_view token) {
  if (token.empty()) return std::nullopt;
  bool ident = std::all_of(token.begin(), token.end(), is_ident_char);
  for (size_t pos = line.find(token); pos != std::string_view::npos; pos = line.find(token, pos + 1)) {
    if (!ident) return pos;
    bool left_ok = pos == 0 || !is_ident_char(line[pos - 1]);
    size_t end = pos + token.size();
    bool right_ok = end >= line.size() || !is_ident_char(line[end]);
    if (left_ok && right_ok) return pos;
  }
  return std::nullopt;
}

std::string clean_types(std::string text) {
  // glslang spells types of temporaries as "' temp 3-component vector of float'".
  for (std::string_view noise : {"' temp ", "' const ", "' in ", "' uniform "}) {
    for (size_t pos = text.find(noise); pos != std::string::npos; pos = text.find(noise, pos + 1)) {
      text.replace(pos, noise.size(), "'");
    }
  }
  return text;
}

std::string format_message(const LogMessage& m) {
  if (m.text == "Expected") return fmt::format("expected '{}'", m.token);
  std::string text = clean_types(m.text);
  // Diagnostics start in lower case ("Could not ..." -> "could not ...").
  if (text.size() > 1 && std::isupper(static_cast<unsigned char>(text[0])) &&
      std::islower(static_cast<unsigned char>(text[1]))) {
    text[0] = char(std::tolower(static_cast<unsigned char>(text[0])));
  }
  if (m.token.empty()) return text.empty() ? std::string("shader compilation failed") : text;
  return fmt::format("'{}': {}", m.token, text);
}

bool is_entry_point_message(std::string_view text) {
  return text.find("Missing entry point") != std::string_view::npos ||
         text.find("Entry point not found") != std::string_view::npos;
}

class LogMapper {
 public:
  LogMapper(LogContext& context, Diagnostics& diags) : ctx_(context), diags_(diags) {}

  void report(const LogMessage& m) {
    if (is_entry_point_message(m.text)) return report_missing_entry();
    FileId file = resolve_file(m.file);
    SourceSpan span = file != kNoFile && m.line > 0 ? locate(file, m) : SourceSpan{};
    if (m.text.starts_with(kIncludeFailure)) return report_missing_include(m, span, file);
    std::string message = format_message(m);
    if (m.severity == Severity::error) {
      std::string_view line = file != kNoFile && m.line > 0 ? ctx_.sources.line_text(file, m.line) : "";
      if (auto undeclared = undeclared_identifier_message(m.token, m.text, ctx_.program_text, line)) {
        message = std::move(*undeclared);
      }
    }
    if (file == kNoFile && !m.file.empty()) message = fmt::format("{}:{}: {}", m.file, m.line, message);
    DiagId id = m.severity == Severity::error ? ctx_.error_id : DiagId::shader_compiler_warning;
    Diagnostic& d = diags_.add(id, m.severity, span, std::move(message));
    d.include_stack = include_stack(m.file);
  }

 private:
  FileId resolve_file(const std::string& name) {
    if (name.empty()) return kNoFile;
    if (name == ctx_.source.root_name) return ctx_.shader_file;
    if (name == kPreludeName) return prelude_file();
    return ctx_.sources.find(name).value_or(kNoFile);
  }

  FileId prelude_file() {
    if (prelude_ == kNoFile) prelude_ = ctx_.sources.add_file(kPreludeName, ctx_.source.prelude);
    return prelude_;
  }

  SourceSpan locate(FileId file, const LogMessage& m) const {
    std::string_view line = ctx_.sources.line_text(file, m.line);
    uint32_t start = ctx_.sources.offset_of(file, m.line, 1);
    std::string_view token = m.token;
    if (m.text.starts_with(kIncludeFailure)) token = trim(std::string_view(m.text).substr(kIncludeFailure.size()));
    if (m.text != "Expected") {
      if (auto pos = find_token(line, token)) {
        return {file, start + uint32_t(*pos), start + uint32_t(*pos + token.size())};
      }
    }
    size_t col = m.column > 0 ? std::min<size_t>(m.column - 1, line.size()) : line.find_first_not_of(" \t");
    if (col == std::string_view::npos) col = 0;
    // glslang's parse-failure column is the last character of the token.
    while (m.column > 0 && col > 0 && col < line.size() && is_ident_char(line[col]) && is_ident_char(line[col - 1])) {
      --col;
    }
    uint32_t at = start + uint32_t(col);
    // glslang notices a missing ';' at the next token; it belongs after the
    // previous one, as Clang points it.
    if (m.text == "Expected" && m.token == ";") {
      at = m.column > 0 ? end_of_previous_token(ctx_.sources.text(file), at)
                        : missing_semicolon(ctx_.sources.text(file), start, line);
    }
    return {file, at, at};
  }

  // Where a ';' is missing on `line` (which starts at `start`), glslang
  // giving no column: before a '}' that does not follow a ';', '{' or '}'
  // ("return x }"), else after the token before the line when that token
  // ends no statement ("float4 c = 1" on the line above), else the line's
  // first token.
  static uint32_t missing_semicolon(std::string_view text, uint32_t start, std::string_view line) {
    std::string_view code = line.substr(0, line.find("//"));
    for (size_t brace = code.find('}'); brace != std::string_view::npos; brace = code.find('}', brace + 1)) {
      size_t before = code.find_last_not_of(" \t", brace == 0 ? std::string_view::npos : brace - 1);
      if (brace == 0 || before == std::string_view::npos) continue;
      if (code[before] != ';' && code[before] != '{' && code[before] != '}') return start + uint32_t(before + 1);
    }
    size_t first = line.find_first_not_of(" \t");
    uint32_t first_token = start + uint32_t(first == std::string_view::npos ? 0 : first);
    uint32_t previous_end = end_of_previous_token(text, start);
    if (previous_end < start && previous_end > 0) {
      char last = text[previous_end - 1];
      if (last != ';' && last != '{' && last != '}') return previous_end;
    }
    return first_token;
  }

  // Where the token before `pos` ends, skipping spaces, line breaks and
  // comments ("x = 1 // one" ends after "1").
  static uint32_t end_of_previous_token(std::string_view text, uint32_t pos) {
    size_t end = std::min<size_t>(pos, text.size());
    while (end > 0) {
      size_t line_begin = text.rfind('\n', end - 1);
      line_begin = line_begin == std::string_view::npos ? 0 : line_begin + 1;
      std::string_view line = text.substr(line_begin, end - line_begin);
      if (size_t comment = line.find("//"); comment != std::string_view::npos) line = line.substr(0, comment);
      size_t last = line.find_last_not_of(" \t\r");
      if (last != std::string_view::npos && line.substr(0, last + 1).ends_with("*/")) {
        size_t open = text.rfind("/*", line_begin + last);
        if (open == std::string_view::npos) return pos;
        end = open;
        continue;
      }
      if (last != std::string_view::npos) return uint32_t(line_begin + last + 1);
      if (line_begin == 0) return pos;
      end = line_begin - 1;  // the previous line, without its '\n'
    }
    return pos;
  }

  // The `#include` of `header` in the program's own text, for a message
  // whose file glslang names after a `#line "name"` directive (no file of
  // the SourceMap): the span of the name, or none.
  SourceSpan include_in_program(const std::string& header) const {
    std::vector<const ir::SourceChunk*> chunks;
    for (const ir::SourceChunk& c : ctx_.program.includes) chunks.push_back(&c);
    chunks.push_back(&ctx_.program.body);
    for (const ir::SourceChunk* chunk : chunks) {
      if (!chunk->span.has_location()) continue;
      std::string_view text = chunk->text;
      for (size_t line = 0; line < text.size();) {
        size_t eol = std::min(text.find('\n', line), text.size());
        if (auto name = included_name_at(text.substr(line, eol - line), header)) {
          uint32_t begin = chunk->span.begin + uint32_t(line + *name);
          return {chunk->span.file, begin, begin + uint32_t(header.size())};
        }
        line = eol + 1;
      }
    }
    return {};
  }

  // Where `header` begins on `line` when the line is `#include "header"` or
  // `#include <header>` (spaces allowed around '#').
  static std::optional<size_t> included_name_at(std::string_view line, const std::string& header) {
    size_t at = line.find_first_not_of(" \t");
    if (at == std::string_view::npos || line[at] != '#') return std::nullopt;
    at = line.find_first_not_of(" \t", at + 1);
    if (at == std::string_view::npos || line.substr(at, 7) != "include") return std::nullopt;
    at = line.find_first_not_of(" \t", at + 7);
    if (at == std::string_view::npos || (line[at] != '"' && line[at] != '<')) return std::nullopt;
    const char close = line[at] == '"' ? '"' : '>';
    if (line.substr(at + 1, header.size()) != header ||
        line.substr(at + 1 + header.size(), 1) != std::string(1, close)) {
      return std::nullopt;
    }
    return at + 1;
  }

  void report_missing_include(const LogMessage& m, SourceSpan span, FileId file) {
    std::string header(trim(std::string_view(m.text).substr(kIncludeFailure.size())));
    if (!span.has_location() && !header.empty()) {
      span = include_in_program(header);
      file = span.has_location() ? span.file : kNoFile;
    }
    if (span.has_location() && span.begin > 0 && file != kNoFile) {
      const std::string& text = ctx_.sources.text(file);
      // Widen the span over the quotes or angle brackets around the name.
      if (span.end < text.size() && (text[span.begin - 1] == '"' || text[span.begin - 1] == '<')) {
        span.begin -= 1;
        span.end += 1;
      }
    }
    if (const IncludeRefusal* refusal = ctx_.includer.refusal(header)) return report_refusal(*refusal, span, m.file);
    Diagnostic& d = diags_.add(DiagId::backend_include_not_found, span, fmt::format("include file '{}' not found", header));
    std::vector<std::string> dirs = ctx_.includer.search_dirs(m.file);
    std::string list;
    // The folder of a shader named without one is the current folder.
    for (const std::string& dir : dirs) list += (list.empty() ? "" : ", ") + fmt::format("'{}'", dir.empty() ? "." : dir);
    d.note({}, list.empty() ? std::string("no include directories to search") : "searched " + list);
    d.include_stack = include_stack(m.file);
  }

  // An include that was found but refused: at the reason inside the file
  // when there is one (included from the #include), else at the #include.
  // A program-wide budget is reported once.
  void report_refusal(const IncludeRefusal& refusal, SourceSpan directive, const std::string& includer) {
    if (refusal.budget && budget_reported_) return;
    budget_reported_ |= refusal.budget;
    std::vector<SourceSpan> stack = include_stack(includer);
    SourceSpan span = directive;
    if (!refusal.path.empty()) {
      FileId file = ctx_.sources.add_file_once(refusal.path, refusal.text);
      uint32_t at = uint32_t(std::min(refusal.offset, refusal.text.size()));
      span = {file, at, at + (at < refusal.text.size() ? 1u : 0u)};
      stack.insert(stack.begin(), directive);
    }
    Diagnostic& d = diags_.add(refusal.id, span, refusal.message);
    if (!refusal.note.empty()) d.note({}, refusal.note);
    d.include_stack = std::move(stack);
  }

  void report_missing_entry() {
    if (entry_reported_) return;
    entry_reported_ = true;
    const std::string& entry = ctx_.program.entry_points[size_t(ctx_.stage)];
    diags_.add(DiagId::backend_compile_error, entry_pragma_span(ctx_.program, ctx_.stage),
               fmt::format("{} entry point '{}' is not defined", stage_name(ctx_.stage), entry));
  }

  // Span of the `#include` line in `includer` that names `requested`.
  SourceSpan include_directive(const std::string& includer, const std::string& requested) {
    auto search = [&](FileId file, uint32_t begin, uint32_t end) -> std::optional<SourceSpan> {
      const std::string& text = ctx_.sources.text(file);
      end = std::min<uint32_t>(end, uint32_t(text.size()));
      for (uint32_t pos = begin; pos < end;) {
        size_t eol = text.find('\n', pos);
        uint32_t line_end = eol == std::string::npos ? uint32_t(text.size()) : uint32_t(eol);
        std::string_view line(text.data() + pos, line_end - pos);
        size_t hash = line.find('#');
        if (hash != std::string_view::npos && line.find("include", hash) != std::string_view::npos) {
          if (auto at = find_token(line, requested)) {
            return SourceSpan{file, pos + uint32_t(hash), pos + uint32_t(*at + requested.size() + 1)};
          }
        }
        pos = line_end + 1;
      }
      return std::nullopt;
    };
    if (includer == ctx_.source.root_name) {
      if (ctx_.shader_file != kNoFile) {
        for (const ir::SourceChunk& chunk : ctx_.program.includes) {
          if (auto s = search(ctx_.shader_file, chunk.span.begin, chunk.span.end)) return *s;
        }
        const SourceSpan& body = ctx_.program.body.span;
        if (auto s = search(ctx_.shader_file, body.begin, body.end)) return *s;
      }
      FileId prelude = prelude_file();
      return search(prelude, 0, UINT32_MAX).value_or(SourceSpan{prelude, 0, 0});
    }
    if (auto file = ctx_.sources.find(includer)) {
      return search(*file, 0, UINT32_MAX).value_or(SourceSpan{*file, 0, 0});
    }
    return {};
  }

  // Innermost first: where the file was included, where that file was, ...
  std::vector<SourceSpan> include_stack(const std::string& file) {
    std::vector<SourceSpan> stack;
    std::string current = file;
    for (size_t depth = 0; depth < 64; ++depth) {
      const auto& records = ctx_.includer.records();
      auto it = std::find_if(records.begin(), records.end(), [&](const IncludeRecord& r) { return r.path == current; });
      if (it == records.end()) break;
      stack.push_back(include_directive(it->includer, it->requested));
      if (it->includer == current) break;
      current = it->includer;
    }
    return stack;
  }

  LogContext& ctx_;
  Diagnostics& diags_;
  FileId prelude_ = kNoFile;
  bool entry_reported_ = false;
  bool budget_reported_ = false;
};

}  // namespace

std::vector<LogMessage> parse_info_log(std::string_view log) {
  static const std::vector<std::pair<std::string_view, Severity>> prefixes = {
      {"ERROR: ", Severity::error},          {"WARNING: ", Severity::warning},
      {"INTERNAL ERROR: ", Severity::error}, {"UNIMPLEMENTED: ", Severity::error},
      {"NOTE: ", Severity::note}};
  std::vector<LogMessage> out;
  size_t pos = 0;
  while (pos < log.size()) {
    size_t eol = log.find('\n', pos);
    if (eol == std::string_view::npos) eol = log.size();
    std::string line(trim(log.substr(pos, eol - pos)));
    pos = eol + 1;
    if (line.empty()) continue;
    auto prefix = std::find_if(prefixes.begin(), prefixes.end(), [&](const auto& p) { return line.starts_with(p.first); });
    if (prefix == prefixes.end()) {
      if (auto failed = match_parse_failed(line)) {
        LogMessage m;
        m.file = std::move(failed->file);
        m.line = failed->line;
        m.column = failed->column;
        m.text = std::move(failed->text);
        m.parse_failed_marker = true;
        out.push_back(std::move(m));
      } else if (!out.empty()) {
        out.back().text += " " + line;  // a continuation line
      }
      continue;
    }
    std::string rest = line.substr(prefix->first.size());
    if (is_noise(rest)) continue;
    LogMessage m;
    m.severity = prefix->second;
    if (auto located = match_located(rest)) {
      m.file = std::move(located->file);
      m.line = located->line;
      split_token(located->text, m);
    } else {
      split_token(rest, m);
    }
    out.push_back(std::move(m));
  }
  return out;
}

void report_info_log(std::string_view log, LogContext& context, Diagnostics& diags) {
  std::vector<LogMessage> messages = parse_info_log(log);
  auto same_place = [](const LogMessage& a, const LogMessage& b) { return a.file == b.file && a.line == b.line; };
  // "error at column N, HLSL parsing failed" lends its column to the messages
  // of its line and is dropped; alone, it becomes a syntax error.
  for (const LogMessage& marker : messages) {
    if (!marker.parse_failed_marker) continue;
    for (LogMessage& m : messages) {
      if (!m.parse_failed_marker && same_place(m, marker) && m.column == 0) m.column = marker.column;
    }
  }
  size_t real_errors = std::count_if(messages.begin(), messages.end(), [](const LogMessage& m) {
    return !m.parse_failed_marker && m.severity == Severity::error && m.text != "compilation terminated";
  });
  // glslang's HLSL parser stops at the first declaration it cannot finish;
  // what it reports after that (stray '#' in the rest of an include, "syntax
  // error" at the end) is noise. Keep the first error's line only.
  bool parse_failed = std::any_of(messages.begin(), messages.end(), [](const LogMessage& m) {
    return m.parse_failed_marker;
  });
  auto first_error = std::find_if(messages.begin(), messages.end(), [](const LogMessage& m) {
    return !m.parse_failed_marker && m.severity == Severity::error && m.text != "compilation terminated";
  });
  LogMapper mapper(context, diags);
  for (LogMessage& m : messages) {
    bool cascade = parse_failed && first_error != messages.end() && m.severity == Severity::error &&
                   !same_place(m, *first_error);
    if (cascade) continue;
    if (m.parse_failed_marker) {
      bool covered = std::any_of(messages.begin(), messages.end(),
                                 [&](const LogMessage& o) { return !o.parse_failed_marker && same_place(o, m); });
      if (covered) continue;
      m.text = "syntax error";
    }
    if (m.text == "compilation terminated" && real_errors > 0) continue;
    // Follow-on complaints after the first error of a line: the parser's
    // "expected ..." and messages without a token of their own, and any
    // error after a name that does not resolve (the expression it was in
    // has no type, as Clang treats it).
    bool follow_on = m.severity == Severity::error &&
                     std::any_of(messages.begin(), messages.end(), [&](const LogMessage& o) {
                       bool unresolved = o.text == "unknown variable" || o.text == "no matching overloaded function found";
                       return &o < &m && !o.parse_failed_marker && o.severity == Severity::error &&
                              same_place(o, m) && !m.file.empty() &&
                              (m.text == "Expected" || m.token.empty() || unresolved);
                     });
    if (follow_on) continue;
    mapper.report(m);
  }
}

void add_included_files(const FileIncluder& includer, SourceMap& sources) {
  for (const IncludeRecord& record : includer.records()) {
    if (sources.find(record.path)) continue;
    if (const std::string* text = includer.text_of(record.path)) sources.add_file_once(record.path, *text);
  }
}

SourceSpan entry_pragma_span(const ir::Program& program, Stage stage) {
  for (const ir::Pragma& pragma : program.pragmas) {
    if (pragma.name == stage_name(stage)) return pragma.span;
  }
  return program.body.span;
}

}  // namespace facet::backend
