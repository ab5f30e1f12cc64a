// The variant report: for each pass and stage, Unity's counting ladder plus
// facet's (full space -> after skip_variants -> after material usage ->
// after scene needs -> unique after preprocessing -> unique SPIR-V), what
// each keyword set multiplies, keywords that are dead, misspelt or free to
// drop from a stage, "what if" savings, and compile time and SPIR-V size per
// variant. Built from a compile (facet/compiler.h); printed as text, JSON or
// one self-contained HTML page (docs/reports.md).
//
//   auto compiled = compiler.compile(*shader, {}, sources, diags);
//   report::ShaderReport r = report::build_report(*shader, *passes, *compiled, sources, {});
//   std::cout << report::to_text(r);
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "facet/bigcount.h"
#include "facet/compiler.h"
#include "facet/ir.h"
#include "facet/source.h"
#include "facet/variants.h"

namespace facet::report {

struct ReportOptions {
  // The keyword lists of the materials that use the shader (material
  // manifests); nullopt: no material rung.
  std::optional<std::vector<variants::KeywordList>> materials;
  // The compile holds only each pass's default variant, because its space is
  // too large to enumerate: the counting rungs stay exact, the rungs that
  // need every program (after strip .. unique SPIR-V) are left out, and the
  // what-ifs are counted from the keyword sets (PassReport::enumerated).
  bool counted_only = false;
};

// One rung per column; counts of variants (full .. after_materials) and of
// stage programs (programs .. unique_spirv) for one stage, or the pass.
struct Ladder {
  std::string scope;  // "pass", "vertex", "fragment", ...
  BigCount full, after_skip, after_materials;
  BigCount reachable;         // after_materials without the unreachable keywords' variants
  bool has_materials = false;
  uint64_t after_strip = 0;   // variants (stage: distinct stage views) left by keyword_rule and --strip
  uint64_t programs = 0;      // distinct (stage, keywords the stage sees) compiled
  uint64_t unique_tokens = 0; // distinct relevant preprocessed tokens: compiles
  uint64_t unique_spirv = 0;  // distinct SPIR-V modules stored
};

struct KeywordSetRow {
  std::string pragma;                 // as written, e.g. "shader_feature_local_fragment"
  std::vector<std::string> keywords;  // "" is the off state, shown as "_"
  std::vector<std::string> stages;    // the stages it applies to
  uint64_t factor = 1;                // states after skip_variants: what it multiplies the pass by
};

enum class FindingKind { dead, undeclared, free_in_stage };

struct Finding {
  FindingKind kind = FindingKind::dead;
  std::string keyword;
  std::string stage;      // free_in_stage: the stage
  std::string detail;     // one sentence, e.g. "did you mean '_EMISSION'?"
};

struct WhatIf {
  std::string change;           // "make 'multi_compile _ A' shader_feature"
  BigCount programs_saved = 0;  // stage programs fewer to compile
  double seconds_saved = 0;     // at this build's mean seconds per compiled program
                                // (counted what-ifs: per program, before deduplication)
};

// A what-if a strip file applies: one keyword set of a pass held in its
// default state (its other keywords always off). Savings are marginal: with
// the pass's steps before it applied.
struct StripStep {
  std::string change;                    // "hold 'multi_compile_fog _ FOG_LINEAR ...' off (always_off ...)"
  std::vector<std::string> always_off;   // the strip rule's keywords
  uint64_t programs_saved = 0;
  double seconds_saved = 0;              // measured compile time of the programs no longer needed
};

struct VariantRow {
  std::vector<std::string> keywords;
  double seconds = 0;         // compile time of the programs it was first to need
  uint64_t spirv_bytes = 0;   // all its stages
};

struct PassReport {
  uint32_t index = 0;
  std::string name, light_mode;
  // false: too many variants to enumerate (ReportOptions::counted_only);
  // the ladders' program rungs are 0 and only the default variant was built.
  bool enumerated = true;
  std::vector<Ladder> ladders;  // "pass" first, then each stage the program has
  std::vector<KeywordSetRow> sets;
  // Shortcut keywords facet's renderer never enables (lightmaps, ...):
  // counted in full, not built unless asked (--build-unreachable).
  std::vector<std::string> unreachable_keywords;
  std::vector<Finding> findings;
  std::vector<WhatIf> what_ifs;      // by programs saved, most first; none that saves nothing
  // Up to three steps, each the best given those before it, counted from the
  // build's variants; empty for a pass not enumerated.
  std::vector<StripStep> strip_steps;
  std::vector<VariantRow> variants;  // in key order
  double compile_seconds = 0;        // sum over the programs compiled
  uint64_t spirv_bytes = 0;          // unique modules of the pass
};

struct ShaderReport {
  std::string path, name;
  std::optional<BuildEstimate> estimate;  // made before the build, from a timed sample
  std::vector<PassReport> passes;
  double compile_seconds = 0;
  uint64_t programs = 0, compiled = 0;
};

// `passes` and `compiled` must come from the same Compiler::select_passes and
// Compiler::compile call options (all variants); `sources` holds the shader
// and the files it included.
ShaderReport build_report(const ir::Shader& shader, const std::vector<SelectedPass>& passes,
                          const CompiledShader& compiled, const SourceMap& sources, const ReportOptions& options);

// The summary at the top of a shader's report: its programs now, and after
// the three best what-ifs a strip file can apply, chosen across its
// enumerated passes (each the best given those before it). Feeding
// `--emit-strip`'s file back with `--strip` builds `programs_after` programs.
struct PlannedStep {
  uint32_t pass = 0;  // PassReport::index
  std::string pass_name;
  StripStep step;
};

struct StripPlan {
  uint64_t programs_now = 0, programs_after = 0;  // enumerated passes only
  double seconds_saved = 0;
  std::vector<PlannedStep> steps;
  uint32_t passes_not_enumerated = 0;  // not in these figures
};

StripPlan strip_plan(const ShaderReport& report, size_t max_steps = 3);

std::string to_text(const std::vector<ShaderReport>& reports);
// Stable keys; times are rounded to microseconds.
std::string to_json(const std::vector<ShaderReport>& reports);
// One self-contained page with inline SVG charts, readable offline.
std::string to_html(const std::vector<ShaderReport>& reports);

std::string_view finding_name(FindingKind kind);  // "dead", "undeclared", "free"

}  // namespace facet::report
