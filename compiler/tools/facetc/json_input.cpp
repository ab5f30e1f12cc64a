// Reading facetc's JSON inputs.
#include "json_input.h"

#include <fmt/format.h>

namespace facet::tools {
namespace {

// nlohmann's parser recurses per nesting level; refuse hostile depths first.
std::optional<size_t> excessive_nesting(const std::string& text, int limit = 64) {
  int depth = 0;
  bool in_string = false;
  for (size_t i = 0; i < text.size(); ++i) {
    char c = text[i];
    if (in_string) {
      if (c == '\\') ++i;
      else if (c == '"') in_string = false;
    } else if (c == '"') {
      in_string = true;
    } else if (c == '[' || c == '{') {
      if (++depth > limit) return i;
    } else if (c == ']' || c == '}') {
      --depth;
    }
  }
  return std::nullopt;
}

}  // namespace

Result<JsonInput> read_json_input(const std::string& path, SourceMap& sources, Diagnostics& diags) {
  auto text = read_file(path, kMaxShaderBytes, diags);
  FACET_TRY(text);
  FileId file = sources.add_file(path, *text);
  if (auto at = excessive_nesting(*text)) {
    diags.add(DiagId::json_input_invalid, SourceSpan{file, uint32_t(*at), uint32_t(*at) + 1},
              "JSON nests more than 64 deep");
    return failure("bad JSON");
  }
  JsonInput input{.file = file};
  try {
    input.json = nlohmann::json::parse(*text);
  } catch (const nlohmann::json::parse_error& e) {
    uint32_t at = e.byte > 0 ? uint32_t(std::min<size_t>(e.byte - 1, text->size())) : 0;
    std::string what = e.what();
    if (auto colon = what.rfind(": "); colon != std::string::npos) what = what.substr(colon + 2);
    diags.add(DiagId::json_input_invalid, SourceSpan{file, at, at + 1}, "invalid JSON: " + what);
    return failure("bad JSON");
  }
  return input;
}

void JsonInputErrors::add(const std::string& where, const std::string& what) {
  diags.add(DiagId::json_input_invalid, SourceSpan{file, 0, 0}, fmt::format("{}: {}", where, what));
  failed = true;
}

}  // namespace facet::tools
