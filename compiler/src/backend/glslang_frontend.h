// Runs glslang on an assembled source: parse (HLSL with DX9 compatibility,
// or GLSL), link, map bindings and locations, and generate SPIR-V. Nothing
// here reports diagnostics; the logs are returned for info_log.h to map.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "includer.h"
#include "source_assembly.h"
#include "facet/backend.h"

namespace glslang {
class TIntermediate;
}

namespace facet::backend {

class CrashIsolation;

// A uniform resource (texture, sampler, cbuffer, the "$Global" block) as
// declared, in declaration order. `key` is the variable name, or the block's
// type name for blocks (how the SPIR-V fix-ups find it again).
struct DeclaredResource {
  std::string key;
  bool block = false;
  bool has_set = false, has_binding = false;
  uint32_t set = 0, binding = 0;
};

struct GlslangOutput {
  bool ok = false;
  std::string parse_log;  // info log of TShader::parse (or preprocess)
  std::string link_log;   // info log of TProgram::link / mapIO
  std::string spirv_log;  // messages of GlslangToSpv
  std::vector<uint32_t> spirv;
  std::vector<DeclaredResource> declared;  // stage-independent order
  // preprocess_glslang's text; from run_glslang on HLSL, the whole program
  // after preprocessing (before unreachable functions are dropped).
  std::string preprocessed;
};

// Compiles `source` for `stage` with entry point `entry` ("main" for GLSL).
// With `isolation`, HLSL (preprocessed here) is parsed, linked and turned
// into SPIR-V in a child process: a glslang crash becomes an error in the
// parse log. GLSL, and HLSL with debug_info, are compiled in this process.
GlslangOutput run_glslang(const AssembledSource& source, ir::ProgramLanguage language, Stage stage,
                          const std::string& entry, const BackendOptions& options, FileIncluder& includer,
                          const CrashIsolation* isolation);

// Parses only, then hands the AST to `visit` while it is alive; ok when the
// parse succeeded. For reading the code's structure (program_analysis.h).
// With `isolation`, HLSL is parsed in a child process first, and here only
// when the child parsed it.
GlslangOutput parse_glslang(const AssembledSource& source, ir::ProgramLanguage language, Stage stage,
                            const std::string& entry, const BackendOptions& options, FileIncluder& includer,
                            const std::function<void(const glslang::TIntermediate&)>& visit,
                            const CrashIsolation* isolation);

// Builds glslang's built-in symbol tables of HLSL vertex and fragment
// programs for `options`' target, which glslang keeps for the process: a
// child process forked afterwards (crash_isolation.h) starts with them
// instead of building them for each program.
void warm_glslang_symbol_tables(const BackendOptions& options);

// Only the preprocessor; `preprocessed` holds the text when ok.
GlslangOutput preprocess_glslang(const AssembledSource& source, ir::ProgramLanguage language, Stage stage,
                                 const BackendOptions& options, FileIncluder& includer);

// glslang's complaints about a GLSL or ESSL text (as cross_compile makes for
// OpenGL), parsed as GLSL for OpenGL; empty when it parses. For tests and
// self-checks.
std::string glsl_errors(const std::string& text, Stage stage);

}  // namespace facet::backend
