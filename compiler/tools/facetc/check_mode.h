// facetc --check: the linter a CI job runs over a project's shaders. Every
// .shader of the files and folders given is compiled (its default variant,
// every variant, or the variants materials use), nothing is written but the
// reports asked for, and each shader gets one line (docs/cli.md).
#pragma once

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

#include "args.h"
#include "find_shaders.h"
#include "facet/compiler.h"
#include "report_mode.h"
#include "run.h"

namespace facet::tools {

// One diagnostic of a checked shader, resolved to text and positions so that
// it outlives the shader's SourceMap.
struct CheckDiagnostic {
  DiagId id{};
  Severity severity = Severity::error;
  std::string file;                    // "" when it has no location
  uint32_t line = 0, column = 0;       // 1-based; 0 without a location
  uint32_t end_line = 0, end_column = 0;  // the position after the span; 0 for an empty span
  std::string message;                 // with "[in N of M variants]" when merged
  std::vector<std::string> notes;      // the notes' messages
};

// What checking one shader found.
struct ShaderCheck {
  std::string path;  // as found: the FILE argument, or DIR joined with the path under it
  bool ok = false;
  uint64_t variants = 0;  // variants compiled
  size_t warnings = 0;
  std::vector<CheckDiagnostic> diagnostics;  // after -w, -Werror and -Wno-
  std::string text;  // every diagnostic as GCC-style text without colour (JUnit's failure text)
  double seconds = 0;
};

// "file:line:col: error: message" of the first error (or "error: message"
// without a location); "" when there is none.
std::string first_error(const ShaderCheck& check);

// Exit code: 0 every shader compiles, 1 one does not (or an input or report
// failed).
int run_check(const FacetcArgs& args, const Compiler& compiler, const StripInputs& strip, Console& console,
              nlohmann::json& json_diagnostics);

}  // namespace facet::tools
