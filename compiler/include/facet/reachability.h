// The part of a preprocessed HLSL program one entry point can reach: what
// glslang compiles (fxc's rule), and what the driver hashes, so that a
// keyword that only the fragment function tests does not change the vertex
// stage's key and such programs compile once.
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

// The same reduction of a preprocessed program glslang is to compile, fxc's
// way: fxc compiles only what the entry point reaches, so an unreachable
// function may call one that does not exist, recurse, or fail to type-check.
// The functions left out become as many empty lines as they had, so that
// `#line` positions still hold.
std::string without_unreachable_functions(const std::string& text, const std::string& entry);

// glslang reports "Recursion detected" for any static global whose
// initialiser calls a function of the program; fxc runs such initialisers at
// the start of each invocation. So each "static [const] TYPE NAME = INIT;"
// that calls one becomes "static TYPE NAME;" (the initialiser blanked, lines
// kept), and "NAME = INIT;" is run first in `entry`'s body, in declaration
// order, on the line of its '{'. Text without `entry` is returned unchanged.
std::string with_static_initializers_in_entry(const std::string& text, const std::string& entry);

// A fragment entry point's "TYPE NAME : VFACE" or non-bool "TYPE NAME :
// SV_IsFrontFace" parameter: glslang makes the first a plain varying that no
// vertex stage writes and the second a FrontFacing built-in of the wrong
// type (invalid SPIR-V). Both become "bool NAME_facet_front :
// SV_IsFrontFace", and the body starts with "TYPE NAME = NAME_facet_front
// ? 1 : -1;" (VFACE's sign) or "? 1 : 0;". Lines are kept. Text without
// such a parameter is returned unchanged.
std::string with_front_facing_as_bool(const std::string& text, const std::string& entry);

}  // namespace facet
