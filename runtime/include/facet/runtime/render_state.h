// A pass's ShaderLab render state (ir::RenderState, `[_Prop]` references
// included) resolved against a material into the fixed-function state of a
// Vulkan pipeline. Property values use Unity's enums (UnityEngine.Rendering
// CullMode, CompareFunction, BlendMode, BlendOp, StencilOp, ColorWriteMask).
#pragma once

#include <vulkan/vulkan.h>

#include <string>

#include "facet/ir.h"
#include "facet/result.h"
#include "facet/runtime/material.h"

namespace facet::runtime {

struct PipelineState {
  VkCullModeFlags cull = VK_CULL_MODE_BACK_BIT;
  bool depth_test = true;  // false for "ZTest Always"-like Disabled (Unity's 0)
  VkCompareOp ztest = VK_COMPARE_OP_LESS_OR_EQUAL;
  bool zwrite = true;
  bool blend = false;
  VkBlendFactor src = VK_BLEND_FACTOR_ONE, dst = VK_BLEND_FACTOR_ZERO;
  VkBlendFactor src_alpha = VK_BLEND_FACTOR_ONE, dst_alpha = VK_BLEND_FACTOR_ZERO;
  VkBlendOp op = VK_BLEND_OP_ADD, op_alpha = VK_BLEND_OP_ADD;
  VkColorComponentFlags color_mask = VK_COLOR_COMPONENT_R_BIT | VK_COLOR_COMPONENT_G_BIT |
                                     VK_COLOR_COMPONENT_B_BIT | VK_COLOR_COMPONENT_A_BIT;
  float offset_factor = 0, offset_units = 0;
  bool alpha_to_mask = false;
  bool depth_clamp = false;  // ZClip False
  bool stencil = false;
  VkStencilOpState front{}, back{};

  bool operator==(const PipelineState&) const = default;
};

// The pass's render state with each [_Prop] value read from the material; an
// error (render_state_property) names the command and why: "Cull
// [_CullMode]: the material has no property '_CullMode'".
Result<PipelineState> resolve_state(const ir::RenderState& state, const Material& material, Diagnostics& diags);

// A short text that identifies the state, for pipeline cache keys and --explain.
std::string describe(const PipelineState& state);

}  // namespace facet::runtime
