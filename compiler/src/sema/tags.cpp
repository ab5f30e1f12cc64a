// Tags are kept as written; only the values facet interprets are checked.
#include "lower.h"
#include "facet/support/render_queue.h"
#include "facet/support/text.h"

namespace facet::sema {
namespace {

// The part of a Queue value that is wrong, for the message and its
// did-you-mean: the name, or the whole value when the offset is.
std::string queue_problem(std::string_view value) {
  value = trim(value);
  size_t sign = value.find_first_of("+-");
  if (sign == std::string_view::npos) return std::string(value);
  std::string_view name = trim(value.substr(0, sign));
  return std::string(queue_number(name) ? value : name);
}

std::string escape(std::string_view s) {
  std::string out;
  for (char c : s) {
    if (c == '"' || c == '\\') out += '\\';
    out += c;
  }
  return out;
}

}  // namespace

std::vector<ir::Tag> lower_tags(const std::vector<ast::Tag>& tags) {
  std::vector<ir::Tag> out;
  out.reserve(tags.size());
  for (const ast::Tag& t : tags) out.push_back({t.key, t.value, t.span});
  return out;
}

std::vector<ir::Tag> inherit_tags(const std::vector<ir::Tag>& outer, const std::vector<ir::Tag>& inner) {
  std::vector<ir::Tag> out;
  for (const ir::Tag& t : outer) {
    bool overridden = false;
    for (const ir::Tag& i : inner) overridden = overridden || iequals(i.key, t.key);
    if (!overridden) out.push_back(t);
  }
  out.insert(out.end(), inner.begin(), inner.end());
  return out;
}

void check_tags(const std::vector<ast::Tag>& tags, Context& ctx) {
  for (const ast::Tag& t : tags) {
    if (!iequals(t.key, "Queue")) continue;
    if (queue_number(t.value)) continue;
    const std::vector<std::string_view> names = render_queue_names();
    Diagnostic& d = ctx.error(DiagId::sema_bad_queue, t.value_span, "unknown render queue '" + t.value + "'");
    if (auto best = suggest(queue_problem(t.value), names)) {
      d.note(t.value_span, "did you mean '" + std::string(*best) + "'?");
    }
    d.note({}, "a queue is one of " + join(names) + ", optionally with an offset such as 'Geometry+1', or a number");
  }
}

void propagate_lightmode(const ast::SubShader& sub, const std::vector<ir::Tag>& sub_tags,
                         std::vector<ir::Pass>& passes, Context& ctx) {
  const ir::Tag* lightmode = nullptr;
  for (const ir::Tag& t : sub_tags) {
    if (iequals(t.key, "LightMode")) lightmode = &t;
  }
  if (!lightmode) return;
  std::string pair = "\"" + escape(lightmode->key) + "\"=\"" + escape(lightmode->value) + "\"";
  Diagnostic& d = ctx.report(DiagId::sema_lightmode_in_subshader, lightmode->span,
                             "'LightMode' is a pass tag; Unity ignores it in a SubShader's Tags");
  d.note(lightmode->span, std::string(ctx.options.propagate_subshader_lightmode
                                          ? "facet copies it into each Pass that has no LightMode; "
                                          : "") +
                              "write 'Tags { " + pair + " }' inside each Pass instead");
  d.fix(lightmode->span, "");
  for (size_t i = 0; i < passes.size() && i < sub.passes.size(); ++i) {
    const ast::Pass& src = sub.passes[i];
    ir::Pass& pass = passes[i];
    if (pass.kind != ir::PassKind::normal || !pass.tag("LightMode").empty()) continue;
    if (src.tags_brace.has_location()) {
      d.fix({src.tags_brace.file, src.tags_brace.end, src.tags_brace.end}, " " + pair);
    } else if (src.body_brace.has_location()) {
      d.fix({src.body_brace.file, src.body_brace.end, src.body_brace.end}, " Tags { " + pair + " }");
    }
    if (ctx.options.propagate_subshader_lightmode) pass.tags.push_back(*lightmode);
  }
}

}  // namespace facet::sema
