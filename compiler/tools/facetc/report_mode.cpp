// facetc --report: compile every input's variants, then report them together.
#include "report_mode.h"

#include <fmt/format.h>

#include <algorithm>
#include <iostream>
#include <unistd.h>

#include "facet/report.h"
#include "facet/support/text.h"
#include "find_shaders.h"
#include "output_safety.h"
#include "progress.h"
#include "strip_filter.h"
#include "units.h"

namespace facet::tools {
void show_diagnostics(const FacetcArgs& args, const Diagnostics& raw, const SourceMap& sources, Console& console,
                      nlohmann::json& json_diagnostics) {
  Diagnostics diags = apply_warning_options(raw, args.warnings);
  if (args.diagnostics_format == DiagnosticsFormat::json) {
    for (auto& d : nlohmann::json::parse(render_json(diags, sources))) json_diagnostics.push_back(std::move(d));
  } else {
    console.err << render_text(diags, sources, {.color = args.color.value_or(isatty(STDERR_FILENO) == 1)});
  }
}

std::vector<variants::KeywordList> material_keywords(const std::vector<ManifestMaterial>& materials,
                                                     const ir::Shader& shader) {
  std::vector<variants::KeywordList> out;
  for (const ManifestMaterial& m : materials) {
    if (m.shader != shader.name) continue;
    variants::KeywordList keywords = m.keywords;
    for (std::string& k : variants::keywords_from_properties(shader.properties, m.properties)) {
      if (std::find(keywords.begin(), keywords.end(), k) == keywords.end()) keywords.push_back(std::move(k));
    }
    out.push_back(std::move(keywords));
  }
  return out;
}

CompileOptions stripped_options(CompileOptions options, const StripInputs& strip, const ir::Shader& shader) {
  if (strip.materials) options.materials = material_keywords(*strip.materials, shader);
  options.strip = strip.filter;
  if (strip.collection) apply_collection(options, *strip.collection, shader);
  return options;
}

namespace {

// A pass whose variants (as the build would enumerate them) pass the limit
// is reported from its counts, with only its default variant compiled.
bool too_large_to_enumerate(const SelectedPass& pass, const CompileOptions& options) {
  if (options.max_variants_per_pass == 0) return false;
  variants::VariantCounts counts = variants::count_variants(pass.keywords, {.materials = options.materials});
  const BigCount& built = options.build_unreachable ? counts.after_materials : counts.reachable;
  return built > BigCount(options.max_variants_per_pass);
}

// The report of the passes `subset` names (SubShader indices), compiled in
// full, or only their default variants when `counted`.
std::optional<report::ShaderReport> report_passes(const Compiler& compiler, const ir::Shader& shader,
                                                  CompileOptions options, std::vector<std::string> subset,
                                                  bool counted, report::ReportOptions report_options,
                                                  SourceMap& sources, Diagnostics& diags,
                                                  std::vector<std::string>& read, bool show_progress) {
  options.passes = std::move(subset);
  if (counted) {
    options.keywords = std::vector<std::string>{};
    options.strip = {};
    options.materials.reset();
  }
  Diagnostics selection_diags;  // the first selection, of every pass, reported these
  auto passes = compiler.select_passes(shader, options, selection_diags);
  if (!passes) return std::nullopt;
  ProgressBar bar(std::cerr, show_progress);
  options.progress = [&](uint64_t done, uint64_t total) { bar.update(done, total); };
  auto compiled = compiler.compile(shader, options, sources, diags);
  bar.finish();
  if (!compiled) return std::nullopt;
  read.insert(read.end(), compiled->dependencies.begin(), compiled->dependencies.end());
  report_options.counted_only = counted;
  report::ShaderReport r = report::build_report(shader, *passes, *compiled, sources, report_options);
  if (!counted) r.estimate = compiled->estimate;
  return r;
}

// `into` gains the passes and totals of `part`; passes stay in SubShader order.
void merge_report(report::ShaderReport& into, report::ShaderReport part) {
  into.compile_seconds += part.compile_seconds;
  into.programs += part.programs;
  into.compiled += part.compiled;
  if (!into.estimate) into.estimate = part.estimate;
  for (report::PassReport& p : part.passes) into.passes.push_back(std::move(p));
  std::stable_sort(into.passes.begin(), into.passes.end(),
                   [](const report::PassReport& a, const report::PassReport& b) { return a.index < b.index; });
}

// `read` gains every file the shader's build read (itself and its includes).
std::optional<report::ShaderReport> report_one(const FacetcArgs& args, const Compiler& compiler,
                                               const std::string& path, const StripInputs& strip, Console& console,
                                               nlohmann::json& json_diagnostics, std::vector<std::string>& read) {
  SourceMap sources;
  Diagnostics diags;
  std::optional<report::ShaderReport> result;
  auto shader = compiler.load(path, sources, diags, compile_options(args, false));
  if (shader) {
    // The build the options describe: the variants left by the keyword rules,
    // the material manifests and the strip filter; the ladder still counts
    // the rungs before them, so that the report shows what each removes.
    CompileOptions options = stripped_options(compile_options(args, false), strip, *shader);
    report::ReportOptions report_options;
    if (strip.materials) report_options.materials = material_keywords(*strip.materials, *shader);
    if (auto passes = compiler.select_passes(*shader, options, diags)) {
      std::vector<std::string> enumerable, counted;
      for (const SelectedPass& pass : *passes) {
        (too_large_to_enumerate(pass, options) ? counted : enumerable).push_back(std::to_string(pass.pass));
      }
      bool ok = true;
      // A bar only for people: on a terminal, with text diagnostics.
      bool show_progress = isatty(STDERR_FILENO) == 1 && args.diagnostics_format == DiagnosticsFormat::text;
      report::ShaderReport merged{.path = sources.path(shader->file), .name = shader->name};
      for (bool counting : {false, true}) {
        std::vector<std::string>& subset = counting ? counted : enumerable;
        if (subset.empty() || !ok) continue;
        auto part = report_passes(compiler, *shader, options, subset, counting, report_options, sources, diags, read,
                                  show_progress);
        if (part) merge_report(merged, std::move(*part));
        ok = part.has_value();
      }
      if (ok && !apply_warning_options(diags, args.warnings).has_errors()) result = std::move(merged);
    }
  }
  for (FileId id = 0; id < sources.file_count(); ++id) read.push_back(sources.path(id));
  show_diagnostics(args, diags, sources, console, json_diagnostics);
  return result;
}

// The filter the report was built with, plus one always_off rule per step
// of the summary: the build that `programs_after` counts.
variants::StripFilter planned_filter(variants::StripFilter filter, const report::ShaderReport& report) {
  for (const report::PlannedStep& s : report::strip_plan(report).steps) {
    filter.rules.push_back(
        {.kind = variants::StripKind::always_off, .keywords = s.step.always_off, .pass = std::to_string(s.pass)});
  }
  return filter;
}

}  // namespace

int run_report(const FacetcArgs& args, const Compiler& compiler, const StripInputs& strip, Console& console,
               nlohmann::json& json_diagnostics) {
  bool failed = false;
  std::vector<report::ShaderReport> reports;
  std::vector<RunInput> inputs;
  add_inputs(inputs, args.material_files, "a materials file");
  add_inputs(inputs, args.strip_files, "a strip filter");
  add_inputs(inputs, args.variant_files, "a variant collection");
  std::vector<std::string> errors;
  std::vector<std::string> paths = find_shaders(args.inputs, errors);
  if (!errors.empty()) {
    for (const std::string& e : errors) console.err << "facetc: error: " << e << "\n";
    return 1;
  }
  if (!args.emit_strip_file.empty() && paths.size() != 1) {
    console.err << fmt::format("facetc: error: --emit-strip writes the strip filter of one shader; the inputs name {}\n",
                               count_of(paths.size(), "shader", "shaders"));
    return 1;
  }
  for (const std::string& path : paths) {
    std::vector<std::string> read;
    auto r = report_one(args, compiler, path, strip, console, json_diagnostics, read);
    inputs.push_back({path, "a shader"});
    add_inputs(inputs, read, "a file the build read");
    if (r) reports.push_back(std::move(*r));
    failed |= !r;
  }
  if (reports.empty()) return 1;
  std::string text = args.report == ReportFormat::json   ? report::to_json(reports)
                     : args.report == ReportFormat::html ? report::to_html(reports)
                                                         : report::to_text(reports);
  std::vector<std::string> outputs;
  if (!args.output.empty() && args.output != "-") outputs.push_back(args.output);
  if (!args.emit_strip_file.empty()) outputs.push_back(args.emit_strip_file);
  Diagnostics diags;
  if (!outputs_spare_inputs(outputs, inputs, diags)) {
    show_diagnostics(args, diags, SourceMap{}, console, json_diagnostics);
    return 1;
  }
  if (outputs.empty() || outputs.front() != args.output) {
    console.out << text;
  } else if (!write_file_atomically(args.output, text, diags)) {
    show_diagnostics(args, diags, SourceMap{}, console, json_diagnostics);
    return 1;
  }
  if (!args.emit_strip_file.empty() &&
      !write_file_atomically(args.emit_strip_file, strip_filter_json(planned_filter(strip.filter, reports.front())),
                             diags)) {
    show_diagnostics(args, diags, SourceMap{}, console, json_diagnostics);
    return 1;
  }
  return failed ? 1 : 0;
}

}  // namespace facet::tools
