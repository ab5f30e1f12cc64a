// lower_surface_shaders: directive -> analysis -> shape -> generated passes.
#include <fmt/format.h>

#include <algorithm>

#include "facet/program_analysis.h"
#include "facet/surface.h"
#include "directive.h"
#include "generate.h"
#include "shape.h"

namespace facet::surface {
namespace {

size_t count_lines(std::string_view text) { return size_t(std::count(text.begin(), text.end(), '\n')); }

const ir::Pragma* surface_pragma(const ir::Program& program) {
  for (const ir::Pragma& p : program.pragmas) {
    if (p.name == "surface") return &p;
  }
  return nullptr;
}

// Generated text as a file of its own: the prologue, then the epilogue.
struct GeneratedFile {
  ir::SourceChunk prologue, epilogue;
};

GeneratedFile add_generated_file(const std::string& name, const GeneratedCode& code, SourceMap& sources) {
  FileId file = sources.add_file(name, code.prologue + code.epilogue);
  GeneratedFile out;
  out.prologue = {.text = code.prologue,
                  .span = {file, 0, uint32_t(code.prologue.size())},
                  .first_line = 1,
                  .line_file = name};
  out.epilogue = {.text = code.epilogue,
                  .span = {file, uint32_t(code.prologue.size()), uint32_t(code.prologue.size() + code.epilogue.size())},
                  .first_line = uint32_t(count_lines(code.prologue) + 1),
                  .line_file = name};
  return out;
}

// The user's program with the generated code around it: prologue, the
// CGINCLUDE chunks, the user's body, epilogue.
// With `tessellated`, the vertex stage is tessvert_surf and hs_surf/ds_surf
// are the hull and domain stages, at shader model 4.6 at least (as in Unity).
ir::Program wrap(const ir::Program& user, const GeneratedFile& file, std::vector<ir::Pragma> pragmas,
                 bool tessellated = false) {
  ir::Program p = user;
  p.surface_function.clear();
  p.includes.clear();
  p.includes.push_back(file.prologue);
  p.includes.insert(p.includes.end(), user.includes.begin(), user.includes.end());
  p.includes.push_back(user.body);
  p.body = file.epilogue;
  p.pragmas = std::move(pragmas);
  p.entry_points = {};
  p.entry_points[size_t(Stage::vertex)] = tessellated ? "tessvert_surf" : "vert_surf";
  p.entry_points[size_t(Stage::fragment)] = "frag_surf";
  if (tessellated) {
    p.entry_points[size_t(Stage::hull)] = "hs_surf";
    p.entry_points[size_t(Stage::domain)] = "ds_surf";
    p.shader_target = std::max(p.shader_target, 46);
  }
  return p;
}

ir::Pragma pragma(std::string name, std::vector<std::string> args, SourceSpan span) {
  return {std::move(name), std::move(args), span};
}

// The user's keyword and target pragmas, then the pass's own.
std::vector<ir::Pragma> pass_pragmas(const ir::Program& user, GeneratedPass pass, const Directive& d,
                                     bool tessellated) {
  std::vector<ir::Pragma> out;
  for (const ir::Pragma& p : user.pragmas) {
    bool stage = p.name == "vertex" || p.name == "fragment" || p.name == "hull" || p.name == "domain";
    if (p.name != "surface" && !stage) out.push_back(p);
  }
  out.push_back(pragma("vertex", {tessellated ? "tessvert_surf" : "vert_surf"}, d.span));
  if (tessellated) {
    out.push_back(pragma("hull", {"hs_surf"}, d.span));
    out.push_back(pragma("domain", {"ds_surf"}, d.span));
  }
  out.push_back(pragma("fragment", {"frag_surf"}, d.span));
  std::vector<std::string> shadow_modifier;
  if (d.no_shadow) shadow_modifier.push_back("noshadow");
  switch (pass) {
    case GeneratedPass::forward_base: {
      std::vector<std::string> modifiers = shadow_modifier;
      if (d.no_vertex_lights) modifiers.push_back("novertexlight");
      out.push_back(pragma("multi_compile_fwdbase", modifiers, d.span));
      break;
    }
    case GeneratedPass::forward_add:
      out.push_back(pragma(d.full_forward_shadows ? "multi_compile_fwdadd_fullshadows" : "multi_compile_fwdadd",
                           shadow_modifier, d.span));
      break;
    case GeneratedPass::deferred:
      out.push_back(pragma("multi_compile_prepassfinal", {}, d.span));
      break;
    default:
      out.push_back(pragma("multi_compile_shadowcaster", {}, d.span));
      break;
  }
  bool lit = pass == GeneratedPass::forward_base || pass == GeneratedPass::forward_add;
  if (lit && !d.no_fog) out.push_back(pragma("multi_compile_fog", {}, d.span));
  if (pass != GeneratedPass::forward_add && !d.no_instancing) out.push_back(pragma("multi_compile_instancing", {}, d.span));
  return out;
}

ir::StateValue literal(std::string text, SourceSpan span) { return {std::move(text), "", span}; }

ir::BlendState blend(const char* src, const char* dst, SourceSpan span) {
  return {.render_target = -1, .off = false, .src = literal(src, span), .dst = literal(dst, span)};
}

// The SubShader's state with what the pass and the alpha/decal options add.
ir::RenderState pass_state(const ir::SubShader& sub, GeneratedPass pass, const Directive& d) {
  ir::RenderState s = sub.state;
  const SourceSpan at = d.span;
  switch (pass) {
    case GeneratedPass::forward_base:
      if (d.decal == DecalMode::add) s.blend = {blend("One", "One", at)};
      else if (d.decal == DecalMode::blend || d.alpha == AlphaMode::fade) s.blend = {blend("SrcAlpha", "OneMinusSrcAlpha", at)};
      else if (d.alpha == AlphaMode::premultiply) s.blend = {blend("One", "OneMinusSrcAlpha", at)};
      break;
    case GeneratedPass::forward_add:
      s.blend = {d.alpha == AlphaMode::fade || d.decal == DecalMode::blend ? blend("SrcAlpha", "One", at)
                                                                           : blend("One", "One", at)};
      s.zwrite = literal("Off", at);
      break;
    default:
      s.blend.clear();
      s.zwrite = literal("On", at);
      s.ztest = literal("LEqual", at);
      return s;
  }
  if (d.decal != DecalMode::none) {
    s.zwrite = literal("Off", at);
    s.offset_factor = literal("-1", at);
    s.offset_units = literal("-1", at);
  }
  if (d.alpha != AlphaMode::none || d.decal != DecalMode::none) s.color_mask = {{-1, literal("RGB", at)}};
  return s;
}

struct PassInfo {
  GeneratedPass kind;
  const char* name;
  const char* light_mode;
};

// Unity generates a Deferred pass when the lighting model has a
// Lighting<Model>_Deferred function and the surface is neither blended nor a
// decal (those draw forward), unless `exclude_path:deferred`.
bool has_deferred_pass(const Directive& d, const Shape& shape) {
  bool gi = shape.lighting == LightingForm::gi || shape.lighting == LightingForm::view_gi;
  return gi && shape.has_deferred_function && !d.exclude_deferred && d.decal == DecalMode::none &&
         d.alpha == AlphaMode::none;
}

std::vector<PassInfo> passes_for(const Directive& d, const Shape& shape, bool has_fallback) {
  std::vector<PassInfo> out{{GeneratedPass::forward_base, "FORWARD", "ForwardBase"}};
  if (!d.no_forward_add) out.push_back({GeneratedPass::forward_add, "FORWARD_DELTA", "ForwardAdd"});
  if (has_deferred_pass(d, shape)) out.push_back({GeneratedPass::deferred, "DEFERRED", "Deferred"});
  if (d.add_shadow) out.push_back({GeneratedPass::shadow_caster, "ShadowCaster", "ShadowCaster"});
  else if (has_fallback) out.push_back({GeneratedPass::fallback_shadow_caster, "ShadowCaster", "ShadowCaster"});
  return out;
}

// Whether the user's code names `name` outside preprocessor lines (a rough
// stand-in for "declares it": enough to avoid declaring _ST and alphatest
// properties twice).
bool declares(const ir::Program& program, const std::string& name) {
  auto in = [&](const std::string& text) {
    for (size_t at = text.find(name); at != std::string::npos; at = text.find(name, at + 1)) {
      auto ident = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; };
      bool starts = at == 0 || !ident(text[at - 1]);
      bool ends = at + name.size() >= text.size() || !ident(text[at + name.size()]);
      size_t line_start = text.rfind('\n', at);
      line_start = line_start == std::string::npos ? 0 : line_start + 1;
      size_t first = text.find_first_not_of(" \t", line_start);
      bool directive = first != std::string::npos && text[first] == '#';  // "#pragma surface ... alphatest:_Cutoff"
      if (starts && ends && !directive) return true;
    }
    return false;
  };
  if (in(program.body.text)) return true;
  return std::any_of(program.includes.begin(), program.includes.end(), [&](const ir::SourceChunk& c) { return in(c.text); });
}

// `tag` names the program in generated file names (" SubShader 1 #2").
// `first`: the SubShader's first surface program, the one that stands in
// for the Fallback's shadow caster (one ShadowCaster pass is enough).
Result<std::vector<ir::Pass>> lower_one(const ir::Shader& shader, const ir::SubShader& sub, const ir::Program& user,
                                        const std::string& tag, bool first, const ProgramAnalyzer& analyze,
                                        SourceMap& sources, Diagnostics& diags) {
  const ir::Pragma* p = surface_pragma(user);
  if (!p) FACET_ICE("a surface program without '#pragma surface'");
  auto directive = parse_directive(*p, diags);
  FACET_TRY(directive);

  const std::string base = shader.file != kNoFile ? sources.path(shader.file) : std::string("<shader>");
  GeneratedFile probe = add_generated_file(fmt::format("{} [surface analysis{}]", base, tag),
                                           {analysis_prologue(), ""}, sources);
  auto analysis = analyze(shader, wrap(user, probe, {}), sources, diags);
  FACET_TRY(analysis);
  auto shape = read_shape(*analysis, *directive, diags);
  FACET_TRY(shape);
  std::vector<std::string> output_fields;
  if (const auto* fields = analysis->find_struct(shape->output_struct)) {
    for (const AnalyzedField& f : *fields) output_fields.push_back(f.name);
  }

  std::vector<ir::Pass> out;
  for (const PassInfo& info : passes_for(*directive, *shape, first && shader.fallback.has_value())) {
    GeneratedCode code = generate(info.kind, *directive, *shape, output_fields,
                                  [&](const std::string& name) { return declares(user, name); });
    GeneratedFile file = add_generated_file(fmt::format("{} [surface {}{}]", base, info.name, tag), code, sources);
    ir::Pass pass;
    pass.name = info.name;
    pass.tags.push_back({"LightMode", info.light_mode, directive->span});
    pass.state = pass_state(sub, info.kind, *directive);
    // The Fallback's shadow caster is Legacy VertexLit's: not tessellated.
    bool tessellated = directive->tessellated() && info.kind != GeneratedPass::fallback_shadow_caster;
    pass.program = wrap(user, file, pass_pragmas(user, info.kind, *directive, tessellated), tessellated);
    pass.program->light_mode = info.light_mode;
    pass.fallback_stand_in = info.kind == GeneratedPass::fallback_shadow_caster;
    pass.span = user.body.span;
    out.push_back(std::move(pass));
  }
  return out;
}

}  // namespace

Result<void> lower_surface_shaders(ir::Shader& shader, const ProgramAnalyzer& analyze, SourceMap& sources,
                                   Diagnostics& diags) {
  bool failed = false;
  for (size_t i = 0; i < shader.subshaders.size(); ++i) {
    ir::SubShader& sub = shader.subshaders[i];
    if (sub.surface_programs.empty()) continue;
    // Each program's passes go before the Pass written after it.
    std::vector<std::vector<ir::Pass>> before(sub.passes.size() + 1);
    for (size_t k = 0; k < sub.surface_programs.size(); ++k) {
      const ir::SurfaceProgram& sp = sub.surface_programs[k];
      std::string tag = (i ? fmt::format(" SubShader {}", i) : std::string()) +
                        (sub.surface_programs.size() > 1 ? fmt::format(" #{}", k + 1) : std::string());
      auto passes = lower_one(shader, sub, sp.program, tag, k == 0, analyze, sources, diags);
      if (!passes) {
        failed = true;
        continue;
      }
      std::vector<ir::Pass>& slot = before[std::min(sp.before_pass, sub.passes.size())];
      slot.insert(slot.end(), passes->begin(), passes->end());
    }
    std::vector<ir::Pass> ordered;
    for (size_t p = 0; p <= sub.passes.size(); ++p) {
      for (ir::Pass& generated : before[p]) ordered.push_back(std::move(generated));
      if (p < sub.passes.size()) ordered.push_back(std::move(sub.passes[p]));
    }
    sub.passes = std::move(ordered);
    sub.surface_programs.clear();
  }
  if (failed) return failure("surface shader errors");
  return {};
}

}  // namespace facet::surface
