// A .shader text parsed and analysed, with its diagnostics: what the sema
// tests look at.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <string_view>

#include "facet/sema.h"
#include "facet/shaderlab.h"

namespace facet::sema::test_util {

struct Analyzed {
  SourceMap sources;
  Diagnostics diags;
  FileId file = kNoFile;
  std::optional<ir::Shader> ir;

  const Diagnostic* find(DiagId id) const {
    for (const Diagnostic& d : diags.all()) {
      if (d.id == id) return &d;
    }
    return nullptr;
  }
  LineColumn at(SourceSpan s) const { return sources.line_column(s.file, s.begin); }
  // The source text a diagnostic points at.
  std::string_view text_at(const Diagnostic& d) const {
    return std::string_view(sources.text(d.span.file)).substr(d.span.begin, d.span.end - d.span.begin);
  }
  const ir::Pass& pass(size_t i = 0, size_t sub = 0) const { return ir->subshaders.at(sub).passes.at(i); }
  const ir::Program& program(size_t i = 0) const { return *pass(i).program; }
  // The program text of pass `i` (generated HLSL for fixed-function passes).
  const std::string& hlsl(size_t i = 0) const { return program(i).body.text; }
};

inline std::unique_ptr<Analyzed> analyze_text(std::string text, const SemaOptions& options = {},
                                              std::string name = "test.shader") {
  auto a = std::make_unique<Analyzed>();
  a->file = a->sources.add_file(std::move(name), std::move(text));
  auto ast = shaderlab::parse(a->file, a->sources, {}, a->diags);
  if (!ast) return a;
  auto ir = analyze(*ast, a->sources, options, a->diags);
  if (ir) a->ir = std::move(*ir);
  return a;
}

}  // namespace facet::sema::test_util
