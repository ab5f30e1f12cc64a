// Builds the text that glslang compiles for one (program, stage, keywords):
// a prelude of #defines (and, for CGPROGRAM, the implicit includes), then
// every CGINCLUDE chunk and the program body, each behind a `#line` that
// names the .shader file, so that glslang's messages point into it.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "facet/backend.h"

namespace facet::backend {

// The name glslang reports for lines of the generated prelude.
inline constexpr const char* kPreludeName = "<prelude>";

struct AssembledSource {
  std::string text;
  // The name of the one string handed to glslang: the .shader path. glslang
  // passes it to the includer as the includer of the body's #includes.
  std::string root_name;
  // The prelude's text (a prefix of `text`); its lines have the same numbers
  // in both, so a "<prelude>:N" message is line N of this text.
  std::string prelude;
};

// `shader_path` is the path of ir::Shader::file in the SourceMap (or "" when
// the shader has no file). Never fails: bad defines surface as glslang errors
// located in the prelude.
AssembledSource assemble_source(const ir::Program& program, Stage stage, const std::vector<std::string>& keywords,
                                const BackendOptions& options, const std::string& shader_path);

// glslang parses expressions recursively; a few thousand nested brackets
// overflow the stack. Sources nesting deeper than this are refused first.
inline constexpr int kMaxNesting = 256;

// Offset of the bracket ( [ { that opens level `limit` + 1 outside comments
// and strings, if any.
std::optional<size_t> find_excessive_nesting(std::string_view text, int limit = kMaxNesting);

// "SHADER_STAGE_VERTEX" etc.
std::string stage_define(Stage stage);

}  // namespace facet::backend
