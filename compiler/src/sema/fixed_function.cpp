// A Pass with no program block but fixed-function commands in scope gets a
// generated program, as Unity generates one at import: the commands of the
// enclosing Categories (outer first), the SubShader and the Pass are applied
// in that order, so the inner scope wins per command.
#include <algorithm>

#include "fixed_function.h"

namespace facet::sema {
namespace {

std::vector<const ast::LegacyCommand*> legacy_of(const std::vector<ast::IgnoredCommand>& ignored) {
  std::vector<const ast::LegacyCommand*> out;
  for (const ast::IgnoredCommand& c : ignored) {
    if (c.legacy) out.push_back(&*c.legacy);
  }
  return out;
}

// The scopes around the passes of `sub`, outermost first.
std::vector<std::vector<const ast::LegacyCommand*>> enclosing_scopes(const ast::Shader& shader,
                                                                     const ast::SubShader& sub) {
  std::vector<std::vector<const ast::LegacyCommand*>> out;
  // Categories point at their parents; a bad index ends the walk.
  for (int c = sub.category; c >= 0 && size_t(c) < shader.categories.size() && out.size() <= shader.categories.size();
       c = shader.categories[size_t(c)].parent) {
    out.push_back(legacy_of(shader.categories[size_t(c)].ignored));
  }
  std::reverse(out.begin(), out.end());
  out.push_back(legacy_of(sub.ignored));
  return out;
}

// How the stage samples its texture: the property's type and its legacy
// texture options ("_Cube ("Cube", Cube) = "" { TexGen CubeReflect }").
FfTexture describe_texture(const ast::Shader& shader, const std::string& name) {
  FfTexture t{name, FfTextureKind::tex2d, ""};
  for (const ast::Property& p : shader.properties) {
    if (p.name != name) continue;
    if (iequals(p.type, "Cube")) t.kind = FfTextureKind::cube;
    else if (iequals(p.type, "3D")) t.kind = FfTextureKind::tex3d;
    const std::string& options = p.default_value.texture_options;
    if (t.kind == FfTextureKind::cube && options.find("CubeReflect") != std::string::npos) t.texgen = "CubeReflect";
    if (t.kind == FfTextureKind::cube && options.find("CubeNormal") != std::string::npos) t.texgen = "CubeNormal";
  }
  return t;
}

ir::Program make_program(const ast::Shader& shader, const ast::Pass& pass, const FixedFunctionState& state,
                         const std::string& title, Context& ctx) {
  std::vector<FfTexture> textures;
  for (const FfStage& stage : state.stages) textures.push_back(describe_texture(shader, stage.texture));
  std::string file = ctx.sources.path(shader.file) + "[" + title + "]";
  ir::Program program;
  program.language = ir::ProgramLanguage::cg;
  // The text is not in the .shader file: its span is the Pass, so that errors
  // in it point there, and `#line` names a file of its own.
  program.body = {generate_fixed_function_hlsl(state, textures, title), pass.span, 1, file};
  ctx.program_bytes += program.body.text.size();
  program.pragmas.push_back({"vertex", {"ff_vert"}, pass.span});
  program.pragmas.push_back({"fragment", {"ff_frag"}, pass.span});
  if (state.fog == FfFog::global) program.pragmas.push_back({"multi_compile_fog", {}, pass.span});
  program.entry_points[size_t(Stage::vertex)] = "ff_vert";
  program.entry_points[size_t(Stage::fragment)] = "ff_frag";
  return program;
}

}  // namespace

void lower_fixed_function_passes(const ast::Shader& shader, const ast::SubShader& sub, size_t sub_index,
                                 ir::SubShader& out, Context& ctx) {
  auto scopes = enclosing_scopes(shader, sub);
  bool scope_has_commands = std::any_of(scopes.begin(), scopes.end(), [](const auto& s) { return !s.empty(); });
  std::optional<FixedFunctionState> inherited;  // read once, when a pass needs it
  for (size_t i = 0; i < sub.passes.size() && i < out.passes.size(); ++i) {
    const ast::Pass& pass = sub.passes[i];
    if (pass.kind != ast::PassKind::normal || pass.program) continue;
    auto commands = legacy_of(pass.ignored);
    if (commands.empty() && !scope_has_commands) continue;
    if (!inherited) {
      inherited.emplace();
      for (const auto& scope : scopes) apply_legacy_commands(scope, *inherited, ctx);
    }
    FixedFunctionState state = *inherited;
    apply_legacy_commands(commands, state, ctx);
    std::string title = "fixed-function subshader " + std::to_string(sub_index) + " pass " + std::to_string(i);
    out.passes[i].program = make_program(shader, pass, state, title, ctx);
  }
}

}  // namespace facet::sema
