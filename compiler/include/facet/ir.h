// ShaderIr: a validated .shader, the output of facet::sema::analyze and the
// input of every later stage. Plain data, owned by value; cross-references
// are indices. Invariants are written on each type.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "facet/source.h"
#include "facet/stage.h"

namespace facet::ir {

enum class PropertyType : uint8_t {
  float_, int_, integer, range, color, vector, tex2d, tex3d, cube, tex2d_array, cube_array,
  tex_any  // Unity's "any": a texture of whatever dimension the program declares
};

// The canonical spelling of a property type ("Float", "2D", "Any", ...), as
// the IR dump and the package's JSON view print it.
constexpr std::string_view property_type_name(PropertyType t) {
  constexpr std::string_view kNames[] = {"Float", "Int", "Integer", "Range", "Color", "Vector",
                                         "2D",    "3D",  "Cube",    "2DArray", "CubeArray", "Any"};
  return size_t(t) < std::size(kNames) ? kNames[size_t(t)] : "unknown";
}

// "[Toggle(_FOO)]" -> {name "Toggle", args {"_FOO"}}. Names keep their
// spelling; unknown attributes are kept too.
struct PropertyAttribute {
  std::string name;
  std::vector<std::string> args;  // trimmed, each one comma-separated argument
  SourceSpan span;
};

struct Property {
  std::string name;          // "_MainTex"
  std::string display_name;  // "Albedo"
  PropertyType type = PropertyType::float_;
  std::vector<PropertyAttribute> attributes;
  float range_min = 0, range_max = 0;         // type == range
  std::array<float, 4> default_value{0, 0, 0, 0};  // scalars in [0]; 3-number colours get a = 1
  std::string default_texture;                // textures: "white", "bump", "" ...
  SourceSpan span;

  bool is_texture() const { return type >= PropertyType::tex2d; }
};

struct Tag {
  std::string key;
  std::string value;
  SourceSpan span;
};

// A render-state argument: a literal in canonical spelling ("Back", "LEqual",
// "One", "RGBA", "0", "On") or a material property reference "[_Prop]".
// Exactly one of the two is non-empty.
struct StateValue {
  std::string literal;
  std::string property;
  SourceSpan span;

  bool is_property() const { return !property.empty(); }
};

struct BlendState {
  int render_target = -1;  // -1: all targets
  bool off = false;        // "Blend Off"
  StateValue src, dst;
  std::optional<StateValue> src_alpha, dst_alpha;
};

struct BlendOpState {
  int render_target = -1;
  StateValue color_op;
  std::optional<StateValue> alpha_op;
};

struct ColorMaskState {
  int render_target = -1;
  StateValue mask;  // "0", "RGBA", "RGB", ...
};

struct StencilState {
  std::optional<StateValue> ref, read_mask, write_mask;
  std::optional<StateValue> comp, pass, fail, zfail;
  std::optional<StateValue> comp_back, pass_back, fail_back, zfail_back;
  std::optional<StateValue> comp_front, pass_front, fail_front, zfail_front;
  SourceSpan span;
};

// Every command is optional: unset means "the default" (Cull Back, ZTest
// LEqual, ZWrite On, Blend Off, ColorMask RGBA, ...). In a Pass, the state is
// already merged with its SubShader's (Pass wins per field).
struct RenderState {
  std::optional<StateValue> cull, ztest, zwrite, alpha_to_mask, zclip, conservative;
  std::optional<StateValue> offset_factor, offset_units;
  std::vector<BlendState> blend;
  std::vector<BlendOpState> blend_op;
  std::vector<ColorMaskState> color_mask;
  std::optional<StencilState> stencil;
};

enum class ProgramLanguage : uint8_t { cg, hlsl, glsl };

// A piece of source text and where it starts in its file, so that the back
// end can emit `#line` and map errors back.
struct SourceChunk {
  std::string text;
  SourceSpan span;        // the text's bytes in the original file
  uint32_t first_line = 1;  // 1-based line of text[0]
  // The file `#line` names; empty: the shader's own file. Generated code
  // (surface-shader lowering) names a file of its own in the SourceMap.
  std::string line_file;
};

// "#pragma name args..." as written; args split on whitespace.
struct Pragma {
  std::string name;
  std::vector<std::string> args;
  SourceSpan span;
};

// A CGPROGRAM/HLSLPROGRAM/GLSLPROGRAM block with everything in scope.
struct Program {
  ProgramLanguage language = ProgramLanguage::cg;
  // CGINCLUDE/HLSLINCLUDE blocks in scope (Shader scope first, then
  // SubShader), prepended in this order.
  std::vector<SourceChunk> includes;
  SourceChunk body;
  // Every #pragma of includes and body, in order.
  std::vector<Pragma> pragmas;
  // From "#pragma vertex fn" etc.; empty when the stage is absent. For GLSL
  // programs the stages are the #ifdef VERTEX/FRAGMENT sections present.
  std::array<std::string, 5> entry_points;
  int shader_target = 25;             // "#pragma target 3.0" -> 30 (Unity's default 2.5)
  std::string surface_function;       // "#pragma surface fn Model ..." when present
  // The LightMode tag of the pass that runs it ("" when none): Unity's
  // compiler defines UNITY_PASS_<MODE> from it (UNITY_PASS_META, ...).
  std::string light_mode;
  // The .shader file the program was written in when that is not the shader
  // holding it: a pass taken from another shader by UsePass or a Fallback.
  // kNoFile: the holding shader's own file. Includes are found relative to
  // this file, and messages point into it.
  FileId home_file = kNoFile;
  bool is_surface() const { return !surface_function.empty(); }
  bool has_stage(Stage s) const { return !entry_points[size_t(s)].empty(); }
};

enum class PassKind : uint8_t { normal, use_pass, grab_pass };

struct Pass {
  PassKind kind = PassKind::normal;
  std::string name;  // as written; lookups compare upper-cased
  std::vector<Tag> tags;  // pass tags; a SubShader-level LightMode is copied here
  RenderState state;      // merged with the SubShader's
  std::optional<Program> program;  // normal passes only
  std::string use_pass;            // use_pass: "Shader/PASSNAME"
  std::string grab_texture;        // grab_pass: "" means _GrabTexture
  // Where a pass taken from another shader came from, as Unity names it:
  // `UsePass "Legacy Shaders/VertexLit/SHADOWCASTER"`, `Fallback "Diffuse"`;
  // empty for the shader's own passes.
  std::string origin;
  // A ShadowCaster that surface-shader lowering generated in place of the
  // Fallback's (as Legacy VertexLit's): the Fallback's own replaces it when
  // the Fallback is found.
  bool fallback_stand_in = false;
  SourceSpan span;

  // The value of a tag, case-insensitive key; "" if absent.
  std::string tag(std::string_view key) const;
};

// A program block directly in a SubShader: a surface shader, lowered into
// passes by compiler/surface. Its passes go where the block is written:
// before passes[before_pass] (passes.size(): after every Pass).
struct SurfaceProgram {
  Program program;
  size_t before_pass = 0;
};

struct SubShader {
  std::vector<Tag> tags;
  int lod = 0;  // 0 when not given
  int queue = 2000;  // the render queue of its Queue tag (sema resolves it); Geometry without one
  RenderState state;
  std::vector<Pass> passes;  // in file order
  std::vector<SurfaceProgram> surface_programs;  // in file order; Unity allows several
  SourceSpan span;
};

struct Shader {
  std::string name;  // "Custom/Foo"
  std::vector<Property> properties;  // in file order
  std::vector<SubShader> subshaders; // in file order, Category blocks flattened
  std::optional<std::string> fallback;  // absent: none; "Off" is kept as absent
  SourceSpan fallback_span;             // the Fallback command, when there is one
  std::string custom_editor;
  FileId file = kNoFile;
  SourceSpan span;

  const Property* find_property(std::string_view name) const;
};

// The texture `GrabPass { }` fills; a named GrabPass fills its name.
inline constexpr const char* kGrabTexture = "_GrabTexture";

// The textures of the GrabPasses among passes [from, to) of `sub`, in order:
// what is grabbed before the pass at `to` when the pass drawn before it is
// at from - 1.
inline std::vector<std::string> grab_textures(const SubShader& sub, size_t from, size_t to) {
  std::vector<std::string> out;
  for (size_t i = from; i < to && i < sub.passes.size(); ++i) {
    if (sub.passes[i].kind != PassKind::grab_pass) continue;
    out.push_back(sub.passes[i].grab_texture.empty() ? kGrabTexture : sub.passes[i].grab_texture);
  }
  return out;
}

// The file a program of `shader` was written in (Program::home_file).
inline FileId program_file(const Shader& shader, const Program& program) {
  return program.home_file != kNoFile ? program.home_file : shader.file;
}

}  // namespace facet::ir
