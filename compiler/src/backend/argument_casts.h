// fxc truncates a vector argument wider than its parameter (warning X3206);
// glslang finds no overload instead. For each call glslang rejected this
// way, the program text gets explicit casts of the arguments to the
// parameter types of the function's definition, and the compile is tried
// again. Internal to the backend stage.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "info_log.h"
#include "facet/ir.h"

namespace facet::backend {

struct CastCall {
  std::string function;
  SourceSpan span;  // the function name at the call, in the .shader file
};

// Rewrites, in `program`'s chunks that `root_name` names, the calls that
// `messages` reports as "no matching overloaded function found" for a
// function the program (or a file it includes, of `included`: text by path)
// defines with one definition of the call's arity: every scalar or vector
// argument of an `in` parameter becomes "(type)(argument)". Lines keep their
// breaks, so #line mapping still holds. Returns the calls rewritten (none:
// nothing to retry).
std::vector<CastCall> cast_rejected_calls(ir::Program& program, const std::string& root_name,
                                          const std::vector<LogMessage>& messages,
                                          const std::map<std::string, std::string>& included);

// fxc switches on a float (converted to int); glslang wants an integer. Each
// "switch (x)" in `program`'s chunks on a line that `messages` reports so
// becomes "switch ((int)(x))"; returns how many were rewritten.
size_t cast_float_switches(ir::Program& program, const std::string& root_name, const std::vector<LogMessage>& messages);
// The same for switches in included files: `texts` holds the rewritten
// texts by path (the includer's overrides), `current` the texts the
// includer returned.
size_t cast_float_switches_in_includes(std::map<std::string, std::string>& texts,
                                       const std::map<std::string, std::string>& current,
                                       const std::vector<LogMessage>& messages);

// The same for calls in included files: `texts` holds each file's text by
// the path glslang names (edited in place; a file not yet in it is read
// from `current`); definitions are looked up in those texts and `program`.
// Spans point into `sources`, which must hold the files as written.
std::vector<CastCall> cast_rejected_calls_in_includes(std::map<std::string, std::string>& texts,
                                                      const std::map<std::string, std::string>& current,
                                                      const ir::Program& program,
                                                      const std::vector<LogMessage>& messages,
                                                      const SourceMap& sources);

}  // namespace facet::backend
