// An output must never replace an input of the run: `facetc X.shader -o
// X.shader` would write the package over its own source. Paths are compared
// by identity (device and inode), so another spelling (`./a/../X.shader`)
// or a hard link of an input counts as that input.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "facet/diagnostics.h"

namespace facet::tools {

// A file the run reads, and what it is to the run, for the error.
struct RunInput {
  std::string path;
  std::string what;  // "the shader", "an include file", "a materials file", ...
};

// Adds every path of `paths` as an input that is `what`.
void add_inputs(std::vector<RunInput>& inputs, const std::vector<std::string>& paths, const std::string& what);

// The error for two outputs that are one file ("outputs 'X' and 'Y' are the
// same file; nothing was written"), else for the first output that is the
// same file as an input: "output 'X' is also an input of this build (what);
// nothing was written".
std::optional<std::string> output_input_clash(const std::vector<std::string>& outputs,
                                              const std::vector<RunInput>& inputs);

// true when no output (standard output, "" and "-", is none) is the same
// file as an input or as another output. Otherwise output_input_clash's error as an
// io_cannot_write diagnostic, and false: the caller writes none of its
// outputs.
bool outputs_spare_inputs(const std::vector<std::string>& outputs, const std::vector<RunInput>& inputs,
                          Diagnostics& diags);

}  // namespace facet::tools
