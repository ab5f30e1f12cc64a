#include "source_assembly.h"

#include "hlsl_rewrite.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <set>
#include "facet/support/text.h"

namespace facet::backend {
namespace {

// `#line` takes a string literal; glslang has no escapes in it, so quotes
// and backslashes in a path are replaced.
std::string line_file(const std::string& path) {
  std::string out = path.empty() ? std::string("<shader>") : path;
  std::replace(out.begin(), out.end(), '"', '\'');
  std::replace(out.begin(), out.end(), '\\', '/');
  return out;
}

size_t count_lines(std::string_view text) { return size_t(std::count(text.begin(), text.end(), '\n')); }

// Unity's own CGIncludes are on the -I path (a folder holding its
// HLSLSupport.cginc and UnityPBSLighting.cginc).
bool unity_cgincludes_on_path(const BackendOptions& options) {
  std::error_code ec;
  for (const std::string& dir : options.include_dirs) {
    std::filesystem::path d(dir);
    if (std::filesystem::is_regular_file(d / "HLSLSupport.cginc", ec) &&
        std::filesystem::is_regular_file(d / "UnityPBSLighting.cginc", ec)) {
      return true;
    }
  }
  return false;
}

// What Unity's graphics settings define for a desktop Vulkan player at tier 3
// with the default project settings. facet's stdlib makes these choices
// itself (UnityStandardConfig.cginc); Unity's include files expect them.
constexpr std::string_view kUnityTier3Defines =
    "#define UNITY_HARDWARE_TIER3 1\n"
    "#define UNITY_PBS_USE_BRDF1 1\n"
    "#define UNITY_SPECCUBE_BOX_PROJECTION 1\n"
    "#define UNITY_SPECCUBE_BLENDING 1\n"
    "#define UNITY_ENABLE_DETAIL_NORMALMAP 1\n"
    "#define UNITY_ENABLE_REFLECTION_BUFFERS 1\n"
    "#define UNITY_USE_DITHER_MASK_FOR_ALPHABLENDED_SHADOWS 1\n"
    "#define UNITY_ENABLE_NATIVE_SHADOW_LOOKUPS 1\n"
    "#define UNITY_LIGHTMAP_RGBM_ENCODING 1\n";

// Whether `text` has a "#define NAME" of its own.
bool defines_macro(std::string_view text, std::string_view name) {
  for (size_t at = text.find(name); at != std::string_view::npos; at = text.find(name, at + 1)) {
    size_t line = text.rfind('\n', at);
    line = line == std::string_view::npos ? 0 : line + 1;
    std::string_view before = text.substr(line, at - line);
    size_t hash = before.find_first_not_of(" \t");
    if (hash == std::string_view::npos || before[hash] != '#') continue;
    std::string_view directive = before.substr(hash + 1);
    size_t word = directive.find_first_not_of(" \t");
    if (word == std::string_view::npos || directive.substr(word, 6) != "define") continue;
    if (directive.substr(word + 6).find_first_not_of(" \t") == std::string_view::npos) return true;
  }
  return false;
}

// Unity 2018.1 and later define UNITY_PASS_<MODE> for the LightModes their
// include files test (UnityStandardInput reads the lightmap uv in the Meta
// pass by it), unless the program defines it itself, as surface shaders'
// generated code does. Unity 2017's include files define it themselves
// (UnityStandardMeta), and its Illumin-VertexLit has code under
// UNITY_PASS_META that only compiles because it is not defined.
void append_pass_define(std::string& out, const ir::Program& program, const BackendOptions& options) {
  if (options.unity_version < 201810) return;
  static constexpr std::pair<std::string_view, std::string_view> kPassDefines[] = {
      {"ForwardBase", "UNITY_PASS_FORWARDBASE"},   {"ForwardAdd", "UNITY_PASS_FORWARDADD"},
      {"Deferred", "UNITY_PASS_DEFERRED"},         {"ShadowCaster", "UNITY_PASS_SHADOWCASTER"},
      {"PrepassBase", "UNITY_PASS_PREPASSBASE"},   {"PrepassFinal", "UNITY_PASS_PREPASSFINAL"},
      {"Meta", "UNITY_PASS_META"},
  };
  for (auto [mode, name] : kPassDefines) {
    if (upper(program.light_mode) != upper(mode)) continue;
    bool own = defines_macro(program.body.text, name) ||
               std::any_of(program.includes.begin(), program.includes.end(),
                           // `name = name`: clang before 16 cannot capture a structured binding.
                           [name = name](const ir::SourceChunk& c) { return defines_macro(c.text, name); });
    if (!own) out += fmt::format("#define {} 1\n", name);
  }
}

void append_defines(std::string& out, const ir::Program& program, Stage stage,
                    const std::vector<std::string>& keywords, const BackendOptions& options) {
  out += fmt::format("#define {} 1\n", stage_define(stage));
  out += fmt::format("#define SHADER_TARGET {}\n", program.shader_target);
  out += "#define SHADER_API_VULKAN 1\n";
  out += "#define SHADER_API_DESKTOP 1\n";
  out += fmt::format("#define UNITY_VERSION {}\n", options.unity_version);
  if (program.language != ir::ProgramLanguage::glsl) {
    // Unity compiles Vulkan shaders with an HLSL compiler and HLSLcc; Unity's
    // own HLSLSupport.cginc (given with -I) picks its Vulkan code by these.
    out += "#define UNITY_COMPILER_HLSL\n";
    out += "#define UNITY_COMPILER_HLSLCC\n";
    // glslang lowers this intrinsic to gl_NumSamples, which SPIR-V lacks,
    // and crashes generating SPIR-V; facet's targets are single-sampled.
    out += "#define GetRenderTargetSampleCount() 1u\n";
    if (unity_cgincludes_on_path(options)) out += kUnityTier3Defines;
  }
  append_pass_define(out, program, options);
  for (const std::string& keyword : keywords) {
    if (!keyword.empty()) out += fmt::format("#define {} 1\n", keyword);
  }
  for (const auto& [name, value] : options.defines) {
    out += fmt::format("#define {} {}\n", name, value.empty() ? "1" : value);
  }
}

// A GLSL body may carry its own "#version"; it must come first, so it is
// lifted out (the line is blanked to keep line numbers) and used instead of 450.
std::string take_glsl_version(std::string& body) {
  size_t pos = 0;
  while (pos < body.size()) {
    size_t end = body.find('\n', pos);
    if (end == std::string::npos) end = body.size();
    std::string_view line(body.data() + pos, end - pos);
    size_t i = line.find_first_not_of(" \t");
    if (i != std::string_view::npos && line[i] == '#') {
      size_t j = line.find_first_not_of(" \t", i + 1);
      if (j != std::string_view::npos && line.substr(j, 7) == "version") {
        std::string version(line.substr(j + 7));
        version.erase(0, version.find_first_not_of(" \t"));
        while (!version.empty() && std::isspace(static_cast<unsigned char>(version.back()))) version.pop_back();
        body.replace(pos, end - pos, std::string(end - pos, ' '));
        return version;
      }
    }
    pos = end + 1;
  }
  return "450";
}

void append_chunk(std::string& out, const ir::SourceChunk& chunk, const std::string& file) {
  out += fmt::format("#line {} \"{}\"\n", chunk.first_line, chunk.line_file.empty() ? file : line_file(chunk.line_file));
  out += chunk.text;
  if (chunk.text.empty() || chunk.text.back() != '\n') out += '\n';
}

// ---- GLSLPROGRAM with Unity's GLSL conventions (docs/language.md §7.3) ------
// A body without #version, or with GLSL 1.x's or ES 3.0's, is Unity-style GLSL
// (gl_Vertex, varying, gl_FragColor, texture2D, loose uniforms). It is
// compiled as GLSL 450 with stdlib/FacetGLSLUnity.glslinc, which maps those
// names by macros; this code finds which of them the program uses and gives
// `varying`/`attribute` declarations explicit locations.

bool unity_glsl_version(std::string_view version) {
  if (version == "300 es") return true;
  return version.size() == 3 && version[0] == '1' && std::isdigit(static_cast<unsigned char>(version[1])) &&
         std::isdigit(static_cast<unsigned char>(version[2]));
}

struct GlslToken {
  enum Kind { ident, number, punct } kind;
  size_t begin, end;
  bool directive;  // on a preprocessor line
};

bool ident_start(char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '_'; }
bool ident_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

// The tokens of a GLSL text outside comments (string literals, which occur in
// #include and #line, are skipped).
std::vector<GlslToken> glsl_tokens(std::string_view text) {
  std::vector<GlslToken> out;
  bool directive = false, line_start = true;
  for (size_t i = 0; i < text.size();) {
    char c = text[i];
    char next = i + 1 < text.size() ? text[i + 1] : '\0';
    if (c == '\n') {
      if (!(i > 0 && text[i - 1] == '\\')) directive = false;
      line_start = true;
      ++i;
    } else if (c == ' ' || c == '\t' || c == '\r' || c == '\\') {
      ++i;
    } else if (c == '/' && next == '/') {
      i = std::min(text.find('\n', i), text.size());
    } else if (c == '/' && next == '*') {
      size_t end = text.find("*/", i + 2);
      i = end == std::string_view::npos ? text.size() : end + 2;
    } else if (c == '"') {
      for (++i; i < text.size() && text[i] != '"' && text[i] != '\n'; ++i) {}
      if (i < text.size() && text[i] == '"') ++i;
      line_start = false;
    } else {
      if (line_start && c == '#') directive = true;
      line_start = false;
      size_t begin = i;
      GlslToken::Kind kind = GlslToken::punct;
      if (ident_start(c)) {
        while (i < text.size() && ident_char(text[i])) ++i;
        kind = GlslToken::ident;
      } else if (std::isdigit(static_cast<unsigned char>(c))) {
        while (i < text.size() && (ident_char(text[i]) || text[i] == '.')) ++i;
        kind = GlslToken::number;
      } else {
        ++i;
      }
      out.push_back({kind, begin, i, directive});
    }
  }
  return out;
}

// The names GLSLSupport.glslinc gives a Unity-style program.
bool is_glsl_support_name(std::string_view name) {
  static constexpr std::string_view kNames[] = {
      "gl_ModelViewProjectionMatrix", "gl_ModelViewMatrix", "gl_ModelViewMatrixTranspose", "gl_ModelViewMatrixInverse",
      "gl_ModelViewMatrixInverseTranspose", "gl_NormalMatrix", "gl_ProjectionMatrix", "gl_ProjectionMatrixInverse",
      "gl_ModelViewProjectionMatrixTranspose", "unity_ObjectToWorld", "unity_WorldToObject", "unity_MatrixVP",
      "unity_MatrixV", "unity_MatrixInvV", "unity_MatrixP", "glstate_matrix_projection", "_Object2World",
      "_World2Object"};
  return std::find(std::begin(kNames), std::end(kNames), name) != std::end(kNames);
}

// Of those, the ones GLSLSupport.glslinc makes macros of: a program's own
// `uniform mat4 <name>;` of them is blanked (Unity's GLSLSupport.glslinc
// declares them; old shaders declare _Object2World themselves).
bool is_glsl_support_uniform(std::string_view name) {
  return name.substr(0, 3) != "gl_" && is_glsl_support_name(name);
}

// Locations one varying takes: a matrix one per column, an array per element.
uint32_t glsl_location_count(std::string_view type, uint32_t array) {
  uint32_t per = 1;
  if (type.size() >= 4 && (type.substr(0, 3) == "mat" || type.substr(0, 4) == "dmat")) {
    size_t digit = type[0] == 'd' ? 4 : 3;
    if (digit < type.size() && std::isdigit(static_cast<unsigned char>(type[digit]))) per = uint32_t(type[digit] - '0');
  }
  return per * std::max(1u, array);
}

struct UnityGlslScan {
  bool vertex = false, normal = false, color = false;
  bool multitexcoord[4] = {};
  bool frag_color = false;
  uint32_t frag_data = 0;  // targets, 0 if unused
  bool matrices = false, texture_matrix = false;
  std::map<std::string, uint32_t> varyings;  // name -> locations it takes
  std::set<std::string> attributes;
};

struct UnityGlslEdit {
  size_t at, erase;
  std::string insert;
};

// "varying [qualifiers] type name [N];" at token `i`: the name, type and array
// size; nullopt for other shapes (several declarators, structs), which keep
// glslang's automatic locations.
struct IoDeclaration {
  std::string name, type;
  uint32_t array = 0;
};
std::optional<IoDeclaration> io_declaration(std::string_view text, const std::vector<GlslToken>& t, size_t i) {
  auto word = [&](size_t k) { return std::string_view(text.data() + t[k].begin, t[k].end - t[k].begin); };
  static constexpr std::string_view kQualifiers[] = {"highp", "mediump", "lowp", "flat", "smooth", "noperspective",
                                                     "centroid", "invariant"};
  size_t k = i + 1;
  while (k < t.size() && std::find(std::begin(kQualifiers), std::end(kQualifiers), word(k)) != std::end(kQualifiers)) ++k;
  if (k + 2 >= t.size() || t[k].kind != GlslToken::ident || t[k + 1].kind != GlslToken::ident) return std::nullopt;
  IoDeclaration d{std::string(word(k + 1)), std::string(word(k)), 0};
  k += 2;
  if (k + 2 < t.size() && word(k) == "[" && t[k + 1].kind == GlslToken::number && word(k + 2) == "]") {
    d.array = uint32_t(std::strtoul(std::string(word(k + 1)).c_str(), nullptr, 10));
    k += 3;
  }
  if (k >= t.size() || word(k) != ";" || t[k].directive) return std::nullopt;
  return d;
}

void scan_unity_glsl(std::string_view text, UnityGlslScan& scan) {
  std::vector<GlslToken> t = glsl_tokens(text);
  auto word = [&](size_t k) { return std::string_view(text.data() + t[k].begin, t[k].end - t[k].begin); };
  if (text.find("UnityCG.glslinc") != std::string_view::npos || text.find("GLSLSupport.glslinc") != std::string_view::npos) {
    scan.matrices = true;
  }
  for (size_t i = 0; i < t.size(); ++i) {
    if (t[i].kind != GlslToken::ident) continue;
    std::string_view w = word(i);
    if (w == "gl_Vertex") scan.vertex = true;
    if (w == "gl_Normal" || w == "TANGENT_SPACE_ROTATION") scan.normal = true;
    if (w == "gl_Color") scan.color = true;
    if (w.size() == 17 && w.substr(0, 16) == "gl_MultiTexCoord" && w[16] >= '0' && w[16] <= '3') {
      scan.multitexcoord[w[16] - '0'] = true;
    }
    if (w == "gl_FragColor") scan.frag_color = true;
    if (w == "gl_FragData") {
      uint32_t targets = 8;
      if (i + 3 < t.size() && word(i + 1) == "[" && t[i + 2].kind == GlslToken::number && word(i + 3) == "]") {
        targets = uint32_t(std::strtoul(std::string(word(i + 2)).c_str(), nullptr, 10)) + 1;
        targets = std::clamp(targets, 1u, 8u);
      }
      scan.frag_data = std::max(scan.frag_data, targets);
    }
    if (w == "gl_TextureMatrix") scan.texture_matrix = true;
    if (is_glsl_support_name(w)) scan.matrices = true;
    if ((w == "varying" || w == "attribute") && !t[i].directive) {
      if (std::optional<IoDeclaration> d = io_declaration(text, t, i)) {
        if (w == "varying") {
          uint32_t& n = scan.varyings[d->name];
          n = std::max(n, glsl_location_count(d->type, d->array));
        } else {
          scan.attributes.insert(d->name);
        }
      }
    }
  }
}

// Locations of the program's varyings (by name, so that stages compiled
// apart agree) and attributes (Unity's "Tangent" at TANGENT's location 2, the
// others from 16 on, after facet's fixed vertex inputs).
std::map<std::string, uint32_t> unity_glsl_locations(const UnityGlslScan& scan, bool attributes) {
  std::map<std::string, uint32_t> out;
  if (attributes) {
    uint32_t next = 16;
    for (const std::string& name : scan.attributes) out[name] = (name == "Tangent" || name == "tangent") ? 2 : next++;
  } else {
    uint32_t next = 0;
    for (const auto& [name, count] : scan.varyings) {
      out[name] = next;
      next += count;
    }
  }
  return out;
}

// The text with `layout(location = N)` before each `varying`/`attribute`
// declaration, and with `#extension GL_OES_EGL_image_external...` lines and
// declarations of GLSLSupport's matrices blanked (line numbers are kept).
std::string rewrite_unity_glsl(const std::string& text, const UnityGlslScan& scan) {
  std::vector<GlslToken> t = glsl_tokens(text);
  auto word = [&](size_t k) { return std::string_view(text.data() + t[k].begin, t[k].end - t[k].begin); };
  std::map<std::string, uint32_t> varyings = unity_glsl_locations(scan, false);
  std::map<std::string, uint32_t> attributes = unity_glsl_locations(scan, true);
  std::vector<UnityGlslEdit> edits;
  auto blank = [&](size_t begin, size_t end) {
    std::string spaces;
    for (size_t k = begin; k < end; ++k) spaces += text[k] == '\n' ? '\n' : ' ';
    edits.push_back({begin, end - begin, spaces});
  };
  for (size_t i = 0; i < t.size(); ++i) {
    std::string_view w = word(i);
    if (t[i].directive && w == "#" && i + 2 < t.size() && word(i + 1) == "extension" &&
        word(i + 2).substr(0, 25) == "GL_OES_EGL_image_external") {
      size_t end = text.find('\n', t[i].begin);
      blank(t[i].begin, end == std::string::npos ? text.size() : end);
      continue;
    }
    if (t[i].directive || t[i].kind != GlslToken::ident) continue;
    if (w == "varying" || w == "attribute") {
      std::optional<IoDeclaration> d = io_declaration(text, t, i);
      const auto& table = w == "varying" ? varyings : attributes;
      if (d && table.count(d->name)) {
        edits.push_back({t[i].begin, 0, fmt::format("layout(location = {}) ", table.at(d->name))});
      }
    } else if (w == "uniform") {
      // uniform [precision] mat4 <GLSLSupport name>;
      size_t k = i + 1;
      if (k < t.size() && (word(k) == "highp" || word(k) == "mediump" || word(k) == "lowp")) ++k;
      if (k + 2 < t.size() && word(k) == "mat4" && is_glsl_support_uniform(word(k + 1)) && word(k + 2) == ";") {
        blank(t[i].begin, t[k + 2].end);
      }
    }
  }
  std::string out = text;
  std::sort(edits.begin(), edits.end(), [](const auto& a, const auto& b) { return a.at > b.at; });
  for (const UnityGlslEdit& e : edits) out.replace(e.at, e.erase, e.insert);
  return out;
}

// The defines FacetGLSLUnity.glslinc reads, and the include itself.
void append_unity_glsl_prelude(std::string& out, const UnityGlslScan& scan) {
  out += "#define FACET_GLSL_UNITY 1\n";
  if (scan.vertex) out += "#define FACET_GLSL_USES_VERTEX 1\n";
  if (scan.normal) out += "#define FACET_GLSL_USES_NORMAL 1\n";
  if (scan.color) out += "#define FACET_GLSL_USES_COLOR 1\n";
  for (int n = 0; n < 4; ++n) {
    if (scan.multitexcoord[n]) out += fmt::format("#define FACET_GLSL_USES_MULTITEXCOORD{} 1\n", n);
  }
  if (scan.frag_color) out += "#define FACET_GLSL_USES_FRAGCOLOR 1\n";
  if (scan.frag_data) out += fmt::format("#define FACET_GLSL_USES_FRAGDATA {}\n", scan.frag_data);
  if (scan.matrices) out += "#define FACET_GLSL_USES_MATRICES 1\n";
  if (scan.texture_matrix) out += "#define FACET_GLSL_USES_TEXTUREMATRIX 1\n";
  out += "#include <FacetGLSLUnity.glslinc>\n";
}

}  // namespace

std::optional<size_t> find_excessive_nesting(std::string_view text, int limit) {
  int depth = 0;
  for (size_t i = 0; i < text.size(); ++i) {
    char c = text[i];
    char next = i + 1 < text.size() ? text[i + 1] : '\0';
    if (c == '/' && next == '/') {
      i = std::min(text.find('\n', i), text.size());
    } else if (c == '/' && next == '*') {
      size_t end = text.find("*/", i + 2);
      i = end == std::string_view::npos ? text.size() : end + 1;
    } else if (c == '"') {
      for (++i; i < text.size() && text[i] != '"' && text[i] != '\n'; ++i) {
        if (text[i] == '\\') ++i;
      }
    } else if (c == '(' || c == '[' || c == '{') {
      if (++depth > limit) return i;
    } else if ((c == ')' || c == ']' || c == '}') && depth > 0) {
      --depth;
    }
  }
  return std::nullopt;
}

namespace {

bool is_unary_char(char c) { return c == '!' || c == '~' || c == '-' || c == '+'; }

// An '=' at `i` that assigns: not ==, !=, <=, >= (but <<= and >>= do).
bool is_assignment(std::string_view text, size_t i) {
  if (i + 1 < text.size() && text[i + 1] == '=') return false;
  if (i == 0) return true;
  char before = text[i - 1];
  if (before == '=' || before == '!') return false;
  if (before == '<' || before == '>') return i >= 2 && text[i - 2] == before;
  return true;
}

// The hazard scan's state: one pass over the text, counting each kind of
// run since it last broke.
class HazardScan {
 public:
  explicit HazardScan(std::string_view text) : text_(text) {}

  std::optional<RecursionHazard> run() {
    bool line_start = true;
    for (size_t i = 0; i < text_.size() && !found_; ++i) {
      char c = text_[i];
      char next = i + 1 < text_.size() ? text_[i + 1] : '\0';
      if (c == '\n') {
        if (directive_ && !(i > 0 && text_[i - 1] == '\\')) end_directive();
        line_start = true;
        continue;
      }
      if (c == ' ' || c == '\t' || c == '\r' || c == '\\') continue;
      if (c == '/' && next == '/') {
        i = std::min(text_.find('\n', i), text_.size()) - 1;
        continue;
      }
      if (c == '/' && next == '*') {
        size_t end = text_.find("*/", i + 2);
        i = end == std::string_view::npos ? text_.size() : end + 1;
        continue;
      }
      if (line_start && c == '#') {
        directive_ = true;
        check_line_directive(i);
      }
      line_start = false;
      if (c == '"') {
        for (++i; i < text_.size() && text_[i] != '"' && text_[i] != '\n'; ++i) {
          if (text_[i] == '\\') ++i;
        }
        token(i);
      } else if (ident_start(c)) {
        size_t begin = i;
        while (i + 1 < text_.size() && ident_char(text_[i + 1])) ++i;
        word(text_.substr(begin, i + 1 - begin), begin);
      } else {
        punct(c, i);
      }
    }
    return hazard_;
  }

 private:
  void fail(size_t at, std::string message) {
    if (!found_) hazard_ = RecursionHazard{at, std::move(message)};
    found_ = true;
  }

  // `#line N`: N must fit glslang's line counter.
  void check_line_directive(size_t hash) {
    size_t w = text_.find_first_not_of(" \t", hash + 1);
    if (w == std::string_view::npos || text_.substr(w, 4) != "line") return;
    size_t n = text_.find_first_not_of(" \t", w + 4);
    if (n == std::string_view::npos || n == w + 4 || !std::isdigit(static_cast<unsigned char>(text_[n]))) return;
    uint64_t value = 0;
    for (size_t k = n; k < text_.size() && std::isdigit(static_cast<unsigned char>(text_[k])); ++k) {
      value = std::min<uint64_t>(value * 10 + uint64_t(text_[k] - '0'), kMaxLineNumber + 1);
    }
    if (value > kMaxLineNumber) fail(n, fmt::format("#line number out of range (at most {})", kMaxLineNumber));
  }

  // Any token but a unary operator ends a run of them.
  void token(size_t at, bool is_else = false) {
    unary_ = 0;
    if (statement_start_ == std::string_view::npos) statement_start_ = at;
    if_chain_token(is_else);
  }

  void word(std::string_view w, size_t at) {
    token(at, w == "else");
    if (w == "if") {
      IfChain& chain = if_chain();
      if (chain.count++ == 0) chain.start = at;
      if (chain.count > kMaxIfChain) {
        fail(chain.start, fmt::format("more than {} if statements chained or nested (if ... else if ...)", kMaxIfChain));
      }
    }
  }

  void punct(char c, size_t at) {
    if (is_unary_char(c)) {
      if (unary_++ == 0) unary_start_ = at;
      if (unary_ > kMaxUnaryRun) fail(unary_start_, fmt::format("more than {} unary operators in a row", kMaxUnaryRun));
      if (statement_start_ == std::string_view::npos) statement_start_ = at;
      if_chain_token(false);
      return;
    }
    token(at);
    if (c == '(' || c == '[' || c == '{') {
      if (c == '{') end_statement();
      // HLSL has no braces inside [ ]; glslang's HLSL front end crashes on
      // an initializer list there (float w[X = { 0.1 }; found by fuzzing).
      if (c == '{' && !open_.empty() && open_.back() == '[') fail(at, "'{' inside '[ ]': a ']' is missing before it");
      open_.push_back(c);
      if (++depth_ > kMaxNesting) fail(at, fmt::format("brackets nest more than {} deep", kMaxNesting));
      if (depth_ >= 0 && size_t(depth_) >= if_chains_.size()) if_chains_.resize(size_t(depth_) + 1);
      if (depth_ >= 0) if_chains_[size_t(depth_)] = {};
    } else if (c == ')' || c == ']' || c == '}') {
      if (depth_ > 0) --depth_;
      if (!open_.empty()) open_.pop_back();
      if (c == '}') end_statement();
    } else if (c == ';' || c == ',') {
      end_statement();
    } else if (c == '=' && is_assignment(text_, at)) {
      if (++assignments_ > kMaxAssignmentChain) {
        fail(statement_start_, fmt::format("more than {} assignments chained in one expression", kMaxAssignmentChain));
      }
    } else if (c == '?') {
      if (++conditionals_ > kMaxAssignmentChain) {
        fail(statement_start_, fmt::format("more than {} '?:' chained in one expression", kMaxAssignmentChain));
      }
    }
  }

  // ; , { } and the end of a directive end the chains of one expression; a
  // statement ending (; }) lets an if chain go on only through `else`.
  void end_statement() {
    assignments_ = conditionals_ = 0;
    statement_start_ = std::string_view::npos;
    if_chain().pending_end = true;
  }

  void end_directive() {
    directive_ = false;
    unary_ = 0;
    end_statement();
  }

  struct IfChain {
    int count = 0;
    size_t start = 0;
    bool pending_end = false;
  };

  IfChain& if_chain() {
    size_t d = size_t(std::max(depth_, 0));
    if (d >= if_chains_.size()) if_chains_.resize(d + 1);
    return if_chains_[d];
  }

  // A token after a statement's end breaks its depth's if chain unless it
  // is `else`.
  void if_chain_token(bool is_else) {
    IfChain& chain = if_chain();
    if (!chain.pending_end) return;
    chain.pending_end = false;
    if (!is_else) chain.count = 0;
  }

  std::string_view text_;
  bool found_ = false, directive_ = false;
  std::optional<RecursionHazard> hazard_;
  int depth_ = 0, unary_ = 0, assignments_ = 0, conditionals_ = 0;
  size_t unary_start_ = 0, statement_start_ = std::string_view::npos;
  std::vector<IfChain> if_chains_{1};
  std::vector<char> open_;  // the brackets open at this point, innermost last
};

// ---- Unity's shader upgrade --------------------------------------------------
// Unity 5.4 renamed the built-in matrices below; when it imports a shader it
// rewrites the old names in the file (unless the file says
// UNITY_SHADER_NO_UPGRADE), so shaders written for Unity 5.3 and earlier
// still build. facet maps the old names by macros instead, for the names a
// program uses and does not declare itself.
struct RenamedBuiltin {
  std::string_view old_name, new_name;
};
constexpr RenamedBuiltin kRenamedBuiltins[] = {
    {"_Object2World", "unity_ObjectToWorld"},      {"_World2Object", "unity_WorldToObject"},
    {"_LightMatrix0", "unity_WorldToLight"},       {"_World2Shadow", "unity_WorldToShadow[0]"},
    {"_World2Shadow1", "unity_WorldToShadow[1]"}, {"_World2Shadow2", "unity_WorldToShadow[2]"},
    {"_World2Shadow3", "unity_WorldToShadow[3]"},
};

struct UpgradeScan {
  bool no_upgrade = false;
  std::set<std::string_view> used, declared;
};

void scan_for_upgrade(std::string_view text, UpgradeScan& scan) {
  if (text.find("UNITY_SHADER_NO_UPGRADE") != std::string_view::npos) scan.no_upgrade = true;
  std::vector<GlslToken> tokens = glsl_tokens(text);
  for (size_t i = 0; i < tokens.size(); ++i) {
    if (tokens[i].kind != GlslToken::ident || tokens[i].directive) continue;
    std::string_view word = text.substr(tokens[i].begin, tokens[i].end - tokens[i].begin);
    for (const RenamedBuiltin& r : kRenamedBuiltins) {
      if (word != r.old_name) continue;
      scan.used.insert(r.old_name);
      // "TYPE NAME;" (or "[", "=", ":"): the program's own uniform.
      bool after_type = i > 0 && tokens[i - 1].kind == GlslToken::ident;
      char next = i + 1 < tokens.size() ? text[tokens[i + 1].begin] : ';';
      if (after_type && (next == ';' || next == '[' || next == '=' || next == ':' || next == ',')) {
        scan.declared.insert(r.old_name);
      }
    }
  }
}

void append_upgraded_names(std::string& out, const ir::Program& program) {
  UpgradeScan scan;
  for (const ir::SourceChunk& chunk : program.includes) scan_for_upgrade(chunk.text, scan);
  scan_for_upgrade(program.body.text, scan);
  if (scan.no_upgrade) return;
  for (const RenamedBuiltin& r : kRenamedBuiltins) {
    if (scan.used.count(r.old_name) && !scan.declared.count(r.old_name)) {
      out += fmt::format("#define {} {}\n", r.old_name, r.new_name);
    }
  }
}

}  // namespace

std::optional<RecursionHazard> find_recursion_hazard(std::string_view text) { return HazardScan(text).run(); }

std::string stage_define(Stage stage) { return "SHADER_STAGE_" + upper(stage_name(stage)); }

AssembledSource assemble_source(const ir::Program& program, Stage stage, const std::vector<std::string>& keywords,
                                const BackendOptions& options, const std::string& shader_path) {
  AssembledSource result;
  result.root_name = line_file(shader_path);
  std::string& out = result.text;
  if (program.language == ir::ProgramLanguage::glsl) {
    std::string body = program.body.text;
    std::string version = take_glsl_version(body);
    // take_glsl_version blanks the line it takes: an unchanged body had none.
    bool unity = body == program.body.text || unity_glsl_version(version);
    UnityGlslScan scan;
    if (unity) {
      version = "450";
      for (const ir::SourceChunk& chunk : program.includes) scan_unity_glsl(chunk.text, scan);
      scan_unity_glsl(body, scan);
    }
    out += fmt::format("#version {}\n", version);
    out += "#extension GL_GOOGLE_include_directive : require\n";
    out += fmt::format("#line {} \"{}\"\n", count_lines(out) + 2, kPreludeName);
    out += fmt::format("#define {} 1\n", upper(stage_name(stage)));
    append_defines(out, program, stage, keywords, options);
    if (unity) append_unity_glsl_prelude(out, scan);
    result.prelude = out;
    for (ir::SourceChunk chunk : program.includes) {
      if (unity) chunk.text = rewrite_unity_glsl(chunk.text, scan);
      append_chunk(out, chunk, result.root_name);
    }
    ir::SourceChunk main = program.body;
    main.text = unity ? rewrite_unity_glsl(body, scan) : std::move(body);
    append_chunk(out, main, result.root_name);
    return result;
  }
  // "#line 2" on line 1: the prelude's lines keep their physical numbers.
  out += fmt::format("#line 2 \"{}\"\n", kPreludeName);
  append_defines(out, program, stage, keywords, options);
  append_upgraded_names(out, program);
  if (program.language == ir::ProgramLanguage::cg) {
    // Unity includes these implicitly in CGPROGRAM (not in HLSLPROGRAM);
    // with Unity's CGIncludes on the -I path, Unity's files are the ones found.
    out += "#include <FacetHLSLccTypes.hlsl>\n";
    out += "#include <HLSLSupport.cginc>\n";
    out += "#include <UnityShaderVariables.cginc>\n";
    out += "#include <UnityShaderUtilities.cginc>\n";
  }
  result.prelude = out;
  for (ir::SourceChunk chunk : program.includes) {
    chunk.text = rewrite_matrix_swizzles(chunk.text);
    append_chunk(out, chunk, result.root_name);
  }
  ir::SourceChunk body = program.body;
  body.text = rewrite_matrix_swizzles(body.text);
  append_chunk(out, body, result.root_name);
  return result;
}

}  // namespace facet::backend
