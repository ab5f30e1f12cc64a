// Stage relevance: the part of a preprocessed HLSL program one entry point
// can reach. Every stage compiles the whole program text, so a keyword that
// only the fragment function tests still changes the vertex stage's text;
// hashing only what the entry point reaches lets such programs compile once.
#pragma once

#include <string>

namespace facet {

// The token text (as the driver's token_text makes it: one logical line per
// source line, `#line` markers without numbers) reduced to every top-level
// declaration that is not a function (structs, cbuffers, globals, textures,
// directives: they shape the module's interface and $Globals layout) plus the
// functions reachable from `entry` through calls (string literals count as
// references too, for [patchconstantfunc("f")]). Top-level items keep their
// order. Text that does not split into balanced items is returned unchanged.
std::string reachable_text(const std::string& tokens, const std::string& entry);

}  // namespace facet
