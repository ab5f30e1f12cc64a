// Fixed-function ShaderLab (Lighting, Material, SetTexture combiners,
// AlphaTest, Fog, ...) lowered into a generated vertex/fragment program, as
// Unity does when it imports a Pass without a program block.
//
//   read:     the legacy commands in scope (Category -> SubShader -> Pass,
//             the inner scope winning per command) -> FixedFunctionState,
//             with located errors for what Unity would reject;
//   generate: FixedFunctionState -> HLSL text (fixed_function_hlsl.cpp);
//   lower:    the text -> ir::Program for the Pass (fixed_function.cpp).
#pragma once

#include <array>
#include <string>
#include <vector>

#include "lower.h"

namespace facet::sema {

// A colour or number argument: a literal or a material property "[_Prop]".
struct FfValue {
  std::array<float, 4> literal{0, 0, 0, 0};  // numbers: literal[0]
  std::string property;
  // "(0, 0, 0, [_Alpha])": a colour component read from a float property
  // ("" where literal holds it).
  std::array<std::string, 4> component_properties;
  SourceSpan span;
};

enum class FfSource : uint8_t { previous, primary, texture, constant };

// "one - texture alpha": a source, negated (1 - x) and/or reduced to its alpha.
struct FfOperand {
  FfSource source = FfSource::previous;
  bool one_minus = false;
  bool alpha = false;
};

// The combiner forms of Unity's "combine" (args as written, left to right):
//   a | a * b | a + b | a - b | a +- b (a + b - 0.5) | a lerp (b) c (lerp(c, a, b.a))
//   | a * b + c | a * b +- c | a * b - c
enum class FfOp : uint8_t { replace, mul, add, sub, add_signed, lerp, mul_add, mul_add_signed, mul_sub };

struct FfCombine {
  FfOp op = FfOp::replace;
  std::array<FfOperand, 3> args{};
  int scale = 1;  // Double: 2, Quad: 4
};

// One "SetTexture [_T] { ... }": a texture stage.
struct FfStage {
  std::string texture;
  SourceSpan span;
  FfCombine color;
  FfCombine alpha;  // equals `color` unless a separate alpha follows a comma
  bool has_constant = false;
  FfValue constant;   // constantColor
  std::string matrix;  // "matrix [_Prop]": a float4x4 applied to the UVs
};

enum class FfColorMaterial : uint8_t { none, ambient_and_diffuse, emission };
enum class FfFog : uint8_t { global, off, linear, exp, exp2 };

struct FixedFunctionState {
  bool lighting = false;
  bool separate_specular = false;
  FfColorMaterial color_material = FfColorMaterial::none;
  // Material { ... }: Unity's defaults are black.
  FfValue diffuse, ambient, specular, emission, shininess;
  bool has_color = false;
  FfValue color;  // "Color": the unlit primary colour
  std::vector<FfStage> stages;
  std::string alpha_test;  // "" or Off/Always: none; else Greater, GEqual, ...
  FfValue alpha_ref;
  FfFog fog = FfFog::global;
  bool has_fog_color = false;
  FfValue fog_color;
  // BindChannels: the mesh UV set of each texture stage ("texcoord" binds all).
  std::array<int, 8> stage_texcoord{0, 0, 0, 0, 0, 0, 0, 0};
};

// Applies one scope's legacy commands to `state`, in order; errors go to ctx.
// A scope with SetTexture commands replaces the inherited stages.
void apply_legacy_commands(const std::vector<const ast::LegacyCommand*>& commands, FixedFunctionState& state,
                           Context& ctx);

// The texture types the generated code samples with.
enum class FfTextureKind : uint8_t { tex2d, tex3d, cube };
struct FfTexture {
  std::string name;
  FfTextureKind kind = FfTextureKind::tex2d;
  std::string texgen;  // "CubeReflect", "CubeNormal" or "" (mesh UVs)
};

// The program text for `state`: "#pragma vertex ff_vert", "#pragma fragment
// ff_frag", includes UnityCG.cginc. `textures` describes each stage's texture.
std::string generate_fixed_function_hlsl(const FixedFunctionState& state, const std::vector<FfTexture>& textures,
                                         const std::string& title);

// Gives every normal Pass of `sub` that has no program block but
// fixed-function commands in scope a generated program. `out` is the
// lowered SubShader (its passes in the order of sub.passes).
void lower_fixed_function_passes(const ast::Shader& shader, const ast::SubShader& sub, size_t sub_index,
                                 ir::SubShader& out, Context& ctx);

}  // namespace facet::sema
