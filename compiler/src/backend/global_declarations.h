// Checks of a preprocessed HLSL program before glslang parses it: glslang's
// HLSL front end (Debian 12's glslang) dereferences a null pointer on
// malformed forms fuzzing found, which fxc rejects with an error:
//   float4 X; float X;    a global uniform declared again with another type
//                         (also "float4 f(v2f i) X;": glslang reads X as a
//                         declarator of float4)
//   struct S {...}; float S;  a global named like a struct
//   float w[C+U] = {...};  an array size naming something undeclared
//   return c ? a : X;     X never declared
//   case 0: ...           a case label outside a switch
//   RWStructuredBuffer<float4> vert(...)  an entry point returning a resource
//   float a[t a];         an array size with two operands in a row
//   float w[N * k);       a bracket closed by the wrong one
// Internal to the backend stage.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace facet::backend {

// A problem at a line of the program, as glslang would report it.
struct DeclarationProblem {
  std::string file;  // the name of the `#line` in force ("" before any)
  uint32_t line = 0;
  std::string token;
  std::string message;
};

// The first such problem of `text` (preprocessed: no comments, `#line N
// "file"` markers), or nullopt. `entry`: the entry point's name, if any.
std::optional<DeclarationProblem> find_declaration_problem(std::string_view text, std::string_view entry = {});

// Where function `name` is first declared at the top level of `text` (the
// same preprocessed form), its name as the token; nullopt when it is not.
// An empty `name` gives the first token of the text.
std::optional<DeclarationProblem> function_position(std::string_view text, std::string_view name);

}  // namespace facet::backend
