// sema::analyze: properties, then Category scopes (outer to inner), then
// each SubShader with its passes. Render state, tags and include blocks flow
// inward: Category -> SubShader -> Pass, the inner scope winning.
#include "facet/sema.h"

#include "fixed_function.h"
#include "facet/support/render_queue.h"
#include "lower.h"

namespace facet::sema {
namespace {

// What an enclosing scope hands to the scopes inside it.
struct Scope {
  ir::RenderState state;
  std::vector<ir::Tag> tags;
  std::vector<const ast::ProgramBlock*> includes;  // Shader scope first
  std::optional<int> lod;                          // the innermost Category's LOD
};

std::vector<const ast::ProgramBlock*> with_includes(std::vector<const ast::ProgramBlock*> outer,
                                                    const std::vector<ast::ProgramBlock>& inner) {
  for (const ast::ProgramBlock& b : inner) outer.push_back(&b);
  return outer;
}

// Categories are stored parents-first, so one pass in index order resolves
// each one's inherited scope.
std::vector<Scope> lower_categories(const ast::Shader& shader, const Scope& root, Context& ctx) {
  std::vector<Scope> out(shader.categories.size());
  for (size_t i = 0; i < shader.categories.size(); ++i) {
    const ast::Category& c = shader.categories[i];
    const Scope& base = (c.parent >= 0 && size_t(c.parent) < i) ? out[size_t(c.parent)] : root;
    check_tags(c.tags, ctx);
    out[i].state = merge_state(base.state, lower_state(c.state, ctx));
    out[i].tags = inherit_tags(base.tags, lower_tags(c.tags));
    out[i].includes = with_includes(base.includes, c.includes);
    out[i].lod = c.lod ? c.lod : base.lod;
  }
  return out;
}

const ir::Pragma* find_pragma(const ir::Program& program, std::string_view name) {
  for (const ir::Pragma& p : program.pragmas) {
    if (p.name == name) return &p;
  }
  return nullptr;
}

ir::Pass lower_normal_pass(const ast::Pass& p, const ir::SubShader& sub,
                           const std::vector<const ast::ProgramBlock*>& includes, Context& ctx) {
  ir::Pass out;
  check_tags(p.tags, ctx);
  out.tags = lower_tags(p.tags);
  out.state = merge_state(sub.state, lower_state(p.state, ctx));
  if (!p.program) return out;
  out.program = lower_program(*p.program, includes, ctx);
  if (const ir::Pragma* surface = find_pragma(*out.program, "surface")) {
    ctx.error(DiagId::sema_surface_in_pass, surface->span, "a surface shader cannot be inside a Pass")
        .note(p.span, "move the program block out of this Pass, directly into the SubShader");
    out.program->surface_function.clear();
  }
  return out;
}

ir::Pass lower_pass(const ast::Pass& p, const ir::SubShader& sub, const std::vector<const ast::ProgramBlock*>& includes,
                    Context& ctx) {
  ir::Pass out;
  switch (p.kind) {
    case ast::PassKind::normal: out = lower_normal_pass(p, sub, includes, ctx); break;
    case ast::PassKind::use_pass: {
      out.kind = ir::PassKind::use_pass;
      out.use_pass = p.use_pass;
      size_t slash = p.use_pass.rfind('/');
      if (slash == std::string::npos || slash == 0 || slash + 1 == p.use_pass.size()) {
        ctx.error(DiagId::sema_bad_use_pass, p.span, "expected \"Shader/PASSNAME\" after 'UsePass', not \"" + p.use_pass + "\"");
      } else {
        out.name = p.use_pass.substr(slash + 1);
      }
      break;
    }
    case ast::PassKind::grab_pass:
      out.kind = ir::PassKind::grab_pass;
      out.grab_texture = p.grab_texture;
      out.tags = lower_tags(p.tags);
      break;
  }
  if (p.kind != ast::PassKind::use_pass) out.name = p.name;
  out.span = p.span;
  return out;
}

// Program blocks directly in a SubShader are surface shaders; there may be
// several (Unity lowers each into its own passes, in file order: multi-layer
// fur and outline shaders stack them).
void lower_surface_programs(const ast::SubShader& sub, const std::vector<const ast::ProgramBlock*>& includes,
                            ir::SubShader& out, Context& ctx) {
  for (const ast::ProgramBlock& block : sub.programs) {
    ir::Program program = lower_program(block, includes, ctx);
    if (!program.is_surface()) {
      ctx.error(DiagId::sema_program_outside_pass, block.keyword_span,
                "a program block outside a Pass must be a surface shader")
          .note({}, "add '#pragma surface surf Lambert' (or your functions), or put the program in a Pass");
    }
    size_t before = 0;
    while (before < sub.passes.size() && sub.passes[before].span.begin < block.keyword_span.begin) ++before;
    out.surface_programs.push_back({.program = std::move(program), .before_pass = before});
  }
}

ir::SubShader lower_subshader(const ast::SubShader& sub, const Scope& scope, Context& ctx) {
  ir::SubShader out;
  check_tags(sub.tags, ctx);
  out.tags = inherit_tags(scope.tags, lower_tags(sub.tags));
  out.lod = sub.lod.value_or(scope.lod.value_or(0));
  for (const ir::Tag& tag : out.tags) {
    if (!iequals(tag.key, "Queue")) continue;
    if (std::optional<int> queue = queue_number(tag.value)) out.queue = *queue;
  }
  out.state = merge_state(scope.state, lower_state(sub.state, ctx));
  out.span = sub.span;
  auto includes = with_includes(scope.includes, sub.includes);
  lower_surface_programs(sub, includes, out, ctx);
  for (const ast::Pass& p : sub.passes) out.passes.push_back(lower_pass(p, out, includes, ctx));
  propagate_lightmode(sub, out.tags, out.passes, ctx);
  return out;
}

}  // namespace

Result<ir::Shader> analyze(const ast::Shader& shader, const SourceMap& sources, const SemaOptions& options,
                           Diagnostics& diags) {
  Context ctx{sources, options, diags};
  ir::Shader out;
  out.name = shader.name;
  out.file = shader.file;
  out.span = shader.span;
  out.custom_editor = shader.custom_editor;
  if (shader.fallback && !shader.fallback_off && !iequals(*shader.fallback, "Off")) {
    out.fallback = shader.fallback;
    out.fallback_span = shader.fallback_span;
  }
  out.properties = lower_properties(shader.properties, ctx);
  for (const ir::Property& p : out.properties) ctx.property_names.push_back(p.name);
  Scope root;
  root.includes = with_includes({}, shader.includes);
  std::vector<Scope> categories = lower_categories(shader, root, ctx);
  for (const ast::SubShader& sub : shader.subshaders) {
    bool in_category = sub.category >= 0 && size_t(sub.category) < categories.size();
    out.subshaders.push_back(lower_subshader(sub, in_category ? categories[size_t(sub.category)] : root, ctx));
    lower_fixed_function_passes(shader, sub, out.subshaders.size() - 1, out.subshaders.back(), ctx);
    for (ir::Pass& pass : out.subshaders.back().passes) {
      if (pass.program) pass.program->light_mode = pass.tag("LightMode");
    }
  }
  if (ctx.errors > 0) return failure(std::to_string(ctx.errors) + " error(s) in '" + shader.name + "'");
  return out;
}

}  // namespace facet::sema
