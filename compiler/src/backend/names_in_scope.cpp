#include "names_in_scope.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <set>

#include "facet/support/suggest.h"

namespace facet::backend {
namespace {

// Sorted, for binary search.
constexpr std::array<std::string_view, 160> kIntrinsics = {
    "AllMemoryBarrier", "AllMemoryBarrierWithGroupSync", "CheckAccessFullyMapped", "D3DCOLORtoUBYTE4",
    "DeviceMemoryBarrier", "DeviceMemoryBarrierWithGroupSync", "EvaluateAttributeAtCentroid",
    "EvaluateAttributeAtSample", "EvaluateAttributeSnapped", "GetRenderTargetSampleCount",
    "GetRenderTargetSamplePosition", "GroupMemoryBarrier", "GroupMemoryBarrierWithGroupSync", "InterlockedAdd",
    "InterlockedAnd", "InterlockedCompareExchange", "InterlockedCompareStore", "InterlockedExchange",
    "InterlockedMax", "InterlockedMin", "InterlockedOr", "InterlockedXor", "NonUniformResourceIndex",
    "Process2DQuadTessFactorsAvg", "Process2DQuadTessFactorsMax", "Process2DQuadTessFactorsMin",
    "ProcessIsolineTessFactors", "ProcessQuadTessFactorsAvg", "ProcessQuadTessFactorsMax",
    "ProcessQuadTessFactorsMin", "ProcessTriTessFactorsAvg", "ProcessTriTessFactorsMax", "ProcessTriTessFactorsMin",
    "QuadReadAcrossDiagonal", "QuadReadAcrossX", "QuadReadAcrossY", "QuadReadLaneAt", "WaveActiveAllEqual",
    "WaveActiveAllTrue", "WaveActiveAnyTrue", "WaveActiveBallot", "WaveActiveBitAnd", "WaveActiveBitOr",
    "WaveActiveBitXor", "WaveActiveCountBits", "WaveActiveMax", "WaveActiveMin", "WaveActiveProduct",
    "WaveActiveSum", "WaveGetLaneCount", "WaveGetLaneIndex", "WaveIsFirstLane", "WavePrefixCountBits",
    "WavePrefixProduct", "WavePrefixSum", "WaveReadLaneAt", "WaveReadLaneFirst", "abort", "abs", "acos", "all",
    "any", "asdouble", "asfloat", "asin", "asint", "asuint", "atan", "atan2", "ceil", "clamp", "clip", "cos",
    "cosh", "countbits", "cross", "ddx", "ddx_coarse", "ddx_fine", "ddy", "ddy_coarse", "ddy_fine", "degrees",
    "determinant", "distance", "dot", "dst", "errorf", "exp", "exp2", "f16tof32", "f32tof16", "faceforward",
    "firstbithigh", "firstbitlow", "floor", "fma", "fmod", "frac", "frexp", "fwidth", "isfinite", "isinf", "isnan",
    "ldexp", "length", "lerp", "lit", "log", "log10", "log2", "mad", "max", "min", "modf", "msad4", "mul",
    "noise", "normalize", "pow", "printf", "radians", "rcp", "reflect", "refract", "reversebits", "round",
    "rsqrt", "saturate", "sign", "sin", "sincos", "sinh", "smoothstep", "sqrt", "step", "tan", "tanh", "tex1D",
    "tex1Dbias", "tex1Dgrad", "tex1Dlod", "tex1Dproj", "tex2D", "tex2Dbias", "tex2Dgrad", "tex2Dlod", "tex2Dproj",
    "tex3D", "tex3Dbias", "tex3Dgrad", "tex3Dlod", "tex3Dproj", "texCUBE", "texCUBEbias", "texCUBEgrad",
    "texCUBElod", "texCUBEproj", "transpose", "trunc",
};
static_assert(std::is_sorted(kIntrinsics.begin(), kIntrinsics.end()) && !kIntrinsics.back().empty());

// Words that read as identifiers but name no variable.
constexpr std::array<std::string_view, 48> kKeywords = {
    "break",    "buffer",   "case",      "cbuffer",      "centroid",  "class",   "column_major", "const",
    "continue", "default",  "discard",   "do",           "else",      "extern",  "false",        "for",
    "groupshared", "if",    "in",        "inline",       "inout",     "interface", "linear",     "matrix",
    "namespace", "nointerpolation", "noperspective", "out", "packoffset", "precise", "register", "return",
    "row_major", "sample",  "sampler",   "shared",       "static",    "string",  "struct",       "switch",
    "tbuffer",  "true",     "typedef",   "uniform",      "vector",    "void",    "volatile",     "while",
};

constexpr std::array<std::string_view, 13> kScalarTypes = {
    "bool", "double", "dword", "fixed", "float", "half", "int", "min10float", "min12int", "min16float",
    "min16int", "min16uint", "uint",
};

bool ident_start(char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_'; }
bool ident_char(char c) { return ident_start(c) || (c >= '0' && c <= '9'); }

bool is_dimension(char c) { return c >= '1' && c <= '4'; }

// "float", "half3", "int2x2": a scalar, vector or matrix type.
bool is_numeric_type(std::string_view word) {
  for (std::string_view scalar : kScalarTypes) {
    if (!word.starts_with(scalar)) continue;
    std::string_view rest = word.substr(scalar.size());
    if (rest.empty() || (rest.size() == 1 && is_dimension(rest[0])) ||
        (rest.size() == 3 && is_dimension(rest[0]) && rest[1] == 'x' && is_dimension(rest[2]))) {
      return true;
    }
  }
  return false;
}

bool is_keyword(std::string_view word) {
  return std::find(kKeywords.begin(), kKeywords.end(), word) != kKeywords.end();
}

// Calls `visit(word, next)` for each identifier of `text` outside comments,
// with the next non-space character after it and the brace depth.
template <typename Visit>
void for_each_identifier(std::string_view text, Visit visit) {
  int depth = 0;
  for (size_t i = 0; i < text.size();) {
    char c = text[i];
    if (c == '/' && i + 1 < text.size() && text[i + 1] == '/') {
      i = std::min(text.size(), text.find('\n', i));
    } else if (c == '/' && i + 1 < text.size() && text[i + 1] == '*') {
      size_t close = text.find("*/", i + 2);
      i = close == std::string_view::npos ? text.size() : close + 2;
    } else if (c == '"') {
      size_t close = text.find('"', i + 1);
      i = close == std::string_view::npos ? text.size() : close + 1;
    } else if (ident_start(c) || (c >= '0' && c <= '9')) {
      size_t j = i;
      while (j < text.size() && ident_char(text[j])) ++j;
      if (ident_start(c)) {
        size_t k = j;
        while (k < text.size() && (text[k] == ' ' || text[k] == '\t' || text[k] == '\n' || text[k] == '\r')) ++k;
        visit(text.substr(i, j - i), k < text.size() ? text[k] : '\0', depth);
      }
      i = j;
    } else {
      depth += c == '{' ? 1 : c == '}' ? -1 : 0;
      ++i;
    }
  }
}

std::string with_suggestion(std::string message, std::string_view token, const std::vector<std::string>& names) {
  std::vector<std::string_view> candidates;
  for (const std::string& n : names) {
    if (n != token) candidates.push_back(n);
  }
  if (auto best = closest_name(token, candidates)) message += fmt::format("; did you mean '{}'?", *best);
  return message;
}

// Whether `token` is read as a member on `line` ("tex.Sampel(", "v.posiiton"):
// a member is not a name in scope.
bool used_as_member(std::string_view line, std::string_view token) {
  for (size_t pos = line.find(token); pos != std::string_view::npos; pos = line.find(token, pos + 1)) {
    bool whole = (pos == 0 || !ident_char(line[pos - 1])) &&
                 (pos + token.size() >= line.size() || !ident_char(line[pos + token.size()]));
    if (!whole) continue;
    size_t before = line.find_last_not_of(" \t", pos == 0 ? std::string_view::npos : pos - 1);
    if (pos > 0 && before != std::string_view::npos && line[before] == '.') return true;
  }
  return false;
}

}  // namespace

bool is_hlsl_intrinsic(std::string_view name) {
  return std::binary_search(kIntrinsics.begin(), kIntrinsics.end(), name);
}

std::vector<std::string> top_level_functions(std::string_view text) {
  std::set<std::string> names;
  for_each_identifier(text, [&](std::string_view word, char next, int depth) {
    if (depth == 0 && next == '(' && !is_keyword(word) && !is_numeric_type(word)) names.emplace(word);
  });
  return {names.begin(), names.end()};
}

std::vector<std::string> variable_like_identifiers(std::string_view text) {
  std::set<std::string> names;
  for_each_identifier(text, [&](std::string_view word, char, int) {
    if (!is_keyword(word) && !is_numeric_type(word) && !is_hlsl_intrinsic(word)) names.emplace(word);
  });
  return {names.begin(), names.end()};
}

std::optional<std::string> undeclared_identifier_message(std::string_view token, std::string_view text,
                                                         std::string_view program, std::string_view line) {
  if (program.empty() || token.empty() || !ident_start(token[0]) ||
      !std::all_of(token.begin(), token.end(), ident_char) || used_as_member(line, token)) {
    return std::nullopt;
  }
  std::string message = fmt::format("use of undeclared identifier '{}'", token);
  if (text == "unknown variable") return with_suggestion(message, token, variable_like_identifiers(program));
  if (text != "no matching overloaded function found") return std::nullopt;
  if (is_hlsl_intrinsic(token) || is_numeric_type(token) || is_keyword(token)) return std::nullopt;
  std::vector<std::string> functions = top_level_functions(program);
  if (std::binary_search(functions.begin(), functions.end(), token)) return std::nullopt;
  // A struct's name called as a constructor is not a function either, but
  // it is declared: glslang's message stands.
  bool is_struct = false;
  std::string_view previous;
  for_each_identifier(program, [&](std::string_view word, char, int) {
    is_struct |= previous == "struct" && word == token;
    previous = word;
  });
  if (is_struct) return std::nullopt;
  functions.insert(functions.end(), kIntrinsics.begin(), kIntrinsics.end());
  return with_suggestion(message, token, functions);
}

}  // namespace facet::backend
