// FixedFunctionState -> HLSL, after Unity's manual pages on legacy lighting,
// texture combiners, alpha testing and fog:
//   vertex:   the primary colour (vertex lighting, or Color, or the vertex
//             colour) and the specular colour, the UVs of each stage;
//   fragment: the SetTexture stages in order ("previous" is the stage before,
//             the primary colour for the first one), each saturated as the
//             hardware combiners were, then separate specular, alpha test, fog.
#include <fmt/format.h>

#include <algorithm>
#include <map>

#include "fixed_function.h"

namespace facet::sema {
namespace {

std::string number(float f) { return fmt::format("{}", f); }

// The textures the stdlib's built-in blocks declare (FacetBuiltins.hlsl),
// which a legacy pass may name: "SetTexture [unity_Lightmap]" in Unity's
// VertexLM passes.
bool declared_by_the_stdlib(std::string_view name) {
  static constexpr std::string_view kNames[] = {
      "unity_Lightmap",        "unity_LightmapInd",           "unity_ShadowMask", "unity_DynamicLightmap",
      "unity_DynamicDirectionality", "unity_DynamicNormal",   "unity_SpecCube0",  "unity_SpecCube1",
      "unity_ProbeVolumeSH",   "_LightTexture0"};
  return std::find(std::begin(kNames), std::end(kNames), name) != std::end(kNames);
}

// Uniforms the generated code reads, each declared once ("float4 _Color;").
class Uniforms {
 public:
  void add(const std::string& name, std::string_view type) {
    if (name.empty() || types_.count(name) || declared_by_the_stdlib(name)) return;
    types_[name] = std::string(type);
    order_.push_back(name);
  }
  std::string declarations() const {
    std::string out;
    for (const std::string& name : order_) out += types_.at(name) + " " + name + ";\n";
    return out;
  }

 private:
  std::map<std::string, std::string> types_;
  std::vector<std::string> order_;
};

std::string color_expr(const FfValue& v, Uniforms& u) {
  if (!v.property.empty()) {
    u.add(v.property, "float4");
    return v.property;
  }
  std::array<std::string, 4> parts;
  for (size_t i = 0; i < parts.size(); ++i) {
    const std::string& property = v.component_properties[i];
    if (!property.empty()) u.add(property, "float");
    parts[i] = property.empty() ? number(v.literal[i]) : property;
  }
  return fmt::format("float4({}, {}, {}, {})", parts[0], parts[1], parts[2], parts[3]);
}

std::string scalar_expr(const FfValue& v, Uniforms& u) {
  if (!v.property.empty()) {
    u.add(v.property, "float");
    return v.property;
  }
  return number(v.literal[0]);
}

bool is_set(const FfValue& v) {
  bool component_property = std::any_of(v.component_properties.begin(), v.component_properties.begin() + 3,
                                        [](const std::string& p) { return !p.empty(); });
  return !v.property.empty() || component_property || v.literal[0] != 0 || v.literal[1] != 0 || v.literal[2] != 0;
}

std::string_view source_name(FfSource s) {
  switch (s) {
    case FfSource::previous: return "ffPrevious";
    case FfSource::primary: return "ffPrimary";
    case FfSource::texture: return "ffTexture";
    case FfSource::constant: return "ffConstant";
  }
  return "ffPrevious";
}

// One operand in the colour (rgb) or the alpha (a) part of a combiner.
std::string operand(const FfOperand& o, bool alpha_part) {
  std::string s = std::string(source_name(o.source)) + (alpha_part ? ".a" : o.alpha ? ".aaa" : ".rgb");
  return o.one_minus ? "(1.0 - " + s + ")" : s;
}

std::string combine(const FfCombine& c, bool alpha_part) {
  auto a = [&](size_t i) { return operand(c.args[i], alpha_part); };
  std::string e;
  switch (c.op) {
    case FfOp::replace: e = a(0); break;
    case FfOp::mul: e = a(0) + " * " + a(1); break;
    case FfOp::add: e = a(0) + " + " + a(1); break;
    case FfOp::sub: e = a(0) + " - " + a(1); break;
    case FfOp::add_signed: e = a(0) + " + " + a(1) + " - 0.5"; break;
    // "a lerp (b) c": a where b's alpha is one, c where it is zero.
    case FfOp::lerp: e = "lerp(" + a(2) + ", " + a(0) + ", " + std::string(source_name(c.args[1].source)) + ".a)"; break;
    case FfOp::mul_add: e = a(0) + " * " + a(1) + " + " + a(2); break;
    case FfOp::mul_add_signed: e = a(0) + " * " + a(1) + " + " + a(2) + " - 0.5"; break;
    case FfOp::mul_sub: e = a(0) + " * " + a(1) + " - " + a(2); break;
  }
  if (c.op == FfOp::lerp && c.args[1].one_minus) {
    e = "lerp(" + a(2) + ", " + a(0) + ", 1.0 - " + std::string(source_name(c.args[1].source)) + ".a)";
  }
  if (c.scale != 1) e = "(" + e + ") * " + std::to_string(c.scale) + ".0";
  return "saturate(" + e + ")";
}

bool reads(const FfStage& st, FfSource source) {
  for (const FfCombine* c : {&st.color, &st.alpha}) {
    size_t n = c->op == FfOp::replace ? 1 : (c->op == FfOp::lerp || c->op >= FfOp::mul_add) ? 3 : 2;
    for (size_t i = 0; i < n; ++i) {
      if (c->args[i].source == source) return true;
    }
  }
  return false;
}

// Whether the primary colour reaches the output: "previous" of the first
// stage is the primary colour, and without stages it is the output.
bool reads_primary(const FixedFunctionState& s) {
  if (s.stages.empty() || reads(s.stages[0], FfSource::previous)) return true;
  return std::any_of(s.stages.begin(), s.stages.end(), [](const FfStage& st) { return reads(st, FfSource::primary); });
}

struct Layout {
  bool normal = false, color = false;
  std::array<bool, 2> texcoord{false, false};
  bool specular = false;  // specular is computed
};

void vertex_lighting(const FixedFunctionState& s, const Layout& layout, Uniforms& u, std::string& out) {
  std::string diffuse = color_expr(s.diffuse, u), ambient = color_expr(s.ambient, u);
  std::string emission = color_expr(s.emission, u);
  if (s.color_material == FfColorMaterial::ambient_and_diffuse) diffuse = ambient = "v.color";
  if (s.color_material == FfColorMaterial::emission) emission = "v.color";
  out += "    // Vertex lighting in view space: emission + ambient * scene ambient, then\n";
  out += "    // per light the diffuse N.L";
  out += layout.specular ? " and Blinn-Phong specular (exponent Shininess * 128)" : "";
  out += ",\n    // attenuated by 1 / (1 + atten.z * d^2), zero past the range (atten.w = range^2),\n";
  out += "    // and by the spot cone saturate((cos - atten.x) * atten.y).\n";
  out += "    float4 matDiffuse = " + diffuse + ";\n";
  out += "    float3 viewPos = UnityObjectToViewPos(v.vertex.xyz);\n";
  out += "    float3 viewN = normalize(mul((float3x3)UNITY_MATRIX_IT_MV, v.normal));\n";
  out += "    float3 lit = (" + emission + ").rgb + (" + ambient + ").rgb * UNITY_LIGHTMODEL_AMBIENT.rgb;\n";
  if (layout.specular) {
    out += "    float3 viewDir = normalize(-viewPos);\n";
    out += "    float specPower = max(" + scalar_expr(s.shininess, u) + " * 128.0, 0.0001);\n";
    out += "    float3 spec = 0;\n";
  }
  out += "    for (int i = 0; i < 8; i++) {\n";
  out += "        float3 toLight = unity_LightPosition[i].xyz - viewPos * unity_LightPosition[i].w;\n";
  out += "        float distSq = max(dot(toLight, toLight), 0.000001);\n";
  out += "        toLight *= rsqrt(distSq);\n";
  out += "        float atten = 1.0 / (1.0 + unity_LightAtten[i].z * distSq);\n";
  out += "        if (unity_LightPosition[i].w != 0.0 && distSq > unity_LightAtten[i].w) atten = 0.0;\n";
  out += "        float cosAngle = max(0.0, dot(toLight, unity_SpotDirection[i].xyz));\n";
  out += "        atten *= saturate((cosAngle - unity_LightAtten[i].x) * unity_LightAtten[i].y);\n";
  out += "        float nDotL = max(0.0, dot(viewN, toLight));\n";
  out += "        lit += unity_LightColor[i].rgb * matDiffuse.rgb * (nDotL * atten);\n";
  if (layout.specular) {
    out += "        float nDotH = max(0.0, dot(viewN, normalize(toLight + viewDir)));\n";
    out += "        if (nDotL > 0.0) spec += unity_LightColor[i].rgb * (pow(nDotH, specPower) * atten);\n";
  }
  out += "    }\n";
  if (layout.specular) {
    out += "    spec *= (" + color_expr(s.specular, u) + ").rgb;\n";
    if (s.separate_specular) {
      out += "    o.specular = float4(saturate(spec), 0.0);\n";
    } else {
      out += "    lit += spec;\n";
    }
  }
  out += "    o.primary = saturate(float4(lit, matDiffuse.a));\n";
}

std::string_view sampler_type(FfTextureKind k) {
  switch (k) {
    case FfTextureKind::tex3d: return "sampler3D";
    case FfTextureKind::cube: return "samplerCUBE";
    case FfTextureKind::tex2d: break;
  }
  return "sampler2D";
}

std::string_view comparison(const std::string& test) {
  static const std::pair<std::string_view, std::string_view> kOps[] = {
      {"Less", "<"}, {"LEqual", "<="}, {"Equal", "=="}, {"GEqual", ">="}, {"Greater", ">"}, {"NotEqual", "!="}};
  for (auto [name, op] : kOps) {
    if (name == test) return op;
  }
  return "";
}

}  // namespace

std::string generate_fixed_function_hlsl(const FixedFunctionState& s, const std::vector<FfTexture>& textures,
                                         const std::string& title) {
  Uniforms u;
  Layout layout;
  layout.specular = s.lighting && (s.separate_specular || is_set(s.specular));
  // Unlit, the vertex colour is the primary colour; it is only read (and
  // only asked of the mesh) when a stage, or the output without stages, uses it.
  layout.color = s.lighting ? s.color_material != FfColorMaterial::none : !s.has_color && reads_primary(s);
  layout.normal = s.lighting;
  for (size_t i = 0; i < s.stages.size(); ++i) {
    if (textures[i].texgen.empty()) layout.texcoord[size_t(s.stage_texcoord[i] == 1)] = true;
    else layout.normal = true;
  }
  bool fog = s.fog != FfFog::off;

  std::string head = "// " + title + ": generated from the Pass's fixed-function state.\n";
  head += "#pragma vertex ff_vert\n#pragma fragment ff_frag\n";
  if (s.fog == FfFog::global) head += "#pragma multi_compile_fog\n";
  if (s.fog == FfFog::linear) head += "#define FOG_LINEAR 1\n";
  if (s.fog == FfFog::exp) head += "#define FOG_EXP 1\n";
  if (s.fog == FfFog::exp2) head += "#define FOG_EXP2 1\n";
  head += "#include \"UnityCG.cginc\"\n\n";

  std::string types = "struct ff_appdata {\n    float4 vertex : POSITION;\n";
  if (layout.normal) types += "    float3 normal : NORMAL;\n";
  if (layout.color) types += "    float4 color : COLOR;\n";
  if (layout.texcoord[0]) types += "    float4 texcoord0 : TEXCOORD0;\n";
  if (layout.texcoord[1]) types += "    float4 texcoord1 : TEXCOORD1;\n";
  types += "};\n\nstruct ff_v2f {\n    float4 pos : SV_POSITION;\n    float4 primary : COLOR0;\n";
  if (layout.specular && s.separate_specular) types += "    float4 specular : COLOR1;\n";
  for (size_t i = 0; i < s.stages.size(); ++i) {
    bool uvw = textures[i].kind != FfTextureKind::tex2d;
    types += fmt::format("    float{} uv{} : TEXCOORD{};\n", uvw ? 3 : 2, i, i);
  }
  if (fog) types += fmt::format("    UNITY_FOG_COORDS({})\n", s.stages.size());
  types += "};\n\n";

  std::string vert = "ff_v2f ff_vert(ff_appdata v) {\n    ff_v2f o = (ff_v2f)0;\n";
  vert += "    o.pos = UnityObjectToClipPos(v.vertex.xyz);\n";
  if (s.lighting) vertex_lighting(s, layout, u, vert);
  else if (s.has_color) vert += "    o.primary = " + color_expr(s.color, u) + ";\n";
  else if (layout.color) vert += "    o.primary = saturate(v.color);\n";
  else vert += "    o.primary = float4(1.0, 1.0, 1.0, 1.0);\n";
  bool world = false;
  for (size_t i = 0; i < s.stages.size(); ++i) {
    const FfStage& st = s.stages[i];
    const FfTexture& t = textures[i];
    u.add(st.texture, sampler_type(t.kind));
    if (!t.texgen.empty()) {
      if (!world) {
        vert += "    float3 worldPos = mul(unity_ObjectToWorld, float4(v.vertex.xyz, 1.0)).xyz;\n";
        vert += "    float3 worldN = UnityObjectToWorldNormal(v.normal);\n";
        world = true;
      }
      vert += fmt::format("    o.uv{} = {};\n", i,
                          t.texgen == "CubeNormal" ? "worldN" : "reflect(worldPos - _WorldSpaceCameraPos, worldN)");
      continue;
    }
    std::string uv = fmt::format("v.texcoord{}", s.stage_texcoord[i] == 1 ? 1 : 0);
    if (t.kind != FfTextureKind::tex2d) {
      vert += fmt::format("    o.uv{} = {}.xyz;\n", i, uv);
      continue;
    }
    u.add(st.texture + "_ST", "float4");
    vert += fmt::format("    o.uv{} = {}.xy * {}_ST.xy + {}_ST.zw;\n", i, uv, st.texture, st.texture);
    if (!st.matrix.empty()) {
      u.add(st.matrix, "float4x4");
      vert += fmt::format("    o.uv{} = mul({}, float4(o.uv{}, 0.0, 1.0)).xy;\n", i, st.matrix, i);
    }
  }
  if (fog) vert += "    UNITY_TRANSFER_FOG(o, o.pos);\n";
  vert += "    return o;\n}\n\n";

  std::string frag = "float4 ff_frag(ff_v2f i) : SV_Target {\n";
  frag += "    float4 ffPrimary = i.primary;\n    float4 ffPrevious = ffPrimary;\n";
  if (!s.stages.empty()) frag += "    float4 ffTexture, ffConstant;\n";
  for (size_t i = 0; i < s.stages.size(); ++i) {
    const FfStage& st = s.stages[i];
    std::string_view lookup = textures[i].kind == FfTextureKind::cube    ? "texCUBE"
                              : textures[i].kind == FfTextureKind::tex3d ? "tex3D"
                                                                         : "tex2D";
    frag += fmt::format("    // SetTexture [{}]\n", st.texture);
    frag += fmt::format("    ffTexture = {}({}, i.uv{});\n", lookup, st.texture, i);
    frag += "    ffConstant = " + (st.has_constant ? color_expr(st.constant, u) : std::string("float4(0, 0, 0, 0)")) + ";\n";
    frag += "    ffPrevious = float4(" + combine(st.color, false) + ", " + combine(st.alpha, true) + ");\n";
  }
  if (layout.specular && s.separate_specular) frag += "    ffPrevious.rgb = saturate(ffPrevious.rgb + i.specular.rgb);\n";
  if (s.alpha_test == "Never") {
    frag += "    clip(-1.0);  // AlphaTest Never\n";
  } else if (std::string_view op = comparison(s.alpha_test); !op.empty()) {
    frag += fmt::format("    clip((ffPrevious.a {} {}) ? 1.0 : -1.0);  // AlphaTest {}\n", op,
                        scalar_expr(s.alpha_ref, u), s.alpha_test);
  }
  if (fog) {
    frag += s.has_fog_color ? "    UNITY_APPLY_FOG_COLOR(i.fogCoord, ffPrevious, " + color_expr(s.fog_color, u) + ");\n"
                            : "    UNITY_APPLY_FOG(i.fogCoord, ffPrevious);\n";
  }
  frag += "    return ffPrevious;\n}\n";

  std::string decls = u.declarations();
  return head + (decls.empty() ? "" : decls + "\n") + types + vert + frag;
}

}  // namespace facet::sema
