#include "mesh/obj_check.h"

#include <fmt/format.h>

#include <cfloat>
#include <climits>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <vector>

#include "facet/support/text.h"

namespace facet::runtime {
namespace {

struct Word {
  std::string_view text;
  size_t column = 0;  // of its first byte, from 1
};

// Words as tinyobjloader separates them: by spaces and tabs only.
std::vector<Word> split_words(std::string_view line) {
  std::vector<Word> words;
  size_t i = 0;
  while (i < line.size()) {
    if (line[i] == ' ' || line[i] == '\t') {
      ++i;
      continue;
    }
    size_t start = i;
    while (i < line.size() && line[i] != ' ' && line[i] != '\t') ++i;
    words.push_back({line.substr(start, i - start), start + 1});
  }
  return words;
}


bool all_digits(std::string_view s) {
  if (s.empty()) return false;
  for (char c : s)
    if (c < '0' || c > '9') return false;
  return true;
}

// [+-] digits [. digits] | [+-] . digits, then an optional exponent: the
// decimal numbers that tinyobjloader and strtod read alike (no hex, no inf/nan).
bool is_decimal(std::string_view s) {
  if (!s.empty() && (s[0] == '+' || s[0] == '-')) s.remove_prefix(1);
  size_t e = s.find_first_of("eE");
  std::string_view mantissa = s.substr(0, e);
  size_t dot = mantissa.find('.');
  std::string_view whole = mantissa.substr(0, dot);
  std::string_view fraction = dot == std::string_view::npos ? std::string_view() : mantissa.substr(dot + 1);
  if (!(whole.empty() || all_digits(whole)) || !(fraction.empty() || all_digits(fraction))) return false;
  if (whole.empty() && fraction.empty()) return false;
  if (e == std::string_view::npos) return true;
  std::string_view exponent = s.substr(e + 1);
  if (!exponent.empty() && (exponent[0] == '+' || exponent[0] == '-')) exponent.remove_prefix(1);
  return all_digits(exponent);
}

// A coordinate: a decimal number that fits a float (the mesh stores floats;
// inf or NaN would poison the bounds, the normals and the shadow fitting).
std::optional<std::string> coordinate_problem(std::string_view word) {
  if (!is_decimal(word)) return fmt::format("'{}' is not a number", word);
  double value = std::strtod(std::string(word).c_str(), nullptr);
  if (!std::isfinite(value) || std::abs(value) > FLT_MAX) {
    return fmt::format("'{}' is out of range (a coordinate must fit a float, at most {:g})", word, double(FLT_MAX));
  }
  return std::nullopt;
}

// What a face index refers to, for its messages.
struct IndexKind {
  const char* index_name;  // "face index"
  const char* one;         // "vertex"
  const char* many;        // "vertices"
};
constexpr IndexKind kPosition{"face index", "vertex", "vertices"};
constexpr IndexKind kTexcoord{"texture coordinate index", "texture coordinate", "texture coordinates"};
constexpr IndexKind kNormal{"normal index", "normal", "normals"};

// One index of a face corner, 1-based or negative (relative to the last
// element defined so far, -1 being that one), checked against `defined`.
std::optional<std::string> index_problem(std::string_view word, uint64_t defined, const IndexKind& kind) {
  bool negative = !word.empty() && word[0] == '-';
  std::string_view digits = !word.empty() && (word[0] == '-' || word[0] == '+') ? word.substr(1) : word;
  if (!all_digits(digits)) return fmt::format("'{}' is not a {} (expected a whole number)", word, kind.index_name);
  uint64_t magnitude = 0;
  auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), magnitude);
  bool too_large = ec == std::errc::result_out_of_range;
  if (!too_large && magnitude == 0) {
    return fmt::format("{} 0 is not allowed (OBJ counts from 1; -1 is the last one)", kind.index_name);
  }
  if (!too_large && magnitude <= defined) return std::nullopt;
  if (negative) {
    return fmt::format("relative {} {} refers before the first {} (only {} defined so far)", kind.index_name, word,
                       kind.one, count_of(defined, kind.one, kind.many));
  }
  return fmt::format("{} {} refers past the {} defined so far", kind.index_name, word,
                     count_of(defined, kind.one, kind.many));
}

struct Counts {
  uint64_t positions = 0, texcoords = 0, normals = 0;
  uint64_t faces = 0, triangle_corners = 0;
};

std::optional<ObjProblem> at(const Word& word, std::string why) { return ObjProblem{0, word.column, std::move(why)}; }

// v/vt/vn: at least `min` numbers (a trailing # comment is allowed, as
// tinyobjloader ignores what follows the numbers it reads).
std::optional<ObjProblem> check_element(const std::vector<Word>& words, size_t min, const char* what, uint64_t& count,
                                        const ObjLimits& limits) {
  size_t numbers = 0;
  for (size_t i = 1; i < words.size(); ++i) {
    if (words[i].text[0] == '#') break;
    if (auto why = coordinate_problem(words[i].text)) return at(words[i], *why);
    ++numbers;
  }
  if (numbers < min) return at(words[0], fmt::format("{} needs {} numbers, this one has {}", what, min, numbers));
  if (++count > limits.max_elements) return at(words[0], fmt::format("more than {} {} lines", limits.max_elements, words[0].text));
  return std::nullopt;
}

// vw VERTEX JOINT WEIGHT ...: tinyobjloader's skin weights, which facet
// does not use but tinyobjloader reads, converting each joint number to an
// int unchecked (1e30 is undefined behaviour): every number must fit one.
std::optional<ObjProblem> check_skin_weights(const std::vector<Word>& words) {
  if (words.size() < 2) return at(words[0], "a skin weight line needs a vertex index");
  for (size_t i = 1; i < words.size(); ++i) {
    if (!is_decimal(words[i].text)) return at(words[i], fmt::format("'{}' is not a number", words[i].text));
    double value = std::strtod(std::string(words[i].text).c_str(), nullptr);
    if (!std::isfinite(value) || std::abs(value) > double(INT_MAX)) {
      return at(words[i], fmt::format("'{}' is out of range (the numbers of a skin weight line must fit an int, at "
                                      "most {})",
                                      words[i].text, INT_MAX));
    }
  }
  return std::nullopt;
}

// One corner: v, v/vt, v//vn or v/vt/vn.
std::optional<ObjProblem> check_corner(const Word& word, const Counts& counts) {
  std::string_view text = word.text;
  size_t first = text.find('/');
  size_t second = first == std::string_view::npos ? first : text.find('/', first + 1);
  if (second != std::string_view::npos && text.find('/', second + 1) != std::string_view::npos) {
    return at(word, fmt::format("'{}' is not a face corner (expected v, v/vt, v//vn or v/vt/vn)", text));
  }
  struct Part {
    std::string_view text;
    size_t offset;
    const IndexKind* kind;
    uint64_t defined;
  };
  std::vector<Part> parts = {{text.substr(0, first), 0, &kPosition, counts.positions}};
  if (first != std::string_view::npos) {
    size_t uv_end = second == std::string_view::npos ? text.size() : second;
    std::string_view uv = text.substr(first + 1, uv_end - first - 1);
    if (!uv.empty() || second == std::string_view::npos) parts.push_back({uv, first + 1, &kTexcoord, counts.texcoords});
    if (second != std::string_view::npos) parts.push_back({text.substr(second + 1), second + 1, &kNormal, counts.normals});
  }
  for (const Part& part : parts) {
    Word at_part{part.text, word.column + part.offset};
    if (part.text.empty()) return at(at_part, fmt::format("missing {} in '{}'", part.kind->index_name, text));
    if (auto why = index_problem(part.text, part.defined, *part.kind)) return at(at_part, *why);
  }
  return std::nullopt;
}

std::optional<ObjProblem> check_face(const std::vector<Word>& words, Counts& counts, const ObjLimits& limits) {
  size_t corners = words.size() - 1;
  if (corners < 3) return at(words[0], fmt::format("a face needs at least 3 corners, this one has {}", corners));
  if (corners > limits.max_face_corners) {
    return at(words[0], fmt::format("a face of {} corners (at most {} are supported)", corners, limits.max_face_corners));
  }
  for (size_t i = 1; i < words.size(); ++i) {
    if (auto problem = check_corner(words[i], counts)) return problem;
  }
  counts.triangle_corners += 3 * (corners - 2);
  if (counts.triangle_corners > limits.max_triangle_corners) {
    return at(words[0], fmt::format("the mesh has more than {} triangle corners (the limit of one OBJ mesh)",
                                    limits.max_triangle_corners));
  }
  ++counts.faces;
  return std::nullopt;
}

std::optional<ObjProblem> check_line(std::string_view line, Counts& counts, const ObjLimits& limits) {
  std::vector<Word> words = split_words(line);
  if (words.empty()) return std::nullopt;
  std::string_view keyword = words[0].text;
  if (keyword == "v") return check_element(words, 3, "a vertex", counts.positions, limits);
  if (keyword == "vt") return check_element(words, 1, "a texture coordinate", counts.texcoords, limits);
  if (keyword == "vn") return check_element(words, 3, "a normal", counts.normals, limits);
  if (keyword == "f") return check_face(words, counts, limits);
  if (keyword == "vw") return check_skin_weights(words);
  return std::nullopt;  // comments, groups, materials, lines and points: nothing the mesh reads
}

}  // namespace

std::optional<ObjProblem> check_obj_text(std::string_view text, const ObjLimits& limits) {
  if (text.size() > limits.max_file_bytes) {
    return ObjProblem{0, 0, fmt::format("the file has {} bytes, more than the {} an OBJ mesh may have", text.size(),
                                        limits.max_file_bytes)};
  }
  Counts counts;
  size_t line_number = 1, start = 0;
  while (start <= text.size()) {
    size_t end = text.find_first_of("\r\n", start);
    if (end == std::string_view::npos) end = text.size();
    if (std::optional<ObjProblem> problem = check_line(text.substr(start, end - start), counts, limits)) {
      problem->line = line_number;
      return problem;
    }
    if (end == text.size()) break;
    start = end + (text[end] == '\r' && end + 1 < text.size() && text[end + 1] == '\n' ? 2 : 1);
    ++line_number;
  }
  if (counts.faces == 0) return ObjProblem{0, 0, "the OBJ file has no faces (an empty mesh)"};
  return std::nullopt;
}

}  // namespace facet::runtime
