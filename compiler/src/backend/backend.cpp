// Backend: the recipe. assemble -> glslang -> map the log -> check what
// glslang produced -> fix up bindings and locations -> legalise (HLSL) ->
// spirv-opt -> reflect -> strip the semantic decorations -> spirv-val.
#include "facet/backend.h"

#include <fmt/format.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>

#include "backend/glslang_frontend.h"
#include "backend/includer.h"
#include "backend/info_log.h"
#include "backend/reflect.h"
#include "backend/source_assembly.h"
#include "backend/spirv_fixup.h"
#include "backend/spirv_tools.h"

namespace facet::backend {
namespace {

bool is_hlsl(const ir::Program& program) { return program.language != ir::ProgramLanguage::glsl; }

std::string shader_path(const ir::Shader& shader, const SourceMap& sources) {
  return shader.file != kNoFile && shader.file < sources.file_count() ? sources.path(shader.file) : std::string();
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

// Refuses chunks whose brackets nest deeper than glslang can parse safely.
bool check_nesting(const ir::Program& program, Diagnostics& diags) {
  std::vector<const ir::SourceChunk*> chunks;
  for (const ir::SourceChunk& chunk : program.includes) chunks.push_back(&chunk);
  chunks.push_back(&program.body);
  for (const ir::SourceChunk* chunk : chunks) {
    if (auto at = find_excessive_nesting(chunk->text)) {
      SourceSpan span = chunk->span;
      if (span.has_location()) span = {span.file, span.begin + uint32_t(*at), span.begin + uint32_t(*at) + 1};
      diags.add(DiagId::backend_nesting_too_deep, span, fmt::format("brackets nest more than {} deep", kMaxNesting));
      return false;
    }
  }
  return true;
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

Backend::Backend() { glslang::InitializeProcess(); }

Backend::~Backend() { glslang::FinalizeProcess(); }

Result<std::string> Backend::source_text(const ir::Shader& shader, const ir::Program& program, Stage stage,
                                         const std::vector<std::string>& keywords, const BackendOptions& options,
                                         bool preprocess, SourceMap& sources, Diagnostics& diags,
                                         std::vector<std::string>* included_files) const {
  AssembledSource source = assemble_source(program, stage, keywords, options, shader_path(shader, sources));
  if (!preprocess) return source.text;
  FileIncluder includer(options, stdlib_dir(options));
  GlslangOutput out = preprocess_glslang(source, program.language, stage, options, includer);
  add_included_files(includer, sources);
  if (included_files) *included_files = included_paths(includer);
  LogContext context{program, stage, shader.file, source, includer, sources,
                     is_hlsl(program) ? DiagId::hlsl_error : DiagId::glsl_error};
  report_logs(out, context, diags);
  if (!out.ok) return failure("preprocessing failed");
  return out.preprocessed;
}

Result<CompiledStage> Backend::compile(const ir::Shader& shader, const ir::Program& program, Stage stage,
                                       const std::vector<std::string>& keywords, const BackendOptions& options,
                                       SourceMap& sources, Diagnostics& diags) const {
  Result<std::string> entry = entry_point(program, stage, diags);
  if (!entry) return unexpected(entry.error());
  if (!check_nesting(program, diags)) return failure("nesting too deep");
  size_t errors_before = diags.error_count();
  AssembledSource source = assemble_source(program, stage, keywords, options, shader_path(shader, sources));
  FileIncluder includer(options, stdlib_dir(options));
  GlslangOutput out = run_glslang(source, program.language, stage, *entry, options, includer);
  add_included_files(includer, sources);
  LogContext context{program, stage, shader.file, source, includer, sources,
                     is_hlsl(program) ? DiagId::hlsl_error : DiagId::glsl_error};
  report_logs(out, context, diags);
  if (!out.ok) {
    if (diags.error_count() == errors_before) {
      diags.add(DiagId::backend_compile_error, program.body.span,
                fmt::format("glslang could not compile the {} stage and gave no reason", stage_name(stage)));
    }
    return failure(fmt::format("{} stage did not compile", stage_name(stage)));
  }

  CompiledStage result;
  result.stage = stage;
  result.spirv = std::move(out.spirv);
  result.included_files = included_paths(includer);
  if (!check_generated(result.spirv, is_hlsl(program), options.target, diags)) return failure("glslang bug");
  report_overlaps(fix_up_spirv(result.spirv, out.declared, stage, is_hlsl(program)), program, stage, diags);
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

}  // namespace facet::backend
