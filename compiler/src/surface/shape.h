// What the user's surface code looks like, read from glslang's AST: the
// Input fields `surf` (and finalcolor) read, the output struct and what
// `surf` writes, the lighting function's form, the vertex modifier's form.
#pragma once

#include <string>
#include <vector>

#include "facet/program_analysis.h"
#include "directive.h"

namespace facet::surface {

enum class InputKind : uint8_t {
  uv,          // uv_<Tex>: TEXCOORD0 with <Tex>_ST
  uv2,         // uv2_<Tex>: TEXCOORD1 with <Tex>_ST
  view_dir, world_pos, world_normal, world_refl, screen_pos,
  color,       // the member with semantic COLOR
  face,        // the member with semantic VFACE
  internal,    // INTERNAL_DATA's members
  custom,      // filled by the vertex modifier
};

struct InputField {
  std::string name, type;
  InputKind kind = InputKind::custom;
  std::string texture;  // uv/uv2: the texture whose _ST transforms it
  bool used = false;    // read by surf or finalcolor (and so interpolated)
};

enum class LightingForm : uint8_t {
  gi,              // (s, UnityGI gi)
  view_gi,         // (s, viewDir, UnityGI gi)
  light_atten,     // legacy (s, lightDir, atten)
  light_view_atten // legacy (s, lightDir, viewDir, atten)
};

struct Shape {
  std::string input_struct, output_struct;
  std::vector<InputField> inputs;
  bool writes_normal = false, writes_emission = false, writes_alpha = false;
  bool has_internal_data = false;
  LightingForm lighting = LightingForm::view_gi;
  bool has_gi_function = false;
  bool has_deferred_function = false;  // Lighting<Model>_Deferred: the surface gets a Deferred pass
  std::string vertex_input = "appdata_full";  // the vertex modifier's struct
  bool vertex_fills_input = false;             // vert(inout appdata v, out Input o)
  bool output_has_occlusion = false;
  // tessellate:fn: the vertex input's members (what the hull and domain
  // stages carry) and whether fn takes the patch's three vertices.
  std::vector<AnalyzedField> vertex_fields;
  bool tessellate_takes_vertices = false;
};

Result<Shape> read_shape(const ProgramAnalysis& analysis, const Directive& directive, Diagnostics& diags);

}  // namespace facet::surface
