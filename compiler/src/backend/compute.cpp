// compile_hlsl_compute: the back end's recipe for a compute shader that is not
// part of a .shader file (the runtime's evaluators and test kernels).
// glslang -> log to diagnostics -> check -> legalise -> spirv-opt -> spirv-val.
// Stage has no compute member (ShaderLab programs have no compute stage), so
// this file drives glslang itself instead of going through run_glslang.
#include "includer.h"  // first: defines ENABLE_HLSL for glslang's headers

#include <fmt/format.h>
#include <glslang/Public/ResourceLimits.h>
#include <glslang/SPIRV/GlslangToSpv.h>

#include <algorithm>
#include <memory>
#include <string_view>

#include "info_log.h"
#include "source_assembly.h"
#include "spirv_tools.h"
#include "worker.h"
#include "facet/backend.h"

namespace facet::backend {
namespace {

// The name glslang reports for lines of `source`; '<' marks it as no file,
// so `#include "x"` falls through to the include dirs and the stdlib.
constexpr const char* kComputeName = "<compute>";

constexpr EShMessages kHlslMessages =
    EShMessages(EShMsgSpvRules | EShMsgVulkanRules | EShMsgReadHlsl | EShMsgHlslDX9Compatible |
                EShMsgHlslLegalization);

// With BackendOptions::hlsl_16bit_types, half and min16float are float16_t.
EShMessages messages_for(const BackendOptions& options) {
  return options.hlsl_16bit_types ? EShMessages(kHlslMessages | EShMsgHlslEnable16BitTypes) : kHlslMessages;
}
// Defined for 16-bit kernels (a preamble keeps the source's line numbers).
constexpr const char* k16BitPreamble = "#define FACET_16BIT_TYPES 1\n";

void configure(glslang::TShader& shader, const std::string& entry, const BackendOptions& options) {
  bool v12 = options.target == TargetEnv::vulkan1_2;
  shader.setEnvInput(glslang::EShSourceHlsl, EShLangCompute, glslang::EShClientVulkan, 100);
  shader.setEnvClient(glslang::EShClientVulkan, v12 ? glslang::EShTargetVulkan_1_2 : glslang::EShTargetVulkan_1_1);
  shader.setEnvTarget(glslang::EShTargetSpv, v12 ? glslang::EShTargetSpv_1_5 : glslang::EShTargetSpv_1_3);
  shader.setEntryPoint(entry.c_str());
  shader.setSourceEntryPoint(entry.c_str());
  shader.setHlslIoMapping(true);
  shader.setAutoMapBindings(true);
  if (options.hlsl_16bit_types) shader.setPreamble(k16BitPreamble);
}

// Line `line` (1-based) of `text`, without its newline; empty when out of range.
std::string_view line_of(std::string_view text, uint32_t line) {
  size_t begin = 0;
  for (uint32_t n = 1; n < line; ++n) {
    begin = text.find('\n', begin);
    if (begin == std::string_view::npos) return {};
    ++begin;
  }
  size_t end = text.find('\n', begin);
  return text.substr(begin, end == std::string_view::npos ? std::string_view::npos : end - begin);
}

// glslang's log as diagnostics without spans: the message names the file and
// line, and a note quotes that line.
void report_log(std::string_view log, const std::string& source, const FileIncluder& includer,
                Diagnostics& diags) {
  std::vector<LogMessage> messages = parse_info_log(log);
  bool has_real_error = false;
  for (const LogMessage& m : messages) has_real_error |= !m.parse_failed_marker && m.severity == Severity::error;
  for (LogMessage& m : messages) {
    // "HLSL parsing failed" only repeats a real error; alone, it is the error.
    if (m.parse_failed_marker && has_real_error) continue;
    if (m.parse_failed_marker) m.text = "syntax error";
    std::string where = m.file.empty() ? std::string() : fmt::format("{}:{}: ", m.file, m.line);
    std::string token = m.token.empty() ? std::string() : fmt::format("'{}' : ", m.token);
    DiagId id = m.severity == Severity::error ? DiagId::hlsl_error : DiagId::shader_compiler_warning;
    Diagnostic& d = diags.add(id, m.severity, SourceSpan{}, where + token + m.text);
    const std::string* text = m.file == kComputeName ? &source : includer.text_of(m.file);
    if (text && m.line > 0) {
      if (std::string_view line = line_of(*text, m.line); !line.empty()) d.note({}, std::string(line));
    }
  }
}

uint32_t line_number(std::string_view text, size_t offset) {
  return 1 + uint32_t(std::count(text.begin(), text.begin() + std::min(offset, text.size()), '\n'));
}

// Parse, link and generate SPIR-V; the logs go to `diags`. Empty on failure.
std::vector<uint32_t> run_glslang_compute(const std::string& source, const std::string& entry,
                                          const BackendOptions& options, FileIncluder& includer, Diagnostics& diags) {
  glslang::TShader shader(EShLangCompute);
  const char* text = source.c_str();
  const int length = int(source.size());
  const char* name = kComputeName;
  shader.setStringsWithLengthsAndNames(&text, &length, &name, 1);
  configure(shader, entry, options);
  bool parsed = shader.parse(GetDefaultResources(), 100, false, messages_for(options), includer);
  report_log(shader.getInfoLog(), source, includer, diags);
  if (!parsed) return {};
  // The program must die before the shader it links (glslang's rule).
  auto program = std::make_unique<glslang::TProgram>();
  program->addShader(&shader);
  bool linked = program->link(messages_for(options)) && program->mapIO();
  report_log(program->getInfoLog(), source, includer, diags);
  if (!linked) return {};
  glslang::SpvOptions spv_options;
  spv_options.generateDebugInfo = options.debug_info;
  spv_options.disableOptimizer = true;  // legalised below, after check_generated (as in Backend::compile)
  spv_options.validate = false;
  spv::SpvBuildLogger logger;
  std::vector<uint32_t> spirv;
  glslang::GlslangToSpv(*program->getIntermediate(EShLangCompute), spirv, &logger, &spv_options);
  if (std::string messages = logger.getAllMessages(); !messages.empty()) {
    diags.add(DiagId::shader_compiler_warning, SourceSpan{}, "SPIR-V generation: " + messages);
  }
  return spirv;
}

}  // namespace

Result<std::vector<uint32_t>> compile_hlsl_compute(const std::string& source, const std::string& entry,
                                                   const BackendOptions& options, Diagnostics& diags) {
  if (options.target == TargetEnv::opengl4_5) {
    diags.add(DiagId::backend_compile_error, SourceSpan{}, "compute shaders are compiled for Vulkan targets only");
    return failure("compute needs a Vulkan target");
  }
  if (auto hazard = find_recursion_hazard(source)) {
    diags.add(DiagId::backend_nesting_too_deep, SourceSpan{},
              fmt::format("{}:{}: {}", kComputeName, line_number(source, hazard->offset), hazard->message));
    return failure("nesting too deep");
  }
  Backend process;  // glslang's process initialisation, reference-counted
  size_t errors_before = diags.error_count();
  FileIncluder includer(options, options.stdlib_dir.empty() ? default_stdlib_dir() : options.stdlib_dir);
  if (auto excess = includer.macro_budget().add_text(source)) {
    diags.add(DiagId::backend_input_limit, SourceSpan{},
              fmt::format("{}:{}: {}", kComputeName, line_number(source, excess->offset), excess->message));
    return failure("input limit");
  }
  std::vector<uint32_t> spirv;
  std::string timeout = fmt::format("{}: error: compiling the compute shader took longer than {} s (--time-limit)\n",
                                    kComputeName, options.limits.time_limit_s);
  run_on_worker([&] { spirv = run_glslang_compute(source, entry, options, includer, diags); },
                options.limits.time_limit_s, [&] { return timeout; });
  if (spirv.empty()) {
    if (diags.error_count() == errors_before) {
      diags.add(DiagId::backend_compile_error, SourceSpan{}, "glslang could not compile the compute shader and gave no reason");
    }
    return failure("compute shader did not compile");
  }
  if (!check_generated(spirv, true, options.target, diags)) return failure("glslang bug");
  if (uint64_t trips = longest_unrolled_loop(spirv, options.target);
      options.limits.max_unroll != 0 && trips > options.limits.max_unroll) {
    diags.add(DiagId::backend_input_limit, SourceSpan{},
              fmt::format("{}: a loop marked [unroll] runs {} times, more than the limit of {} (--max-unroll)",
                          kComputeName, trips, options.limits.max_unroll));
    return failure("input limit");
  }
  if (!legalize_hlsl(spirv, options.target, diags)) return failure("legalization failed");
  if (!optimize(spirv, options.opt, options.target, diags)) return failure("spirv-opt failed");
  if (!validate(spirv, options.target, diags)) return failure("invalid SPIR-V");
  return spirv;
}

}  // namespace facet::backend
