// Tags are kept as written; only the values facet interprets are checked.
#include <charconv>

#include "lower.h"
#include "facet/support/text.h"

namespace facet::sema {
namespace {

struct NamedQueue {
  std::string_view name;
  int number;
};
constexpr NamedQueue kQueues[] = {
    {"Background", 1000}, {"Geometry", 2000}, {"AlphaTest", 2450}, {"Transparent", 3000}, {"Overlay", 4000}};

std::optional<int> integer(std::string_view s) {
  int value = 0;
  auto [ptr, ec] = std::from_chars(s.data(), s.data() + s.size(), value);
  if (s.empty() || ec != std::errc() || ptr != s.data() + s.size()) return std::nullopt;
  return value;
}

std::vector<std::string_view> queue_names() {
  std::vector<std::string_view> names;
  for (const NamedQueue& q : kQueues) names.push_back(q.name);
  return names;
}

// The part of a Queue value that is wrong, for the message and its
// did-you-mean: the name, or the whole value when the offset is.
std::string queue_problem(std::string_view value) {
  value = trim(value);
  size_t sign = value.find_first_of("+-");
  if (sign == std::string_view::npos) return std::string(value);
  std::string_view name = trim(value.substr(0, sign));
  return std::string(queue_number(name) ? value : name);
}

}  // namespace

std::optional<int> queue_number(std::string_view value) {
  value = trim(value);
  if (std::optional<int> number = integer(value)) return number;
  size_t sign = value.find_first_of("+-");
  std::string_view name = trim(value.substr(0, sign));
  int offset = 0;
  if (sign != std::string_view::npos) {
    std::string_view digits = trim(value.substr(sign + 1));
    std::optional<int> magnitude = digits.empty() || digits[0] == '-' || digits[0] == '+' ? std::nullopt : integer(digits);
    if (!magnitude) return std::nullopt;
    offset = value[sign] == '-' ? -*magnitude : *magnitude;
  }
  for (const NamedQueue& q : kQueues) {
    if (iequals(q.name, name)) return q.number + offset;
  }
  return std::nullopt;
}

namespace {

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
    const std::vector<std::string_view> names = queue_names();
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
