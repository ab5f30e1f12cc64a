// The names a preprocessed HLSL program declares, for Clang-style
// "use of undeclared identifier 'x'; did you mean 'y'?" in place of
// glslang's "no matching overloaded function found" and "unknown variable".
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace facet::backend {

// HLSL's intrinsic functions (Shader Model 5 and the legacy tex* family):
// a call to one of them with the wrong arguments is an overload mismatch,
// never an undeclared name.
bool is_hlsl_intrinsic(std::string_view name);

// Functions declared or defined at the top level of `text` (outside every
// brace): an identifier directly followed by '('.
std::vector<std::string> top_level_functions(std::string_view text);

// Every distinct identifier of `text` that could name a variable: no
// keywords and no scalar, vector or matrix type names.
std::vector<std::string> variable_like_identifiers(std::string_view text);

// The message for glslang's `text` about `token`, when the token is an
// undeclared name in `program` (the whole preprocessed program) and `line`
// (the source line it is on) calls it as a function or reads it as a
// variable: "use of undeclared identifier 'tok'", with a did-you-mean from
// the program's names. nullopt: glslang's message stands.
std::optional<std::string> undeclared_identifier_message(std::string_view token, std::string_view text,
                                                         std::string_view program, std::string_view line);

}  // namespace facet::backend
