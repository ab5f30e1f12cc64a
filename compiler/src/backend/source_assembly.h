// Builds the text that glslang compiles for one (program, stage, keywords):
// a prelude of #defines (and, for CGPROGRAM, the implicit includes), then
// every CGINCLUDE chunk and the program body, each behind a `#line` that
// names the .shader file, so that glslang's messages point into it.
#pragma once

#include <cstdint>
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

// glslang's HLSL parser is recursive descent, its preprocessor evaluates
// #if expressions recursively, and its AST walks recurse on every nested
// node; a few thousand nested constructs overflow a thread's stack.
// glslang runs on a large stack (worker.h), and text that nests deeper
// than these limits is refused before glslang sees it (docs/cli.md, "Input
// limits"). Legitimate code stays far below them.
inline constexpr int kMaxNesting = 256;        // brackets ( [ { inside one another
inline constexpr int kMaxUnaryRun = 256;       // unary operators in a row: ! ~ - +
inline constexpr int kMaxAssignmentChain = 256;  // a = b = c ...; also a ? b : c ? ...
inline constexpr int kMaxIfChain = 1024;       // if ... else if ... (and if (a) if (b) ...)
// glslang keeps line numbers in an int and counts on from a #line.
inline constexpr uint64_t kMaxLineNumber = 1000000000;

// Where a text first exceeds one of the limits above, and how.
struct RecursionHazard {
  size_t offset = 0;  // where the run, chain or too-deep bracket starts
  std::string message;
};

// The first hazard of `text` outside comments and strings; #if lines are
// scanned like code. Also refuses `#line N` with N above kMaxLineNumber.
std::optional<RecursionHazard> find_recursion_hazard(std::string_view text);

// Offset of the bracket ( [ { that opens level `limit` + 1 outside comments
// and strings, if any.
std::optional<size_t> find_excessive_nesting(std::string_view text, int limit = kMaxNesting);

// "SHADER_STAGE_VERTEX" etc.
std::string stage_define(Stage stage);

}  // namespace facet::backend
