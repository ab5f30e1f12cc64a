#include "generate.h"

#include <fmt/format.h>

#include <algorithm>
#include <functional>

namespace facet::surface {
namespace {

constexpr const char* kIncludes =
    "#include \"UnityCG.cginc\"\n"
    "#include \"Lighting.cginc\"\n"
    "#include \"UnityPBSLighting.cginc\"\n"
    "#include \"AutoLight.cginc\"\n";

// With a tangent-space o.Normal, Input carries the tangent-to-world rows and
// the World*Vector helpers rotate by them; otherwise they are plain fields.
constexpr const char* kInternalDataTangent =
    "#define INTERNAL_DATA half3 internalSurfaceTtoW0; half3 internalSurfaceTtoW1; half3 internalSurfaceTtoW2;\n"
    "#define WorldNormalVector(data, normal) fixed3(dot(data.internalSurfaceTtoW0, normal), "
    "dot(data.internalSurfaceTtoW1, normal), dot(data.internalSurfaceTtoW2, normal))\n"
    "#define WorldReflectionVector(data, normal) reflect(data.worldRefl, half3(dot(data.internalSurfaceTtoW0, "
    "normal), dot(data.internalSurfaceTtoW1, normal), dot(data.internalSurfaceTtoW2, normal)))\n";
constexpr const char* kInternalDataWorld =
    "#define INTERNAL_DATA\n"
    "#define WorldNormalVector(data, normal) data.worldNormal\n"
    "#define WorldReflectionVector(data, normal) data.worldRefl\n";

const char* pass_define(GeneratedPass pass) {
  switch (pass) {
    case GeneratedPass::forward_base: return "UNITY_PASS_FORWARDBASE";
    case GeneratedPass::forward_add: return "UNITY_PASS_FORWARDADD";
    case GeneratedPass::deferred: return "UNITY_PASS_DEFERRED";
    default: return "UNITY_PASS_SHADOWCASTER";
  }
}

// Writes the interpolator struct and the two functions, one line at a time.
class Writer {
 public:
  Writer(GeneratedPass pass, const Directive& d, const Shape& s, const std::vector<std::string>& output_fields)
      : pass_(pass), d_(d), s_(s), output_fields_(output_fields) {}

  void line(std::string text) { out_ += text + "\n"; }
  std::string semantic() { return fmt::format("TEXCOORD{}", next_texcoord_++); }
  std::string take() { return std::move(out_); }

  bool shadow() const {
    return pass_ == GeneratedPass::shadow_caster || pass_ == GeneratedPass::fallback_shadow_caster;
  }
  // The deferred pass has no light of its own, no shadow and no fog.
  bool deferred() const { return pass_ == GeneratedPass::deferred; }
  bool lit() const { return !shadow() && !deferred(); }
  // The fallback caster is Legacy VertexLit's: no user code runs in it.
  bool runs_user_code() const { return pass_ != GeneratedPass::fallback_shadow_caster; }
  bool runs_surf() const { return !shadow() || (runs_user_code() && !d_.alpha_test_property.empty()); }
  bool tangent_frame() const { return s_.writes_normal && !shadow(); }
  bool has_output(std::string_view name) const {
    return std::find(output_fields_.begin(), output_fields_.end(), name) != output_fields_.end();
  }
  // A shadow caster interpolates the world position only for an Input field
  // that surf reads and that derives from it (an unread output is a validation warning).
  bool caster_world_pos() const {
    return runs_surf() && std::any_of(s_.inputs.begin(), s_.inputs.end(), [](const InputField& f) {
             return f.used && (f.kind == InputKind::world_pos || f.kind == InputKind::view_dir ||
                               f.kind == InputKind::world_refl);
           });
  }
  // ForwardBase's four per-vertex point lights (VERTEXLIGHT_ON, which only
  // the vertex stage sees): computed there, added to the ambient per pixel.
  bool vertex_lights() const {
    bool gi = s_.lighting == LightingForm::gi || s_.lighting == LightingForm::view_gi;
    return pass_ == GeneratedPass::forward_base && !d_.no_vertex_lights && !d_.no_ambient &&
           (gi || has_output("Albedo"));
  }
  bool interpolated(const InputField& f) const {
    if (!f.used || !runs_surf()) return false;
    switch (f.kind) {
      case InputKind::uv: case InputKind::uv2: case InputKind::color: case InputKind::screen_pos:
      case InputKind::custom:
        return true;
      default: return false;
    }
  }

  void interpolators() {
    line("struct v2f_surf {");
    next_texcoord_ = 0;
    if (shadow()) {
      line("  V2F_SHADOW_CASTER;");
      next_texcoord_ = 1;  // V2F_SHADOW_CASTER takes TEXCOORD0
      if (caster_world_pos()) line(fmt::format("  float3 worldPos : {};", semantic()));
    } else {
      line("  UNITY_POSITION(pos);");
      if (tangent_frame()) {
        for (int i = 0; i < 3; ++i) line(fmt::format("  float4 tSpace{} : {};", i, semantic()));
      } else {
        line(fmt::format("  float3 worldNormal : {};", semantic()));
        line(fmt::format("  float3 worldPos : {};", semantic()));
      }
    }
    for (const InputField& f : s_.inputs) {
      if (!interpolated(f)) continue;
      if (f.kind == InputKind::color) line(fmt::format("  fixed4 {} : COLOR0;", member(f)));
      else line(fmt::format("  {} {} : {};", f.type, member(f), semantic()));
    }
    if (vertex_lights()) line(fmt::format("  float3 vertexLight : {};", semantic()));
    if (lit() && !d_.no_fog) line(fmt::format("  UNITY_FOG_COORDS({})", next_texcoord_++));
    if (lit()) line(fmt::format("  UNITY_SHADOW_COORDS({})", next_texcoord_++));
    line("  UNITY_VERTEX_INPUT_INSTANCE_ID");
    line("};");
  }

  void vertex_function() {
    // The instance comes in as a parameter of its own, so that an appdata
    // without UNITY_VERTEX_INPUT_INSTANCE_ID draws instanced too.
    line("#if defined(UNITY_INSTANCING_ENABLED)");
    line(fmt::format("v2f_surf vert_surf({} v, uint facetInstanceID : SV_InstanceID) {{", s_.vertex_input));
    line("#else");
    line(fmt::format("v2f_surf vert_surf({} v) {{", s_.vertex_input));
    line("#endif");
    line("  v2f_surf o;");
    line("  UNITY_INITIALIZE_OUTPUT(v2f_surf, o);");
    line("#if defined(UNITY_INSTANCING_ENABLED)");
    line("  unity_InstanceID = facetInstanceID + unity_BaseInstanceID;");
    line("  o.instanceID = facetInstanceID;");
    line("#endif");
    if (runs_user_code() && !d_.vertex_function.empty()) {
      if (s_.vertex_fills_input) {
        line(fmt::format("  {} customInputData;", s_.input_struct));
        line(fmt::format("  UNITY_INITIALIZE_OUTPUT({}, customInputData);", s_.input_struct));
        line(fmt::format("  {}(v, customInputData);", d_.vertex_function));
      } else {
        line(fmt::format("  {}(v);", d_.vertex_function));
      }
    }
    line("  float3 worldPos = mul(unity_ObjectToWorld, v.vertex).xyz;");
    if (shadow()) {
      if (caster_world_pos()) line("  o.worldPos = worldPos;");
      line("  TRANSFER_SHADOW_CASTER_NORMALOFFSET(o)");
    } else {
      line("  o.pos = UnityObjectToClipPos(v.vertex);");
      line("  float3 worldNormal = UnityObjectToWorldNormal(v.normal);");
      if (tangent_frame()) {
        line("  float3 worldTangent = UnityObjectToWorldDir(v.tangent.xyz);");
        line("  float3 worldBinormal = cross(worldNormal, worldTangent) * v.tangent.w;");
        line("  o.tSpace0 = float4(worldTangent.x, worldBinormal.x, worldNormal.x, worldPos.x);");
        line("  o.tSpace1 = float4(worldTangent.y, worldBinormal.y, worldNormal.y, worldPos.y);");
        line("  o.tSpace2 = float4(worldTangent.z, worldBinormal.z, worldNormal.z, worldPos.z);");
      } else {
        line("  o.worldNormal = worldNormal;");
        line("  o.worldPos = worldPos;");
      }
    }
    for (const InputField& f : s_.inputs) {
      if (!interpolated(f)) continue;
      switch (f.kind) {
        case InputKind::uv: line(fmt::format("  o.{} = TRANSFORM_TEX(v.texcoord, {});", member(f), f.texture)); break;
        case InputKind::uv2: line(fmt::format("  o.{} = TRANSFORM_TEX(v.texcoord1, {});", member(f), f.texture)); break;
        case InputKind::color: line(fmt::format("  o.{} = v.color;", member(f))); break;
        case InputKind::screen_pos:
          line(fmt::format("  o.{} = ComputeScreenPos(UnityObjectToClipPos(v.vertex));", member(f)));
          break;
        case InputKind::custom:
          if (s_.vertex_fills_input) line(fmt::format("  o.{} = customInputData.{};", member(f), f.name));
          break;
        default: break;
      }
    }
    if (vertex_lights()) {
      line("  o.vertexLight = 0;");
      line("#ifdef VERTEXLIGHT_ON");
      line("  o.vertexLight = Shade4PointLights(unity_4LightPosX0, unity_4LightPosY0, unity_4LightPosZ0, "
           "unity_LightColor[0].rgb, unity_LightColor[1].rgb, unity_LightColor[2].rgb, unity_LightColor[3].rgb, "
           "unity_4LightAtten0, worldPos, worldNormal);");
      line("#endif");
    }
    if (lit()) {
      line("  TRANSFER_SHADOW(o);");
      if (!d_.no_fog) line("  UNITY_TRANSFER_FOG(o, o.pos);");
    }
    line("  return o;");
    line("}");
  }

  // tessellate: the vertex stage passes the vertex input on; the hull stage
  // passes the control points through and its patch-constant function calls
  // the user's tessellation function; the domain stage interpolates the
  // vertex input barycentrically, applies Phong tessellation, and runs
  // vert_surf (and so the vertex modifier) on the result, as Unity does.
  void tessellation() {
    const std::string& in = s_.vertex_input;
    const std::string cp = "InternalTessInterp_" + in;
    auto carried = [](const AnalyzedField& f) { return !f.semantic.starts_with("SV_"); };
    line("struct UnityTessellationFactors {");
    line("  float edge[3] : SV_TessFactor;");
    line("  float inside : SV_InsideTessFactor;");
    line("};");
    line(fmt::format("struct {} {{", cp));
    for (const AnalyzedField& f : s_.vertex_fields) {
      if (!carried(f)) continue;
      // POSITION between stages would be the clip position; Unity's name.
      bool position = f.semantic == "POSITION" || f.semantic.empty();
      line(fmt::format("  {} {} : {};", f.type, f.name, position ? "INTERNALTESSPOS" : f.semantic));
    }
    line("};");
    line(fmt::format("{} tessvert_surf({} v) {{", cp, in));
    line(fmt::format("  {} o;", cp));
    for (const AnalyzedField& f : s_.vertex_fields) {
      if (carried(f)) line(fmt::format("  o.{0} = v.{0};", f.name));
    }
    line("  return o;");
    line("}");
    line(fmt::format("UnityTessellationFactors hsconst_surf(InputPatch<{}, 3> v) {{", cp));
    line("  UnityTessellationFactors o;");
    if (s_.tessellate_takes_vertices) {
      line(fmt::format("  {} vi[3];", in));
      line("  for (int i = 0; i < 3; ++i) {");
      line(fmt::format("    UNITY_INITIALIZE_OUTPUT({}, vi[i]);", in));
      for (const AnalyzedField& f : s_.vertex_fields) {
        if (carried(f)) line(fmt::format("    vi[i].{0} = v[i].{0};", f.name));
      }
      line("  }");
      line(fmt::format("  float4 tf = {}(vi[0], vi[1], vi[2]);", d_.tessellate_function));
    } else {
      line(fmt::format("  float4 tf = {}();", d_.tessellate_function));
    }
    line("  o.edge[0] = tf.x;");
    line("  o.edge[1] = tf.y;");
    line("  o.edge[2] = tf.z;");
    line("  o.inside = tf.w;");
    line("  return o;");
    line("}");
    line("[UNITY_domain(\"tri\")]");
    line("[UNITY_partitioning(\"fractional_odd\")]");
    line("[UNITY_outputtopology(\"triangle_cw\")]");
    line("[UNITY_patchconstantfunc(\"hsconst_surf\")]");
    line("[UNITY_outputcontrolpoints(3)]");
    line(fmt::format("{0} hs_surf(InputPatch<{0}, 3> v, uint id : SV_OutputControlPointID) {{", cp));
    line("  return v[id];");
    line("}");
    line("[UNITY_domain(\"tri\")]");
    line(fmt::format("v2f_surf ds_surf(UnityTessellationFactors tessFactors, const OutputPatch<{}, 3> vi, "
                     "float3 bary : SV_DomainLocation) {{",
                     cp));
    line(fmt::format("  {} v;", in));
    line(fmt::format("  UNITY_INITIALIZE_OUTPUT({}, v);", in));
    for (const AnalyzedField& f : s_.vertex_fields) {
      if (carried(f)) line(fmt::format("  v.{0} = vi[0].{0} * bary.x + vi[1].{0} * bary.y + vi[2].{0} * bary.z;", f.name));
    }
    if (!d_.tess_phong.empty()) {
      // Each corner's tangent plane, the point projected onto it, blended.
      line("  float3 pp[3];");
      line("  for (int i = 0; i < 3; ++i) {");
      line("    pp[i] = v.vertex.xyz - vi[i].normal * (dot(v.vertex.xyz, vi[i].normal) - dot(vi[i].vertex.xyz, "
           "vi[i].normal));");
      line("  }");
      line(fmt::format("  v.vertex.xyz = ({0}) * (pp[0] * bary.x + pp[1] * bary.y + pp[2] * bary.z) + "
                       "(1.0 - ({0})) * v.vertex.xyz;",
                       d_.tess_phong));
    }
    line("  return vert_surf(v);");
    line("}");
  }

  void fill_input() {
    line(fmt::format("  {} surfIN;", s_.input_struct));
    line(fmt::format("  UNITY_INITIALIZE_OUTPUT({}, surfIN);", s_.input_struct));
    for (const InputField& f : s_.inputs) {
      if (!f.used && f.kind != InputKind::internal) continue;
      std::string to = "  surfIN." + f.name + " = ";
      switch (f.kind) {
        case InputKind::uv: case InputKind::uv2: case InputKind::color: case InputKind::screen_pos:
        case InputKind::custom:
          line(to + "IN." + member(f) + ";");
          break;
        case InputKind::world_pos: line(to + "worldPos;"); break;
        case InputKind::view_dir:
          // Tangent space when surf writes a tangent-space normal, as in Unity.
          line(to + (tangent_frame() ? "IN.tSpace0.xyz * worldViewDir.x + IN.tSpace1.xyz * worldViewDir.y + "
                                       "IN.tSpace2.xyz * worldViewDir.z;"
                                     : "worldViewDir;"));
          break;
        case InputKind::world_normal: line(to + (tangent_frame() ? "0.0;" : "worldNormal;")); break;
        case InputKind::world_refl:
          line(to + (tangent_frame() ? "-worldViewDir;" : "reflect(-worldViewDir, worldNormal);"));
          break;
        case InputKind::face: line(to + "(frontFacing ? 1.0 : -1.0);"); break;
        case InputKind::internal:
          if (tangent_frame()) line(to + "IN.tSpace" + f.name.substr(f.name.size() - 1) + ".xyz;");
          break;
      }
    }
  }

  void run_surf() {
    line(fmt::format("  {} o;", s_.output_struct));
    line(fmt::format("  UNITY_INITIALIZE_OUTPUT({}, o);", s_.output_struct));
    if (has_output("Occlusion")) line("  o.Occlusion = 1.0;");
    if (has_output("Normal")) line(tangent_frame() ? "  o.Normal = fixed3(0, 0, 1);" : "  o.Normal = worldNormal;");
    line(fmt::format("  {}(surfIN, o);", d_.surface_function));
    if (!d_.alpha_test_property.empty()) line(fmt::format("  clip(o.Alpha - {});", d_.alpha_test_property));
  }

  void light() {
    bool base = pass_ == GeneratedPass::forward_base;
    line("  UNITY_LIGHT_ATTENUATION(atten, IN, worldPos);");
    if (tangent_frame()) {
      line("  float3 worldN = float3(dot(IN.tSpace0.xyz, o.Normal), dot(IN.tSpace1.xyz, o.Normal), "
           "dot(IN.tSpace2.xyz, o.Normal));");
      line("  o.Normal = normalize(worldN);");
    }
    line("  fixed4 c = 0;");
    std::string fn = "Lighting" + d_.model;
    if (s_.lighting == LightingForm::gi || s_.lighting == LightingForm::view_gi) {
      line("  UnityGI gi;");
      line("  UNITY_INITIALIZE_OUTPUT(UnityGI, gi);");
      line("  gi.indirect.diffuse = 0;");
      line("  gi.indirect.specular = 0;");
      line("  gi.light.color = _LightColor0.rgb;");
      line("  gi.light.dir = lightDir;");
      if (base && !d_.no_ambient) {
        line("  UnityGIInput giInput;");
        line("  UNITY_INITIALIZE_OUTPUT(UnityGIInput, giInput);");
        line("  giInput.light = gi.light;");
        line("  giInput.worldPos = worldPos;");
        line("  giInput.worldViewDir = worldViewDir;");
        line("  giInput.atten = atten;");
        // SH is evaluated per pixel (ShadeSHPerPixel), added to the vertex lights.
        line(vertex_lights() ? "  giInput.ambient = IN.vertexLight;" : "  giInput.ambient = 0;");
        line("  giInput.probeHDR[0] = unity_SpecCube0_HDR;");
        line(fmt::format("  {}_GI(o, giInput, gi);", fn));
      } else {
        line("  gi.light.color *= atten;");
      }
      line(s_.lighting == LightingForm::gi ? fmt::format("  c += {}(o, gi);", fn)
                                           : fmt::format("  c += {}(o, worldViewDir, gi);", fn));
    } else {
      line(s_.lighting == LightingForm::light_atten ? fmt::format("  c += {}(o, lightDir, atten);", fn)
                                                    : fmt::format("  c += {}(o, lightDir, worldViewDir, atten);", fn));
      if (base && !d_.no_ambient && has_output("Albedo")) {
        line(vertex_lights() ? "  c.rgb += o.Albedo * (ShadeSH9(float4(o.Normal, 1.0)) + IN.vertexLight);"
                             : "  c.rgb += o.Albedo * ShadeSH9(float4(o.Normal, 1.0));");
      }
    }
    if (base && has_output("Emission")) line("  c.rgb += o.Emission;");
  }

  // The G-buffer through Lighting<Model>_Deferred, which returns what the
  // surface gives off by itself (emission and, under
  // UNITY_LIGHT_FUNCTION_APPLY_INDIRECT, ambient and reflections from
  // <Model>_GI with a black light) for the light buffer.
  void deferred_output() {
    if (tangent_frame()) {
      line("  float3 worldN = float3(dot(IN.tSpace0.xyz, o.Normal), dot(IN.tSpace1.xyz, o.Normal), "
           "dot(IN.tSpace2.xyz, o.Normal));");
      line("  o.Normal = normalize(worldN);");
    }
    std::string fn = "Lighting" + d_.model;
    line("  UnityGI gi;");
    line("  UNITY_INITIALIZE_OUTPUT(UnityGI, gi);");
    line("  gi.indirect.diffuse = 0;");
    line("  gi.indirect.specular = 0;");
    line("  gi.light.color = 0;");
    line("  gi.light.dir = half3(0, 1, 0);");
    if (!d_.no_ambient) {
      line("  UnityGIInput giInput;");
      line("  UNITY_INITIALIZE_OUTPUT(UnityGIInput, giInput);");
      line("  giInput.light = gi.light;");
      line("  giInput.worldPos = worldPos;");
      line("  giInput.worldViewDir = worldViewDir;");
      line("  giInput.atten = 1;");
      line("  giInput.ambient = 0;");
      line("  giInput.probeHDR[0] = unity_SpecCube0_HDR;");
      line(fmt::format("  {}_GI(o, giInput, gi);", fn));
    }
    line(s_.lighting == LightingForm::gi
             ? fmt::format("  outEmission = {}_Deferred(o, gi, outGBuffer0, outGBuffer1, outGBuffer2);", fn)
             : fmt::format("  outEmission = {}_Deferred(o, worldViewDir, gi, outGBuffer0, outGBuffer1, outGBuffer2);", fn));
    line("#ifndef UNITY_HDR_ON");
    line("  outEmission.rgb = exp2(-outEmission.rgb);");
    line("#endif");
  }

  void fragment_function() {
    bool face = std::any_of(s_.inputs.begin(), s_.inputs.end(),
                            [&](const InputField& f) { return f.kind == InputKind::face && f.used && runs_surf(); });
    // SV_IsFrontFace, not VFACE: glslang makes a DX9 VFACE parameter a plain
    // varying that no vertex stage writes. The Input's VFACE field gets +-1.
    std::string front = face ? ", bool frontFacing : SV_IsFrontFace" : "";
    if (deferred()) {
      line(fmt::format("void frag_surf(v2f_surf IN{}, out half4 outGBuffer0 : SV_Target0, out half4 outGBuffer1 : "
                       "SV_Target1, out half4 outGBuffer2 : SV_Target2, out half4 outEmission : SV_Target3) {{",
                       front));
    } else {
      line(fmt::format("fixed4 frag_surf(v2f_surf IN{}) : SV_Target {{", front));
    }
    line("  UNITY_SETUP_INSTANCE_ID(IN);");
    if (shadow()) {
      if (runs_surf()) {
        if (caster_world_pos()) {
          line("  float3 worldPos = IN.worldPos;");
          line("  float3 worldViewDir = normalize(UnityWorldSpaceViewDir(worldPos));");
        }
        line("  float3 worldNormal = float3(0, 0, 1);");
        fill_input();
        run_surf();
      }
      line("  SHADOW_CASTER_FRAGMENT(IN)");
      line("}");
      return;
    }
    line(tangent_frame() ? "  float3 worldPos = float3(IN.tSpace0.w, IN.tSpace1.w, IN.tSpace2.w);"
                         : "  float3 worldPos = IN.worldPos;");
    line(tangent_frame() ? "  float3 worldNormal = normalize(float3(IN.tSpace0.z, IN.tSpace1.z, IN.tSpace2.z));"
                         : "  float3 worldNormal = normalize(IN.worldNormal);");
    line("  float3 worldViewDir = normalize(UnityWorldSpaceViewDir(worldPos));");
    if (!deferred()) line("  float3 lightDir = normalize(UnityWorldSpaceLightDir(worldPos));");
    fill_input();
    run_surf();
    if (deferred()) {
      deferred_output();
      line("}");
      return;
    }
    light();
    if (!d_.final_color_function.empty()) line(fmt::format("  {}(surfIN, o, c);", d_.final_color_function));
    if (!d_.no_fog) line("  UNITY_APPLY_FOG(IN.fogCoord, c);");
    if (d_.alpha == AlphaMode::none && d_.decal == DecalMode::none && !d_.keep_alpha) line("  UNITY_OPAQUE_ALPHA(c.a);");
    line("  return c;");
    line("}");
  }

 private:
  static std::string member(const InputField& f) { return "surf_" + f.name; }

  GeneratedPass pass_;
  const Directive& d_;
  const Shape& s_;
  const std::vector<std::string>& output_fields_;
  std::string out_;
  int next_texcoord_ = 0;
};

}  // namespace

std::string analysis_prologue() {
  return std::string("#define SHADER_TARGET_SURFACE_ANALYSIS 1\n#define UNITY_PASS_FORWARDBASE 1\n") + kIncludes +
         kInternalDataTangent;
}

GeneratedCode generate(GeneratedPass pass, const Directive& directive, const Shape& shape,
                       const std::vector<std::string>& output_fields,
                       const std::function<bool(const std::string&)>& declared) {
  GeneratedCode code;
  code.prologue = fmt::format("#define {} 1\n", pass_define(pass));
  if (directive.alpha == AlphaMode::premultiply) code.prologue += "#define _ALPHAPREMULTIPLY_ON 1\n";
  code.prologue += kIncludes;
  code.prologue += shape.writes_normal ? kInternalDataTangent : kInternalDataWorld;

  Writer w(pass, directive, shape, output_fields);
  std::vector<std::string> scale_offsets;
  for (const InputField& f : shape.inputs) {
    if ((f.kind == InputKind::uv || f.kind == InputKind::uv2) && w.interpolated(f)) {
      std::string st = f.texture + "_ST";
      if (!declared(st) && std::find(scale_offsets.begin(), scale_offsets.end(), st) == scale_offsets.end()) {
        scale_offsets.push_back(st);
      }
    }
  }
  for (const std::string& st : scale_offsets) w.line(fmt::format("float4 {};", st));
  // Like Unity, the alphatest property needs no declaration of the user's.
  if (!directive.alpha_test_property.empty() && !declared(directive.alpha_test_property)) {
    w.line(fmt::format("fixed {};", directive.alpha_test_property));
  }
  w.interpolators();
  w.vertex_function();
  if (directive.tessellated() && pass != GeneratedPass::fallback_shadow_caster) w.tessellation();
  w.fragment_function();
  code.epilogue = w.take();
  return code;
}

}  // namespace facet::surface
