#include "output_safety.h"

#include <fmt/format.h>

#include <filesystem>

#include "facet/support/output_paths.h"

namespace facet::tools {
namespace fs = std::filesystem;

namespace {

// The input that `output` is, or nullptr. An output that does not exist yet
// is no input (the common case costs one stat).
const RunInput* input_at(const std::string& output, const std::vector<RunInput>& inputs) {
  std::error_code ec;
  if (!fs::exists(output, ec)) return nullptr;
  for (const RunInput& input : inputs) {
    if (fs::equivalent(output, input.path, ec)) return &input;
  }
  return nullptr;
}

}  // namespace

void add_inputs(std::vector<RunInput>& inputs, const std::vector<std::string>& paths, const std::string& what) {
  for (const std::string& path : paths) inputs.push_back({path, what});
}

std::optional<std::string> output_input_clash(const std::vector<std::string>& outputs,
                                              const std::vector<RunInput>& inputs) {
  if (auto twice = support::repeated_output(outputs)) {
    return fmt::format("outputs '{}' and '{}' are the same file; nothing was written", twice->first, twice->second);
  }
  for (const std::string& output : outputs) {
    if (output.empty() || output == "-") continue;
    if (const RunInput* input = input_at(output, inputs)) {
      return fmt::format("output '{}' is also an input of this build ({}); nothing was written", output, input->what);
    }
  }
  return std::nullopt;
}

bool outputs_spare_inputs(const std::vector<std::string>& outputs, const std::vector<RunInput>& inputs,
                          Diagnostics& diags) {
  auto clash = output_input_clash(outputs, inputs);
  if (clash) diags.add(DiagId::io_cannot_write, {}, *clash);
  return !clash;
}

}  // namespace facet::tools
