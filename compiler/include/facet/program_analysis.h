// What an HLSL program's code declares and touches: its functions, their
// parameters, and which members of each struct parameter a function reads and
// writes. The backend reads it from glslang's AST (backend::Backend::analyze_program,
// facet/backend.h); surface-shader lowering consumes it to learn which Input
// fields `surf` reads and which outputs it writes, and which form a lighting
// function has, from the code rather than by guessing. Plain data, so that
// the consumer needs no HLSL parser of its own.
#pragma once

#include <map>
#include <string>
#include <string_view>
#include <vector>

namespace facet {

struct AnalyzedField {
  std::string name;
  std::string type;      // "float2", "half3" as float3, or a struct name
  std::string semantic;  // upper-cased HLSL semantic ("COLOR", "VFACE"), "" when none
};

struct AnalyzedParam {
  std::string name;
  std::string type;  // "float3", or the struct's name
  bool is_struct = false;
  bool is_out = false;  // out or inout
  // Of a struct parameter: the members the function body reads and writes
  // (sorted, directly or through swizzles); `whole_*` when the parameter is
  // used as a whole (copied, passed on), which counts as every member.
  std::vector<std::string> members_read, members_written;
  bool whole_read = false, whole_written = false;

  bool reads(std::string_view member) const;
  bool writes(std::string_view member) const;
};

struct AnalyzedFunction {
  std::string name;  // as written, without glslang's mangling
  std::string return_type;
  std::vector<AnalyzedParam> params;
};

struct ProgramAnalysis {
  std::vector<AnalyzedFunction> functions;  // every function defined, in definition order
  std::map<std::string, std::vector<AnalyzedField>> structs;  // struct types of those functions' parameters

  // The last definition named `name` (user code follows the stdlib), or nullptr.
  const AnalyzedFunction* find(std::string_view name) const;
  const std::vector<AnalyzedField>* find_struct(std::string_view name) const;
};

}  // namespace facet
