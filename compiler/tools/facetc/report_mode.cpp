// facetc --report: compile every input's variants, then report them together.
#include "report_mode.h"

#include <fmt/format.h>

#include <algorithm>
#include <unistd.h>

#include "facet/report.h"
#include "find_shaders.h"
#include "output_safety.h"
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
  return options;
}

namespace {

// A pass whose variants (as the build would enumerate them) pass the limit
// is reported from its counts, with only its default variant compiled.
bool too_large_to_enumerate(const SelectedPass& pass, const CompileOptions& options) {
  if (options.max_variants_per_pass == 0) return false;
  variants::VariantCounts counts = variants::count_variants(pass.keywords);
  const BigCount& built = options.build_unreachable ? counts.after_skip : counts.reachable;
  return built > BigCount(options.max_variants_per_pass);
}

// The report of the passes `subset` names (SubShader indices), compiled in
// full, or only their default variants when `counted`.
std::optional<report::ShaderReport> report_passes(const Compiler& compiler, const ir::Shader& shader,
                                                  CompileOptions options, std::vector<std::string> subset,
                                                  bool counted, report::ReportOptions report_options,
                                                  SourceMap& sources, Diagnostics& diags,
                                                  std::vector<std::string>& read) {
  options.passes = std::move(subset);
  if (counted) {
    options.keywords = std::vector<std::string>{};
    options.strip = {};
  }
  Diagnostics selection_diags;  // the first selection, of every pass, reported these
  auto passes = compiler.select_passes(shader, options, selection_diags);
  if (!passes) return std::nullopt;
  auto compiled = compiler.compile(shader, options, sources, diags);
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
    // Every variant after the keyword rules and the strip filter; the material
    // rung is counted, not stripped, so that the report shows what it removes.
    CompileOptions options = compile_options(args, false);
    options.strip = strip.filter;
    report::ReportOptions report_options;
    if (strip.materials) report_options.materials = material_keywords(*strip.materials, *shader);
    if (auto passes = compiler.select_passes(*shader, options, diags)) {
      std::vector<std::string> enumerable, counted;
      for (const SelectedPass& pass : *passes) {
        (too_large_to_enumerate(pass, options) ? counted : enumerable).push_back(std::to_string(pass.pass));
      }
      bool ok = true;
      report::ShaderReport merged{.path = sources.path(shader->file), .name = shader->name};
      for (bool counting : {false, true}) {
        std::vector<std::string>& subset = counting ? counted : enumerable;
        if (subset.empty() || !ok) continue;
        auto part = report_passes(compiler, *shader, options, subset, counting, report_options, sources, diags, read);
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

}  // namespace

int run_report(const FacetcArgs& args, const Compiler& compiler, const StripInputs& strip, Console& console,
               nlohmann::json& json_diagnostics) {
  bool failed = false;
  std::vector<report::ShaderReport> reports;
  std::vector<RunInput> inputs;
  add_inputs(inputs, args.material_files, "a materials file");
  add_inputs(inputs, args.strip_files, "a strip filter");
  std::vector<std::string> errors;
  std::vector<std::string> paths = find_shaders(args.inputs, errors);
  if (!errors.empty()) {
    for (const std::string& e : errors) console.err << "facetc: error: " << e << "\n";
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
  if (args.output.empty() || args.output == "-") {
    console.out << text;
  } else {
    Diagnostics diags;
    if (!outputs_spare_inputs({args.output}, inputs, diags) || !write_file_atomically(args.output, text, diags)) {
      show_diagnostics(args, diags, SourceMap{}, console, json_diagnostics);
      return 1;
    }
  }
  return failed ? 1 : 0;
}

}  // namespace facet::tools
