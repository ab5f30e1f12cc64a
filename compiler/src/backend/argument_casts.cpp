#include "argument_casts.h"

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <optional>
#include <set>
#include <string_view>

namespace facet::backend {
namespace {

constexpr std::string_view kNoOverload = "no matching overloaded function found";
constexpr std::string_view kSwitchNotInteger = "condition must be a scalar integer expression";

bool is_ident(char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_'; }

bool is_word_at(std::string_view text, size_t at, std::string_view word) {
  return text.substr(at, word.size()) == word && (at == 0 || !is_ident(text[at - 1])) &&
         (at + word.size() >= text.size() || !is_ident(text[at + word.size()]));
}

size_t skip_space(std::string_view text, size_t i) {
  while (i < text.size() && (text[i] == ' ' || text[i] == '\t' || text[i] == '\r' || text[i] == '\n')) ++i;
  return i;
}

// The index of the ')' closing the '(' at `open`, npos when unbalanced.
size_t matching_paren(std::string_view text, size_t open) {
  int depth = 0;
  for (size_t i = open; i < text.size(); ++i) {
    if (text[i] == '(') ++depth;
    else if (text[i] == ')' && --depth == 0) return i;
  }
  return std::string_view::npos;
}

// Byte ranges of the comma-separated pieces of (begin, end), at depth 0.
std::vector<std::pair<size_t, size_t>> split_arguments(std::string_view text, size_t begin, size_t end) {
  std::vector<std::pair<size_t, size_t>> out;
  int depth = 0;
  size_t start = begin;
  for (size_t i = begin; i < end; ++i) {
    char c = text[i];
    if (c == '(' || c == '[' || c == '{') ++depth;
    else if (c == ')' || c == ']' || c == '}') --depth;
    else if (c == ',' && depth == 0) {
      out.push_back({start, i});
      start = i + 1;
    }
  }
  if (skip_space(text, start) < end || !out.empty()) out.push_back({start, end});
  return out;
}

// "float3", "half", "min16float2", "int4": a type an argument can be cast to
// by truncation; nullopt for structs, matrices, textures.
bool is_castable(std::string_view type) {
  for (std::string_view base : {"float", "half", "fixed", "int", "uint", "bool", "double", "min16float",
                                "min10float", "min16int", "min16uint"}) {
    if (!type.starts_with(base)) continue;
    std::string_view rest = type.substr(base.size());
    if (rest.empty() || (rest.size() == 1 && rest[0] >= '1' && rest[0] <= '4')) return true;
  }
  return false;
}

struct Param {
  std::string type;  // "" when the argument stays as it is
};

// The parameter lists of every definition "TYPE name(...) [: SEMANTIC] {".
std::vector<std::vector<Param>> definitions_of(const std::vector<const ir::SourceChunk*>& chunks,
                                               std::string_view name) {
  static const std::set<std::string_view> kQualifiers = {"in", "const", "uniform", "inline", "static", "precise",
                                                         "linear", "centroid", "nointerpolation", "noperspective",
                                                         "sample", "row_major", "column_major"};
  std::vector<std::vector<Param>> out;
  for (const ir::SourceChunk* chunk : chunks) {
    std::string_view text = chunk->text;
    for (size_t at = text.find(name); at != std::string_view::npos; at = text.find(name, at + 1)) {
      if (!is_word_at(text, at, name)) continue;
      // A definition: a type word before the name.
      size_t before = at;
      while (before > 0 && (text[before - 1] == ' ' || text[before - 1] == '\t')) --before;
      if (before == 0 || !is_ident(text[before - 1])) continue;
      size_t open = skip_space(text, at + name.size());
      if (open >= text.size() || text[open] != '(') continue;
      size_t close = matching_paren(text, open);
      if (close == std::string_view::npos) continue;
      size_t after = skip_space(text, close + 1);
      if (after < text.size() && text[after] == ':') {  // a return semantic
        after = skip_space(text, after + 1);
        while (after < text.size() && is_ident(text[after])) ++after;
        after = skip_space(text, after);
      }
      if (after >= text.size() || text[after] != '{') continue;
      std::vector<Param> params;
      for (auto [b, e] : split_arguments(text, open + 1, close)) {
        std::vector<std::string> words;
        for (size_t i = b; i < e;) {
          i = skip_space(text, i);
          size_t w = i;
          while (i < e && is_ident(text[i])) ++i;
          if (i == w) {
            ++i;
            continue;
          }
          words.emplace_back(text.substr(w, i - w));
        }
        std::erase_if(words, [&](const std::string& w) { return kQualifiers.count(w) > 0; });
        bool writes = std::find(words.begin(), words.end(), "out") != words.end() ||
                      std::find(words.begin(), words.end(), "inout") != words.end();
        Param p;
        if (!writes && !words.empty() && is_castable(words[0])) p.type = words[0];
        params.push_back(std::move(p));
      }
      if (params.size() == 1 && split_arguments(text, open + 1, close).empty()) params.clear();
      out.push_back(std::move(params));
    }
  }
  return out;
}

size_t line_start(std::string_view text, uint32_t line_in_chunk) {
  size_t pos = 0;
  for (uint32_t l = 0; l < line_in_chunk && pos != std::string_view::npos; ++l) {
    pos = text.find('\n', pos);
    if (pos != std::string_view::npos) ++pos;
  }
  return pos;
}

// The offsets of the calls of `name` ("name (") that start on the line at `from`.
std::vector<size_t> calls_on_line(std::string_view text, size_t from, std::string_view name) {
  std::vector<size_t> out;
  size_t line_end = text.find('\n', from);
  if (line_end == std::string_view::npos) line_end = text.size();
  for (size_t at = text.find(name, from); at != std::string_view::npos && at < line_end; at = text.find(name, at + 1)) {
    if (!is_word_at(text, at, name)) continue;
    size_t open = skip_space(text, at + name.size());
    if (open < text.size() && text[open] == '(') out.push_back(at);
  }
  return out;
}

// Casts the arguments of every call of `name` that starts on the line at
// `from`; returns the ordinals (among calls_on_line) of the calls rewritten.
std::vector<size_t> cast_calls_on_line(std::string& text, size_t from, std::string_view name,
                                       const std::vector<std::vector<Param>>& definitions) {
  std::vector<size_t> rewritten;
  std::vector<size_t> calls = calls_on_line(text, from, name);
  // Back to front, so that the earlier calls' offsets stay valid.
  for (size_t ordinal = calls.size(); ordinal-- > 0;) {
    size_t at = calls[ordinal];
    size_t open = skip_space(text, at + name.size());
    size_t close = matching_paren(text, open);
    if (close == std::string::npos) continue;
    auto args = split_arguments(text, open + 1, close);
    const std::vector<Param>* params = nullptr;
    for (const auto& d : definitions) {
      if (d.size() != args.size()) continue;
      if (params) return rewritten;  // two definitions of this arity: no guess
      params = &d;
    }
    if (!params) continue;
    bool changed = false;
    for (size_t i = args.size(); i-- > 0;) {
      if ((*params)[i].type.empty()) continue;
      auto [b, e] = args[i];
      text.insert(e, ")");
      text.insert(b, "(" + (*params)[i].type + ")(");
      changed = true;
    }
    if (changed) rewritten.push_back(ordinal);
  }
  return rewritten;
}

uint32_t line_count(std::string_view text) { return uint32_t(std::count(text.begin(), text.end(), '\n')) + 1; }

}  // namespace

std::vector<CastCall> cast_rejected_calls(ir::Program& program, const std::string& root_name,
                                          const std::vector<LogMessage>& messages,
                                          const std::map<std::string, std::string>& included) {
  std::vector<ir::SourceChunk*> chunks;
  for (ir::SourceChunk& c : program.includes) chunks.push_back(&c);
  chunks.push_back(&program.body);
  // Definitions: in the program's chunks and the files it includes.
  std::vector<const ir::SourceChunk*> readonly(chunks.begin(), chunks.end());
  std::vector<ir::SourceChunk> files;
  files.reserve(included.size());
  for (const auto& [path, text] : included) files.push_back({text, {}, 1, path});
  for (const ir::SourceChunk& f : files) readonly.push_back(&f);
  // The texts as written: spans are computed in them, not in the rewrites.
  std::vector<std::string> originals;
  for (const ir::SourceChunk* c : chunks) originals.push_back(c->text);
  std::vector<CastCall> out;
  std::set<std::pair<std::string, uint32_t>> done;
  for (const LogMessage& m : messages) {
    if (m.severity != Severity::error || m.token.empty() || m.text.find(kNoOverload) == std::string::npos) continue;
    if (!done.insert({m.token, m.line}).second) continue;
    for (size_t c = 0; c < chunks.size(); ++c) {
      ir::SourceChunk* chunk = chunks[c];
      bool same_file = chunk->line_file.empty() ? m.file == root_name : m.file == chunk->line_file;
      if (!same_file || m.line < chunk->first_line || m.line >= chunk->first_line + line_count(chunk->text)) continue;
      auto definitions = definitions_of(readonly, m.token);
      if (definitions.empty()) break;
      size_t from = line_start(chunk->text, m.line - chunk->first_line);
      size_t original_from = line_start(originals[c], m.line - chunk->first_line);
      if (from == std::string::npos || original_from == std::string::npos) break;
      std::vector<size_t> written = calls_on_line(originals[c], original_from, m.token);
      std::vector<size_t> ordinals = cast_calls_on_line(chunk->text, from, m.token, definitions);
      std::sort(ordinals.begin(), ordinals.end());
      for (size_t ordinal : ordinals) {
        if (ordinal >= written.size()) continue;
        uint32_t begin = uint32_t(chunk->span.begin + written[ordinal]);
        out.push_back({m.token, SourceSpan{chunk->span.file, begin, uint32_t(begin + m.token.size())}});
      }
      break;
    }
  }
  return out;
}

namespace {

// The float literal labels of the switch body whose '{' is at `open`
// (`case 1.0:`, `case 2.5f:`) become integers, as fxc converts them: glslang
// would find "duplicated value" once the condition is an int. Lengths are
// kept with spaces, so later offsets on the line hold.
bool integer_case_labels(std::string& text, size_t open) {
  bool changed = false;
  int depth = 0;
  for (size_t i = open; i < text.size(); ++i) {
    if (text[i] == '{') ++depth;
    if (text[i] == '}' && --depth == 0) return changed;
    if (depth != 1 || !is_word_at(text, i, "case")) continue;
    size_t begin = skip_space(text, i + 4), end = begin;
    while (end < text.size() && (is_ident(text[end]) || text[end] == '.' || text[end] == '-' || text[end] == '+')) ++end;
    std::string_view label(text.data() + begin, end - begin);
    bool is_float = !label.empty() && (std::isdigit(static_cast<unsigned char>(label[0])) || label[0] == '.' ||
                                       label[0] == '-') &&
                    label.find_first_of(".eEfF") != std::string_view::npos;
    if (!is_float) continue;
    char* parsed = nullptr;
    std::string literal(label);
    if (!literal.empty() && (literal.back() == 'f' || literal.back() == 'F')) literal.pop_back();
    double value = std::strtod(literal.c_str(), &parsed);
    if (parsed != literal.c_str() + literal.size()) continue;
    std::string integer = std::to_string(static_cast<long long>(value));
    integer.resize(std::max(integer.size(), label.size()), ' ');
    text.replace(begin, label.size(), integer);
    changed = true;
    i = begin + integer.size() - 1;
  }
  return changed;
}

// The switch whose "switch" word is at `at` becomes "switch ((int)(x))"
// (unless it is already), and its float case labels integers; false when
// nothing changed (a switch on an int with two equal labels stays an error).
bool cast_switch_at(std::string& text, size_t at) {
  size_t open = skip_space(text, at + 6);
  size_t close = open < text.size() && text[open] == '(' ? matching_paren(text, open) : std::string::npos;
  if (close == std::string::npos) return false;
  bool changed = false;
  if (text.compare(open + 1, 6, "(int)(") != 0) {
    text.insert(close, ")");
    text.insert(open + 1, "(int)(");
    close += 7;  // the original ')', past the ")" and "(int)(" just inserted
    changed = true;
  }
  size_t body = skip_space(text, close + 1);
  if (body < text.size() && text[body] == '{') changed |= integer_case_labels(text, body);
  return changed;
}

// "switch (x)" on the 0-based line `line` of `text`: cast_switch_at; false
// when the line holds no such switch.
bool cast_switch_on_line(std::string& text, uint32_t line) {
  size_t from = line_start(text, line);
  size_t end = from == std::string::npos ? from : text.find('\n', from);
  if (end == std::string::npos) end = text.size();
  for (size_t at = text.find("switch", from); at != std::string::npos && at < end; at = text.find("switch", at + 1)) {
    if (is_word_at(text, at, "switch")) return cast_switch_at(text, at);
  }
  return false;
}

// The innermost switch whose body holds the 0-based line `line` (a "case"
// glslang names): cast_switch_at; false when there is none.
bool cast_switch_around_line(std::string& text, uint32_t line) {
  size_t target = line_start(text, line);
  if (target == std::string::npos) return false;
  for (size_t at = text.rfind("switch", target); at != std::string::npos && at > 0; at = text.rfind("switch", at - 1)) {
    if (!is_word_at(text, at, "switch")) continue;
    size_t open = skip_space(text, at + 6);
    size_t close = open < text.size() && text[open] == '(' ? matching_paren(text, open) : std::string::npos;
    size_t body = close == std::string::npos ? close : skip_space(text, close + 1);
    if (body >= text.size() || text[body] != '{') continue;
    int depth = 0;
    size_t end = body;
    for (; end < text.size(); ++end) {
      if (text[end] == '{') ++depth;
      if (text[end] == '}' && --depth == 0) break;
    }
    if (target > body && target < end) return cast_switch_at(text, at);
  }
  return false;
}

bool is_float_switch_error(const LogMessage& m) {
  return m.severity == Severity::error && m.token == "switch" && m.text.find(kSwitchNotInteger) != std::string::npos;
}

// glslang converts float case labels of a switch on a float and may find
// them equal ("case 0.0:" and "case 1.0:"): the switch is cast where fxc
// would have converted it.
bool is_float_case_error(const LogMessage& m) {
  return m.severity == Severity::error && m.token == "case" && m.text.find("duplicated value") != std::string::npos;
}

// Casts the switch a message names, in `text` whose 0-based line `line` it names.
bool cast_switch_of(const LogMessage& m, std::string& text, uint32_t line) {
  return is_float_switch_error(m) ? cast_switch_on_line(text, line) : cast_switch_around_line(text, line);
}

}  // namespace

size_t cast_float_switches(ir::Program& program, const std::string& root_name, const std::vector<LogMessage>& messages) {
  std::vector<ir::SourceChunk*> chunks;
  for (ir::SourceChunk& c : program.includes) chunks.push_back(&c);
  chunks.push_back(&program.body);
  size_t cast = 0;
  std::set<std::pair<std::string, uint32_t>> done;
  for (const LogMessage& m : messages) {
    if ((!is_float_switch_error(m) && !is_float_case_error(m)) || !done.insert({m.file, m.line}).second) continue;
    for (ir::SourceChunk* chunk : chunks) {
      bool same_file = chunk->line_file.empty() ? m.file == root_name : m.file == chunk->line_file;
      if (!same_file || m.line < chunk->first_line || m.line >= chunk->first_line + line_count(chunk->text)) continue;
      cast += cast_switch_of(m, chunk->text, m.line - chunk->first_line);
      break;
    }
  }
  return cast;
}

size_t cast_float_switches_in_includes(std::map<std::string, std::string>& texts,
                                       const std::map<std::string, std::string>& current,
                                       const std::vector<LogMessage>& messages) {
  size_t cast = 0;
  std::set<std::pair<std::string, uint32_t>> done;
  for (const LogMessage& m : messages) {
    bool relevant = is_float_switch_error(m) || is_float_case_error(m);
    if (!relevant || m.line == 0 || !done.insert({m.file, m.line}).second) continue;
    auto source = current.find(m.file);
    if (source == current.end()) continue;
    if (!texts.count(m.file)) texts[m.file] = source->second;
    cast += cast_switch_of(m, texts[m.file], m.line - 1);
  }
  return cast;
}

std::vector<CastCall> cast_rejected_calls_in_includes(std::map<std::string, std::string>& texts,
                                                      const std::map<std::string, std::string>& current,
                                                      const ir::Program& program,
                                                      const std::vector<LogMessage>& messages,
                                                      const SourceMap& sources) {
  std::vector<CastCall> out;
  std::set<std::pair<std::string, uint32_t>> done;
  for (const LogMessage& m : messages) {
    if (m.severity != Severity::error || m.token.empty() || m.text.find(kNoOverload) == std::string::npos) continue;
    auto source = current.find(m.file);
    std::optional<FileId> id = sources.find(m.file);
    if (source == current.end() || !id || !done.insert({m.token, m.line}).second) continue;
    if (!texts.count(m.file)) texts[m.file] = source->second;
    // Definitions: in the program's chunks and every included file.
    std::vector<ir::SourceChunk> files;
    for (const auto& [path, text] : current) files.push_back({texts.count(path) ? texts[path] : text, {}, 1, path});
    std::vector<const ir::SourceChunk*> scope;
    for (const ir::SourceChunk& c : program.includes) scope.push_back(&c);
    scope.push_back(&program.body);
    for (const ir::SourceChunk& f : files) scope.push_back(&f);
    auto definitions = definitions_of(scope, m.token);
    if (definitions.empty()) continue;
    std::string& text = texts[m.file];
    const std::string& original = sources.text(*id);
    size_t from = line_start(text, m.line - 1), original_from = line_start(original, m.line - 1);
    if (from == std::string::npos || original_from == std::string::npos) continue;
    std::vector<size_t> written = calls_on_line(original, original_from, m.token);
    std::vector<size_t> ordinals = cast_calls_on_line(text, from, m.token, definitions);
    std::sort(ordinals.begin(), ordinals.end());
    for (size_t ordinal : ordinals) {
      if (ordinal >= written.size()) continue;
      uint32_t begin = uint32_t(written[ordinal]);
      out.push_back({m.token, SourceSpan{*id, begin, uint32_t(begin + m.token.size())}});
    }
  }
  return out;
}

}  // namespace facet::backend
