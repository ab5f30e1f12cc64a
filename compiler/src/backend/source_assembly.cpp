#include "backend/source_assembly.h"

#include "backend/hlsl_rewrite.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <filesystem>

namespace facet::backend {
namespace {

std::string upper(std::string_view s) {
  std::string out(s);
  std::transform(out.begin(), out.end(), out.begin(), [](unsigned char c) { return char(std::toupper(c)); });
  return out;
}

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
    out += "#define UNITY_COMPILER_HLSL 1\n";
    out += "#define UNITY_COMPILER_HLSLCC 1\n";
    if (unity_cgincludes_on_path(options)) out += kUnityTier3Defines;
  }
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

std::string stage_define(Stage stage) { return "SHADER_STAGE_" + upper(stage_name(stage)); }

AssembledSource assemble_source(const ir::Program& program, Stage stage, const std::vector<std::string>& keywords,
                                const BackendOptions& options, const std::string& shader_path) {
  AssembledSource result;
  result.root_name = line_file(shader_path);
  std::string& out = result.text;
  if (program.language == ir::ProgramLanguage::glsl) {
    std::string body = program.body.text;
    out += fmt::format("#version {}\n", take_glsl_version(body));
    out += "#extension GL_GOOGLE_include_directive : require\n";
    out += fmt::format("#line {} \"{}\"\n", count_lines(out) + 2, kPreludeName);
    out += fmt::format("#define {} 1\n", upper(stage_name(stage)));
    append_defines(out, program, stage, keywords, options);
    result.prelude = out;
    for (const ir::SourceChunk& chunk : program.includes) append_chunk(out, chunk, result.root_name);
    ir::SourceChunk main = program.body;
    main.text = std::move(body);
    append_chunk(out, main, result.root_name);
    return result;
  }
  // "#line 2" on line 1: the prelude's lines keep their physical numbers.
  out += fmt::format("#line 2 \"{}\"\n", kPreludeName);
  append_defines(out, program, stage, keywords, options);
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
