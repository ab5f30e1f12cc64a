#include "backend/spirv_tools.h"

#include <fmt/format.h>

#include <spirv-tools/libspirv.hpp>
#include <spirv-tools/optimizer.hpp>

#include <string>

namespace facet::backend {
namespace {

// Collects SPIRV-Tools messages as "line: text" strings.
struct MessageLog {
  std::vector<std::string> lines;

  spvtools::MessageConsumer consumer() {
    return [this](spv_message_level_t level, const char*, const spv_position_t& position, const char* message) {
      if (level > SPV_MSG_WARNING) return;
      lines.push_back(position.index ? fmt::format("{} (word {})", message, position.index) : std::string(message));
    };
  }
};

bool run_passes(std::vector<uint32_t>& spirv, TargetEnv target, Diagnostics& diags, DiagId id,
                const char* what, void (*register_passes)(spvtools::Optimizer&)) {
  spvtools::Optimizer optimizer(spirv_env(target));
  MessageLog log;
  optimizer.SetMessageConsumer(log.consumer());
  register_passes(optimizer);
  std::vector<uint32_t> out;
  spvtools::OptimizerOptions opt_options;
  opt_options.set_run_validator(false);  // validate() runs once at the end
  if (!optimizer.Run(spirv.data(), spirv.size(), &out, opt_options)) {
    Diagnostic& d = diags.add(id, SourceSpan{}, fmt::format("{} failed", what));
    for (const std::string& line : log.lines) d.note({}, line);
    return false;
  }
  spirv = std::move(out);
  return true;
}

}  // namespace

spv_target_env spirv_env(TargetEnv target) {
  switch (target) {
    case TargetEnv::vulkan1_1: return SPV_ENV_VULKAN_1_1;
    case TargetEnv::vulkan1_2: return SPV_ENV_VULKAN_1_2;
    case TargetEnv::opengl4_5: return SPV_ENV_OPENGL_4_5;
  }
  return SPV_ENV_VULKAN_1_1;
}

bool check_generated(const std::vector<uint32_t>& spirv, bool hlsl, TargetEnv target, Diagnostics& diags) {
  spvtools::SpirvTools tools(spirv_env(target));
  MessageLog log;
  tools.SetMessageConsumer(log.consumer());
  spvtools::ValidatorOptions options;
  options.SetBeforeHlslLegalization(hlsl);
  if (tools.Validate(spirv.data(), spirv.size(), options)) return true;
  Diagnostic& d = diags.add(DiagId::backend_invalid_spirv, SourceSpan{},
                            "glslang produced invalid SPIR-V for this program (a glslang bug); rewriting the "
                            "construct named below may avoid it");
  for (const std::string& line : log.lines) d.note({}, line);
  return false;
}

bool legalize_hlsl(std::vector<uint32_t>& spirv, TargetEnv target, Diagnostics& diags) {
  return run_passes(spirv, target, diags, DiagId::backend_optimizer_failed, "HLSL legalization",
                    [](spvtools::Optimizer& o) { o.RegisterLegalizationPasses(); });
}

bool optimize(std::vector<uint32_t>& spirv, OptLevel level, TargetEnv target, Diagnostics& diags) {
  switch (level) {
    case OptLevel::none: return true;
    case OptLevel::performance:
      return run_passes(spirv, target, diags, DiagId::backend_optimizer_failed, "spirv-opt -O",
                        [](spvtools::Optimizer& o) { o.RegisterPerformancePasses(); });
    case OptLevel::size:
      return run_passes(spirv, target, diags, DiagId::backend_optimizer_failed, "spirv-opt -Os",
                        [](spvtools::Optimizer& o) { o.RegisterSizePasses(); });
  }
  return true;
}

bool strip_reflection_info(std::vector<uint32_t>& spirv, TargetEnv target, Diagnostics& diags) {
  return run_passes(spirv, target, diags, DiagId::backend_optimizer_failed, "stripping reflection decorations",
                    [](spvtools::Optimizer& o) { o.RegisterPass(spvtools::CreateStripReflectInfoPass()); });
}

std::string disassemble(const std::vector<uint32_t>& spirv) {
  spvtools::SpirvTools tools(SPV_ENV_UNIVERSAL_1_5);
  std::string text;
  uint32_t options = SPV_BINARY_TO_TEXT_OPTION_FRIENDLY_NAMES | SPV_BINARY_TO_TEXT_OPTION_INDENT;
  if (!tools.Disassemble(spirv, &text, options)) return {};
  return text;
}

bool validate(const std::vector<uint32_t>& spirv, TargetEnv target, Diagnostics& diags) {
  spvtools::SpirvTools tools(spirv_env(target));
  MessageLog log;
  tools.SetMessageConsumer(log.consumer());
  spvtools::ValidatorOptions options;
  if (tools.Validate(spirv.data(), spirv.size(), options)) return true;
  std::string first = log.lines.empty() ? std::string("no details") : log.lines.front();
  Diagnostic& d = diags.add(DiagId::backend_invalid_spirv, SourceSpan{}, "generated SPIR-V is invalid: " + first);
  for (size_t i = 1; i < log.lines.size(); ++i) d.note({}, log.lines[i]);
  return false;
}

}  // namespace facet::backend
