#include "scene/json_locate.h"

#include <cctype>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <variant>
#include <vector>

namespace facet::runtime {
namespace {

constexpr int kMaxDepth = 512;  // deeper documents are refused by the reader before any message locates into them

using Step = std::variant<std::string, size_t>;  // a member's key or an element's index

std::optional<std::vector<Step>> parse_path(std::string_view path) {
  std::vector<Step> steps;
  size_t i = 0;
  while (i < path.size()) {
    if (path[i] == '[') {
      size_t close = path.find(']', i);
      if (close == std::string_view::npos || close == i + 1) return std::nullopt;
      size_t index = 0;
      for (size_t d = i + 1; d < close; ++d) {
        if (!std::isdigit(static_cast<unsigned char>(path[d]))) return std::nullopt;
        index = index * 10 + size_t(path[d] - '0');
      }
      steps.emplace_back(index);
      i = close + 1;
      if (i < path.size() && path[i] == '.') ++i;
    } else {
      size_t end = path.find_first_of(".[", i);
      if (end == std::string_view::npos) end = path.size();
      steps.emplace_back(std::string(path.substr(i, end - i)));
      i = end < path.size() && path[end] == '.' ? end + 1 : end;
    }
  }
  return steps;
}

struct Scanner {
  std::string_view text;
  size_t at = 0;

  void skip_space() {
    while (at < text.size() && (text[at] == ' ' || text[at] == '\t' || text[at] == '\n' || text[at] == '\r')) ++at;
  }
  bool take(char c) {
    skip_space();
    if (at < text.size() && text[at] == c) {
      ++at;
      return true;
    }
    return false;
  }
  // A string's contents with the simple escapes decoded (a key the reader
  // names is ASCII); false when the text has no string here.
  bool string(std::string* out) {
    skip_space();
    if (at >= text.size() || text[at] != '"') return false;
    for (++at; at < text.size(); ++at) {
      char c = text[at];
      if (c == '"') {
        ++at;
        return true;
      }
      if (c == '\\' && at + 1 < text.size()) c = text[++at];
      if (out) out->push_back(c);
    }
    return false;
  }
  bool value(int depth) {
    skip_space();
    if (at >= text.size() || depth > kMaxDepth) return false;
    char c = text[at];
    if (c == '"') return string(nullptr);
    if (c == '{' || c == '[') {
      const char close = c == '{' ? '}' : ']';
      ++at;
      if (take(close)) return true;
      do {
        if (c == '{' && !(string(nullptr) && take(':'))) return false;
        if (!value(depth + 1)) return false;
      } while (take(','));
      return take(close);
    }
    size_t start = at;
    while (at < text.size() && !std::strchr(",]} \t\r\n", text[at])) ++at;
    return at > start;
  }
};

std::optional<JsonExtent> find(Scanner& s, const std::vector<Step>& steps, size_t next, int depth) {
  s.skip_space();
  if (next == steps.size()) {
    size_t begin = s.at;
    if (!s.value(depth)) return std::nullopt;
    return JsonExtent{begin, s.at};
  }
  if (depth > kMaxDepth) return std::nullopt;
  if (const std::string* key = std::get_if<std::string>(&steps[next])) {
    if (!s.take('{') || s.take('}')) return std::nullopt;
    // Of a key given twice the reader keeps the last value: so does this.
    std::optional<size_t> last;
    do {
      std::string name;
      if (!s.string(&name) || !s.take(':')) return std::nullopt;
      s.skip_space();
      if (name == *key) last = s.at;
      if (!s.value(depth + 1)) return std::nullopt;
    } while (s.take(','));
    if (!last) return std::nullopt;
    s.at = *last;
    return find(s, steps, next + 1, depth + 1);
  }
  const size_t index = std::get<size_t>(steps[next]);
  if (!s.take('[') || s.take(']')) return std::nullopt;
  size_t i = 0;
  do {
    if (i++ == index) return find(s, steps, next + 1, depth + 1);
    if (!s.value(depth + 1)) return std::nullopt;
  } while (s.take(','));
  return std::nullopt;
}

// The scene file's text; nullopt when it is not a regular file of at most
// a scene's size (load_scene's 64 MiB) or cannot be read.
std::optional<std::string> read_scene_text(const std::string& path) {
  constexpr uintmax_t kMaxSceneBytes = uintmax_t(64) << 20;
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) return std::nullopt;
  if (uintmax_t size = std::filesystem::file_size(path, ec); ec || size > kMaxSceneBytes) return std::nullopt;
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  if (!in && !in.eof()) return std::nullopt;
  return std::move(text).str();
}

}  // namespace

std::optional<JsonExtent> locate_json_value(std::string_view text, std::string_view path) {
  std::optional<std::vector<Step>> steps = parse_path(path);
  if (!steps) return std::nullopt;
  Scanner scanner{text};
  if (text.starts_with("\xEF\xBB\xBF")) scanner.at = 3;  // a UTF-8 byte order mark, which the reader skips
  return find(scanner, *steps, 0, 0);
}

SourceSpan scene_value_span(SourceMap& sources, const std::string& scene_path, std::string_view path) {
  if (scene_path.empty()) return {};
  // Read now, so that a scene edited since it was loaded is located in its
  // text of today (a version `sources` holds already is reused); a file that
  // cannot be read is located in the text `sources` has under its name.
  std::optional<FileId> file;
  if (std::optional<std::string> text = read_scene_text(scene_path)) {
    file = sources.add_file_version(scene_path, std::move(*text));
  } else {
    file = sources.find(scene_path);
  }
  if (!file) return {};
  std::optional<JsonExtent> extent = locate_json_value(sources.text(*file), path);
  if (!extent) return {};
  return {*file, uint32_t(extent->begin), uint32_t(extent->end)};
}

}  // namespace facet::runtime
