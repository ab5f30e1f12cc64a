#include "backend/hlsl_rewrite.h"

#include <algorithm>
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

std::string rewrite_assigned_uniforms(std::string_view text, const std::vector<std::string>& names) {
  if (names.empty()) return std::string(text);
  std::string out;
  out.reserve(text.size());
  int depth = 0;
  size_t line_begin = 0;
  while (line_begin <= text.size()) {
    size_t line_end = text.find('\n', line_begin);
    if (line_end == std::string_view::npos) line_end = text.size();
    std::string_view line = text.substr(line_begin, line_end - line_begin);
    std::string replaced;
    if (depth == 0) {
      // "[uniform] TYPE NAME;" alone on its line (a trailing comment is kept).
      std::vector<std::string_view> words;
      size_t i = 0, semicolon = std::string_view::npos;
      while (i < line.size()) {
        while (i < line.size() && (line[i] == ' ' || line[i] == '\t' || line[i] == '\r')) ++i;
        if (i < line.size() && line[i] == ';') {
          semicolon = i;
          break;
        }
        size_t w = i;
        while (i < line.size() && is_ident(line[i])) ++i;
        if (i == w) break;
        words.push_back(line.substr(w, i - w));
      }
      bool rest_is_comment = semicolon != std::string_view::npos;
      if (rest_is_comment) {
        size_t after = line.find_first_not_of(" \t\r", semicolon + 1);
        rest_is_comment = after == std::string_view::npos || line.substr(after, 2) == "//";
      }
      if (!words.empty() && words[0] == "uniform") words.erase(words.begin());
      if (rest_is_comment && words.size() == 2 &&
          std::find(names.begin(), names.end(), std::string(words[1])) != names.end()) {
        std::string type(words[0]), name(words[1]), uniform = name + std::string(kAssignedUniformSuffix);
        replaced = type + " " + uniform + "; static " + type + " " + name + " = " + uniform + ";" +
                   std::string(line.substr(semicolon + 1));
      }
    }
    out += replaced.empty() ? std::string(line) : replaced;
    for (char c : line) depth += c == '{' ? 1 : c == '}' ? -1 : 0;
    if (depth < 0) depth = 0;
    if (line_end == text.size()) break;
    out += '\n';
    line_begin = line_end + 1;
  }
  return out;
}

}  // namespace facet::backend
