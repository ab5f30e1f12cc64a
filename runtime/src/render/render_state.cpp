#include "facet/runtime/render_state.h"

#include <fmt/format.h>

#include <array>
#include <cmath>
#include <optional>
#include <string_view>

namespace facet::runtime {
namespace {

template <typename T>
struct Word {
  std::string_view name;
  T value;
};

// Unity's enum order is the position in each table (CompareFunction starts at 1: 0 is Disabled).
constexpr std::array<Word<VkCompareOp>, 8> kCompare = {{{"Never", VK_COMPARE_OP_NEVER},
                                                         {"Less", VK_COMPARE_OP_LESS},
                                                         {"Equal", VK_COMPARE_OP_EQUAL},
                                                         {"LEqual", VK_COMPARE_OP_LESS_OR_EQUAL},
                                                         {"Greater", VK_COMPARE_OP_GREATER},
                                                         {"NotEqual", VK_COMPARE_OP_NOT_EQUAL},
                                                         {"GEqual", VK_COMPARE_OP_GREATER_OR_EQUAL},
                                                         {"Always", VK_COMPARE_OP_ALWAYS}}};
constexpr std::array<Word<VkBlendFactor>, 11> kFactors = {{{"Zero", VK_BLEND_FACTOR_ZERO},
                                                            {"One", VK_BLEND_FACTOR_ONE},
                                                            {"DstColor", VK_BLEND_FACTOR_DST_COLOR},
                                                            {"SrcColor", VK_BLEND_FACTOR_SRC_COLOR},
                                                            {"OneMinusDstColor", VK_BLEND_FACTOR_ONE_MINUS_DST_COLOR},
                                                            {"SrcAlpha", VK_BLEND_FACTOR_SRC_ALPHA},
                                                            {"OneMinusSrcColor", VK_BLEND_FACTOR_ONE_MINUS_SRC_COLOR},
                                                            {"DstAlpha", VK_BLEND_FACTOR_DST_ALPHA},
                                                            {"OneMinusDstAlpha", VK_BLEND_FACTOR_ONE_MINUS_DST_ALPHA},
                                                            {"SrcAlphaSaturate", VK_BLEND_FACTOR_SRC_ALPHA_SATURATE},
                                                            {"OneMinusSrcAlpha", VK_BLEND_FACTOR_ONE_MINUS_SRC_ALPHA}}};
constexpr std::array<Word<VkBlendOp>, 5> kOps = {{{"Add", VK_BLEND_OP_ADD},
                                                  {"Sub", VK_BLEND_OP_SUBTRACT},
                                                  {"RevSub", VK_BLEND_OP_REVERSE_SUBTRACT},
                                                  {"Min", VK_BLEND_OP_MIN},
                                                  {"Max", VK_BLEND_OP_MAX}}};
constexpr std::array<Word<VkStencilOp>, 8> kStencilOps = {{{"Keep", VK_STENCIL_OP_KEEP},
                                                            {"Zero", VK_STENCIL_OP_ZERO},
                                                            {"Replace", VK_STENCIL_OP_REPLACE},
                                                            {"IncrSat", VK_STENCIL_OP_INCREMENT_AND_CLAMP},
                                                            {"DecrSat", VK_STENCIL_OP_DECREMENT_AND_CLAMP},
                                                            {"Invert", VK_STENCIL_OP_INVERT},
                                                            {"IncrWrap", VK_STENCIL_OP_INCREMENT_AND_WRAP},
                                                            {"DecrWrap", VK_STENCIL_OP_DECREMENT_AND_WRAP}}};

constexpr float kLargestStateNumber = 1 << 24;

struct Resolver {
  const Material& material;
  std::optional<std::string> error;

  void fail(std::string_view command, std::string what) {
    if (!error) error = fmt::format("{}: {}", command, what);
  }

  std::string name_of(const ir::StateValue& v) const {
    std::string n = v.property;
    if (n.size() > 2 && n.front() == '[' && n.back() == ']') n = n.substr(1, n.size() - 2);
    return n;
  }

  // The property's value as Unity's enum index.
  std::optional<int> number(std::string_view command, const ir::StateValue& v) {
    std::optional<float> value = state_property(material, name_of(v));
    if (!value) {
      fail(command, fmt::format("the material has no number property '{}'", name_of(v)));
      return std::nullopt;
    }
    // An enum index or a mask is a small integer; a value past int (1e30,
    // 2^31) would wrap or convert to 0, and so pick a state nobody wrote.
    if (!std::isfinite(*value) || std::fabs(*value) > kLargestStateNumber) {
      fail(command, fmt::format("property '{}' = {} is out of range", name_of(v), *value));
      return std::nullopt;
    }
    return int(std::lround(*value));
  }

  template <typename T, size_t N>
  T word(std::string_view command, const ir::StateValue& v, const std::array<Word<T>, N>& words, int first_index,
         T fallback) {
    if (v.is_property()) {
      std::optional<int> n = number(command, v);
      if (!n) return fallback;
      int i = *n - first_index;
      if (i < 0 || i >= int(N)) {
        fail(command, fmt::format("property '{}' = {} is out of range", name_of(v), *n));
        return fallback;
      }
      return words[size_t(i)].value;
    }
    for (const Word<T>& w : words) {
      if (w.name == v.literal) return w.value;
    }
    fail(command, fmt::format("unsupported value '{}'", v.literal));
    return fallback;
  }

  float scalar(std::string_view command, const ir::StateValue& v) {
    if (v.is_property()) {
      std::optional<float> value = state_property(material, name_of(v));
      if (!value) fail(command, fmt::format("the material has no number property '{}'", name_of(v)));
      return value.value_or(0);
    }
    try {
      return std::stof(v.literal);
    } catch (...) {
      fail(command, fmt::format("'{}' is not a number", v.literal));
      return 0;
    }
  }

  bool on_off(std::string_view command, const ir::StateValue& v) {
    if (v.is_property()) return number(command, v).value_or(1) != 0;
    return v.literal == "On" || v.literal == "True";
  }

  VkCullModeFlags cull(const ir::StateValue& v) {
    if (v.is_property()) {  // CullMode: 0 Off, 1 Front, 2 Back
      int n = number("Cull", v).value_or(2);
      return n == 0 ? VK_CULL_MODE_NONE : n == 1 ? VK_CULL_MODE_FRONT_BIT : VK_CULL_MODE_BACK_BIT;
    }
    if (v.literal == "Off") return VK_CULL_MODE_NONE;
    if (v.literal == "Front") return VK_CULL_MODE_FRONT_BIT;
    return VK_CULL_MODE_BACK_BIT;
  }

  VkColorComponentFlags color_mask(const ir::StateValue& v) {
    if (v.is_property()) {  // ColorWriteMask: A 1, B 2, G 4, R 8
      int n = number("ColorMask", v).value_or(15);
      VkColorComponentFlags f = 0;
      if (n & 8) f |= VK_COLOR_COMPONENT_R_BIT;
      if (n & 4) f |= VK_COLOR_COMPONENT_G_BIT;
      if (n & 2) f |= VK_COLOR_COMPONENT_B_BIT;
      if (n & 1) f |= VK_COLOR_COMPONENT_A_BIT;
      return f;
    }
    VkColorComponentFlags f = 0;
    for (char c : v.literal) {
      if (c == 'R' || c == 'r') f |= VK_COLOR_COMPONENT_R_BIT;
      if (c == 'G' || c == 'g') f |= VK_COLOR_COMPONENT_G_BIT;
      if (c == 'B' || c == 'b') f |= VK_COLOR_COMPONENT_B_BIT;
      if (c == 'A' || c == 'a') f |= VK_COLOR_COMPONENT_A_BIT;
    }
    return f;
  }

  void stencil(const ir::StencilState& s, PipelineState& out) {
    out.stencil = true;
    uint32_t ref = s.ref ? uint32_t(scalar("Stencil Ref", *s.ref)) : 0;
    uint32_t read = s.read_mask ? uint32_t(scalar("Stencil ReadMask", *s.read_mask)) : 255;
    uint32_t write = s.write_mask ? uint32_t(scalar("Stencil WriteMask", *s.write_mask)) : 255;
    auto face = [&](const std::optional<ir::StateValue>& comp, const std::optional<ir::StateValue>& pass,
                    const std::optional<ir::StateValue>& fail_op, const std::optional<ir::StateValue>& zfail) {
      VkStencilOpState f{};
      f.compareOp = comp ? word("Stencil Comp", *comp, kCompare, 1, VK_COMPARE_OP_ALWAYS) : VK_COMPARE_OP_ALWAYS;
      f.passOp = pass ? word("Stencil Pass", *pass, kStencilOps, 0, VK_STENCIL_OP_KEEP) : VK_STENCIL_OP_KEEP;
      f.failOp = fail_op ? word("Stencil Fail", *fail_op, kStencilOps, 0, VK_STENCIL_OP_KEEP) : VK_STENCIL_OP_KEEP;
      f.depthFailOp = zfail ? word("Stencil ZFail", *zfail, kStencilOps, 0, VK_STENCIL_OP_KEEP) : VK_STENCIL_OP_KEEP;
      f.reference = ref;
      f.compareMask = read;
      f.writeMask = write;
      return f;
    };
    auto pick = [](const std::optional<ir::StateValue>& sided, const std::optional<ir::StateValue>& both) {
      return sided ? sided : both;
    };
    out.front = face(pick(s.comp_front, s.comp), pick(s.pass_front, s.pass), pick(s.fail_front, s.fail),
                     pick(s.zfail_front, s.zfail));
    out.back = face(pick(s.comp_back, s.comp), pick(s.pass_back, s.pass), pick(s.fail_back, s.fail),
                    pick(s.zfail_back, s.zfail));
  }
};

const char* factor_name(VkBlendFactor f) {
  for (const auto& w : kFactors) {
    if (w.value == f) return w.name.data();
  }
  return "?";
}

}  // namespace

Result<PipelineState> resolve_state(const ir::RenderState& state, const Material& material, Diagnostics& diags) {
  Resolver r{material, std::nullopt};
  PipelineState out;
  if (state.cull) out.cull = r.cull(*state.cull);
  if (state.ztest) {
    if (state.ztest->is_property() && r.number("ZTest", *state.ztest).value_or(4) == 0) {
      out.depth_test = false;  // CompareFunction.Disabled
    } else {
      out.ztest = r.word("ZTest", *state.ztest, kCompare, 1, VK_COMPARE_OP_LESS_OR_EQUAL);
    }
  }
  if (state.zwrite) out.zwrite = r.on_off("ZWrite", *state.zwrite);
  if (state.alpha_to_mask) out.alpha_to_mask = r.on_off("AlphaToMask", *state.alpha_to_mask);
  if (state.zclip) out.depth_clamp = !r.on_off("ZClip", *state.zclip);
  if (state.offset_factor) out.offset_factor = r.scalar("Offset", *state.offset_factor);
  if (state.offset_units) out.offset_units = r.scalar("Offset", *state.offset_units);
  // One colour target: the entries for all targets or target 0 apply.
  for (const ir::BlendState& b : state.blend) {
    if (b.render_target > 0) continue;
    out.blend = !b.off;
    if (b.off) continue;
    out.src = r.word("Blend", b.src, kFactors, 0, VK_BLEND_FACTOR_ONE);
    out.dst = r.word("Blend", b.dst, kFactors, 0, VK_BLEND_FACTOR_ZERO);
    out.src_alpha = b.src_alpha ? r.word("Blend", *b.src_alpha, kFactors, 0, VK_BLEND_FACTOR_ONE) : out.src;
    out.dst_alpha = b.dst_alpha ? r.word("Blend", *b.dst_alpha, kFactors, 0, VK_BLEND_FACTOR_ZERO) : out.dst;
  }
  for (const ir::BlendOpState& b : state.blend_op) {
    if (b.render_target > 0) continue;
    out.op = r.word("BlendOp", b.color_op, kOps, 0, VK_BLEND_OP_ADD);
    out.op_alpha = b.alpha_op ? r.word("BlendOp", *b.alpha_op, kOps, 0, VK_BLEND_OP_ADD) : out.op;
  }
  for (const ir::ColorMaskState& m : state.color_mask) {
    if (m.render_target <= 0) out.color_mask = r.color_mask(m.mask);
  }
  if (state.stencil) r.stencil(*state.stencil, out);
  if (r.error) {
    diags.add(DiagId::render_state_property, SourceSpan{}, std::move(*r.error));
    return failure();
  }
  return out;
}

std::string describe(const PipelineState& s) {
  const char* cull = s.cull == VK_CULL_MODE_NONE ? "Off" : s.cull == VK_CULL_MODE_FRONT_BIT ? "Front" : "Back";
  std::string text = fmt::format("Cull {} ZTest {} ZWrite {}", cull,
                                 s.depth_test ? kCompare[size_t(s.ztest)].name : "Disabled", s.zwrite ? "On" : "Off");
  if (s.blend) text += fmt::format(" Blend {} {}", factor_name(s.src), factor_name(s.dst));
  if (s.color_mask != 15) text += fmt::format(" ColorMask {}", unsigned(s.color_mask));
  if (s.offset_factor != 0 || s.offset_units != 0) text += fmt::format(" Offset {}, {}", s.offset_factor, s.offset_units);
  if (s.stencil) text += " Stencil";
  if (s.depth_clamp) text += " ZClip False";
  return text;
}

}  // namespace facet::runtime
