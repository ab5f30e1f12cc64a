#include "hlsl_rewrite.h"
#include "facet/support/text.h"

#include <algorithm>
#include <cctype>
#include <optional>
#include <vector>

namespace facet::backend {
namespace {

bool is_ident(char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_'; }

struct Element {
  int row, column;  // 0-based
};

// "_14_24" or "_m03_m13" right after a '.'; nullopt when the word is not a
// matrix swizzle (a member such as "_Color" stays as it is).
std::optional<std::vector<Element>> parse_swizzle(std::string_view word) {
  std::vector<Element> out;
  size_t i = 0;
  while (i < word.size()) {
    if (word[i] != '_' || out.size() == 4) return std::nullopt;
    ++i;
    bool zero_based = i < word.size() && word[i] == 'm';
    if (zero_based) ++i;
    if (i + 2 > word.size()) return std::nullopt;
    char lo = zero_based ? '0' : '1', hi = zero_based ? '3' : '4';
    char r = word[i], c = word[i + 1];
    if (r < lo || r > hi || c < lo || c > hi) return std::nullopt;
    out.push_back({r - lo, c - lo});
    i += 2;
  }
  if (out.empty()) return std::nullopt;
  return out;
}

// The start of the name or member/index chain that ends at `end` (exclusive).
size_t chain_start(std::string_view text, size_t end) {
  size_t i = end;
  while (i > 0) {
    if (text[i - 1] == ']') {  // an index: skip back over its brackets
      int depth = 0;
      size_t j = i;
      while (j > 0) {
        --j;
        if (text[j] == ']') ++depth;
        else if (text[j] == '[' && --depth == 0) break;
      }
      if (depth != 0) return i;
      i = j;
      continue;
    }
    size_t word_end = i;
    while (i > 0 && is_ident(text[i - 1])) --i;
    if (i == word_end) return word_end;
    if (i > 0 && text[i - 1] == '.' && i > 1 && (is_ident(text[i - 2]) || text[i - 2] == ']')) {
      --i;
      continue;
    }
    return i;
  }
  return i;
}

}  // namespace

std::string rewrite_matrix_swizzles(std::string_view text) {
  if (text.find("._") == std::string_view::npos) return std::string(text);
  std::string out;
  out.reserve(text.size());
  size_t copied = 0;
  for (size_t i = 0; i < text.size(); ++i) {
    char c = text[i];
    char next = i + 1 < text.size() ? text[i + 1] : '\0';
    if (c == '/' && next == '/') {
      size_t end = text.find('\n', i);
      i = end == std::string_view::npos ? text.size() : end;
      continue;
    }
    if (c == '/' && next == '*') {
      size_t end = text.find("*/", i + 2);
      i = end == std::string_view::npos ? text.size() : end + 1;
      continue;
    }
    if (c == '"') {
      for (++i; i < text.size() && text[i] != '"' && text[i] != '\n'; ++i) {
        if (text[i] == '\\') ++i;
      }
      continue;
    }
    if (c != '.' || next != '_' || i == 0) continue;
    size_t word_end = i + 1;
    while (word_end < text.size() && is_ident(text[word_end])) ++word_end;
    auto elements = parse_swizzle(text.substr(i + 1, word_end - i - 1));
    if (!elements) continue;
    size_t start = chain_start(text, i);
    if (start == i || start < copied) continue;
    std::string base(text.substr(start, i - start));
    out.append(text.substr(copied, start - copied));
    std::string reads;
    for (const Element& e : *elements) {
      if (!reads.empty()) reads += ", ";
      reads += base + "[" + std::to_string(e.row) + "][" + std::to_string(e.column) + "]";
    }
    out += elements->size() == 1 ? "(" + reads + ")" : "float" + std::to_string(elements->size()) + "(" + reads + ")";
    copied = word_end;
    i = word_end - 1;
  }
  out.append(text.substr(copied));
  return out;
}

namespace {

// One declarator of a top-level declaration: "NAME" or "NAME = INIT".
struct Declarator {
  std::string_view name, init;  // init: "" without one
};

// "[uniform] TYPE D1, D2 = INIT, ...;" at the start of `line`: the type,
// the declarators and what follows the ';'. Initializers may hold commas
// inside brackets; an array declarator, a semantic or a register makes it
// no such declaration.
struct DeclarationLine {
  std::string_view verbatim;  // a static declaration, kept as written
  std::string_view type;
  std::vector<Declarator> declarators;
  std::string_view rest;
};

bool is_identifier(std::string_view s) {
  return !s.empty() && !(s[0] >= '0' && s[0] <= '9') && std::all_of(s.begin(), s.end(), is_ident);
}

std::optional<DeclarationLine> read_declaration(std::string_view line) {
  // The ';' that ends the declaration, outside brackets.
  int depth = 0;
  size_t semicolon = std::string_view::npos;
  std::vector<size_t> commas;
  for (size_t i = 0; i < line.size() && semicolon == std::string_view::npos; ++i) {
    char c = line[i];
    if (c == '/' && i + 1 < line.size() && (line[i + 1] == '/' || line[i + 1] == '*')) return std::nullopt;
    if (c == '"' || c == '{' || c == '}') return std::nullopt;
    if (c == '(' || c == '[') ++depth;
    if (c == ')' || c == ']') --depth;
    if (depth < 0) return std::nullopt;
    if (depth == 0 && c == ',') commas.push_back(i);
    if (depth == 0 && c == ';') semicolon = i;
  }
  if (semicolon == std::string_view::npos || depth != 0) return std::nullopt;
  DeclarationLine out{.rest = line.substr(semicolon + 1)};
  std::string_view statement = trim(line.substr(0, semicolon));
  if (statement.starts_with("static ") || statement.starts_with("static\t")) {
    out.verbatim = trim(line.substr(0, semicolon + 1));
    return out;
  }
  std::string_view head = trim(line.substr(0, commas.empty() ? semicolon : commas[0]));
  std::vector<std::string_view> parts;  // the first declarator's line: [uniform] TYPE NAME [= INIT]
  size_t equals = head.find('=');
  std::string_view words = trim(head.substr(0, equals));
  for (size_t i = 0; i < words.size();) {
    size_t w = words.find_first_not_of(" \t", i);
    if (w == std::string_view::npos) break;
    size_t e = words.find_first_of(" \t", w);
    if (e == std::string_view::npos) e = words.size();
    parts.push_back(words.substr(w, e - w));
    i = e;
  }
  if (!parts.empty() && parts[0] == "uniform") parts.erase(parts.begin());
  if (parts.size() != 2 || !is_identifier(parts[0]) || !is_identifier(parts[1])) return std::nullopt;
  out.type = parts[0];
  out.declarators.push_back(
      {parts[1], equals == std::string_view::npos ? std::string_view() : trim(head.substr(equals + 1))});
  for (size_t k = 0; k < commas.size(); ++k) {
    size_t end = k + 1 < commas.size() ? commas[k + 1] : semicolon;
    std::string_view item = trim(line.substr(commas[k] + 1, end - commas[k] - 1));
    size_t eq = item.find('=');
    std::string_view name = trim(item.substr(0, eq));
    if (!is_identifier(name)) return std::nullopt;
    out.declarators.push_back({name, eq == std::string_view::npos ? std::string_view() : trim(item.substr(eq + 1))});
  }
  return out;
}

// A line of declarations only (a trailing comment is kept), with the
// assigned names of `assigned` rewritten; nullopt when the line is anything
// else or declares none of them. Each declarator gets a declaration of its
// own; an assigned one becomes the uniform (with its initializer: fxc's
// default value) and a static copy of it that the program writes.
template <typename Assigned>
std::optional<std::string> rewrite_declarations(std::string_view line, const Assigned& assigned) {
  std::string out;
  bool any = false;
  std::string_view rest = line;
  while (true) {
    std::optional<DeclarationLine> decl = read_declaration(rest);
    if (!decl) return std::nullopt;
    if (!decl->verbatim.empty()) out += (out.empty() ? "" : " ") + std::string(decl->verbatim);
    std::string type(decl->type);
    for (const Declarator& d : decl->declarators) {
      std::string name(d.name), init = d.init.empty() ? "" : " = " + std::string(d.init);
      if (!out.empty()) out += ' ';
      if (assigned(d.name)) {
        std::string uniform = name + std::string(kAssignedUniformSuffix);
        out += type + " " + uniform + init + "; static " + type + " " + name + " = " + uniform + ";";
        any = true;
      } else {
        out += type + " " + name + init + ";";
      }
    }
    rest = decl->rest;
    std::string_view after = trim(rest);
    if (after.empty() || after.starts_with("//")) break;
  }
  if (!any) return std::nullopt;
  return out + std::string(rest);
}

}  // namespace

std::string rewrite_assigned_uniforms(std::string_view text, const std::vector<std::string>& names) {
  if (names.empty()) return std::string(text);
  auto assigned = [&](std::string_view name) {
    return std::find(names.begin(), names.end(), std::string(name)) != names.end();
  };
  std::string out;
  out.reserve(text.size());
  int depth = 0;
  bool in_block_comment = false;
  size_t line_begin = 0;
  while (line_begin <= text.size()) {
    size_t line_end = text.find('\n', line_begin);
    if (line_end == std::string_view::npos) line_end = text.size();
    std::string_view line = text.substr(line_begin, line_end - line_begin);
    std::optional<std::string> replaced = depth == 0 ? rewrite_declarations(line, assigned) : std::nullopt;
    out += replaced ? *replaced : std::string(line);
    // Braces in comments and strings (`// if (x) {`) do not nest.
    for (size_t i = 0; i < line.size(); ++i) {
      char c = line[i];
      char next = i + 1 < line.size() ? line[i + 1] : '\0';
      if (in_block_comment) {
        if (c == '*' && next == '/') in_block_comment = false, ++i;
      } else if (c == '/' && next == '/') {
        break;
      } else if (c == '/' && next == '*') {
        in_block_comment = true;
        ++i;
      } else if (c == '"') {
        for (++i; i < line.size() && line[i] != '"'; ++i) i += line[i] == '\\';
      } else {
        depth += c == '{' ? 1 : c == '}' ? -1 : 0;
      }
    }
    if (depth < 0) depth = 0;
    if (line_end == text.size()) break;
    out += '\n';
    line_begin = line_end + 1;
  }
  return out;
}

namespace {

constexpr std::string_view kScalarBases[] = {"float", "half", "fixed", "int", "uint", "bool", "double",
                                             "min16float", "min10float", "min16int", "min12int", "min16uint"};

// "float", "half1", "min16float1": a scalar or a one-component vector, which
// glslang makes a scalar.
bool is_scalar_type(std::string_view word) {
  for (std::string_view base : kScalarBases) {
    if (word == base) return true;
    if (word.size() == base.size() + 1 && word.starts_with(base) && word.back() == '1') return true;
  }
  return false;
}

bool is_one_vector_type(std::string_view word) { return is_scalar_type(word) && word.back() == '1'; }

// Words of `text` with their offsets, comments and strings skipped.
struct Word {
  std::string_view text;
  size_t at;
};

std::vector<Word> words_of(std::string_view text) {
  std::vector<Word> out;
  for (size_t i = 0; i < text.size();) {
    char c = text[i], next = i + 1 < text.size() ? text[i + 1] : '\0';
    if (c == '/' && next == '/') {
      size_t end = text.find('\n', i);
      i = end == std::string_view::npos ? text.size() : end;
    } else if (c == '/' && next == '*') {
      size_t end = text.find("*/", i + 2);
      i = end == std::string_view::npos ? text.size() : end + 2;
    } else if (c == '"') {
      for (++i; i < text.size() && text[i] != '"' && text[i] != '\n'; ++i) i += text[i] == '\\';
      ++i;
    } else if (is_ident(c)) {
      size_t start = i;
      while (i < text.size() && is_ident(text[i])) ++i;
      out.push_back({text.substr(start, i - start), start});
    } else {
      ++i;
    }
  }
  return out;
}

// The character after `at` skipping blanks, or '\0'.
char next_char(std::string_view text, size_t at) {
  while (at < text.size() && (text[at] == ' ' || text[at] == '\t' || text[at] == '\n' || text[at] == '\r')) ++at;
  return at < text.size() ? text[at] : '\0';
}

}  // namespace

std::string drop_scalar_swizzles(std::string_view text) {
  std::vector<Word> words = words_of(text);
  // Names declared as a one-component vector somewhere, and names declared
  // with any other type (a declaration: TYPE NAME followed by ; : , = ) [).
  std::vector<std::string_view> one_vectors, others;
  for (size_t k = 0; k + 1 < words.size(); ++k) {
    const Word& type = words[k];
    const Word& name = words[k + 1];
    if (std::isdigit(static_cast<unsigned char>(name.text[0]))) continue;
    if (text.find_first_not_of(" \t\r\n", type.at + type.text.size()) != name.at) continue;  // "TYPE NAME" only
    char after = next_char(text, name.at + name.text.size());
    if (std::string_view(";:,=)[").find(after) == std::string_view::npos || after == '\0') continue;
    (is_one_vector_type(type.text) ? one_vectors : is_scalar_type(type.text) ? one_vectors : others).push_back(name.text);
  }
  // A name after ',' (a later declarator of a list, or an argument), '}'
  // (an instance of a struct) or '>' (vector<float, 4> v) may be anything:
  // its swizzles stay.
  for (const Word& w : words) {
    size_t before = w.at;
    while (before > 0 && (text[before - 1] == ' ' || text[before - 1] == '\t' || text[before - 1] == '\n' ||
                          text[before - 1] == '\r'))
      --before;
    if (before > 0 && (text[before - 1] == ',' || text[before - 1] == '}' || text[before - 1] == '>')) {
      others.push_back(w.text);
    }
  }
  auto rewritable = [&](std::string_view name) {
    bool one = false;
    for (std::string_view n : one_vectors) one = one || (n == name);
    if (!one) return false;
    for (std::string_view n : others)
      if (n == name) return false;
    return true;
  };
  std::string out;
  out.reserve(text.size());
  size_t copied = 0;
  for (const Word& w : words) {
    const size_t end = w.at + w.text.size();
    // NAME.x or NAME.r, the swizzle a whole word.
    if (end + 1 >= text.size() || text[end] != '.' || (text[end + 1] != 'x' && text[end + 1] != 'r')) continue;
    if (end + 2 < text.size() && is_ident(text[end + 2])) continue;
    if (!rewritable(w.text)) continue;
    out.append(text.substr(copied, end - copied));
    out += "  ";  // the swizzle's two characters, so that columns stay where they were
    copied = end + 2;
  }
  out.append(text.substr(copied));
  return out;
}

}  // namespace facet::backend
