#include "spirv_tools.h"

#include <fmt/format.h>

#include <spirv-tools/libspirv.hpp>
#include <spirv-tools/optimizer.hpp>

#include <algorithm>
#include <map>
#include <optional>
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

// ---- [unroll] trip counts -------------------------------------------------
// SPIR-V opcodes and the LoopControl bit read below (SPIR-V 1.5 spec, 3.32).
constexpr uint32_t kOpTypeInt = 21, kOpConstant = 43, kOpFunction = 54, kOpIAdd = 128, kOpISub = 130,
                   kOpPhi = 245, kOpLoopMerge = 246, kOpLabel = 248;
constexpr uint32_t kOpIEqual = 170, kOpSLessThanEqual = 179;  // the integer comparisons are 170..179
constexpr uint32_t kLoopControlUnroll = 0x1;

struct Instruction {
  uint32_t opcode;
  const uint32_t* words;  // words[0] is the opcode word
  uint32_t count;
};

struct ModuleIndex {
  std::vector<Instruction> instructions;
  std::map<uint32_t, size_t> defining;  // result id -> instruction
  std::map<uint32_t, int64_t> int_constants;
};

uint32_t result_id(const Instruction& in) {
  switch (in.opcode) {
    case kOpLabel: case kOpTypeInt: return in.count > 1 ? in.words[1] : 0;
    case kOpConstant: case kOpIAdd: case kOpISub: case kOpPhi: case kOpFunction: return in.count > 2 ? in.words[2] : 0;
    default: return in.opcode >= kOpIEqual && in.opcode <= kOpSLessThanEqual && in.count > 2 ? in.words[2] : 0;
  }
}

ModuleIndex index_module(const std::vector<uint32_t>& spirv) {
  ModuleIndex m;
  std::map<uint32_t, bool> int_types;  // id -> signed (32-bit and narrower only)
  for (size_t at = 5; at < spirv.size();) {
    uint32_t count = spirv[at] >> 16;
    if (count == 0 || at + count > spirv.size()) break;
    Instruction in{spirv[at] & 0xffff, &spirv[at], count};
    if (uint32_t id = result_id(in)) m.defining[id] = m.instructions.size();
    if (in.opcode == kOpTypeInt && count == 4 && in.words[2] <= 32) int_types[in.words[1]] = in.words[3] != 0;
    if (in.opcode == kOpConstant && count == 4 && int_types.count(in.words[1])) {
      m.int_constants[in.words[2]] = int_types[in.words[1]] ? int64_t(int32_t(in.words[3])) : int64_t(in.words[3]);
    }
    m.instructions.push_back(in);
    at += count;
  }
  return m;
}

std::optional<int64_t> constant(const ModuleIndex& m, uint32_t id) {
  auto it = m.int_constants.find(id);
  return it == m.int_constants.end() ? std::nullopt : std::optional<int64_t>(it->second);
}

// For an induction variable `phi` (init constant, next = phi +- step), the
// iterations until it passes a constant it is compared with, at most.
uint64_t phi_trip_count(const ModuleIndex& m, const Instruction& phi) {
  std::optional<int64_t> init, step;
  uint32_t next_id = 0;
  for (uint32_t k = 3; k + 1 < phi.count; k += 2) {
    if (auto c = constant(m, phi.words[k])) {
      init = c;
    } else {
      next_id = phi.words[k];
    }
  }
  auto next = m.defining.find(next_id);
  if (!init || next == m.defining.end()) return 0;
  const Instruction& add = m.instructions[next->second];
  if ((add.opcode != kOpIAdd && add.opcode != kOpISub) || add.count != 5) return 0;
  uint32_t other = add.words[3] == phi.words[2] ? add.words[4] : add.words[4] == phi.words[2] ? add.words[3] : 0;
  step = constant(m, other);
  if (!step || *step == 0) return 0;
  uint64_t longest = 0;
  for (const Instruction& cmp : m.instructions) {
    if (cmp.opcode < kOpIEqual || cmp.opcode > kOpSLessThanEqual || cmp.count != 5) continue;
    bool uses = cmp.words[3] == phi.words[2] || cmp.words[4] == phi.words[2] || cmp.words[3] == next_id ||
                cmp.words[4] == next_id;
    if (!uses) continue;
    std::optional<int64_t> bound = constant(m, cmp.words[3]);
    if (!bound) bound = constant(m, cmp.words[4]);
    if (!bound) continue;
    uint64_t distance = uint64_t(*bound > *init ? *bound - *init : *init - *bound);
    uint64_t stride = uint64_t(*step < 0 ? -*step : *step);
    longest = std::max(longest, distance / stride + 1);
  }
  return longest;
}

uint64_t longest_marked_loop(const std::vector<uint32_t>& spirv) {
  ModuleIndex m = index_module(spirv);
  uint64_t longest = 0;
  size_t header = 0;
  for (size_t i = 0; i < m.instructions.size(); ++i) {
    const Instruction& in = m.instructions[i];
    if (in.opcode == kOpLabel) header = i;
    if (in.opcode != kOpLoopMerge || in.count < 4 || !(in.words[3] & kLoopControlUnroll)) continue;
    for (size_t k = header + 1; k < i && m.instructions[k].opcode == kOpPhi; ++k) {
      longest = std::max(longest, phi_trip_count(m, m.instructions[k]));
    }
  }
  return longest;
}

bool has_marked_loop(const std::vector<uint32_t>& spirv) {
  for (size_t at = 5; at < spirv.size();) {
    uint32_t count = spirv[at] >> 16;
    if (count == 0) break;
    if ((spirv[at] & 0xffff) == kOpLoopMerge && count >= 4 && at + 3 < spirv.size() &&
        (spirv[at + 3] & kLoopControlUnroll)) {
      return true;
    }
    at += count;
  }
  return false;
}

}  // namespace

uint64_t longest_unrolled_loop(const std::vector<uint32_t>& spirv, TargetEnv target) {
  if (!has_marked_loop(spirv)) return 0;
  // The passes that bring loop counters into SSA form and fold constants
  // into their bounds, as they run before the unroller.
  spvtools::Optimizer optimizer(spirv_env(target));
  optimizer.SetMessageConsumer([](spv_message_level_t, const char*, const spv_position_t&, const char*) {});
  optimizer.RegisterPass(spvtools::CreateMergeReturnPass())
      .RegisterPass(spvtools::CreateInlineExhaustivePass())
      .RegisterPass(spvtools::CreatePrivateToLocalPass())
      .RegisterPass(spvtools::CreateLocalSingleBlockLoadStoreElimPass())
      .RegisterPass(spvtools::CreateLocalSingleStoreElimPass())
      .RegisterPass(spvtools::CreateScalarReplacementPass())
      .RegisterPass(spvtools::CreateLocalAccessChainConvertPass())
      .RegisterPass(spvtools::CreateSSARewritePass())
      .RegisterPass(spvtools::CreateCCPPass());
  std::vector<uint32_t> ssa;
  spvtools::OptimizerOptions options;
  options.set_run_validator(false);
  if (!optimizer.Run(spirv.data(), spirv.size(), &ssa, options)) return longest_marked_loop(spirv);
  return std::max(longest_marked_loop(ssa), longest_marked_loop(spirv));
}

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
