// Render state: every literal is checked against its command's values and
// rewritten in canonical spelling ("lequal" -> "LEqual"); `[_Prop]` stays a
// symbolic reference that the material resolves at draw time.
#include <array>
#include <cmath>
#include <cstdlib>
#include <map>

#include "lower.h"

namespace facet::sema {
namespace {

using Values = std::span<const std::string_view>;

constexpr std::string_view kCull[] = {"Back", "Front", "Off"};
constexpr std::string_view kCompare[] = {"Less", "Greater", "LEqual", "GEqual", "Equal", "NotEqual", "Always", "Never"};
// Unity accepts either pair of words for every boolean command.
constexpr std::string_view kBooleans[] = {"On", "Off", "True", "False"};
struct BooleanSpelling {
  std::string_view yes, no;
};
constexpr BooleanSpelling kOnOff{"On", "Off"};
constexpr BooleanSpelling kTrueFalse{"True", "False"};
constexpr std::string_view kBlendFactors[] = {
    "One", "Zero", "SrcColor", "SrcAlpha", "SrcAlphaSaturate", "DstColor", "DstAlpha",
    "OneMinusSrcColor", "OneMinusSrcAlpha", "OneMinusDstColor", "OneMinusDstAlpha"};
constexpr std::string_view kBlendOps[] = {
    "Add", "Sub", "RevSub", "Min", "Max",
    "LogicalClear", "LogicalSet", "LogicalCopy", "LogicalCopyInverted", "LogicalNoop", "LogicalInvert",
    "LogicalAnd", "LogicalNand", "LogicalOr", "LogicalNor", "LogicalXor", "LogicalEquiv",
    "LogicalAndReverse", "LogicalAndInverted", "LogicalOrReverse", "LogicalOrInverted",
    "Multiply", "Screen", "Overlay", "Darken", "Lighten", "ColorDodge", "ColorBurn", "HardLight",
    "SoftLight", "Difference", "Exclusion", "HSLHue", "HSLSaturation", "HSLColor", "HSLLuminosity"};
constexpr std::string_view kStencilOps[] = {"Keep", "Zero", "Replace", "IncrSat", "DecrSat", "Invert",
                                            "IncrWrap", "DecrWrap"};

ir::StateValue symbolic(const ast::Value& v, Context& ctx) {
  check_property_reference(v.text, v.span, ctx);
  return {"", v.text, v.span};
}

// A word from `values`, in canonical spelling.
std::optional<ir::StateValue> word_value(const ast::Value& v, Values values, std::string_view command, Context& ctx) {
  if (v.kind == ast::Value::Kind::property) return symbolic(v, ctx);
  if (v.kind == ast::Value::Kind::word) {
    for (std::string_view w : values) {
      if (iequals(w, v.text)) return ir::StateValue{std::string(w), "", v.span};
    }
  }
  Diagnostic& d = ctx.error(DiagId::sema_unknown_state_value, v.span,
                            "unknown value '" + v.text + "' for '" + std::string(command) + "'");
  if (auto best = suggest(v.text, values)) {
    d.note(v.span, "did you mean '" + std::string(*best) + "'?");
    d.fix(v.span, std::string(*best));
  }
  d.note({}, "valid values are " + join(values) + ", or a property as in '[_Prop]'");
  return std::nullopt;
}

// On/Off/True/False, written in the command's own canonical pair.
std::optional<ir::StateValue> bool_value(const ast::Value& v, BooleanSpelling spelling, std::string_view command,
                                         Context& ctx) {
  auto word = word_value(v, kBooleans, command, ctx);
  if (!word || word->is_property()) return word;
  bool yes = word->literal == "On" || word->literal == "True";
  word->literal = std::string(yes ? spelling.yes : spelling.no);
  return word;
}

// "ZTest Off" is Unity's alias of "ZTest Always", "ZTest On" of the default
// "LEqual".
std::optional<ir::StateValue> compare_value(const ast::Value& v, std::string_view command, Context& ctx) {
  if (v.kind == ast::Value::Kind::word && iequals(v.text, "Off")) return ir::StateValue{"Always", "", v.span};
  if (v.kind == ast::Value::Kind::word && iequals(v.text, "On")) return ir::StateValue{"LEqual", "", v.span};
  return word_value(v, kCompare, command, ctx);
}

// An integer literal in [lo, hi], printed canonically.
std::optional<ir::StateValue> int_value(const ast::Value& v, long lo, long hi, std::string_view command,
                                        Context& ctx) {
  if (v.kind == ast::Value::Kind::property) return symbolic(v, ctx);
  char* end = nullptr;
  double x = v.kind == ast::Value::Kind::number ? std::strtod(v.text.c_str(), &end) : 0;
  bool ok = end && *end == '\0' && x >= double(lo) && x <= double(hi) && x == std::floor(x);
  if (ok) return ir::StateValue{std::to_string(long(x)), "", v.span};
  ctx.error(DiagId::sema_unknown_state_value, v.span,
            "'" + std::string(command) + "' expects an integer from " + std::to_string(lo) + " to " +
                std::to_string(hi) + ", not '" + v.text + "'")
      .note({}, "a property as in '[_Prop]' is also accepted");
  return std::nullopt;
}

std::optional<ir::StateValue> number_value(const ast::Value& v, std::string_view command, Context& ctx) {
  if (v.kind == ast::Value::Kind::property) return symbolic(v, ctx);
  if (v.kind == ast::Value::Kind::number) return ir::StateValue{v.text, "", v.span};
  ctx.error(DiagId::sema_unknown_state_value, v.span,
            "'" + std::string(command) + "' expects a number or '[_Prop]', not '" + v.text + "'");
  return std::nullopt;
}

// "0", or letters of RGBA each at most once, rewritten in RGBA order.
std::optional<ir::StateValue> color_mask_value(const ast::Value& v, Context& ctx) {
  if (v.kind == ast::Value::Kind::property) return symbolic(v, ctx);
  if (v.kind == ast::Value::Kind::number && v.text == "0") return ir::StateValue{"0", "", v.span};
  static constexpr std::string_view kChannels = "RGBA";
  std::array<bool, 4> used{};
  bool ok = v.kind == ast::Value::Kind::word && !v.text.empty();
  for (char c : v.text) {
    size_t i = kChannels.find(char(c >= 'a' && c <= 'z' ? c - 'a' + 'A' : c));
    if (i == std::string_view::npos || used[i]) ok = false;
    else used[i] = true;
  }
  if (!ok) {
    ctx.error(DiagId::sema_unknown_state_value, v.span, "unknown value '" + v.text + "' for 'ColorMask'")
        .note({}, "valid values are 0 or any of R, G, B, A in one word (RGB, A, RGBA), or '[_Prop]'");
    return std::nullopt;
  }
  std::string canonical;
  for (size_t i = 0; i < 4; ++i) {
    if (used[i]) canonical += kChannels[i];
  }
  return ir::StateValue{canonical, "", v.span};
}

int render_target(const ast::Command& c, Context& ctx) {
  if (!c.render_target) return -1;
  const ast::Value& v = *c.render_target;
  char* end = nullptr;
  double x = std::strtod(v.text.c_str(), &end);
  if (*end == '\0' && x >= 0 && x <= 7 && x == std::floor(x)) return int(x);
  ctx.error(DiagId::sema_bad_render_target, v.span, "render target index must be an integer from 0 to 7, not '" + v.text + "'");
  return -1;
}

// The per-render-target lists: an entry for all targets replaces every
// entry; an entry for target N replaces target N's.
template <typename T>
void apply_per_target(std::vector<T>& list, const T& entry) {
  if (entry.render_target < 0) list.clear();
  std::erase_if(list, [&](const T& e) { return e.render_target == entry.render_target; });
  list.push_back(entry);
}

class StateLowering {
 public:
  explicit StateLowering(Context& ctx) : ctx_(ctx) {}

  void command(const ast::Command& c) {
    // The parser guarantees each command's arity; an AST built by hand that
    // breaks it is skipped rather than read out of bounds.
    size_t needed = c.kind == ast::CommandKind::stencil ? 0 : c.kind == ast::CommandKind::offset ? 2 : 1;
    if (c.values.size() < needed) return;
    std::string_view name = shaderlab::command_name(c.kind);
    check_duplicate(c, name);
    switch (c.kind) {
      case ast::CommandKind::cull: set(state_.cull, word_value(c.values[0], kCull, name, ctx_)); break;
      case ast::CommandKind::ztest: set(state_.ztest, compare_value(c.values[0], name, ctx_)); break;
      case ast::CommandKind::zwrite: set(state_.zwrite, bool_value(c.values[0], kOnOff, name, ctx_)); break;
      case ast::CommandKind::alpha_to_mask: set(state_.alpha_to_mask, bool_value(c.values[0], kOnOff, name, ctx_)); break;
      case ast::CommandKind::zclip: set(state_.zclip, bool_value(c.values[0], kTrueFalse, name, ctx_)); break;
      case ast::CommandKind::conservative: set(state_.conservative, bool_value(c.values[0], kTrueFalse, name, ctx_)); break;
      case ast::CommandKind::offset:
        set(state_.offset_factor, number_value(c.values[0], name, ctx_));
        set(state_.offset_units, number_value(c.values[1], name, ctx_));
        break;
      case ast::CommandKind::blend: blend(c); break;
      case ast::CommandKind::blend_op: blend_op(c); break;
      case ast::CommandKind::color_mask: color_mask(c); break;
      case ast::CommandKind::stencil: stencil(c); break;
    }
  }

  ir::RenderState take() { return std::move(state_); }

 private:
  static void set(std::optional<ir::StateValue>& field, std::optional<ir::StateValue> v) {
    if (v) field = std::move(v);
  }

  void check_duplicate(const ast::Command& c, std::string_view name) {
    std::string key(name);
    if (c.render_target) key += " " + c.render_target->text;
    auto [it, inserted] = seen_.emplace(key, c.span);
    if (inserted) return;
    ctx_.report(DiagId::sema_duplicate_state, c.span, "'" + key + "' is set twice in this block; the last one wins")
        .note(it->second, "first set here");
    it->second = c.span;
  }

  void blend(const ast::Command& c) {
    ir::BlendState b;
    b.render_target = render_target(c, ctx_);
    if (c.values.size() < 2) {  // the parser only lets "Off" stand alone
      b.off = true;
    } else {
      auto src = word_value(c.values[0], kBlendFactors, "Blend", ctx_);
      auto dst = word_value(c.values[1], kBlendFactors, "Blend", ctx_);
      if (!src || !dst) return;
      b.src = *src;
      b.dst = *dst;
      if (c.values.size() >= 4) {
        b.src_alpha = word_value(c.values[2], kBlendFactors, "Blend", ctx_);
        b.dst_alpha = word_value(c.values[3], kBlendFactors, "Blend", ctx_);
        if (!b.src_alpha || !b.dst_alpha) return;
      }
    }
    apply_per_target(state_.blend, b);
  }

  void blend_op(const ast::Command& c) {
    ir::BlendOpState b;
    b.render_target = render_target(c, ctx_);
    auto op = word_value(c.values[0], kBlendOps, "BlendOp", ctx_);
    if (!op) return;
    b.color_op = *op;
    if (c.values.size() >= 2) {
      b.alpha_op = word_value(c.values[1], kBlendOps, "BlendOp", ctx_);
      if (!b.alpha_op) return;
    }
    apply_per_target(state_.blend_op, b);
  }

  void color_mask(const ast::Command& c) {
    ir::ColorMaskState m;
    m.render_target = render_target(c, ctx_);
    auto mask = color_mask_value(c.values[0], ctx_);
    if (!mask) return;
    m.mask = *mask;
    apply_per_target(state_.color_mask, m);
  }

  void stencil(const ast::Command& c) {
    ir::StencilState s;
    s.span = c.span;
    for (const ast::StencilField& f : c.stencil) {
      if (auto* field = stencil_field(s, f.name)) *field = stencil_value(f);
    }
    state_.stencil = std::move(s);
  }

  static std::optional<ir::StateValue>* stencil_field(ir::StencilState& s, std::string_view name) {
    struct Field {
      std::string_view name;
      std::optional<ir::StateValue> ir::StencilState::*member;
    };
    static constexpr Field kFields[] = {
        {"Ref", &ir::StencilState::ref}, {"ReadMask", &ir::StencilState::read_mask},
        {"WriteMask", &ir::StencilState::write_mask}, {"Comp", &ir::StencilState::comp},
        {"Pass", &ir::StencilState::pass}, {"Fail", &ir::StencilState::fail},
        {"ZFail", &ir::StencilState::zfail}, {"CompBack", &ir::StencilState::comp_back},
        {"PassBack", &ir::StencilState::pass_back}, {"FailBack", &ir::StencilState::fail_back},
        {"ZFailBack", &ir::StencilState::zfail_back}, {"CompFront", &ir::StencilState::comp_front},
        {"PassFront", &ir::StencilState::pass_front}, {"FailFront", &ir::StencilState::fail_front},
        {"ZFailFront", &ir::StencilState::zfail_front},
    };
    for (const Field& f : kFields) {
      if (iequals(f.name, name)) return &(s.*f.member);
    }
    return nullptr;  // the parser accepts only the names above
  }

  std::optional<ir::StateValue> stencil_value(const ast::StencilField& f) {
    std::string command = "Stencil " + f.name;
    if (iequals(f.name, "Ref") || iequals(f.name, "ReadMask") || iequals(f.name, "WriteMask")) {
      return stencil_byte(f.value, command);
    }
    bool comparison = f.name.size() >= 4 && iequals(std::string_view(f.name).substr(0, 4), "Comp");
    return word_value(f.value, comparison ? Values(kCompare) : Values(kStencilOps), command, ctx_);
  }

  // Unity takes any 32-bit value here (D3D's StencilRef is a UINT) and the
  // GPU compares only the stencil buffer's 8 bits, so a wider value is kept
  // as its low byte, with a warning, rather than refused.
  std::optional<ir::StateValue> stencil_byte(const ast::Value& v, const std::string& command) {
    constexpr long kMax32 = 4294967295L;
    std::optional<ir::StateValue> wide = v.kind == ast::Value::Kind::number && !v.text.empty() && v.text[0] != '-'
                                             ? int_value(v, 0, kMax32, command, ctx_)
                                             : int_value(v, 0, 255, command, ctx_);
    if (!wide || wide->is_property()) return wide;
    long value = std::stol(wide->literal);
    if (value <= 255) return wide;
    std::string low = std::to_string(value & 0xFF);
    ctx_.report(DiagId::sema_stencil_value_truncated, v.span,
                "'" + command + " " + v.text + "' is wider than the 8-bit stencil buffer; its low 8 bits, " + low +
                    ", are used")
        .note({}, "write a value from 0 to 255 to say which bits are meant");
    wide->literal = low;
    return wide;
  }

  Context& ctx_;
  ir::RenderState state_;
  std::map<std::string, SourceSpan> seen_;
};

template <typename T>
void overlay_list(std::vector<T>& base, const std::vector<T>& overlay) {
  for (const T& e : overlay) apply_per_target(base, e);
}

void overlay_field(std::optional<ir::StateValue>& base, const std::optional<ir::StateValue>& overlay) {
  if (overlay) base = overlay;
}

}  // namespace

ir::RenderState lower_state(const std::vector<ast::Command>& commands, Context& ctx) {
  StateLowering lowering(ctx);
  for (const ast::Command& c : commands) lowering.command(c);
  return lowering.take();
}

ir::RenderState merge_state(const ir::RenderState& base, const ir::RenderState& overlay) {
  ir::RenderState out = base;
  overlay_field(out.cull, overlay.cull);
  overlay_field(out.ztest, overlay.ztest);
  overlay_field(out.zwrite, overlay.zwrite);
  overlay_field(out.alpha_to_mask, overlay.alpha_to_mask);
  overlay_field(out.zclip, overlay.zclip);
  overlay_field(out.conservative, overlay.conservative);
  overlay_field(out.offset_factor, overlay.offset_factor);
  overlay_field(out.offset_units, overlay.offset_units);
  overlay_list(out.blend, overlay.blend);
  overlay_list(out.blend_op, overlay.blend_op);
  overlay_list(out.color_mask, overlay.color_mask);
  if (overlay.stencil) out.stencil = overlay.stencil;
  return out;
}

}  // namespace facet::sema
