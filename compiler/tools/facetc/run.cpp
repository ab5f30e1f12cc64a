// facetc's per-input recipe: read -> produce the output in memory -> report
// diagnostics -> write the output (and depfile) only when nothing failed.
#include "run.h"

#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <iostream>
#include <nlohmann/json.hpp>

#include "facet/build_farm.h"
#include "facet/compiler.h"
#include "facet/package.h"
#include "facet/sema.h"
#include "facet/shaderlab.h"
#include "facet/support/make_rule.h"
#include "facet/support/text.h"
#include "check_mode.h"
#include "jobs.h"
#include "output_safety.h"
#include "progress.h"
#include "report_mode.h"
#include "scene_mode.h"
#include "strip_filter.h"
#include "units.h"

namespace facet::tools {
namespace {
namespace fs = std::filesystem;

// What one input produced, before anything is written.
struct Produced {
  std::string bytes;
  std::vector<uint8_t> package;  // a binary package, written instead of `bytes` when not empty
  std::string output;  // where: a path, or "" / "-" for standard output
  std::string stats;   // the --stats line, if any
  // Files the compile read besides those in the SourceMap (the includes of
  // programs that came from the cache).
  std::vector<std::string> dependencies;
  bool usage_error = false;
};

bool is_package_file(const std::string& path) { return fs::path(path).extension() == ".facetpkg"; }

// <input stem>.facetpkg, in --out-dir if given: where a package goes without -o.
std::string default_package_path(const FacetcArgs& args, const std::string& input) {
  fs::path name = fs::path(input).stem();
  name += ".facetpkg";
  return (args.out_dir.empty() ? name : fs::path(args.out_dir) / name).string();
}

std::string package_output_path(const FacetcArgs& args, const std::string& input) {
  return !args.output.empty() ? args.output : default_package_path(args, input);
}

// Where -M writes its rule: -MF, else -o (as gcc -M -o does), else ""
// (standard output).
std::string rule_destination(const FacetcArgs& args) {
  if (!args.depfile.empty()) return args.depfile;
  return args.output == "-" ? "" : args.output;
}

std::string pass_header(const ir::Pass& pass, size_t index) {
  std::string light_mode = pass.tag("LightMode");
  return fmt::format("pass #{}{}{}\n", index, pass.name.empty() ? "" : fmt::format(" '{}'", pass.name),
                     light_mode.empty() ? "" : " (LightMode " + light_mode + ")");
}

Result<std::string> keyword_spaces(const FacetcArgs& args, const Compiler& compiler, const ir::Shader& shader,
                                   bool list, Diagnostics& diags) {
  auto passes = compiler.select_passes(shader, compile_options(args, false), diags);
  FACET_TRY(passes);
  std::string out = fmt::format("shader '{}'\n", shader.name);
  variants::KeywordList implied = variants::keywords_from_properties(shader.properties);
  out += fmt::format("keywords the property defaults enable (Toggle, KeywordEnum): {}\n",
                     implied.empty() ? "(none)" : fmt::format("{}", fmt::join(implied, " ")));
  for (const SelectedPass& pass : *passes) {
    variants::DumpOptions options{.stages = 0, .list_variants = list};
    for (int s = 0; s < kStageCount; ++s) {
      if (pass.ir.program->has_stage(Stage(s))) options.stages |= stage_bit(Stage(s));
    }
    if (args.stage) options.stages &= stage_bit(*args.stage);
    out += pass_header(pass.ir, pass.pass);
    out += variants::dump_keyword_space(pass.keywords, options);
  }
  return out;
}

// What identifies a build for --merge (docs/package-format.md, "Shards"):
// the shader file's bytes, the options that shape the compiled code, and
// the variants the whole build selects (so every option that changes the
// selection, --keywords, --strip or --materials among them, counts by what
// it selects). Not --shard (the shards of a build and the unsharded build
// share it), -j, the cache or output paths, which change none of the
// package's bytes.
uint64_t build_id(const FacetcArgs& args, const Compiler& compiler, const ir::Shader& shader, CompileOptions options,
                  const std::string& input, const SourceMap& sources) {
  std::string key = "facetc build\n";
  auto field = [&](std::string_view name, std::string_view value) {
    key += fmt::format("{} {}\n", name, value.size());
    key += value;
  };
  for (FileId id = 0; id < sources.file_count(); ++id) {
    if (sources.path(id) == input) {
      field("shader", sources.text(id));
      break;
    }
  }
  for (size_t i = 0; i < args.compile_flags.size(); ++i) {
    const std::string& flag = args.compile_flags[i];
    if (flag == "--cache-dir" || flag == "--remote-cache") {
      ++i;  // and its value
      continue;
    }
    field("flag", flag);
  }
  options.shard_index = 0;
  options.shard_count = 1;
  Diagnostics ignored;  // the compile that succeeded reported them
  auto passes = compiler.select_passes(shader, options, ignored);
  for (const SelectedPass& pass : passes ? *passes : std::vector<SelectedPass>{}) {
    field("pass", fmt::format("{}.{}", pass.subshader, pass.pass));
    auto set = compiler.select_variants(pass, options, ignored);
    for (const variants::VariantKey& k : set ? set->keys : std::vector<variants::VariantKey>{}) {
      field("variant", fmt::format("{}", fmt::join(k.choice, ",")));
    }
  }
  return package::build_id_of(key);
}

Result<Produced> build_package(const FacetcArgs& args, const Compiler& compiler, const StripInputs& strip,
                               const ir::Shader& shader, const std::string& input, SourceMap& sources,
                               Diagnostics& diags) {
  if (strip.collection) {
    if (std::optional<std::string> problem = collection_problem(*strip.collection, shader)) {
      diags.add(DiagId::driver_bad_option, shader.span, *problem);
      return failure("not in the collection");
    }
  }
  CompileOptions options = stripped_options(compile_options(args, false), strip, shader);
  // A bar only for people: on a terminal, with text diagnostics.
  ProgressBar bar(std::cerr, isatty(STDERR_FILENO) == 1 && args.diagnostics_format == DiagnosticsFormat::text);
  options.progress = [&](uint64_t done, uint64_t total) { bar.update(done, total); };
  auto compiled = compiler.compile(shader, options, sources, diags);
  bar.finish();
  FACET_TRY(compiled);
  compiled->package.build = {.shard_index = args.shard_index,
                             .shard_count = args.shard_count,
                             .build_id = build_id(args, compiler, shader, options, input, sources)};
  auto encode_started = std::chrono::steady_clock::now();
  std::vector<uint8_t> bytes = package::write_package(compiled->package);
  double encode_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - encode_started).count();
  const CompileStats& s = compiled->stats;
  Produced out{.output = package_output_path(args, input), .dependencies = compiled->dependencies};
  out.stats = fmt::format("facetc: {}: {}, {} ({} stripped); programs {}, unique after preprocessing {} "
                          "(compiled once each), unique SPIR-V {}; {}, {:.2f} s on {}\n",
                          input, count_of(s.passes, "pass", "passes"), count_of(s.variants, "variant", "variants"),
                          s.variants_stripped, s.stage_programs, s.unique_preprocessed, s.unique_spirv,
                          count_of(bytes.size(), "byte", "bytes"), s.seconds, count_of(s.jobs, "thread", "threads"));
  out.package = std::move(bytes);
  out.stats += fmt::format("facetc: {}: phases: select {:.3f} s, preprocess {:.3f} s, compile {:.3f} s, "
                           "assemble {:.3f} s, encode {:.3f} s\n",
                           input, s.phases.select, s.phases.preprocess, s.phases.compile, s.phases.assemble,
                           encode_seconds);
  if (!args.cache_dir.empty() || !args.cache_url.empty()) {
    out.stats += fmt::format("facetc: {}: cache: local hits {} / remote hits {} / compiled {}{}; {} of {} programs "
                             "not preprocessed (include manifests current)\n",
                             input, s.cache_hits - s.cache_remote_hits, s.cache_remote_hits, s.compiled,
                             s.cache_corrupt ? fmt::format(" ({} corrupt entries recompiled)", s.cache_corrupt) : "",
                             s.preprocess_skipped, s.stage_programs);
  }
  if (args.mode == Mode::dump) {
    out.package.clear();
    out.bytes = package::package_to_json(compiled->package);
  }
  return out;
}

Result<Produced> dump_package_file(const FacetcArgs& args, const std::string& input, Diagnostics& diags) {
  auto pkg = read_package_file(input, diags);
  FACET_TRY(pkg);
  return Produced{.bytes = package::package_to_json(*pkg), .output = args.output};
}

// The input '-': standard input, read whole (at most kMaxShaderBytes), as
// glslc reads it. It is named "<stdin>" and its #includes are found from the
// current folder.
constexpr const char* kStdinName = "<stdin>";

Result<std::string> read_standard_input(std::istream* in, Diagnostics& diags) {
  if (!in) {
    diags.add(DiagId::io_cannot_read, {}, "standard input ('-') cannot be read here");
    return failure("no stdin");
  }
  std::string text;
  char buffer[1 << 16];
  while (in->read(buffer, sizeof buffer) || in->gcount() > 0) {
    text.append(buffer, size_t(in->gcount()));
    if (text.size() > kMaxShaderBytes) {
      diags.add(DiagId::io_too_large, {},
                fmt::format("standard input is over {} bytes, the limit of a shader", kMaxShaderBytes));
      return failure("too large");
    }
  }
  return text;
}

Result<ir::Shader> load_input(const FacetcArgs& args, const Compiler& compiler, const std::string& input,
                              std::istream* in, SourceMap& sources, Diagnostics& diags) {
  if (input != "-") return compiler.load(input, sources, diags, compile_options(args, false));
  auto text = read_standard_input(in, diags);
  FACET_TRY(text);
  return compiler.load_source(kStdinName, std::move(*text), sources, diags, compile_options(args, false));
}

Result<Produced> produce(const FacetcArgs& args, const Compiler& compiler, const StripInputs& strip,
                         const std::string& input, std::istream* in, SourceMap& sources, Diagnostics& diags) {
  if (args.mode == Mode::dump && is_package_file(input)) return dump_package_file(args, input, diags);
  if (input == "-" && args.output.empty() && args.out_dir.empty() &&
      (args.mode == Mode::package || (args.mode == Mode::depfile_only && args.write_depfile))) {
    diags.add(DiagId::driver_bad_option, {}, "a package of standard input ('-') needs a name: give -o");
    return Produced{.usage_error = true};
  }
  if (args.mode == Mode::depfile_only && !args.depfile.empty() && !args.output.empty()) {
    diags.add(DiagId::driver_bad_option, {}, "-M writes its rule to the file -o or -MF names; give one of them");
    return Produced{.usage_error = true};
  }
  if (args.mode == Mode::dump && args.dump == DumpKind::ast) {
    auto text = input == "-" ? read_standard_input(in, diags) : read_file(input, kMaxShaderBytes, diags);
    FACET_TRY(text);
    auto ast = shaderlab::parse(sources.add_file(input == "-" ? kStdinName : input, std::move(*text)), sources, {},
                                diags);
    FACET_TRY(ast);
    return Produced{.bytes = shaderlab::ast_to_json(*ast, sources), .output = args.output};
  }
  auto shader = load_input(args, compiler, input, in, sources, diags);
  FACET_TRY(shader);
  switch (args.mode) {
    case Mode::package:
    case Mode::depfile_only:
      return build_package(args, compiler, strip, *shader, input, sources, diags);
    case Mode::dump:
      if (args.dump == DumpKind::ir) return Produced{.bytes = sema::ir_to_json(*shader), .output = args.output};
      if (args.dump == DumpKind::package) {
        auto built = build_package(args, compiler, strip, *shader, input, sources, diags);
        FACET_TRY(built);
        built->output = args.output;
        return built;
      }
      [[fallthrough]];
    case Mode::list_variants: {
      auto text = keyword_spaces(args, compiler, *shader, args.mode == Mode::list_variants, diags);
      FACET_TRY(text);
      return Produced{.bytes = std::move(*text), .output = args.output};
    }
    case Mode::report:  // run_report handles it
    case Mode::merge:   // run_merge handles it
    case Mode::check:   // run_check handles it
      return failure("not a per-input mode");
    case Mode::emit_jobs: {
      auto text = emit_jobs(args, compiler, *shader, input, args.facetc_path, sources, diags);
      FACET_TRY(text);
      return Produced{.bytes = std::move(*text), .output = args.output};
    }
    case Mode::program: {
      auto job = parse_program_job(args.program);
      if (!job) {
        diags.add(DiagId::driver_bad_option, {}, "--program takes PASS:STAGE:KEYWORDS, e.g. 0:fragment:FOG_LINEAR,_EMISSION");
        return Produced{.usage_error = true};
      }
      auto compiled = compile_program(compiler, *shader, compile_options(args, false), *job, sources, diags);
      FACET_TRY(compiled);
      return Produced{.bytes = fmt::format("{} {}\n", program_job_spec(*job), *compiled ? "compiled" : "cached"),
                      .output = args.output};
    }
    case Mode::estimate: {
      auto e = estimate_build(compiler, *shader, stripped_options(compile_options(args, false), strip, *shader), sources,
                                 diags);
      FACET_TRY(e);
      return Produced{.bytes = fmt::format("{}: {}, {}, {} to compile; ~{:.2f} s on {} "
                                           "(preprocessing {:.2f} s, {:.1f} ms per program from {} sampled)\n",
                                           input, count_of(e->variants, "variant", "variants"),
                                           count_of(e->programs, "program", "programs"), e->unique, e->estimated_seconds,
                                           count_of(e->jobs, "thread", "threads"), e->preprocess_seconds,
                                           1000 * e->seconds_per_program, e->sampled),
                      .output = args.output};
    }
    case Mode::preprocess:
    case Mode::emit:
    case Mode::reflect: {
      auto units = produce_units(args, compiler, *shader, sources, diags);
      FACET_TRY(units);
      return Produced{.bytes = std::move(units->bytes), .output = args.output, .usage_error = units->usage_error};
    }
  }
  return failure("unknown mode");
}

// Every real file the input read: itself first, then its includes, sorted.
std::vector<std::string> dependencies(const std::string& input, const SourceMap& sources,
                                      const std::vector<std::string>& also_read) {
  std::vector<std::string> deps;
  for (FileId id = 0; id < sources.file_count(); ++id) {
    const std::string& path = sources.path(id);
    if (!path.starts_with("<") && path != input) deps.push_back(path);
  }
  for (const std::string& path : also_read) {
    if (!path.starts_with("<") && path != input) deps.push_back(path);
  }
  std::sort(deps.begin(), deps.end());
  deps.erase(std::unique(deps.begin(), deps.end()), deps.end());
  if (input != "-") deps.insert(deps.begin(), input);  // standard input is no file to depend on
  return deps;
}

bool to_stdout(const std::string& output) { return output.empty() || output == "-"; }

// The files this run reads for `input`: the shaders named on the command
// line, the input's includes and those of the inputs before it, the
// materials, strip and variant collection files.
std::vector<RunInput> run_inputs(const FacetcArgs& args, const std::string& input,
                                 const std::vector<std::string>& deps, const std::vector<std::string>& read_before) {
  std::vector<RunInput> inputs{{input, "the shader"}};
  size_t includes_from = input == "-" ? 0 : 1;  // dependencies() lists the input first, unless it is stdin
  add_inputs(inputs, std::vector<std::string>(deps.begin() + includes_from, deps.end()), "an include file");
  add_inputs(inputs, args.inputs, "a shader of this run");
  add_inputs(inputs, read_before, "a file an earlier input read");
  add_inputs(inputs, args.material_files, "a materials file");
  add_inputs(inputs, args.variant_files, "a variant collection");
  add_inputs(inputs, args.strip_files, "a strip filter");
  return inputs;
}

// Every file write_outputs would write (standard output is none).
std::vector<std::string> output_paths(const FacetcArgs& args, const Produced& produced) {
  if (args.mode == Mode::depfile_only) return {rule_destination(args)};
  std::vector<std::string> out{to_stdout(produced.output) ? "" : produced.output};
  if (args.write_depfile) out.push_back(!args.depfile.empty() ? args.depfile : produced.output + ".d");
  return out;
}

// Writes the output, then the depfile; false (with a diagnostic) on I/O
// failure, or when an output is an input of the run (then nothing is
// written: the check runs after the compile, which found the includes).
// `read_before` gains the files this input read.
bool write_outputs(const FacetcArgs& args, const std::string& input, const Produced& produced,
                   const SourceMap& sources, Console& console, Diagnostics& diags,
                   std::vector<std::string>& read_before) {
  // The includes of programs that came from the cache count as inputs too,
  // and belong in the depfile: a warm build must name what a cold one does.
  std::vector<std::string> read = dependencies(input, sources, produced.dependencies);
  std::vector<RunInput> inputs = run_inputs(args, input, read, read_before);
  read_before.insert(read_before.end(), read.begin(), read.end());
  if (!outputs_spare_inputs(output_paths(args, produced), inputs, diags)) return false;
  // -M's -o names the rule's file, not the package it describes.
  std::string target = !args.dep_target.empty()          ? args.dep_target
                       : args.mode == Mode::depfile_only ? default_package_path(args, input)
                       : to_stdout(produced.output)      ? package_output_path(args, input)
                                                         : produced.output;
  std::string rule = make_rule(target, read);
  if (args.mode == Mode::depfile_only) {
    std::string destination = rule_destination(args);
    if (destination.empty()) {
      console.out << rule;
      return true;
    }
    return bool(write_file_atomically(destination, rule, diags));
  }
  std::string_view contents = produced.package.empty()
                                  ? std::string_view(produced.bytes)
                                  : std::string_view(reinterpret_cast<const char*>(produced.package.data()),
                                                     produced.package.size());
  if (to_stdout(produced.output)) {
    console.out.write(contents.data(), std::streamsize(contents.size()));
    console.out.flush();
  } else if (!write_file_atomically(produced.output, contents, diags)) {
    return false;
  }
  if (!args.write_depfile) return true;
  std::string depfile = !args.depfile.empty() ? args.depfile : produced.output + ".d";
  return bool(write_file_atomically(depfile, rule, diags));
}

// --materials and --strip, read once for every input.
std::optional<StripInputs> read_strip_inputs(const FacetcArgs& args, Console& console, nlohmann::json& json_diags) {
  StripInputs inputs;
  bool ok = true;
  if (!args.material_files.empty()) inputs.materials.emplace();
  for (const std::string& file : args.material_files) {
    SourceMap sources;
    Diagnostics diags;
    auto read = read_material_manifest(file, sources, diags);
    show_diagnostics(args, diags, sources, console, json_diags);
    if (read) inputs.materials->insert(inputs.materials->end(), read->begin(), read->end());
    ok = ok && read;
  }
  for (const std::string& file : args.strip_files) {
    SourceMap sources;
    Diagnostics diags;
    auto read = read_strip_filter(file, sources, diags);
    show_diagnostics(args, diags, sources, console, json_diags);
    if (read) inputs.filter.rules.insert(inputs.filter.rules.end(), read->rules.begin(), read->rules.end());
    ok = ok && read;
  }
  for (const std::string& file : args.variant_files) {
    SourceMap sources;
    Diagnostics diags;
    auto read = read_variant_collection(file, sources, diags);
    show_diagnostics(args, diags, sources, console, json_diags);
    if (read && !inputs.collection) inputs.collection.emplace();
    if (read) {
      for (auto& [shader, passes] : read->shaders) {
        for (auto& [index, pass] : passes) {
          CollectedPass& into = inputs.collection->shaders[shader][index];
          if (into.name.empty()) into.name = pass.name;
          into.variants.insert(pass.variants.begin(), pass.variants.end());
        }
      }
    }
    ok = ok && read;
  }
  if (!ok) return std::nullopt;
  return inputs;
}

// One input, start to end. Returns its exit code.
// `read_before`: the files the inputs before this one read (and this one's, after).
int process_input(const FacetcArgs& args, const Compiler& compiler, const StripInputs& strip,
                  const std::string& input, Console& console, nlohmann::json& json_diagnostics,
                  std::vector<std::string>& read_before) {
  SourceMap sources;
  Diagnostics raw;
  Result<Produced> produced = produce(args, compiler, strip, input, console.in, sources, raw);
  Diagnostics diags = apply_warning_options(raw, args.warnings);
  bool ok = produced && !produced->usage_error && !diags.has_errors();
  if (ok && !write_outputs(args, input, *produced, sources, console, diags, read_before)) ok = false;
  show_diagnostics(args, diags, sources, console, json_diagnostics);
  if (ok && args.stats) console.err << produced->stats;
  if (produced && produced->usage_error) return 2;
  return ok ? 0 : 1;
}

// --merge: read every shard, join them, write -o.
int run_merge(const FacetcArgs& args, Console& console, nlohmann::json& json_diagnostics) {
  std::vector<package::Package> shards;
  SourceMap none;
  for (const std::string& input : args.inputs) {
    Diagnostics diags;
    auto pkg = read_package_file(input, diags);
    show_diagnostics(args, diags, none, console, json_diagnostics);
    if (!pkg) return 1;
    shards.push_back(std::move(*pkg));
  }
  Diagnostics diags;
  std::vector<RunInput> inputs;
  add_inputs(inputs, args.inputs, "a package being merged");
  auto merged = package::merge_packages(shards, diags, args.inputs);
  bool ok = merged && outputs_spare_inputs({args.output}, inputs, diags) && write_file_atomically(args.output, [&] {
    std::vector<uint8_t> bytes = package::write_package(*merged);
    return std::string(bytes.begin(), bytes.end());
  }(), diags);
  show_diagnostics(args, diags, none, console, json_diagnostics);
  return ok ? 0 : 1;
}

}  // namespace

int run_facetc(const FacetcArgs& args, Console& console) {
  if (!args.scene.empty()) return run_scene(args, console);
  if (!args.out_dir.empty()) {
    std::error_code ec;
    fs::create_directories(args.out_dir, ec);
    if (ec) {
      console.err << fmt::format("facetc: error: cannot create '{}': {}\n", args.out_dir, ec.message());
      return 1;
    }
  }
  Compiler compiler;
  nlohmann::json json_diagnostics = nlohmann::json::array();
  int exit_code = 0;
  auto strip = read_strip_inputs(args, console, json_diagnostics);
  if (!strip) {
    if (args.diagnostics_format == DiagnosticsFormat::json) console.err << json_diagnostics.dump(2) << "\n";
    return 1;
  }
  if (args.mode == Mode::merge) {
    exit_code = run_merge(args, console, json_diagnostics);
    if (args.diagnostics_format == DiagnosticsFormat::json) console.err << json_diagnostics.dump(2) << "\n";
    return exit_code;
  }
  if (args.mode == Mode::check) {
    exit_code = run_check(args, compiler, *strip, console, json_diagnostics);
    if (args.diagnostics_format == DiagnosticsFormat::json) console.err << json_diagnostics.dump(2) << "\n";
    return exit_code;
  }
  if (args.mode == Mode::report) {
    exit_code = run_report(args, compiler, *strip, console, json_diagnostics);
    if (args.diagnostics_format == DiagnosticsFormat::json) console.err << json_diagnostics.dump(2) << "\n";
    return exit_code;
  }
  if (std::count(args.inputs.begin(), args.inputs.end(), "-") > 1) {
    console.err << "facetc: error: standard input ('-') can be an input once\n";
    return 2;
  }
  std::vector<std::string> read_before;
  for (const std::string& input : args.inputs) {
    exit_code =
        std::max(exit_code, process_input(args, compiler, *strip, input, console, json_diagnostics, read_before));
  }
  if (args.diagnostics_format == DiagnosticsFormat::json) console.err << json_diagnostics.dump(2) << "\n";
  return exit_code;
}

}  // namespace facet::tools
