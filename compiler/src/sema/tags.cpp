// Tags are kept as written; only the values facet interprets are checked.
#include <charconv>

#include "lower.h"
#include "facet/support/text.h"

namespace facet::sema {
namespace {

constexpr std::string_view kQueues[] = {"Background", "Geometry", "AlphaTest", "Transparent", "Overlay"};

bool is_integer(std::string_view s) {
  int value = 0;
  auto [ptr, ec] = std::from_chars(s.data(), s.data() + s.size(), value);
  return !s.empty() && ec == std::errc() && ptr == s.data() + s.size();
}

// "Geometry", "Geometry+1", "Transparent-100", "2450"; returns the queue's
// name part when that is what is wrong, "" when the value is fine.
std::optional<std::string> queue_problem(std::string_view value) {
  value = trim(value);
  if (is_integer(value)) return std::nullopt;
  size_t sign = value.find_first_of("+-");
  std::string_view name = trim(value.substr(0, sign));
  if (sign != std::string_view::npos) {
    std::string_view offset = trim(value.substr(sign + 1));
    if (!is_integer(offset) || offset[0] == '-' || offset[0] == '+') return std::string(value);
  }
  for (std::string_view q : kQueues) {
    if (iequals(q, name)) return std::nullopt;
  }
  return std::string(name);
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
    auto problem = queue_problem(t.value);
    if (!problem) continue;
    Diagnostic& d = ctx.error(DiagId::sema_bad_queue, t.value_span, "unknown render queue '" + t.value + "'");
    if (auto best = suggest(*problem, kQueues)) d.note(t.value_span, "did you mean '" + std::string(*best) + "'?");
    d.note({}, "a queue is one of " + join(kQueues) + ", optionally with an offset such as 'Geometry+1', or a number");
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
