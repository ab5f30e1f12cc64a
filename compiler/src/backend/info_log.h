// glslang's info log -> Diagnostics. glslang 12 writes
//   ERROR: <file>:<line>: '<token>' : <message>
//   WARNING: <file>:<line>: '<token>' : <message>
//   ERROR: <message>                             (no position)
//   <file>(<line>): error at column <n>, HLSL parsing failed.
//   ERROR: <n> compilation errors.  No code generated.   (noise)
// and no columns, so the column is found by looking for the quoted token on
// the mapped line. Files are the names of the `#line` directives (the .shader
// path, "<prelude>") or the paths the includer returned.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "includer.h"
#include "source_assembly.h"
#include "facet/diagnostics.h"
#include "facet/ir.h"

namespace facet::backend {

// One message of the log, before mapping.
struct LogMessage {
  Severity severity = Severity::error;
  std::string file;   // "" when the message has no position
  uint32_t line = 0;  // 0 when the message has no position
  std::string token;  // the quoted token, possibly empty
  std::string text;   // the message after the token
  uint32_t column = 0;  // only from "error at column N" lines
  bool parse_failed_marker = false;  // the "HLSL parsing failed" line
};

std::vector<LogMessage> parse_info_log(std::string_view log);

// Everything needed to turn a file name and line from the log into a span.
struct LogContext {
  const ir::Program& program;
  Stage stage;
  FileId shader_file = kNoFile;
  const AssembledSource& source;
  const FileIncluder& includer;
  SourceMap& sources;
  DiagId error_id = DiagId::hlsl_error;
  // The whole preprocessed program (HLSL; empty otherwise): the names in
  // scope for "use of undeclared identifier" and its did-you-mean.
  std::string_view program_text = {};
};

// Appends the log's messages to `diags`. Included files must already be in
// `sources` (add_included_files) for messages inside them to get positions.
void report_info_log(std::string_view log, LogContext& context, Diagnostics& diags);

// Adds every file the includer returned to `sources` (once per path).
void add_included_files(const FileIncluder& includer, SourceMap& sources);

// The span of the `#pragma <stage> fn` line of `program`, if any.
SourceSpan entry_pragma_span(const ir::Program& program, Stage stage);

}  // namespace facet::backend
