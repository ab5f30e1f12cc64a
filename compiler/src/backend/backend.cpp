// Backend: the recipe. assemble -> glslang -> map the log -> check what
// glslang produced -> fix up bindings and locations -> legalise (HLSL) ->
// spirv-opt -> reflect -> strip the semantic decorations -> spirv-val.
#include "facet/backend.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <string_view>

#include "argument_casts.h"
#include "crash_isolation.h"
#include "glslang_frontend.h"
#include "hlsl_rewrite.h"
#include "include_scan.h"
#include "includer.h"
#include "info_log.h"
#include "reflect.h"
#include "source_assembly.h"
#include "spirv_fixup.h"
#include "spirv_tools.h"
#include "worker.h"

namespace facet::backend {
namespace {

bool is_hlsl(const ir::Program& program) { return program.language != ir::ProgramLanguage::glsl; }

// The file whose folder a program's relative includes are found from.
std::string program_path(const ir::Shader& shader, const ir::Program& program, const SourceMap& sources) {
  FileId file = ir::program_file(shader, program);
  return file != kNoFile && file < sources.file_count() ? sources.path(file) : std::string();
}

std::string stdlib_dir(const BackendOptions& options) {
  return options.stdlib_dir.empty() ? default_stdlib_dir() : options.stdlib_dir;
}

// The entry function of `stage`, or a diagnostic when the program has none.
Result<std::string> entry_point(const ir::Program& program, Stage stage, Diagnostics& diags) {
  if (!program.has_stage(stage)) {
    diags.add(DiagId::backend_no_entry_point, program.body.span,
              fmt::format("program has no {} stage", stage_name(stage)))
        .note({}, is_hlsl(program) ? fmt::format("declare one with '#pragma {} <function>'", stage_name(stage))
                                   : fmt::format("add an '#ifdef {}' section", stage == Stage::vertex ? "VERTEX"
                                                                                                      : "FRAGMENT"));
    return failure("no entry point");
  }
  return is_hlsl(program) ? program.entry_points[size_t(stage)] : std::string("main");
}

void report_logs(const GlslangOutput& out, LogContext& context, Diagnostics& diags) {
  report_info_log(out.parse_log, context, diags);
  report_info_log(out.link_log, context, diags);
  if (!out.spirv_log.empty()) {
    diags.add(DiagId::shader_compiler_warning, SourceSpan{}, "SPIR-V generation: " + out.spirv_log);
  }
}

void report_overlaps(const FixupReport& report, const ir::Program& program, Stage stage, Diagnostics& diags) {
  if (report.overlapping_semantics.empty()) return;
  std::string list;
  for (const std::string& s : report.overlapping_semantics) list += (list.empty() ? "'" : ", '") + s + "'";
  diags.add(DiagId::backend_semantic_overlap, entry_pragma_span(program, stage),
            fmt::format("semantic {} overlaps another input or output of the {} stage; locations follow "
                        "declaration order instead of semantics",
                        list, stage_name(stage)));
}

// Where the program asks for unrolling: its first "unroll" ([unroll],
// UNITY_UNROLL), else its body.
SourceSpan unroll_span(const ir::Program& program) {
  std::vector<const ir::SourceChunk*> chunks;
  for (const ir::SourceChunk& chunk : program.includes) chunks.push_back(&chunk);
  chunks.push_back(&program.body);
  for (const ir::SourceChunk* chunk : chunks) {
    std::string lower = chunk->text;
    std::transform(lower.begin(), lower.end(), lower.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    size_t at = lower.find("unroll");
    if (at == std::string::npos || !chunk->span.has_location()) continue;
    return {chunk->span.file, chunk->span.begin + uint32_t(at), chunk->span.begin + uint32_t(at + 6)};
  }
  return program.body.span;
}

// Refuses a loop marked for unrolling that runs more than the limit's
// iterations: the unroller would copy its body that many times.
bool check_unroll(const std::vector<uint32_t>& spirv, const ir::Program& program, const BackendOptions& options,
                  Diagnostics& diags) {
  uint64_t max = options.limits.max_unroll;
  if (max == 0) return true;
  uint64_t trips = longest_unrolled_loop(spirv, options.target);
  if (trips <= max) return true;
  diags.add(DiagId::backend_input_limit, unroll_span(program),
            fmt::format("a loop marked [unroll] runs {} times, more than the limit of {} (--max-unroll)", trips, max))
      .note({}, "remove [unroll] (or use [loop]) for long loops");
  return false;
}

// The error the time limit ends the process with, located at the program.
// Made before the work starts: when it is printed, the worker may be
// changing the SourceMap.
std::string time_limit_message(const ir::Program& program, Stage stage, const BackendOptions& options,
                               const SourceMap& sources) {
  std::string where = "facet";
  const SourceSpan& span = program.body.span;
  if (span.has_location() && span.file < sources.file_count()) {
    LineColumn at = sources.line_column(span.file, span.begin);
    where = fmt::format("{}:{}:{}", sources.path(span.file), at.line, at.column);
  }
  return fmt::format("{}: error: compiling the {} stage took longer than {} s (--time-limit); facet stopped, "
                     "nothing was written\n",
                     where, stage_name(stage), options.limits.time_limit_s);
}

std::vector<std::string> included_paths(const FileIncluder& includer) {
  std::vector<std::string> paths;
  for (const IncludeRecord& r : includer.records()) paths.push_back(r.path);
  std::sort(paths.begin(), paths.end());
  paths.erase(std::unique(paths.begin(), paths.end()), paths.end());
  return paths;
}

}  // namespace

std::string default_stdlib_dir() {
  namespace fs = std::filesystem;
  if (const char* env = std::getenv("FACET_STDLIB_DIR"); env && *env) return env;
  std::error_code ec;
#ifdef FACET_BUILD_STDLIB_DIR
  if (fs::is_directory(FACET_BUILD_STDLIB_DIR, ec)) return FACET_BUILD_STDLIB_DIR;
#endif
#ifdef FACET_INSTALL_STDLIB_DIR
  return FACET_INSTALL_STDLIB_DIR;
#else
  return {};
#endif
}

// The helper process is forked after glslang has built its symbol tables,
// so that its children start with them (glslang_frontend.h).
// FACET_GLSLANG_IN_PROCESS=1 keeps glslang in this process: to debug it,
// or for a fuzzer to find where it crashes.
Backend::Backend() : scan_cache_(std::make_shared<IncludeScanCache>()) {
  glslang::InitializeProcess();
  const char* in_process = std::getenv("FACET_GLSLANG_IN_PROCESS");
  if (in_process && std::string_view(in_process) == "1") return;
  warm_glslang_symbol_tables(BackendOptions{});
  isolation_ = std::make_unique<CrashIsolation>();
}

Backend::~Backend() {
  isolation_.reset();  // its children run glslang
  glslang::FinalizeProcess();
}

namespace {

Result<std::string> preprocess_source(const ir::Shader& shader, const ir::Program& program, Stage stage,
                                      const std::vector<std::string>& keywords, const BackendOptions& options,
                                      SourceMap& sources, Diagnostics& diags,
                                      std::vector<std::string>* included_files,
                                      const std::shared_ptr<IncludeScanCache>& scan_cache) {
  AssembledSource source = assemble_source(program, stage, keywords, options, program_path(shader, program, sources));
  std::unique_ptr<FileIncluder> includer =
      checked_includer(program, source, options, stdlib_dir(options), diags, scan_cache);
  if (!includer) return failure("input limit");
  GlslangOutput out = preprocess_glslang(source, program.language, stage, options, *includer);
  add_included_files(*includer, sources);
  if (included_files) *included_files = included_paths(*includer);
  LogContext context{program, stage, ir::program_file(shader, program), source, *includer, sources,
                     is_hlsl(program) ? DiagId::hlsl_error : DiagId::glsl_error};
  report_logs(out, context, diags);
  if (!out.ok) return failure("preprocessing failed");
  uint64_t max = options.limits.max_preprocessed_bytes;
  if (max != 0 && out.preprocessed.size() > max) {
    diags.add(DiagId::backend_input_limit, program.body.span,
              fmt::format("the preprocessed program has {} bytes, more than the limit of {} "
                          "(--max-preprocessed-bytes)",
                          out.preprocessed.size(), max));
    return failure("input limit");
  }
  return out.preprocessed;
}

}  // namespace

Result<SourceText> Backend::source_text(const ir::Shader& shader, const ir::Program& program,
                                        const SourceRequest& request, const BackendOptions& options,
                                        SourceMap& sources, Diagnostics& diags) const {
  if (!request.preprocess) {
    return SourceText{
        .text = assemble_source(program, request.stage, request.keywords, options, program_path(shader, program, sources)).text};
  }
  std::string timeout = time_limit_message(program, request.stage, options, sources);
  SourceText out;
  std::optional<Result<std::string>> result;
  run_on_worker([&, scan_cache = scan_cache_] {
                  result = preprocess_source(shader, program, request.stage, request.keywords, options, sources, diags,
                                             &out.included_files, scan_cache);
                },
                options.limits.time_limit_s, [&] { return timeout; });
  if (!*result) return unexpected(result->error());
  out.text = std::move(**result);
  return out;
}

namespace {

// The line `line` (1-based) of the file `file` as glslang saw it: a chunk of
// the program, or a file the includer returned.
std::string_view log_line(const ir::Program& program, const std::string& root_name, const FileIncluder& includer,
                          const std::string& file, uint32_t line) {
  auto nth_line = [](std::string_view text, uint32_t n) -> std::string_view {
    size_t pos = 0;
    for (uint32_t l = 1; l < n; ++l) {
      pos = text.find('\n', pos);
      if (pos == std::string_view::npos) return {};
      ++pos;
    }
    return text.substr(pos, text.find('\n', pos) - pos);
  };
  if (const std::string* text = includer.text_of(file)) return nth_line(*text, line);
  std::vector<const ir::SourceChunk*> chunks;
  for (const ir::SourceChunk& c : program.includes) chunks.push_back(&c);
  chunks.push_back(&program.body);
  for (const ir::SourceChunk* c : chunks) {
    bool same_file = c->line_file.empty() ? file == root_name : file == c->line_file;
    if (same_file && line >= c->first_line) {
      std::string_view l = nth_line(c->text, line - c->first_line + 1);
      if (!l.empty()) return l;
    }
  }
  return {};
}

// The variables assigned on the lines where glslang refused to modify a
// uniform (its message names the block, "$Global", not the variable), less
// those already in `known`.
// The line of preprocessed text that `#line` markers place at `line` of
// `file`; empty when none does.
std::string_view preprocessed_line(std::string_view text, const std::string& file, uint32_t line) {
  std::string current;
  uint32_t number = 1;
  for (size_t pos = 0; pos < text.size();) {
    size_t eol = text.find('\n', pos);
    if (eol == std::string_view::npos) eol = text.size();
    std::string_view l = text.substr(pos, eol - pos);
    pos = eol + 1;
    size_t first = l.find_first_not_of(" \t");
    if (first != std::string_view::npos && l.substr(first).starts_with("#line")) {
      std::string_view rest = l.substr(first + 5);
      number = uint32_t(std::strtoul(std::string(rest).c_str(), nullptr, 10));
      size_t q = rest.find('"');
      if (q != std::string_view::npos) current = std::string(rest.substr(q + 1, rest.rfind('"') - q - 1));
      continue;
    }
    if (number == line && current == file) return l;
    ++number;
  }
  return {};
}

// The names a line assigns to ("NAME =", "NAME += ...", "NAME[i].x = ...").
std::vector<std::string> assigned_names(std::string_view line) {
  auto ident = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; };
  std::vector<std::string> names;
  for (size_t i = 0; i < line.size(); ++i) {
    bool assign = line[i] == '=' && (i + 1 >= line.size() || line[i + 1] != '=') &&
                  (i == 0 || std::string_view("=!<>").find(line[i - 1]) == std::string_view::npos);
    if (!assign) continue;
    size_t end = i;
    while (end > 0 && std::string_view(" \t+-*/%&|^").find(line[end - 1]) != std::string_view::npos) --end;
    while (end > 0 && (line[end - 1] == ']' || std::isalnum(static_cast<unsigned char>(line[end - 1])) ||
                       line[end - 1] == '_' || line[end - 1] == '.' || line[end - 1] == '[')) {
      --end;
    }
    size_t stop = end;
    while (stop < line.size() && ident(line[stop])) ++stop;
    std::string name(line.substr(end, stop - end));
    if (!name.empty() && !std::isdigit(static_cast<unsigned char>(name[0]))) names.push_back(std::move(name));
  }
  return names;
}

std::vector<std::string> assigned_uniforms(const std::vector<LogMessage>& messages, const ir::Program& program,
                                           const std::string& root_name, const FileIncluder& includer,
                                           const std::string& preprocessed, const std::vector<std::string>& known) {
  std::vector<std::string> out;
  for (const LogMessage& m : messages) {
    if (m.severity != Severity::error || m.text.find("can't modify a uniform") == std::string::npos) continue;
    std::vector<std::string> names = assigned_names(log_line(program, root_name, includer, m.file, m.line));
    // An assignment a macro makes ("CLAMP_STRENGTH;") is on the line of
    // the preprocessed text.
    if (names.empty()) names = assigned_names(preprocessed_line(preprocessed, m.file, m.line));
    for (std::string& name : names) {
      if (std::find(known.begin(), known.end(), name) == known.end() &&
          std::find(out.begin(), out.end(), name) == out.end()) {
        out.push_back(std::move(name));
      }
    }
  }
  return out;
}

// True when none of the errors of `before` that the rewrites address (no
// overload, a modified uniform) is reported again, at the same place, in
// `after`; errors that only followed from them (glslang goes on after the
// first error and trips over later lines) may recur.
bool fixed_errors(const std::vector<LogMessage>& before, const std::vector<LogMessage>& after) {
  auto addressed = [](const LogMessage& m) {
    return m.severity == Severity::error && (m.text.find("no matching overloaded function found") != std::string::npos ||
                                             m.text.find("can't modify a uniform") != std::string::npos);
  };
  for (const LogMessage& a : after) {
    if (!addressed(a)) continue;
    for (const LogMessage& b : before) {
      if (addressed(b) && b.file == a.file && b.line == a.line && b.text == a.text) return false;
    }
  }
  return true;
}

// Compiles again after casting calls, copying assigned uniforms and casting
// float switches: glslang reports only some errors of a long program at a
// time (one per function), so large programs need several rounds; each
// round must fix what it rewrote (fixed_errors), so this bounds only
// programs that keep yielding new sites.
constexpr int kMaxRetries = 16;

// Backend::compile, on the worker thread.
Result<CompiledVariant> compile_stage(const ir::Shader& shader, const ir::Program& program, Stage stage,
                                    const std::vector<std::string>& keywords, const BackendOptions& options,
                                    SourceMap& sources, Diagnostics& diags,
                                    const std::shared_ptr<IncludeScanCache>& scan_cache,
                                    const CrashIsolation* isolation) {
  Result<std::string> entry = entry_point(program, stage, diags);
  if (!entry) return unexpected(entry.error());
  size_t errors_before = diags.error_count();
  AssembledSource source = assemble_source(program, stage, keywords, options, program_path(shader, program, sources));
  std::unique_ptr<FileIncluder> includer =
      checked_includer(program, source, options, stdlib_dir(options), diags, scan_cache);
  if (!includer) return failure("input limit");
  GlslangOutput out = run_glslang(source, program.language, stage, *entry, options, *includer, isolation);
  // fxc truncates a wider vector argument (X3206) where glslang finds no
  // overload: retry with the arguments cast, and warn at each call.
  // Likewise an assignment to a global uniform, which fxc turns into a write
  // to a per-invocation copy.
  std::optional<ir::Program> cast_program;
  std::vector<CastCall> casts;
  std::vector<std::string> assigned;
  std::map<std::string, std::string> overrides;  // included files whose calls got casts
  for (int attempt = 0; attempt < kMaxRetries && !out.ok && is_hlsl(program); ++attempt) {
    ir::Program retry = cast_program ? *cast_program : program;
    std::vector<LogMessage> messages = parse_info_log(out.parse_log);
    std::vector<std::string> more_assigned = assigned_uniforms(messages, retry, source.root_name, *includer, out.preprocessed, assigned);
    std::vector<CastCall> more = cast_rejected_calls(retry, source.root_name, messages, includer->returned_texts());
    // The files as written go to the SourceMap first, so warnings point at them.
    add_included_files(*includer, sources);
    std::map<std::string, std::string> retry_overrides = overrides;
    std::vector<CastCall> more_in_files =
        cast_rejected_calls_in_includes(retry_overrides, includer->returned_texts(), retry, messages, sources);
    more.insert(more.end(), more_in_files.begin(), more_in_files.end());
    size_t switches = cast_float_switches(retry, source.root_name, messages) +
                      cast_float_switches_in_includes(retry_overrides, includer->returned_texts(), messages);
    if (more.empty() && more_assigned.empty() && switches == 0) break;
    for (ir::SourceChunk& chunk : retry.includes) chunk.text = rewrite_assigned_uniforms(chunk.text, more_assigned);
    retry.body.text = rewrite_assigned_uniforms(retry.body.text, more_assigned);
    std::vector<std::string> all_assigned = assigned;
    all_assigned.insert(all_assigned.end(), more_assigned.begin(), more_assigned.end());
    AssembledSource retry_source = assemble_source(retry, stage, keywords, options, program_path(shader, program, sources));
    Diagnostics refused;  // the program's text passed these checks before its rewrites
    std::unique_ptr<FileIncluder> retry_includer =
        checked_includer(retry, retry_source, options, stdlib_dir(options), refused, scan_cache);
    if (!retry_includer) break;
    retry_includer->set_assigned_uniforms(all_assigned);
    retry_includer->set_overrides(retry_overrides);
    GlslangOutput retry_out =
        run_glslang(retry_source, retry.language, stage, *entry, options, *retry_includer, isolation);
    // Keep a retry that fixed what it rewrote, even if a later call (glslang
    // stops at the first error of a function) now fails: the next round
    // rewrites that one.
    if (!retry_out.ok && !fixed_errors(messages, parse_info_log(retry_out.parse_log))) break;
    cast_program = std::move(retry);
    casts.insert(casts.end(), more.begin(), more.end());
    assigned = std::move(all_assigned);
    overrides = std::move(retry_overrides);
    source = std::move(retry_source);
    includer = std::move(retry_includer);
    out = std::move(retry_out);
  }
  const ir::Program& compiled = cast_program ? *cast_program : program;
  add_included_files(*includer, sources);
  LogContext context{compiled, stage, ir::program_file(shader, program), source, *includer, sources,
                     is_hlsl(program) ? DiagId::hlsl_error : DiagId::glsl_error, out.preprocessed};
  report_logs(out, context, diags);
  if (out.ok) {
    for (const CastCall& call : casts) {
      diags.add(DiagId::hlsl_implicit_truncation, call.span,
                fmt::format("implicit truncation of vector type in a call to '{}': an argument is wider than its "
                            "parameter; each argument is converted to its parameter's type, as fxc does (X3206)",
                            call.function));
    }
  }
  if (!out.ok) {
    if (diags.error_count() == errors_before) {
      diags.add(DiagId::backend_compile_error, program.body.span,
                fmt::format("glslang could not compile the {} stage and gave no reason", stage_name(stage)));
    }
    return failure(fmt::format("{} stage did not compile", stage_name(stage)));
  }

  CompiledVariant result;
  result.spirv = std::move(out.spirv);
  result.included_files = included_paths(*includer);
  // The word-level fix-ups come first: one of them lists interface variables
  // glslang leaves out, without which the module is invalid.
  report_overlaps(fix_up_spirv(result.spirv, out.declared, stage, is_hlsl(program)), program, stage, diags);
  if (!check_generated(result.spirv, is_hlsl(program), options.target, diags)) return failure("glslang bug");
  if (!check_unroll(result.spirv, program, options, diags)) return failure("input limit");
  if (is_hlsl(program) && !legalize_hlsl(result.spirv, options.target, diags)) return failure("legalization failed");
  if (!optimize(result.spirv, options.opt, options.target, diags)) return failure("spirv-opt failed");
  Result<StageReflection> reflection =
      reflect_stage(result.spirv, {.stage = stage, .entry_point = *entry, .hlsl = is_hlsl(program)}, diags);
  if (!reflection) return unexpected(reflection.error());
  result.reflection = std::move(*reflection);
  bind_properties(shader.properties, result.reflection);
  if (is_hlsl(program) && !strip_reflection_info(result.spirv, options.target, diags)) return failure("strip failed");
  if (!validate(result.spirv, options.target, diags)) return failure("invalid SPIR-V");
  return result;
}

}  // namespace

Result<CompiledVariant> Backend::compile(const ir::Shader& shader, const ir::Program& program, Stage stage,
                                       const std::vector<std::string>& keywords, const BackendOptions& options,
                                       SourceMap& sources, Diagnostics& diags) const {
  std::string timeout = time_limit_message(program, stage, options, sources);
  std::optional<Result<CompiledVariant>> result;
  run_on_worker([&, scan_cache = scan_cache_] {
                  result = compile_stage(shader, program, stage, keywords, options, sources, diags, scan_cache,
                                         isolation_.get());
                },
                options.limits.time_limit_s, [&] { return timeout; });
  return std::move(*result);
}

}  // namespace facet::backend
