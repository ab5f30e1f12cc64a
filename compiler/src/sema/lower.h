// The steps of sema::analyze, one file each. They share a Context that
// counts the errors sema reports (the Diagnostics given to analyze may
// already hold others).
#pragma once

#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "facet/diagnostics.h"
#include "facet/ir.h"
#include "facet/sema.h"
#include "facet/shaderlab.h"
#include "facet/support/text.h"

namespace facet::sema {

namespace ast = shaderlab::ast;

struct Context {
  const SourceMap& sources;
  const SemaOptions& options;
  Diagnostics& diags;
  size_t errors = 0;
  uint64_t program_bytes = 0;  // program text copied into the IR so far
  std::vector<std::string> property_names;  // the Properties block's, once lowered

  Diagnostic& error(DiagId id, SourceSpan span, std::string message) {
    ++errors;
    return diags.add(id, Severity::error, span, std::move(message));
  }
  // Warnings and notes with the id's default severity.
  Diagnostic& report(DiagId id, SourceSpan span, std::string message) {
    if (diag_default_severity(id) == Severity::error) ++errors;
    return diags.add(id, span, std::move(message));
  }
};

// properties.cpp: types, defaults, duplicates.
std::vector<ir::Property> lower_properties(const std::vector<ast::Property>& properties, Context& ctx);
// A `[_Prop]` reference to no declared property reads a global of that name
// (Unity's Shader.SetGlobal*), so only one close to a declared name is
// reported: a warning with the did-you-mean.
void check_property_reference(std::string_view name, SourceSpan span, Context& ctx);

// render_state.cpp: one scope's commands, checked and canonicalised; a later
// command of the same kind (and render target) replaces an earlier one.
ir::RenderState lower_state(const std::vector<ast::Command>& commands, Context& ctx);
// `overlay` wins per field; per-render-target lists are merged per target.
ir::RenderState merge_state(const ir::RenderState& base, const ir::RenderState& overlay);

// tags.cpp
std::vector<ir::Tag> lower_tags(const std::vector<ast::Tag>& tags);
// Tags of an inner scope override the outer scope's tags with the same key.
std::vector<ir::Tag> inherit_tags(const std::vector<ir::Tag>& outer, const std::vector<ir::Tag>& inner);
// Checks known tag values (Queue).
void check_tags(const std::vector<ast::Tag>& tags, Context& ctx);
// Warns about a SubShader-level LightMode tag and copies it into the
// passes that have none (when options ask for it).
void propagate_lightmode(const ast::SubShader& sub, const std::vector<ir::Tag>& sub_tags,
                         std::vector<ir::Pass>& passes, Context& ctx);

// programs.cpp: includes in scope (any language; the matching ones are
// used), pragmas, entry points, shader target.
ir::Program lower_program(const ast::ProgramBlock& block, const std::vector<const ast::ProgramBlock*>& includes,
                          Context& ctx);

// directives.cpp: preprocessor lines of a program text, with `\`
// continuations joined and comments removed.
struct Directive {
  std::string name;               // "pragma", "ifdef", ...
  std::vector<std::string> words;  // the rest, split on whitespace
  std::string rest;               // the rest as one string, trimmed
  SourceSpan span;                // from '#' to the end of the directive
};
std::vector<Directive> scan_directives(const ir::SourceChunk& chunk);

// suggest.cpp: the candidate closest to `word` (case-insensitive), if it is
// close enough to be a likely typo.
std::optional<std::string_view> suggest(std::string_view word, std::span<const std::string_view> candidates);
// "A, B, C"
std::string join(std::span<const std::string_view> words);

}  // namespace facet::sema
