// A coarse reading of top-level declarations: it only has to find the two
// forms below in text glslang is about to parse, and says nothing about
// anything it does not understand.
#include "global_declarations.h"

#include <fmt/format.h>

#include <algorithm>
#include <map>
#include <optional>
#include <set>
#include <utility>
#include <vector>

namespace facet::backend {
namespace {

bool ident_start(char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_'; }
bool ident_char(char c) { return ident_start(c) || (c >= '0' && c <= '9'); }
bool digit(char c) { return c >= '0' && c <= '9'; }

struct Token {
  enum Kind { ident, number, punct } kind;
  std::string_view text;
  size_t file;  // index into the file names
  uint32_t line;
};

struct Tokens {
  std::vector<Token> list;
  std::vector<std::string> files{""};
};

// `#line N "file"`: the next line is line N of that file.
void read_line_directive(std::string_view line, Tokens& out, size_t& file, uint32_t& next_line) {
  size_t n = line.find_first_not_of(" \t", 5);
  if (n == std::string_view::npos || !digit(line[n])) return;
  uint32_t value = 0;
  for (; n < line.size() && digit(line[n]); ++n) value = value * 10 + uint32_t(line[n] - '0');
  next_line = value;
  size_t open = line.find('"', n), close = open == std::string_view::npos ? open : line.find('"', open + 1);
  if (close == std::string_view::npos) return;
  out.files.emplace_back(line.substr(open + 1, close - open - 1));
  file = out.files.size() - 1;
}

Tokens tokenize(std::string_view text) {
  Tokens out;
  size_t file = 0;
  uint32_t line = 1;
  for (size_t begin = 0; begin <= text.size();) {
    size_t end = std::min(text.find('\n', begin), text.size());
    std::string_view l = text.substr(begin, end - begin);
    size_t first = l.find_first_not_of(" \t\r");
    uint32_t next = line + 1;
    if (first != std::string_view::npos && l[first] == '#') {
      if (l.substr(first, 5) == "#line") read_line_directive(l.substr(first), out, file, next);
    } else {
      for (size_t i = 0; i < l.size();) {
        char c = l[i];
        size_t j = i + 1;
        Token::Kind kind = Token::punct;
        if (ident_start(c)) {
          while (j < l.size() && ident_char(l[j])) ++j;
          kind = Token::ident;
        } else if (digit(c) || (c == '.' && j < l.size() && digit(l[j]))) {
          while (j < l.size() && (ident_char(l[j]) || l[j] == '.')) ++j;
          kind = Token::number;
        } else if (c == '"') {
          j = l.find('"', j);
          j = j == std::string_view::npos ? l.size() : j + 1;
        } else if (c == ' ' || c == '\t' || c == '\r') {
          i = j;
          continue;
        }
        out.list.push_back({kind, l.substr(i, j - i), file, line});
        i = j;
      }
    }
    line = next;
    begin = end + 1;
  }
  return out;
}

// half and the min-precision types are float to glslang, matrix and vector
// their 4-wide forms.
std::string normalized_type(std::string_view type) {
  for (std::string_view alias : {"min16float", "min10float", "half"}) {
    if (type.starts_with(alias)) return "float" + std::string(type.substr(alias.size()));
  }
  if (type == "matrix") return "float4x4";
  if (type == "vector") return "float4";
  return std::string(type);
}

const std::set<std::string_view> kSkipped = {"struct", "typedef", "static", "groupshared", "const", "namespace",
                                             "class", "interface", "cbuffer", "tbuffer", "return"};
const std::set<std::string_view> kQualifiers = {"uniform", "extern", "row_major", "column_major", "precise",
                                                "volatile", "shared", "nointerpolation", "linear", "inline",
                                                "export", "unorm", "snorm", "globallycoherent", "centroid",
                                                "noperspective", "sample"};

struct Declared {
  std::string type;
  size_t file;
  uint32_t line;
};

// Built-in scalar, vector and matrix type names (a cast's or constructor's
// type is not an undeclared identifier).
bool builtin_type(std::string_view name) {
  for (std::string_view scalar : {"min16float", "min10float", "min16uint", "min16int", "min12int", "double", "float",
                                  "fixed", "dword", "half", "uint", "bool", "int"}) {
    if (!name.starts_with(scalar)) continue;
    std::string_view rest = name.substr(scalar.size());
    return rest.empty() || (rest.size() == 1 && digit(rest[0])) ||
           (rest.size() == 3 && digit(rest[0]) && rest[1] == 'x' && digit(rest[2]));
  }
  return name == "vector" || name == "matrix" || name == "true" || name == "false";
}

// Resource object types, which an entry point cannot return.
bool resource_type(std::string_view type) {
  for (std::string_view prefix : {"RW", "Texture", "Buffer", "StructuredBuffer", "ByteAddressBuffer", "Append",
                                  "Consume", "Sampler", "sampler", "ConstantBuffer"}) {
    if (type.starts_with(prefix)) return true;
  }
  return false;
}

class Checker {
 public:
  Checker(const Tokens& tokens, std::string_view entry) : t_(tokens), entry_(entry) {}

  std::optional<DeclarationProblem> run() {
    // Statements at the top level, and the members of cbuffer blocks.
    int depth = 0;
    bool in_cbuffer = false;
    size_t start = 0;
    std::vector<size_t> open;  // the brackets open, innermost last
    std::vector<bool> switch_body;  // per open '{': a switch's body
    bool switch_next = false;       // the next '{' opens a switch's body
    for (size_t i = 0; i < t_.list.size() && !problem_; ++i) {
      std::string_view s = t_.list[i].text;
      if (s == "switch") switch_next = true;
      if (s == "{") switch_body.push_back(std::exchange(switch_next, false));
      if (s == "}" && !switch_body.empty()) switch_body.pop_back();
      if ((s == "case" || (s == "default" && i + 1 < t_.list.size() && at(i + 1).text == ":")) &&
          std::find(switch_body.begin(), switch_body.end(), true) == switch_body.end()) {
        fail(at(i), fmt::format("'{}' outside a switch statement", s));
        break;
      }
      if (s == "return") return_with_condition(i);
      if (at(i).kind == Token::ident) seen_.insert(s);
      if (s == "(" || s == "[" || s == "{") open.push_back(i);
      if (s == ")" || s == "]" || s == "}") {
        static constexpr std::string_view kOpener[] = {"(", "[", "{"};
        std::string_view want = kOpener[s == ")" ? 0 : s == "]" ? 1 : 2];
        if (open.empty() || at(open.back()).text != want) {
          if (!open.empty()) {
            fail(at(i), fmt::format("'{}' does not close the '{}' at line {}", s, at(open.back()).text,
                                    at(open.back()).line));
          } else {
            fail(at(i), fmt::format("'{}' closes nothing", s));
          }
          break;
        }
        open.pop_back();
      }
      if (s == "{") {
        // What comes before a top-level '{' may end in a declaration whose
        // ';' is missing ("float X\nfloat4 vert() {").
        if (depth == 0) statement(start, i);
        bool cbuffer = depth == 0 && start < i && (t_.list[start].text == "cbuffer" || t_.list[start].text == "tbuffer");
        if (depth == 0) in_cbuffer = cbuffer;
        ++depth;
        start = i + 1;
      } else if (s == "}") {
        if (depth > 0) --depth;
        if (depth == 0) in_cbuffer = false;
        start = i + 1;
      } else if (s == ";") {
        if (depth == 0 || (depth == 1 && in_cbuffer)) statement(start, i);
        start = i + 1;
      }
    }
    // The end of the text ends the last statement, and must close every bracket.
    if (!problem_ && depth == 0) statement(start, t_.list.size());
    if (!problem_ && !open.empty()) fail(at(open.back()), fmt::format("'{}' is never closed", at(open.back()).text));
    return problem_;
  }

 private:
  const Token& at(size_t i) const { return t_.list[i]; }

  void fail(const Token& token, std::string message) {
    if (!problem_) problem_ = DeclarationProblem{t_.files[token.file], token.line, std::string(token.text), std::move(message)};
  }

  // glslang's HLSL parser crashes on "return c ? a : X;" where X was never
  // declared: a name in a return's conditional expression that the text has
  // not named before (not a call, a member or a built-in type) is refused as
  // undeclared, as fxc refuses it.
  void return_with_condition(size_t begin) {
    size_t end = begin + 1;
    bool conditional = false;
    for (int nesting = 0; end < t_.list.size(); ++end) {
      std::string_view s = at(end).text;
      nesting += (s == "(" || s == "[" || s == "{") ? 1 : (s == ")" || s == "]" || s == "}") ? -1 : 0;
      if (nesting < 0 || (nesting == 0 && s == ";")) break;
      conditional = conditional || s == "?";
    }
    if (!conditional) return;
    for (size_t k = begin + 1; k < end; ++k) {
      const Token& name = at(k);
      if (name.kind != Token::ident || seen_.count(name.text) || builtin_type(name.text)) continue;
      if (at(k - 1).text == "." || (k + 1 < end && at(k + 1).text == "(")) continue;
      return fail(name, fmt::format("undeclared identifier '{}'", name.text));
    }
  }

  // [qualifiers] TYPE[<...>] NAME [dims] [: ...] [= init] (, NAME ...)* in [begin, end).
  void statement(size_t begin, size_t end) {
    size_t i = begin;
    if (i >= end || at(i).kind != Token::ident) return;
    // A static or const global may be declared again (glslang reports that
    // cleanly), but its array sizes are read as any other.
    bool local = at(i).text == "static" || at(i).text == "const";
    while (i < end && (at(i).text == "static" || at(i).text == "const")) ++i;
    if (i + 1 < end && at(i).text == "struct" && at(i + 1).kind == Token::ident) {
      const Token& name = at(i + 1);
      structs_.emplace(std::string(name.text), Declared{"struct", name.file, name.line});
      known_.insert(name.text);
    }
    if (i >= end || kSkipped.count(at(i).text)) return;
    while (i < end && kQualifiers.count(at(i).text)) ++i;
    if (i >= end || at(i).kind != Token::ident) return;
    std::string type = normalized_type(at(i).text);
    ++i;
    if (i < end && at(i).text == "<") {
      for (int angle = 0; i < end; ++i) {
        type += at(i).text;
        angle += at(i).text == "<" ? 1 : at(i).text == ">" ? -1 : 0;
        if (angle == 0) break;
      }
      ++i;
    }
    while (i < end) {
      if (at(i).kind != Token::ident) return;
      const Token& name = at(i++);
      known_.insert(name.text);
      if (i < end && at(i).text == "(") {
        if (!entry_.empty() && name.text == entry_ && resource_type(type)) {
          return fail(name, fmt::format("the entry point '{}' returns a '{}'; an entry point returns values or "
                                        "structs, not resource objects",
                                        name.text, type));
        }
        // A function's declaration: after its ')' and semantic comes its
        // body or ';'. glslang reads a name or ", name" there as another
        // declarator of the type and crashes when the name is taken
        // ("float4 f(v2f i) appdata {" with a struct appdata, "... :
        // SV_Targe sampler_X;", "... : S, V half S;").
        const size_t open_paren = i;
        for (int paren = 0; i < end; ++i) {
          paren += at(i).text == "(" ? 1 : at(i).text == ")" ? -1 : 0;
          if (paren == 0) break;
        }
        if (name.text == entry_ && i < end) {
          if (std::optional<size_t> unnamed = unnamed_parameter(open_paren + 1, i)) {
            return fail(at(*unnamed), fmt::format("a parameter of the entry point '{}' has no name", name.text));
          }
        }
        ++i;
        if (i + 1 < end && at(i).text == ":" && at(i + 1).kind == Token::ident) i += 2;
        if (i < end) {
          return fail(at(i), fmt::format("unexpected '{}' after the declaration of function '{}'; a function's "
                                         "parameters are followed by its body or ';'",
                                         at(i).text, name.text));
        }
        return;
      }
      std::string dims;
      while (i < end && at(i).text == "[") {
        size_t close = i + 1;
        for (int bracket = 1; close < end; ++close) {
          bracket += at(close).text == "[" ? 1 : at(close).text == "]" ? -1 : 0;
          if (bracket == 0) break;
        }
        // A '{' ends the statement when an initializer list follows.
        // A static const array is initialized even without one.
        bool initialized = (end < t_.list.size() && at(end).text == "{") || local;
        if (std::optional<std::string> problem = array_size_problem(i + 1, close, initialized)) {
          return fail(at(i), *problem);
        }
        for (size_t k = i; k <= close && k < end; ++k) dims += at(k).text;
        i = close + 1;
      }
      if (!local) declare(name, type + dims);
      if (i < end && at(i).kind == Token::ident) continue;  // "float X Y;": glslang reads Y as a declarator too
      // Past the semantic, register or initializer, to the next declarator.
      for (int nesting = 0; i < end; ++i) {
        std::string_view s = at(i).text;
        nesting += (s == "(" || s == "[" || s == "{") ? 1 : (s == ")" || s == "]" || s == "}") ? -1 : 0;
        if (nesting == 0 && s == ",") break;
      }
      ++i;
    }
  }

  // An array size glslang can parse without crashing: no stray character or
  // ',', a start and an end an expression may have, no two operands in a row.
  // The first token of a parameter in [begin, end) (a function's parameter
  // list) that has a type but no name ("uint : SV_VertexID"); glslang's
  // entry-point rewriting crashes on one.
  std::optional<size_t> unnamed_parameter(size_t begin, size_t end) const {
    static const std::set<std::string_view> kParameterQualifiers = {
        "in", "out", "inout", "uniform", "const", "precise", "nointerpolation", "linear", "centroid", "noperspective",
        "sample", "point", "line", "triangle", "lineadj", "triangleadj", "vertices", "indices", "primitives", "payload"};
    for (size_t k = begin; k < end;) {
      size_t first = k;
      while (k < end && kParameterQualifiers.count(at(k).text)) ++k;
      if (k >= end || at(k).kind != Token::ident) return std::nullopt;  // not a form this reads
      ++k;
      for (int angle = 0; k < end && (angle > 0 || at(k).text == "<"); ++k) {
        angle += at(k).text == "<" ? 1 : at(k).text == ">" ? -1 : 0;
      }
      if (at(first).text == "void" && k == first + 1 && k >= end) return std::nullopt;  // "f(void)"
      if (k >= end || at(k).kind != Token::ident) return first;
      for (int nesting = 0; k < end; ++k) {  // to the next parameter
        std::string_view s = at(k).text;
        nesting += (s == "(" || s == "[" || s == "<") ? 1 : (s == ")" || s == "]" || s == ">") ? -1 : 0;
        if (nesting == 0 && s == ",") break;
      }
      ++k;
    }
    return std::nullopt;
  }

  // With an initializer list, or as a static const (`initialized`), glslang
  // also crashes on a size naming something undeclared ("w[C+U] = {...}",
  // "static const float w[C&U];").
  std::optional<std::string> array_size_problem(size_t begin, size_t end, bool initialized) const {
    static const std::set<std::string_view> kStarts = {"(", "-", "+", "!", "~"};
    if (begin < end && at(begin).kind == Token::punct && !kStarts.count(at(begin).text)) {
      return fmt::format("an array size cannot start with '{}'", at(begin).text);
    }
    for (size_t k = begin; k < end; ++k) {
      std::string_view s = at(k).text;
      if (s == "," || s == "\\" || s == "@" || s == "$" || s == "`" || s == "#" || s == "'" || s == "." ||
          s == "=") {
        return fmt::format("an array size holds an unexpected '{}'", s);
      }

      if (k + 1 < end && at(k).kind != Token::punct && at(k + 1).kind != Token::punct) {
        return fmt::format("an array size has two operands in a row, the second '{}'", at(k + 1).text);
      }
    }
    if (begin < end && at(end - 1).kind == Token::punct && at(end - 1).text != ")") {
      return fmt::format("an array size cannot end with '{}'", at(end - 1).text);
    }
    for (size_t k = begin; initialized && k < end; ++k) {
      if (at(k).kind == Token::ident && !known_.count(at(k).text) && !(k + 1 < end && at(k + 1).text == "(")) {
        return fmt::format("undeclared identifier '{}' in the array size", at(k).text);
      }
    }
    return std::nullopt;
  }

  void declare(const Token& name, const std::string& type) {
    if (auto named = structs_.find(std::string(name.text)); named != structs_.end()) {
      return fail(name, fmt::format("redefinition of the struct declared at {}:{}; a global cannot take a "
                                    "struct's name",
                                    t_.files[named->second.file], named->second.line));
    }
    auto [it, inserted] = declared_.emplace(std::string(name.text), Declared{type, name.file, name.line});
    if (inserted || it->second.type == type) return;
    fail(name, fmt::format("redefinition with another type ({} here, {} at {}:{}); a global has one type", type,
                           it->second.type, t_.files[it->second.file], it->second.line));
  }

  const Tokens& t_;
  std::map<std::string, Declared> declared_;
  std::map<std::string, Declared> structs_;  // by name, where declared
  std::set<std::string_view> known_;          // every name declared at the top level so far
  std::set<std::string_view> seen_;           // every name the text has used so far
  std::string_view entry_;
  std::optional<DeclarationProblem> problem_;
};

}  // namespace

std::optional<DeclarationProblem> find_declaration_problem(std::string_view text, std::string_view entry) {
  Tokens tokens = tokenize(text);
  return Checker(tokens, entry).run();
}

std::optional<DeclarationProblem> function_position(std::string_view text, std::string_view name) {
  Tokens tokens = tokenize(text);
  if (name.empty()) {
    if (tokens.list.empty()) return std::nullopt;
    const Token& first = tokens.list.front();
    return DeclarationProblem{tokens.files[first.file], first.line, std::string(first.text), {}};
  }
  int depth = 0;
  for (size_t i = 0; i + 1 < tokens.list.size(); ++i) {
    const Token& t = tokens.list[i];
    if (t.text == "{") ++depth;
    if (t.text == "}") --depth;
    if (depth == 0 && t.kind == Token::ident && t.text == name && tokens.list[i + 1].text == "(") {
      return DeclarationProblem{tokens.files[t.file], t.line, std::string(name), {}};
    }
  }
  return std::nullopt;
}

}  // namespace facet::backend
