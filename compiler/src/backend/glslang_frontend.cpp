#include "glslang_frontend.h"

#include "crash_isolation.h"
#include "global_declarations.h"
#include "hlsl_rewrite.h"
#include "facet/reachability.h"

#include <fmt/format.h>
#include <glslang/MachineIndependent/localintermediate.h>
#include <glslang/Public/ResourceLimits.h>
#include <glslang/SPIRV/GlslangToSpv.h>

#include <cctype>
#include <memory>
#include <optional>
#include <string_view>

namespace facet::backend {
namespace {

EShLanguage to_glslang(Stage stage) {
  switch (stage) {
    case Stage::vertex: return EShLangVertex;
    case Stage::fragment: return EShLangFragment;
    case Stage::geometry: return EShLangGeometry;
    case Stage::hull: return EShLangTessControl;
    case Stage::domain: return EShLangTessEvaluation;
  }
  return EShLangVertex;
}

bool is_hlsl(ir::ProgramLanguage language) { return language != ir::ProgramLanguage::glsl; }

EShMessages messages_for(ir::ProgramLanguage language, const BackendOptions& options) {
  int m = EShMsgSpvRules;
  if (options.target != TargetEnv::opengl4_5) m |= EShMsgVulkanRules;
  if (is_hlsl(language)) m |= EShMsgReadHlsl | EShMsgHlslDX9Compatible | EShMsgHlslLegalization;
  return EShMessages(m);
}

// glslang's GLSL preamble defines its macros (the names of GLSL extensions,
// VULKAN, GL_SPIRV) for HLSL input too. fxc defines none of them, and HLSL
// code tests some (FXAA 3.11 picks gather4 by GL_ARB_gpu_shader5), so HLSL
// programs get a preamble that undefines them all.
constexpr const char* kUndefineGlslangPreamble =
    "#undef GL_FRAGMENT_PRECISION_HIGH\n"
    "#undef GL_ARB_texture_rectangle\n"
    "#undef GL_ARB_shading_language_420pack\n"
    "#undef GL_ARB_texture_gather\n"
    "#undef GL_ARB_gpu_shader5\n"
    "#undef GL_ARB_separate_shader_objects\n"
    "#undef GL_ARB_compute_shader\n"
    "#undef GL_ARB_tessellation_shader\n"
    "#undef GL_ARB_enhanced_layouts\n"
    "#undef GL_ARB_texture_cube_map_array\n"
    "#undef GL_ARB_shader_texture_lod\n"
    "#undef GL_ARB_explicit_attrib_location\n"
    "#undef GL_ARB_explicit_uniform_location\n"
    "#undef GL_ARB_shader_image_load_store\n"
    "#undef GL_ARB_shader_atomic_counters\n"
    "#undef GL_ARB_shader_draw_parameters\n"
    "#undef GL_ARB_shader_group_vote\n"
    "#undef GL_ARB_derivative_control\n"
    "#undef GL_ARB_shader_texture_image_samples\n"
    "#undef GL_ARB_viewport_array\n"
    "#undef GL_ARB_gpu_shader_int64\n"
    "#undef GL_ARB_shader_ballot\n"
    "#undef GL_ARB_sparse_texture2\n"
    "#undef GL_ARB_sparse_texture_clamp\n"
    "#undef GL_ARB_shader_stencil_export\n"
    "#undef GL_ARB_sample_shading\n"
    "#undef GL_ARB_post_depth_coverage\n"
    "#undef GL_ARB_fragment_shader_interlock\n"
    "#undef GL_EXT_shader_non_constant_global_initializers\n"
    "#undef GL_EXT_shader_image_load_formatted\n"
    "#undef GL_EXT_post_depth_coverage\n"
    "#undef GL_EXT_control_flow_attributes\n"
    "#undef GL_EXT_nonuniform_qualifier\n"
    "#undef GL_EXT_shader_16bit_storage\n"
    "#undef GL_EXT_shader_8bit_storage\n"
    "#undef GL_EXT_samplerless_texture_functions\n"
    "#undef GL_EXT_scalar_block_layout\n"
    "#undef GL_EXT_fragment_invocation_density\n"
    "#undef GL_EXT_buffer_reference\n"
    "#undef GL_EXT_buffer_reference2\n"
    "#undef GL_EXT_buffer_reference_uvec2\n"
    "#undef GL_EXT_demote_to_helper_invocation\n"
    "#undef GL_KHR_shader_subgroup_basic\n"
    "#undef GL_KHR_shader_subgroup_vote\n"
    "#undef GL_KHR_shader_subgroup_arithmetic\n"
    "#undef GL_KHR_shader_subgroup_ballot\n"
    "#undef GL_KHR_shader_subgroup_shuffle\n"
    "#undef GL_KHR_shader_subgroup_shuffle_relative\n"
    "#undef GL_KHR_shader_subgroup_clustered\n"
    "#undef GL_KHR_shader_subgroup_quad\n"
    "#undef GL_AMD_shader_ballot\n"
    "#undef GL_AMD_shader_trinary_minmax\n"
    "#undef GL_AMD_shader_explicit_vertex_parameter\n"
    "#undef GL_AMD_gcn_shader\n"
    "#undef GL_AMD_gpu_shader_half_float\n"
    "#undef GL_AMD_texture_gather_bias_lod\n"
    "#undef GL_AMD_gpu_shader_int16\n"
    "#undef GL_AMD_shader_image_load_store_lod\n"
    "#undef GL_AMD_shader_fragment_mask\n"
    "#undef GL_AMD_gpu_shader_half_float_fetch\n"
    "#undef GL_INTEL_shader_integer_functions2\n"
    "#undef GL_NV_sample_mask_override_coverage\n"
    "#undef GL_NV_geometry_shader_passthrough\n"
    "#undef GL_NV_viewport_array2\n"
    "#undef GL_NV_shader_atomic_int64\n"
    "#undef GL_NV_conservative_raster_underestimation\n"
    "#undef GL_NV_shader_subgroup_partitioned\n"
    "#undef GL_NV_shading_rate_image\n"
    "#undef GL_NV_ray_tracing\n"
    "#undef GL_NV_fragment_shader_barycentric\n"
    "#undef GL_NV_compute_shader_derivatives\n"
    "#undef GL_NV_shader_texture_footprint\n"
    "#undef GL_NV_mesh_shader\n"
    "#undef GL_NV_cooperative_matrix\n"
    "#undef GL_NV_integer_cooperative_matrix\n"
    "#undef GL_EXT_shader_explicit_arithmetic_types\n"
    "#undef GL_EXT_shader_explicit_arithmetic_types_int8\n"
    "#undef GL_EXT_shader_explicit_arithmetic_types_int16\n"
    "#undef GL_EXT_shader_explicit_arithmetic_types_int32\n"
    "#undef GL_EXT_shader_explicit_arithmetic_types_int64\n"
    "#undef GL_EXT_shader_explicit_arithmetic_types_float16\n"
    "#undef GL_EXT_shader_explicit_arithmetic_types_float32\n"
    "#undef GL_EXT_shader_explicit_arithmetic_types_float64\n"
    "#undef GL_EXT_shader_subgroup_extended_types_int8\n"
    "#undef GL_EXT_shader_subgroup_extended_types_int16\n"
    "#undef GL_EXT_shader_subgroup_extended_types_int64\n"
    "#undef GL_EXT_shader_subgroup_extended_types_float16\n"
    "#undef GL_core_profile\n"
    "#undef GL_compatibility_profile\n"
    "#undef GL_EXT_device_group\n"
    "#undef GL_EXT_multiview\n"
    "#undef GL_NV_shader_sm_builtins\n"
    "#undef GL_OVR_multiview\n"
    "#undef GL_OVR_multiview2\n"
    "#undef GL_GOOGLE_cpp_style_line_directive\n"
    "#undef GL_GOOGLE_include_directive\n"
    "#undef VULKAN\n"
    "#undef GL_SPIRV\n";

// Sets source language, client and SPIR-V version, and the binding model:
// unqualified resources go to the material set, "$Globals" for GLSL's loose
// uniforms, automatic bindings and locations (fixed up later, spirv_fixup.h).
void configure(glslang::TShader& shader, ir::ProgramLanguage language, Stage stage, const std::string& entry,
               const BackendOptions& options) {
  EShLanguage lang = to_glslang(stage);
  glslang::EShSource source = is_hlsl(language) ? glslang::EShSourceHlsl : glslang::EShSourceGlsl;
  if (options.target == TargetEnv::opengl4_5) {
    shader.setEnvInput(source, lang, glslang::EShClientOpenGL, 100);
    shader.setEnvClient(glslang::EShClientOpenGL, glslang::EShTargetOpenGL_450);
    shader.setEnvTarget(glslang::EShTargetSpv, glslang::EShTargetSpv_1_0);
  } else {
    bool v12 = options.target == TargetEnv::vulkan1_2;
    shader.setEnvInput(source, lang, glslang::EShClientVulkan, 100);
    shader.setEnvClient(glslang::EShClientVulkan, v12 ? glslang::EShTargetVulkan_1_2 : glslang::EShTargetVulkan_1_1);
    shader.setEnvTarget(glslang::EShTargetSpv, v12 ? glslang::EShTargetSpv_1_5 : glslang::EShTargetSpv_1_3);
  }
  if (is_hlsl(language)) {
    shader.setEntryPoint(entry.c_str());
    shader.setSourceEntryPoint(entry.c_str());
    shader.setHlslIoMapping(true);
    shader.setEnvTargetHlslFunctionality1();  // semantics as decorations; stripped after reflection
    shader.setPreamble(kUndefineGlslangPreamble);
  } else {
    shader.setEnvInputVulkanRulesRelaxed();  // Unity-style loose uniforms in GLSLPROGRAM
    shader.setGlobalUniformBlockName(kGlobalsBlock);
    shader.setGlobalUniformSet(kMaterialSet);
    shader.setGlobalUniformBinding(0);
  }
  shader.setAutoMapBindings(true);
  shader.setAutoMapLocations(true);
  shader.setResourceSetBinding({std::to_string(kMaterialSet)});
  // Not setDebugInfo(): with #include, glslang 12 then emits DebugSource
  // instructions of a non-semantic set it never imports (invalid SPIR-V).
  // -g still gets OpString/OpLine from SpvOptions::generateDebugInfo.
}

int default_version(ir::ProgramLanguage language) { return is_hlsl(language) ? 100 : 450; }

// Uniform resources in declaration order, from the AST's linker objects
// (which keep unused ones, so every stage sees the same list).
std::vector<DeclaredResource> declared_resources(const glslang::TIntermediate& intermediate) {
  std::vector<DeclaredResource> out;
  const TIntermNode* root = intermediate.getTreeRoot();
  const glslang::TIntermAggregate* aggregate = root ? root->getAsAggregate() : nullptr;
  if (!aggregate || aggregate->getSequence().empty()) return out;
  const glslang::TIntermAggregate* linker = aggregate->getSequence().back()->getAsAggregate();
  if (!linker || linker->getOp() != glslang::EOpLinkerObjects) return out;
  for (const TIntermNode* node : linker->getSequence()) {
    const glslang::TIntermSymbol* symbol = node->getAsSymbolNode();
    if (!symbol) continue;
    const glslang::TType& type = symbol->getType();
    const glslang::TQualifier& q = type.getQualifier();
    bool resource = q.storage == glslang::EvqUniform || q.storage == glslang::EvqBuffer;
    if (!resource || q.isPushConstant() || type.getBasicType() == glslang::EbtVoid) continue;
    bool block = type.getBasicType() == glslang::EbtBlock;
    if (!block && type.getBasicType() != glslang::EbtSampler) continue;  // loose uniforms live in a block
    DeclaredResource r;
    r.key = block ? std::string(type.getTypeName().c_str()) : std::string(symbol->getName().c_str());
    r.block = block;
    r.has_set = q.hasSet();
    r.has_binding = q.hasBinding();
    r.set = r.has_set ? q.layoutSet : 0;
    r.binding = r.has_binding ? q.layoutBinding : 0;
    out.push_back(std::move(r));
  }
  return out;
}

// The definition of HLSL entry function `entry` (glslang renames it
// "@entry(" and wraps it), or nullptr.
const glslang::TIntermAggregate* entry_definition(const glslang::TIntermediate& intermediate, const std::string& entry) {
  const TIntermNode* root = intermediate.getTreeRoot();
  const glslang::TIntermAggregate* aggregate = root ? root->getAsAggregate() : nullptr;
  if (!aggregate) return nullptr;
  for (const TIntermNode* node : aggregate->getSequence()) {
    const glslang::TIntermAggregate* f = node->getAsAggregate();
    if (!f || f->getOp() != glslang::EOpFunction) continue;
    std::string_view name = f->getName().c_str();
    if (name.starts_with("@")) name.remove_prefix(1);
    if (name.starts_with(entry + "(")) return f;
  }
  return nullptr;
}

// The stage attribute a geometry, hull or domain entry point cannot do
// without. glslang finds it missing only when linking, and says so without
// a location; this says it at the entry function's line, in the parse log's
// own form ("ERROR: FILE:LINE: 'TOKEN' : TEXT"), so that it maps to the
// user's line like any other parse error.
std::string missing_stage_attribute(const glslang::TIntermediate& intermediate, Stage stage, const std::string& entry) {
  const char* attribute = nullptr;
  const char* example = nullptr;
  if (stage == Stage::geometry && intermediate.getVertices() == glslang::TQualifier::layoutNotSet) {
    attribute = "maxvertexcount";
    example = "[maxvertexcount(3)]";
  } else if (stage == Stage::hull && intermediate.getVertices() == glslang::TQualifier::layoutNotSet) {
    attribute = "outputcontrolpoints";
    example = "[outputcontrolpoints(3)]";
  } else if (stage == Stage::domain && intermediate.getInputPrimitive() == glslang::ElgNone) {
    attribute = "domain";
    example = "[domain(\"tri\")]";
  }
  if (!attribute) return {};
  const glslang::TIntermAggregate* f = entry_definition(intermediate, entry);
  if (!f) return {};
  const glslang::TSourceLoc& loc = f->getLoc();
  return "ERROR: " + loc.getStringNameOrNum(false) + ":" + std::to_string(loc.line) + ": '" + entry + "' : the " +
         std::string(stage_name(stage)) + " function needs a [" + attribute + "(...)] attribute, e.g. " + example +
         "\n";
}

// The preprocessed text with its #pragma lines blanked but pack_matrix, the
// one glslang's HLSL front end acts on: the others (vertex, multi_compile,
// skip_variants, ...) are facet's, and glslang's preprocessor writes a long
// one back as a single token that its parser then refuses.
std::string without_unity_pragmas(std::string text) {
  for (size_t line = 0; line < text.size();) {
    size_t end = text.find('\n', line);
    if (end == std::string::npos) end = text.size();
    size_t first = text.find_first_not_of(" \t", line);
    if (first < end && text.compare(first, 7, "#pragma") == 0) {
      size_t word = text.find_first_not_of(" \t", first + 7);
      if (word >= end || text.compare(word, 11, "pack_matrix") != 0) {
        std::fill(text.begin() + long(line), text.begin() + long(end), ' ');
      }
    }
    line = end + 1;
  }
  return text;
}

// glslang's preprocessor writes a member access as "m . _11"; the
// spaces go, so that the swizzle rewrite sees "m._11".
std::string without_spaced_member_dots(const std::string& text) {
  auto ident = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; };
  std::string out;
  out.reserve(text.size());
  for (size_t i = 0; i < text.size(); ++i) {
    if (text[i] == ' ' && !out.empty() && (ident(out.back()) || out.back() == ']' || out.back() == ')')) {
      size_t j = i;
      while (j < text.size() && text[j] == ' ') ++j;
      size_t k = j + 1;
      while (k < text.size() && text[k] == ' ') ++k;
      bool member = j < text.size() && text[j] == '.' && k < text.size() && (std::isalpha(static_cast<unsigned char>(text[k])) || text[k] == '_');
      if (member && !std::isdigit(static_cast<unsigned char>(out.back()))) {
        out += '.';
        i = k - 1;
        continue;
      }
    }
    out += text[i];
    if (text[i] == '.' && out.size() > 1 && (ident(out[out.size() - 2]) || out[out.size() - 2] == ']') &&
        !std::isdigit(static_cast<unsigned char>(out[out.size() - 2]))) {
      size_t k = i + 1;
      while (k < text.size() && text[k] == ' ') ++k;
      if (k > i + 1 && k < text.size() && (std::isalpha(static_cast<unsigned char>(text[k])) || text[k] == '_')) i = k - 1;
    }
  }
  return out;
}

// glslang throws on some inputs: Debian's 12.x preprocessor builds a string
// of a negative length for a token at column 0 after an empty macro
// argument (fixed upstream later). An exception is the program's error, not
// a crash of the compiler.
template <class F>
bool without_throwing(GlslangOutput& out, std::string_view root_name, std::string_view step, F&& run) {
  try {
    return run();
  } catch (const std::exception& e) {
    out.parse_log += fmt::format("ERROR: {}:0: '{}' : glslang failed in its {} ({}), a glslang bug; rewriting the "
                                 "construct it fails on (an empty macro argument, for one) may avoid it\n",
                                 root_name, step, step, e.what());
    return false;
  }
}

// An HLSL program as glslang's parser takes it: preprocessed, facet's
// pragmas blanked, member dots closed up, matrix swizzles rewritten
// again (a macro may build one: "input.a" with a = _22_23_24) and scalar
// swizzles dropped (hlsl_rewrite.h). nullopt, with
// the log in `out`, when preprocessing fails.
std::optional<std::string> preprocessed_hlsl(const AssembledSource& source, ir::ProgramLanguage language, Stage stage,
                                             const BackendOptions& options, FileIncluder& includer,
                                             GlslangOutput& out) {
  GlslangOutput preprocessed = preprocess_glslang(source, language, stage, options, includer);
  if (!preprocessed.ok) {
    out.parse_log = std::move(preprocessed.parse_log);
    return std::nullopt;
  }
  return drop_scalar_swizzles(
      rewrite_matrix_swizzles(without_spaced_member_dots(without_unity_pragmas(preprocessed.preprocessed))));
}

// True, with the error in `out`, when `text` holds a declaration glslang's
// HLSL parser crashes on (global_declarations.h).
bool refused_declaration(std::string_view text, std::string_view entry, const AssembledSource& source,
                         GlslangOutput& out) {
  std::optional<DeclarationProblem> problem = find_declaration_problem(text, entry);
  if (!problem) return false;
  std::string file = problem->file.empty() ? source.root_name : problem->file;
  out.parse_log = fmt::format("ERROR: {}:{}: '{}' : {}\n", file, problem->line, problem->token, problem->message);
  return true;
}

// One text for glslang and what to do with it.
struct GlslangJob {
  bool parse_only = false;  // no link, no SPIR-V
  ir::ProgramLanguage language = ir::ProgramLanguage::hlsl;
  Stage stage = Stage::vertex;
  std::string entry;
  std::string name;  // the root file's name in glslang's log
  std::string text;
};

// Parses the job's text (`visit`, when set, walks the AST of a successful
// parse), then unless parse_only links it and generates SPIR-V.
GlslangOutput run_job(const GlslangJob& job, const BackendOptions& options, glslang::TShader::Includer& includer,
                      const std::function<void(const glslang::TIntermediate&)>& visit) {
  GlslangOutput out;
  EShMessages messages = messages_for(job.language, options);
  glslang::TShader shader(to_glslang(job.stage));
  const char* text = job.text.c_str();
  const int length = int(job.text.size());
  const char* name = job.name.c_str();
  shader.setStringsWithLengthsAndNames(&text, &length, &name, 1);
  configure(shader, job.language, job.stage, job.entry, options);
  bool parsed = without_throwing(out, job.name, "parser", [&] {
    return shader.parse(GetDefaultResources(), default_version(job.language), false, messages, includer);
  });
  out.parse_log = shader.getInfoLog() + out.parse_log;
  if (!parsed) return out;
  if (visit) visit(*shader.getIntermediate());
  if (job.parse_only) {
    out.ok = true;
    return out;
  }
  if (is_hlsl(job.language)) {
    std::string missing = missing_stage_attribute(*shader.getIntermediate(), job.stage, job.entry);
    if (!missing.empty()) {
      out.parse_log += missing;
      return out;
    }
  }
  out.declared = declared_resources(*shader.getIntermediate());

  // The program must die before the shader it links (glslang's rule).
  auto program = std::make_unique<glslang::TProgram>();
  program->addShader(&shader);
  bool linked = without_throwing(out, job.name, "linker", [&] { return program->link(messages) && program->mapIO(); });
  out.link_log = program->getInfoLog();
  if (!linked) return out;

  glslang::SpvOptions spv_options;
  spv_options.generateDebugInfo = options.debug_info;
  // No spirv-opt inside glslang: HLSL is legalised in spirv_tools.cpp after
  // the module has been validated, because glslang sometimes emits invalid
  // SPIR-V that crashes the optimiser instead of failing.
  spv_options.disableOptimizer = true;
  spv_options.validate = false;
  spv::SpvBuildLogger logger;
  without_throwing(out, job.name, "SPIR-V generator", [&] {
    glslang::GlslangToSpv(*program->getIntermediate(to_glslang(job.stage)), out.spirv, &logger, &spv_options);
    return true;
  });
  out.spirv_log = logger.getAllMessages();
  out.ok = !out.spirv.empty();
  return out;
}

// ---- The same in a child process (crash_isolation.h) ----------------------

// Only what run_job reads of the options crosses: the target (a child's
// job is never compiled with -g, whose source embeds the #include'd files).
std::string encode_job(const GlslangJob& job, const BackendOptions& options) {
  WireWriter w;
  w.byte(job.parse_only ? 1 : 0);
  w.byte(uint8_t(job.language));
  w.byte(uint8_t(job.stage));
  w.byte(uint8_t(options.target));
  w.text(job.entry);
  w.text(job.name);
  w.text(job.text);
  return w.take();
}

std::string encode_output(const GlslangOutput& out) {
  WireWriter w;
  w.byte(out.ok ? 1 : 0);
  w.text(out.parse_log);
  w.text(out.link_log);
  w.text(out.spirv_log);
  w.words(out.spirv);
  w.u32(uint32_t(out.declared.size()));
  for (const DeclaredResource& r : out.declared) {
    w.text(r.key);
    w.byte(r.block ? 1 : 0);
    w.byte(r.has_set ? 1 : 0);
    w.byte(r.has_binding ? 1 : 0);
    w.u32(r.set);
    w.u32(r.binding);
  }
  return w.take();
}

std::optional<GlslangOutput> decode_output(std::string_view bytes) {
  WireReader r(bytes);
  GlslangOutput out;
  out.ok = r.byte() != 0;
  out.parse_log = r.text();
  out.link_log = r.text();
  out.spirv_log = r.text();
  out.spirv = r.words();
  uint32_t count = r.u32();
  for (uint32_t i = 0; i < count && r.ok(); ++i) {
    DeclaredResource d;
    d.key = r.text();
    d.block = r.byte() != 0;
    d.has_set = r.byte() != 0;
    d.has_binding = r.byte() != 0;
    d.set = r.u32();
    d.binding = r.u32();
    out.declared.push_back(std::move(d));
  }
  if (!r.at_end()) return std::nullopt;
  return out;
}

// The child's side: the text needs no #include (it is preprocessed).
std::string run_job_in_child(std::string_view request) {
  WireReader r(request);
  GlslangJob job;
  BackendOptions options;
  job.parse_only = r.byte() != 0;
  job.language = ir::ProgramLanguage(r.byte());
  job.stage = Stage(r.byte());
  options.target = TargetEnv(r.byte());
  job.entry = r.text();
  job.name = r.text();
  job.text = r.text();
  if (!r.at_end()) return {};
  glslang::TShader::ForbidIncluder no_includes;
  return encode_output(run_job(job, options, no_includes, {}));
}

// run_job in a child; nullopt when no child could be started. A child that
// died is the program's error, located at its entry function: where glslang
// was when it crashed is lost with the child.
std::optional<GlslangOutput> run_job_isolated(const CrashIsolation& isolation, const GlslangJob& job,
                                              const BackendOptions& options) {
  ChildAnswer answer = isolation.run(run_job_in_child, encode_job(job, options), options.limits.time_limit_s);
  if (answer.kind == ChildAnswer::Kind::unavailable) return std::nullopt;
  if (answer.kind == ChildAnswer::Kind::answered) {
    if (std::optional<GlslangOutput> out = decode_output(answer.bytes)) return out;
  }
  std::optional<DeclarationProblem> entry = function_position(job.text, job.entry);
  if (!entry) entry = function_position(job.text, {});
  std::string file = entry && !entry->file.empty() ? entry->file : job.name;
  GlslangOutput out;
  out.parse_log = fmt::format(
      "ERROR: {}:{}: '{}' : glslang crashed on this program, a glslang bug (facet ran it in a child process and "
      "refuses the program instead); simplifying the code of the {} stage may avoid it\n",
      file, entry ? entry->line : 0, entry ? entry->token : job.entry, stage_name(job.stage));
  return out;
}

}  // namespace

GlslangOutput parse_glslang(const AssembledSource& source, ir::ProgramLanguage language, Stage stage,
                            const std::string& entry, const BackendOptions& options, FileIncluder& includer,
                            const std::function<void(const glslang::TIntermediate&)>& visit,
                            const CrashIsolation* isolation) {
  GlslangJob job{true, language, stage, entry, source.root_name, {}};
  if (!is_hlsl(language)) {
    job.text = source.text;
    return run_job(job, options, includer, visit);
  }
  // HLSL is parsed as run_glslang parses it, preprocessed and checked first:
  // the parser would crash on the declarations the check refuses. Then in a
  // child, for the crashes no check foresees; only a program the child
  // parsed is parsed here again, for `visit` to walk its AST.
  GlslangOutput out;
  std::optional<std::string> text = preprocessed_hlsl(source, language, stage, options, includer, out);
  if (!text || refused_declaration(*text, entry, source, out)) return out;
  job.text = std::move(*text);
  if (isolation) {
    std::optional<GlslangOutput> checked = run_job_isolated(*isolation, job, options);
    if (checked && !checked->ok) return std::move(*checked);
  }
  return run_job(job, options, includer, visit);
}

GlslangOutput run_glslang(const AssembledSource& source, ir::ProgramLanguage language, Stage stage,
                          const std::string& entry, const BackendOptions& options, FileIncluder& includer,
                          const CrashIsolation* isolation) {
  GlslangJob job{false, language, stage, entry, source.root_name, {}};
  // HLSL: preprocessed first, and only what the entry point reaches is
  // compiled, as fxc does (with -g the module embeds the source as written,
  // #include'd files and all, so it is compiled here, not in a child).
  if (!is_hlsl(language) || options.debug_info) {
    job.text = source.text;
    return run_job(job, options, includer, {});
  }
  GlslangOutput out;
  std::optional<std::string> text = preprocessed_hlsl(source, language, stage, options, includer, out);
  if (!text) return out;
  job.text = with_static_initializers_in_entry(without_unreachable_functions(*text, entry), entry);
  if (stage == Stage::fragment) job.text = with_front_facing_as_bool(job.text, entry);
  out.preprocessed = std::move(*text);
  if (refused_declaration(job.text, entry, source, out)) return out;
  std::optional<GlslangOutput> isolated;
  if (isolation) isolated = run_job_isolated(*isolation, job, options);
  GlslangOutput result = isolated ? std::move(*isolated) : run_job(job, options, includer, {});
  result.preprocessed = std::move(out.preprocessed);
  return result;
}

GlslangOutput preprocess_glslang(const AssembledSource& source, ir::ProgramLanguage language, Stage stage,
                                 const BackendOptions& options, FileIncluder& includer) {
  GlslangOutput out;
  glslang::TShader shader(to_glslang(stage));
  const char* text = source.text.c_str();
  const int length = int(source.text.size());
  const char* name = source.root_name.c_str();
  shader.setStringsWithLengthsAndNames(&text, &length, &name, 1);
  configure(shader, language, stage, "main", options);
  out.ok = without_throwing(out, source.root_name, "preprocessor", [&] {
    return shader.preprocess(GetDefaultResources(), default_version(language), ENoProfile, false, false,
                             messages_for(language, options), &out.preprocessed, includer);
  });
  out.parse_log = shader.getInfoLog() + out.parse_log;
  return out;
}

void warm_glslang_symbol_tables(const BackendOptions& options) {
  constexpr ir::ProgramLanguage hlsl = ir::ProgramLanguage::hlsl;
  for (Stage stage : {Stage::vertex, Stage::fragment}) {
    glslang::TShader shader(to_glslang(stage));
    const char* text = "";
    shader.setStrings(&text, 1);
    configure(shader, hlsl, stage, "main", options);
    std::string preprocessed;
    glslang::TShader::ForbidIncluder no_includes;
    shader.preprocess(GetDefaultResources(), default_version(hlsl), ENoProfile, false, false,
                      messages_for(hlsl, options), &preprocessed, no_includes);
  }
}

std::string glsl_errors(const std::string& text, Stage stage) {
  EShLanguage language = to_glslang(stage);
  glslang::TShader shader(language);
  const char* source = text.c_str();
  const int length = int(text.size());
  shader.setStringsWithLengths(&source, &length, 1);
  shader.setEnvInput(glslang::EShSourceGlsl, language, glslang::EShClientOpenGL, 100);
  shader.setEnvClient(glslang::EShClientOpenGL, glslang::EShTargetOpenGL_450);
  shader.setEnvTarget(glslang::EShTargetNone, glslang::EShTargetLanguageVersion(0));
  if (shader.parse(GetDefaultResources(), 100, false, EShMsgDefault)) return {};
  std::string log = shader.getInfoLog();
  return log.empty() ? std::string("rejected") : log;
}

}  // namespace facet::backend
