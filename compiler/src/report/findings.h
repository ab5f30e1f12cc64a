// Keyword findings (dead, undeclared, free in a stage) and "what if" lines.
#pragma once

#include <vector>

#include "facet/report.h"

namespace facet::report {

std::vector<Finding> keyword_findings(const ir::Shader& shader, const SelectedPass& pass,
                                      const CompiledShader& compiled, const SourceMap& sources, uint32_t pass_index);

std::vector<WhatIf> what_ifs(const SelectedPass& pass, const std::vector<ProgramRecord>& records, uint32_t pass_index,
                             double compile_seconds, const ReportOptions& options);

// "multi_compile _ A B" as written, "_" for the off state.
std::string set_spelling(const variants::KeywordSet& set);

// Up to `max_steps` removals of one keyword set each (the set held in its
// default state), each the best given those before it, counted from the
// build's variants of the pass exactly as a build with the strip rules
// would enumerate them; a step that would leave no variant, or turn off a
// keyword a manifest's material enables, is never taken.
std::vector<StripStep> strip_steps(const SelectedPass& pass, const package::PackagePass& built,
                                   const std::vector<ProgramRecord>& records, uint32_t pass_index,
                                   const ReportOptions& options, size_t max_steps = 3);

// The same changes for a pass too large to enumerate, counted from its
// keyword sets: stage programs fewer, before any deduplication (so an upper
// bound on compiles), at `seconds_per_program` each.
std::vector<WhatIf> counted_what_ifs(const SelectedPass& pass, const ReportOptions& options,
                                     double seconds_per_program);

}  // namespace facet::report
