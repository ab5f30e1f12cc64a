// to_half_precision and half_precision_stdlib (facet/backend.h): code written
// for float, compiled for 16-bit arithmetic. A token scan, not a parse: it
// skips comments and strings, renames float type names and suffixes floating
// literals, and copies every other character as it is.
#include <cctype>
#include <filesystem>
#include <string>
#include <string_view>

#include "includer.h"
#include "facet/backend.h"

namespace facet::backend {
namespace {

constexpr const char* kHalfIntrinsics = "FacetHalf.hlsl";

bool identifier_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }
bool digit(char c) { return std::isdigit(static_cast<unsigned char>(c)) != 0; }

// float, float1..4, float1x1..float4x4.
bool float_type_name(std::string_view word) {
  if (!word.starts_with("float")) return false;
  std::string_view rest = word.substr(5);
  if (rest.empty()) return true;
  if (rest.size() == 1) return rest[0] >= '1' && rest[0] <= '4';
  return rest.size() == 3 && rest[0] >= '1' && rest[0] <= '4' && rest[1] == 'x' && rest[2] >= '1' && rest[2] <= '4';
}

// The end of the comment or string that starts at `at`, or `at` when none does.
size_t skip_comment_or_string(std::string_view s, size_t at) {
  if (s.substr(at, 2) == "//") {
    size_t eol = s.find('\n', at);
    return eol == std::string_view::npos ? s.size() : eol;
  }
  if (s.substr(at, 2) == "/*") {
    size_t end = s.find("*/", at + 2);
    return end == std::string_view::npos ? s.size() : end + 2;
  }
  if (s[at] == '"') {
    size_t i = at + 1;
    while (i < s.size() && s[i] != '"' && s[i] != '\n') i += s[i] == '\\' ? 2 : 1;
    return std::min(s.size(), i + 1);
  }
  return at;
}

// A number starting at `at`, copied to `out`; floating ones with the suffix h.
size_t copy_number(std::string_view s, size_t at, std::string& out) {
  size_t i = at;
  if (s.substr(i, 2) == "0x" || s.substr(i, 2) == "0X") {
    for (i += 2; i < s.size() && identifier_char(s[i]);) ++i;
    out += s.substr(at, i - at);
    return i;
  }
  bool floating = false;
  while (i < s.size() && digit(s[i])) ++i;
  if (i < s.size() && s[i] == '.') {
    floating = true;
    for (++i; i < s.size() && digit(s[i]);) ++i;
  }
  if (i < s.size() && (s[i] == 'e' || s[i] == 'E')) {
    size_t e = i + 1;
    if (e < s.size() && (s[e] == '+' || s[e] == '-')) ++e;
    if (e < s.size() && digit(s[e])) {
      floating = true;
      for (i = e; i < s.size() && digit(s[i]);) ++i;
    }
  }
  size_t suffix = i;
  while (i < s.size() && identifier_char(s[i])) ++i;
  std::string_view letters = s.substr(suffix, i - suffix);
  floating |= letters == "f" || letters == "F" || letters == "h" || letters == "H";
  if (floating && (letters.empty() || letters == "f" || letters == "F" || letters == "h" || letters == "H")) {
    out += s.substr(at, suffix - at);
    out += 'h';
  } else {
    out += s.substr(at, i - at);  // integers, doubles (l/L) and anything unusual, as written
  }
  return i;
}

}  // namespace

std::string to_half_precision(std::string_view hlsl) {
  std::string out;
  out.reserve(hlsl.size() + hlsl.size() / 16);
  size_t i = 0;
  while (i < hlsl.size()) {
    if (size_t end = skip_comment_or_string(hlsl, i); end != i) {
      out += hlsl.substr(i, end - i);
      i = end;
    } else if (identifier_char(hlsl[i]) && !digit(hlsl[i])) {
      size_t end = i;
      while (end < hlsl.size() && identifier_char(hlsl[end])) ++end;
      std::string_view word = hlsl.substr(i, end - i);
      if (float_type_name(word)) {
        out += "half";
        out += word.substr(5);
      } else {
        out += word;
      }
      i = end;
    } else if (digit(hlsl[i]) || (hlsl[i] == '.' && i + 1 < hlsl.size() && digit(hlsl[i + 1]))) {
      i = copy_number(hlsl, i, out);
    } else {
      out += hlsl[i++];
    }
  }
  return out;
}

IncludeResolver half_precision_stdlib(const std::string& stdlib_dir) {
  return [stdlib_dir](const std::string& requested, const std::string&) -> std::optional<IncludedFile> {
    std::filesystem::path path = std::filesystem::path(stdlib_dir) / requested;
    std::optional<std::string> text = read_text_file(path.string());
    if (!text) return std::nullopt;
    if (requested == kHalfIntrinsics) return IncludedFile{path.string(), std::move(*text)};
    return IncludedFile{path.string(), to_half_precision(*text)};
  };
}

}  // namespace facet::backend
