// Program blocks: the include blocks in scope, every #pragma (includes
// first), the stage entry points, the shader target and the surface
// function. Keyword pragmas stay in `pragmas` for facet::variants.
#include <algorithm>
#include <array>
#include <cctype>

#include "lower.h"

namespace facet::sema {
namespace {

constexpr std::string_view kTargets[] = {"2.0", "2.5", "3.0", "3.5", "4.0", "4.5", "4.6", "5.0"};

// Every pragma Unity's shader compiler (2017-2019 and later) or facet reads,
// and HLSL's own; anything else is most likely a typo ("fragmnet").
constexpr std::string_view kKnownPragmas[] = {
    "vertex", "fragment", "geometry", "hull", "domain", "target", "require", "surface",
    "only_renderers", "exclude_renderers", "instancing_options", "multi_compile", "shader_feature",
    "dynamic_branch", "skip_variants", "keyword_rule", "hardware_tier_variants", "enable_d3d11_debug_symbols",
    "glsl_no_auto_normalization", "glsl", "glsl_es2", "editor_sync_compilation", "enable_cbuffer",
    "prefer_hlslcc", "use_dxc", "never_use_dxc", "skip_optimizations", "disable_fastmath", "debug",
    "fragmentoption", "profileoption", "multi_compile_local", "pack_matrix", "warning", "def", "message",
    "once", "optimize", "unroll", "loop", "lod_fade", "enable_d3d11_debug"};

bool is_known_pragma(std::string_view name) {
  // Keyword pragmas: every multi_compile*/shader_feature*/dynamic_branch*
  // spelling is checked by facet::variants, which names the bad ones.
  for (std::string_view prefix : {"multi_compile", "shader_feature", "dynamic_branch"}) {
    if (name.starts_with(prefix)) return true;
  }
  return std::find(std::begin(kKnownPragmas), std::end(kKnownPragmas), name) != std::end(kKnownPragmas);
}

ir::ProgramLanguage language(ast::ProgramLanguage l) {
  switch (l) {
    case ast::ProgramLanguage::hlsl: return ir::ProgramLanguage::hlsl;
    case ast::ProgramLanguage::glsl: return ir::ProgramLanguage::glsl;
    case ast::ProgramLanguage::cg: break;
  }
  return ir::ProgramLanguage::cg;
}

ir::SourceChunk chunk(const ast::ProgramBlock& block) { return {block.text, block.text_span, block.first_line}; }

// "3.0" -> 30, "3" -> 30, "es3.0" -> 35; nullopt unless one of kTargets
// (or a single digit or an OpenGL/ES alias of one).
std::optional<int> parse_target(std::string_view s) {
  static const std::pair<std::string_view, int> aliases[] = {
      {"es2.0", 20}, {"es3.0", 35}, {"es3.1", 45}, {"es3.1+aep", 46}, {"gl4.1", 40}, {"gl4.3", 45}};
  for (auto [name, value] : aliases) {
    if (s == name) return value;
  }
  std::string text(s);
  if (s.size() == 1) text += ".0";
  for (std::string_view t : kTargets) {
    if (text == t) return (t[0] - '0') * 10 + (t[2] - '0');
  }
  return std::nullopt;
}

class ProgramLowering {
 public:
  ProgramLowering(ir::Program& program, Context& ctx) : program_(program), ctx_(ctx) {}

  void pragma(const Directive& d) {
    if (d.words.empty()) return;  // a bare "#pragma"
    ir::Pragma p{d.words[0], {d.words.begin() + 1, d.words.end()}, d.span};
    if (auto stage = stage_of(p.name)) entry_point(*stage, p);
    else if (p.name == "target") target(p);
    else if (p.name == "surface") surface(p);
    else if (!is_known_pragma(p.name)) unknown(p);
    program_.pragmas.push_back(std::move(p));
  }

  // A vertex function needs a fragment function and the other way round, as
  // Unity requires; a surface program gets both from its lowering.
  void check_stages(const ast::ProgramBlock& block) {
    if (program_.language == ir::ProgramLanguage::glsl || !program_.surface_function.empty()) return;
    bool vertex = program_.has_stage(Stage::vertex), fragment = program_.has_stage(Stage::fragment);
    if (vertex == fragment) return;
    Stage missing = vertex ? Stage::fragment : Stage::vertex;
    Stage present = vertex ? Stage::vertex : Stage::fragment;
    ctx_.error(DiagId::sema_missing_stage, block.keyword_span,
               "this program has a " + std::string(stage_name(present)) + " function but no " +
                   std::string(stage_name(missing)) + " function")
        .note(entry_spans_[size_t(present)], "add '#pragma " + std::string(stage_name(missing)) +
                                                 " <function>' next to this one");
  }

  // A hull stage needs a domain stage and the other way round (Unity's
  // rule: tessellation runs between the two).
  void check_tessellation_stages(const ast::ProgramBlock& block) {
    if (program_.language == ir::ProgramLanguage::glsl || !program_.surface_function.empty()) return;
    bool hull = program_.has_stage(Stage::hull), domain = program_.has_stage(Stage::domain);
    if (hull == domain) return;
    Stage missing = hull ? Stage::domain : Stage::hull;
    Stage present = hull ? Stage::hull : Stage::domain;
    ctx_.error(DiagId::sema_missing_stage, block.keyword_span,
               "this program has a " + std::string(stage_name(present)) + " function but no " +
                   std::string(stage_name(missing)) + " function")
        .note(entry_spans_[size_t(present)], "add '#pragma " + std::string(stage_name(missing)) +
                                                 " <function>' next to this one: tessellation needs both");
  }

  // Unity raises the target for the stages that need it.
  void finish() {
    if (program_.has_stage(Stage::geometry)) program_.shader_target = std::max(program_.shader_target, 40);
    if (program_.has_stage(Stage::hull) || program_.has_stage(Stage::domain)) {
      program_.shader_target = std::max(program_.shader_target, 46);
    }
  }

 private:
  static std::optional<Stage> stage_of(std::string_view name) {
    static constexpr std::pair<std::string_view, Stage> kStages[] = {
        {"vertex", Stage::vertex}, {"fragment", Stage::fragment}, {"geometry", Stage::geometry},
        {"hull", Stage::hull}, {"domain", Stage::domain}};
    for (auto [word, stage] : kStages) {
      if (word == name) return stage;
    }
    return std::nullopt;
  }

  bool has_argument(const ir::Pragma& p, std::string_view what) {
    if (!p.args.empty()) return true;
    ctx_.error(DiagId::sema_missing_pragma_argument, p.span, "'#pragma " + p.name + "' needs " + std::string(what));
    return false;
  }

  void entry_point(Stage stage, const ir::Pragma& p) {
    if (!has_argument(p, "a function name")) return;
    std::string& slot = program_.entry_points[size_t(stage)];
    SourceSpan& first = entry_spans_[size_t(stage)];
    if (!slot.empty() && slot != p.args[0]) {
      ctx_.error(DiagId::sema_duplicate_entry_point, p.span,
                 "the " + std::string(stage_name(stage)) + " function is already '" + slot + "'")
          .note(first, "first chosen here");
      return;
    }
    slot = p.args[0];
    first = p.span;
  }

  void target(const ir::Pragma& p) {
    if (!has_argument(p, "a shader model such as '3.0'")) return;
    if (auto t = parse_target(p.args[0])) {
      program_.shader_target = *t;
      return;
    }
    ctx_.error(DiagId::sema_bad_shader_target, p.span, "invalid shader target '" + p.args[0] + "'")
        .note({}, "valid targets are " + join(kTargets));
  }

  void unknown(const ir::Pragma& p) {
    Diagnostic& d = ctx_.report(DiagId::sema_unknown_pragma, p.span, "unknown pragma '" + p.name + "' is ignored");
    if (auto best = suggest(p.name, kKnownPragmas)) d.note(p.span, "did you mean '" + std::string(*best) + "'?");
  }

  void surface(const ir::Pragma& p) {
    if (!has_argument(p, "a surface function and a lighting model")) return;
    program_.surface_function = p.args[0];
  }

  ir::Program& program_;
  Context& ctx_;
  std::array<SourceSpan, kStageCount> entry_spans_{};
};

// GLSLPROGRAM: the stages are the sections guarded by VERTEX, FRAGMENT or
// GEOMETRY ("#ifdef VERTEX", "#if defined(FRAGMENT)", "#elif defined GEOMETRY").
void find_glsl_stages(ir::Program& program, const std::vector<Directive>& directives) {
  static constexpr std::pair<std::string_view, Stage> kMacros[] = {
      {"VERTEX", Stage::vertex}, {"FRAGMENT", Stage::fragment}, {"GEOMETRY", Stage::geometry}};
  for (const Directive& d : directives) {
    for (auto [macro, stage] : kMacros) {
      bool found = false;
      if (d.name == "ifdef") {
        found = !d.words.empty() && d.words[0] == macro;
      } else if (d.name == "if" || d.name == "elif") {
        std::string_view rest = d.rest;
        for (size_t at = rest.find("defined"); at != std::string_view::npos && !found;
             at = rest.find("defined", at + 1)) {
          size_t i = at + 7;
          while (i < rest.size() && (rest[i] == ' ' || rest[i] == '\t' || rest[i] == '(')) ++i;
          size_t end = i + macro.size();
          found = rest.substr(i, macro.size()) == macro &&
                  (end == rest.size() || !(std::isalnum(uint8_t(rest[end])) || rest[end] == '_'));
        }
      }
      if (found) program.entry_points[size_t(stage)] = "main";
    }
  }
}

// Counts the text a program copies; false (after one error) past the limit.
bool within_size_limit(const ast::ProgramBlock& block, const std::vector<const ast::ProgramBlock*>& includes,
                       Context& ctx) {
  uint64_t bytes = block.text.size();
  for (const ast::ProgramBlock* include : includes) {
    if (include->language == block.language) bytes += include->text.size();
  }
  bool was_within = ctx.program_bytes <= ctx.options.max_program_bytes;
  ctx.program_bytes += bytes;
  if (ctx.program_bytes <= ctx.options.max_program_bytes) return true;
  if (was_within) {
    ctx.error(DiagId::sema_programs_too_large, block.keyword_span,
              "the programs of this shader, with their include blocks, exceed " +
                  std::to_string(ctx.options.max_program_bytes >> 20) + " MiB");
  }
  return false;
}

}  // namespace

ir::Program lower_program(const ast::ProgramBlock& block, const std::vector<const ast::ProgramBlock*>& includes,
                          Context& ctx) {
  ir::Program program;
  program.language = language(block.language);
  if (!within_size_limit(block, includes, ctx)) return program;
  for (const ast::ProgramBlock* include : includes) {
    if (include->language == block.language) program.includes.push_back(chunk(*include));
  }
  program.body = chunk(block);
  ProgramLowering lowering(program, ctx);
  std::vector<const ir::SourceChunk*> chunks;
  for (const ir::SourceChunk& c : program.includes) chunks.push_back(&c);
  chunks.push_back(&program.body);
  std::vector<Directive> all;
  for (const ir::SourceChunk* c : chunks) {
    for (Directive& d : scan_directives(*c)) {
      if (d.name == "pragma") lowering.pragma(d);
      all.push_back(std::move(d));
    }
  }
  if (program.language == ir::ProgramLanguage::glsl) find_glsl_stages(program, all);
  lowering.finish();
  lowering.check_stages(block);
  lowering.check_tessellation_stages(block);
  return program;
}

}  // namespace facet::sema
