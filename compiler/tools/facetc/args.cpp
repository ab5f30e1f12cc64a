// facetc's command line, parsed by CLI11 (the one place its exceptions are caught).
#include "args.h"

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <sstream>

#include "facet/compiler.h"

namespace facet::tools {
namespace {

// Everything CLI11 binds to before it is checked and turned into FacetcArgs.
struct RawArgs {
  std::vector<std::string> inputs, defines, include_dirs, passes, keywords, disabled_groups;
  std::string output, out_dir, opt = "performance", target_env = "vulkan1.1", emit, dump, stage, report;
  std::vector<std::string> material_files, strip_files, variant_files;
  std::string scene;
  std::string diagnostics_format = "text", color = "auto", depfile, dep_target, stdlib_dir;
  bool preprocess = false, assemble = false, reflect = false, list_variants = false, debug_info = false;
  bool all_variants = false, strict_variants = false, no_warnings = false, werror = false;
  bool build_unreachable = false;
  bool depfile_only = false, write_depfile = false, stats = false, version = false;
  uint64_t max_variants = 65536;
  unsigned jobs = 0;
  std::string cache_dir, cache_url, shard;
  bool merge = false, estimate = false;
  std::string emit_jobs, program;
  bool no_cache = false;
  std::string unity_version;
  bool check = false;
  std::string junit, sarif, emit_strip;
  // Input limits (docs/cli.md): sizes as N, NK, NM or NG; "" keeps the default.
  std::string max_includes, max_include_bytes, max_preprocessed_bytes, max_unroll, time_limit;
};

// Repeatable options take one value per occurrence (allow_extra_args(false)),
// so `-I dir shader.shader` leaves the shader as an input.
void add_options(CLI::App& app, RawArgs& raw) {
  app.add_option("inputs", raw.inputs, ".shader files (or .facetpkg files with --dump)");
  app.add_option("-o", raw.output, "output file; '-' is standard output");
  app.add_option("--out-dir", raw.out_dir, "folder for the packages of several inputs");
  app.add_option("-D", raw.defines, "define a macro: NAME or NAME=VALUE")->allow_extra_args(false);
  app.add_option("-I", raw.include_dirs, "add a folder to the #include search path")->allow_extra_args(false);
  app.add_option("--opt", raw.opt, "optimisation (also -O, -Os, -O0)")
      ->check(CLI::IsMember({"performance", "size", "none"}));
  app.add_flag("-g", raw.debug_info, "keep debug information in the SPIR-V");
  app.add_option("--target-env", raw.target_env, "vulkan1.1 (default), vulkan1.2 or opengl4.5")
      ->check(CLI::IsMember({"vulkan1.1", "vulkan1.2", "opengl4.5"}));
  app.add_option("--stdlib-dir", raw.stdlib_dir, "the stdlib folder (default: the built-in one)");
  app.add_option("--unity-version", raw.unity_version, "the Unity version to define UNITY_VERSION for, e.g. 2017.4 "
                                                       "(default 2019.4)");
  app.add_flag("-E", raw.preprocess, "print the preprocessed source of the selected variant");
  app.add_flag("-S", raw.assemble, "print SPIR-V assembly (or --emit's kind) instead of a package");
  app.add_option("--emit", raw.emit, "spirv-asm, spirv, glsl, essl, msl, or source (before preprocessing; implies -S)")
      ->check(CLI::IsMember({"spirv-asm", "spirv", "glsl", "essl", "msl", "source"}));
  app.add_flag("--reflect", raw.reflect, "print the reflection of the selected variant as JSON");
  app.add_flag("--list-variants", raw.list_variants, "print keyword sets, counts and every variant");
  app.add_option("--dump", raw.dump, "print as JSON: package (default), ast, ir or variants")
      ->check(CLI::IsMember({"package", "ast", "ir", "variants"}));
  app.add_option("--report", raw.report, "the variant report of every input: text (default), json or html")
      ->check(CLI::IsMember({"text", "json", "html"}));
  app.add_option("--materials", raw.material_files,
                 "a material manifest (JSON): only the shader_feature combinations its materials use")
      ->allow_extra_args(false);
  app.add_option("--strip", raw.strip_files, "a strip filter (JSON): deny/allow/always_on/always_off rules")
      ->allow_extra_args(false);
  app.add_option("--scene", raw.scene,
                 "render the scene (facet render) and build a package of each .shader it names holding exactly the "
                 "passes and variants it draws, into --out-dir, with the collection as <scene>.variants.json");
  app.add_option("--variants", raw.variant_files,
                 "a variant collection (JSON, as facet render --emit-variants writes it): only the passes and keyword "
                 "sets it lists")
      ->allow_extra_args(false);
  app.add_option("--emit-strip", raw.emit_strip,
                 "with --report: write the strip filter that applies the summary's what-ifs to FILE");
  app.add_option("--pass", raw.passes, "a pass by name (case-insensitive) or 0-based index; repeatable")->allow_extra_args(false);
  app.add_option("--stage", raw.stage, "vertex, fragment, geometry, hull or domain");
  app.add_option("--keywords", raw.keywords, "enabled keywords, e.g. \"FOG_LINEAR _EMISSION\"")->allow_extra_args(false);
  app.add_flag("--all-variants", raw.all_variants, "every variant (the default for packages)");
  app.add_flag("--strict-variants", raw.strict_variants, "a keyword set without its exact variant is an error");
  app.add_flag("--build-unreachable", raw.build_unreachable,
               "also build variants of shortcut keywords facet's renderer never enables (lightmaps, ...)");
  app.add_option("--max-variants", raw.max_variants, "refuse passes with more variants (0: no limit)");
  app.add_option("--max-includes", raw.max_includes, "#includes one program may follow (default 4096; 0: no limit)");
  app.add_option("--max-include-bytes", raw.max_include_bytes,
                 "bytes of one program's included files together (default 64M; 0: no limit)");
  app.add_option("--max-preprocessed-bytes", raw.max_preprocessed_bytes,
                 "bytes of one program after macro expansion (default 64M; 0: no limit)");
  app.add_option("--max-unroll", raw.max_unroll, "iterations of one [unroll] loop (default 4096; 0: no limit)");
  app.add_option("--time-limit", raw.time_limit, "seconds one stage may take to compile (default 60; 0: no limit)");
  app.add_flag("-w", raw.no_warnings, "suppress every warning");
  app.add_flag("--Werror", raw.werror, "treat warnings as errors (also --Werror)");
  app.add_option("--Wno", raw.disabled_groups, "switch the warning group <group> off (also --Wno <group>)")->allow_extra_args(false);
  app.add_option("--diagnostics-format", raw.diagnostics_format, "text (default) or json")
      ->check(CLI::IsMember({"text", "json"}));
  app.add_option("--color", raw.color, "auto (default), always or never")
      ->check(CLI::IsMember({"auto", "always", "never"}));
  app.add_flag("-M", raw.depfile_only, "print the make rule of the files the build reads; build nothing");
  app.add_flag("--MD", raw.write_depfile, "also write a depfile (also --MD)");
  app.add_option("--MF", raw.depfile, "the depfile's path (also --MF)");
  app.add_option("--MT", raw.dep_target, "the depfile rule's target (also --MT)");
  app.add_option("-j,--jobs", raw.jobs, "worker threads (default: one per core); output does not depend on it");
  app.add_option("--shard", raw.shard, "build shard i of N (every N-th variant), e.g. 0/4; join with --merge");
  app.add_option("--emit-jobs", raw.emit_jobs, "write a ninja file (or JSON) with one job per distinct program")
      ->check(CLI::IsMember({"ninja", "json"}));
  app.add_option("--program", raw.program, "compile one program (PASS:STAGE:KW1,KW2) into the cache: a farm job");
  app.add_flag("--estimate", raw.estimate, "estimate the build's time from a timed sample, before building");
  app.add_flag("--merge", raw.merge, "join the .facetpkg files of --shard builds into the package of -o");
  app.add_option("--cache-dir", raw.cache_dir, "the compile cache folder (default: $FACET_CACHE_DIR, else none)");
  app.add_option("--remote-cache", raw.cache_url,
                 "a shared cache server, bazel-remote HTTP layout (default: $FACET_REMOTE_CACHE)");
  app.add_flag("--no-cache", raw.no_cache, "neither read nor write the compile cache");
  app.add_flag("--check", raw.check, "compile every .shader of the files and folders given, one line each; "
                                      "write no package (a CI linter)");
  app.add_option("--junit", raw.junit, "with --check: write a JUnit XML report to FILE");
  app.add_option("--sarif", raw.sarif, "with --check: write a SARIF 2.1.0 report to FILE");
  app.add_flag("--stats", raw.stats, "print passes, variants and SPIR-V counts per input");
  app.add_flag("--version", raw.version, "print the version and exit");
}

// The options that shape what is compiled, spelled for a job's command line.
std::vector<std::string> compile_flags(const RawArgs& raw) {
  std::vector<std::string> flags;
  for (const std::string& d : raw.defines) flags.push_back("-D" + d);
  for (const std::string& i : raw.include_dirs) flags.insert(flags.end(), {"-I", i});
  flags.push_back("--opt=" + raw.opt);
  flags.push_back("--target-env=" + raw.target_env);
  if (raw.debug_info) flags.push_back("-g");
  if (!raw.stdlib_dir.empty()) flags.insert(flags.end(), {"--stdlib-dir", raw.stdlib_dir});
  if (!raw.unity_version.empty()) flags.insert(flags.end(), {"--unity-version", raw.unity_version});
  for (const auto& [name, value] : {std::pair{"--max-includes", &raw.max_includes},
                                    std::pair{"--max-include-bytes", &raw.max_include_bytes},
                                    std::pair{"--max-preprocessed-bytes", &raw.max_preprocessed_bytes},
                                    std::pair{"--max-unroll", &raw.max_unroll}, std::pair{"--time-limit", &raw.time_limit}}) {
    if (!value->empty()) flags.insert(flags.end(), {name, *value});
  }
  if (!raw.no_cache && !raw.cache_dir.empty()) flags.insert(flags.end(), {"--cache-dir", raw.cache_dir});
  if (!raw.no_cache && !raw.cache_url.empty()) flags.insert(flags.end(), {"--remote-cache", raw.cache_url});
  return flags;
}

std::vector<std::string> split_keywords(const std::vector<std::string>& lists) {
  std::vector<std::string> out;
  for (const std::string& list : lists) {
    std::string word;
    std::istringstream in(list);
    while (in >> word) {
      for (size_t comma; (comma = word.find(',')) != std::string::npos;) {
        if (comma > 0) out.push_back(word.substr(0, comma));
        word.erase(0, comma + 1);
      }
      if (!word.empty()) out.push_back(word);
    }
  }
  return out;
}

std::optional<std::string> apply_defines(const RawArgs& raw, backend::BackendOptions& options) {
  for (const std::string& d : raw.defines) {
    auto eq = d.find('=');
    std::string name = d.substr(0, eq);
    if (name.empty()) return fmt::format("-D needs a macro name, got '{}'", d);
    options.defines.emplace_back(name, eq == std::string::npos ? "1" : d.substr(eq + 1));
  }
  return std::nullopt;
}

// "2017.4" -> 201740, "2019.4.31" -> 201949 (the patch digit saturates, as
// one decimal digit holds it), "6000.0" -> 600000: Unity's UNITY_VERSION.
std::optional<std::string> apply_unity_version(const std::string& text, backend::BackendOptions& options) {
  if (text.empty()) return std::nullopt;
  unsigned major = 0, minor = 0, patch = 0;
  char tail = 0;
  int n = std::sscanf(text.c_str(), "%u.%u.%u%c", &major, &minor, &patch, &tail);
  bool ok = (n == 2 || n == 3) && text.find_first_not_of("0123456789.") == std::string::npos && major >= 5 &&
            major <= 99999 && minor <= 9;
  if (!ok) return fmt::format("--unity-version needs a version such as 2017.4 or 2019.4.1, got '{}'", text);
  options.unity_version = int(major * 100 + minor * 10 + std::min(patch, 9u));
  return std::nullopt;
}

// "4096", "64K", "64M", "1G" (binary multiples) -> a count; nullopt when malformed.
std::optional<uint64_t> parse_amount(const std::string& text) {
  if (text.empty() || !std::isdigit(static_cast<unsigned char>(text[0]))) return std::nullopt;
  size_t digits = std::min(text.find_first_not_of("0123456789"), text.size());
  std::string suffix = text.substr(digits);
  int shift = suffix.empty() ? 0 : suffix == "K" || suffix == "k" ? 10 : suffix == "M" || suffix == "m" ? 20
                                   : suffix == "G" || suffix == "g" ? 30 : -1;
  if (shift < 0 || digits > 12) return std::nullopt;
  uint64_t value = std::stoull(text.substr(0, digits));
  if (value > (uint64_t(1) << (62 - shift))) return std::nullopt;
  return value << shift;
}

std::optional<std::string> apply_limits(const RawArgs& raw, backend::InputLimits& limits) {
  struct Limit {
    const char* name;
    const std::string& text;
    uint64_t* value;
  };
  uint64_t time_limit = limits.time_limit_s;
  for (const Limit& l : {Limit{"--max-includes", raw.max_includes, &limits.max_includes},
                         Limit{"--max-include-bytes", raw.max_include_bytes, &limits.max_include_bytes},
                         Limit{"--max-preprocessed-bytes", raw.max_preprocessed_bytes, &limits.max_preprocessed_bytes},
                         Limit{"--max-unroll", raw.max_unroll, &limits.max_unroll},
                         Limit{"--time-limit", raw.time_limit, &time_limit}}) {
    if (l.text.empty()) continue;
    std::optional<uint64_t> value = parse_amount(l.text);
    if (!value) return fmt::format("{} takes a number such as 4096, 64K, 64M or 1G (0: no limit), got '{}'", l.name, l.text);
    *l.value = *value;
  }
  if (time_limit > 1000000) return fmt::format("--time-limit takes seconds, at most 1000000, got '{}'", raw.time_limit);
  limits.time_limit_s = uint32_t(time_limit);
  return std::nullopt;
}

std::optional<std::string> choose_mode(const RawArgs& raw, FacetcArgs& args) {
  std::vector<std::pair<bool, Mode>> modes = {
      {raw.preprocess, Mode::preprocess},       {raw.assemble || !raw.emit.empty(), Mode::emit},
      {raw.reflect, Mode::reflect},             {raw.list_variants, Mode::list_variants},
      {!raw.dump.empty(), Mode::dump},          {raw.depfile_only, Mode::depfile_only},
      {!raw.report.empty(), Mode::report},     {raw.merge, Mode::merge},
      {raw.estimate, Mode::estimate},          {!raw.emit_jobs.empty(), Mode::emit_jobs},
      {!raw.program.empty(), Mode::program},   {raw.check, Mode::check}};
  int chosen = 0;
  for (auto [on, mode] : modes) {
    if (on) {
      args.mode = mode;
      ++chosen;
    }
  }
  if (chosen > 1) {
    return "-E, -S/--emit, --reflect, --list-variants, --dump, --report, --merge, --estimate, --emit-jobs, --program, "
           "--check and -M exclude each other";
  }
  args.report = raw.report == "json" ? ReportFormat::json : raw.report == "html" ? ReportFormat::html
                                                                                   : ReportFormat::text;
  static const std::map<std::string, EmitKind> emits = {{"", EmitKind::spirv_asm},
      {"spirv-asm", EmitKind::spirv_asm}, {"spirv", EmitKind::spirv}, {"glsl", EmitKind::glsl},
      {"essl", EmitKind::essl}, {"msl", EmitKind::msl}, {"source", EmitKind::source}};
  static const std::map<std::string, DumpKind> dumps = {{"", DumpKind::package}, {"package", DumpKind::package},
      {"ast", DumpKind::ast}, {"ir", DumpKind::ir}, {"variants", DumpKind::variants}};
  args.emit = emits.at(raw.emit);
  args.dump = dumps.at(raw.dump);
  return std::nullopt;
}

// Two spellings of one path ("r.json", "./r.json"), whether or not it exists.
bool same_path(const std::string& a, const std::string& b) {
  std::error_code ec;
  return std::filesystem::weakly_canonical(a, ec) == std::filesystem::weakly_canonical(b, ec);
}

std::optional<std::string> check_consistency(const RawArgs& raw, const FacetcArgs& args) {
  if (!raw.scene.empty()) {
    if (args.mode != Mode::package) return "--scene builds packages; it goes with no other mode";
    if (!args.inputs.empty()) return "--scene names the shaders to build; give no input files with it";
    if (!args.output.empty()) return "--scene builds a package per shader; name their folder with --out-dir";
    if (!raw.variant_files.empty() || !raw.passes.empty() || !raw.keywords.empty() || raw.all_variants) {
      return "--scene chooses the passes and variants; give no --variants, --pass, --keywords or --all-variants";
    }
    if (args.shard_count > 1 || !raw.depfile.empty()) return "--scene takes no --shard or -MF";
    return std::nullopt;
  }
  if (args.inputs.empty()) return "no input files";
  if (!args.output.empty() && args.output != "-" && args.inputs.size() > 1 && args.mode != Mode::report &&
      args.mode != Mode::merge && args.mode != Mode::check) {
    return "-o names one output file; give one input (or --out-dir for the packages of several)";
  }
  if (!args.out_dir.empty() && args.mode != Mode::package) return "--out-dir is for packages";
  bool strips = args.mode == Mode::package || args.mode == Mode::report || args.mode == Mode::depfile_only ||
                args.mode == Mode::check || args.mode == Mode::estimate ||
                (args.mode == Mode::dump && args.dump == DumpKind::package);
  if ((!raw.material_files.empty() || !raw.strip_files.empty() || !raw.variant_files.empty()) && !strips) {
    return "--materials, --strip and --variants apply to packages, --report, --estimate and --check";
  }
  if (!raw.variant_files.empty() && !raw.passes.empty()) {
    return "--variants chooses the passes to build; give no --pass with it";
  }
  if (!raw.emit_strip.empty() && args.mode != Mode::report) return "--emit-strip goes with --report";
  if (!raw.emit_strip.empty() && !args.output.empty() && same_path(raw.emit_strip, args.output)) {
    return "--emit-strip and -o name the same file";
  }
  if ((!raw.junit.empty() || !raw.sarif.empty()) && args.mode != Mode::check) {
    return "--junit and --sarif go with --check";
  }
  if (args.mode == Mode::check && !args.output.empty()) {
    return "--check writes no output; name its reports with --junit and --sarif";
  }
  if (!raw.junit.empty() && raw.junit == raw.sarif) return "--junit and --sarif name the same file";
  if (args.mode == Mode::report && (raw.write_depfile || args.keywords)) {
    return "--report covers every variant; -MD and --keywords do not apply";
  }
  if (!args.output.empty() && !args.out_dir.empty()) return "-o and --out-dir exclude each other";
  if (args.mode == Mode::emit && args.emit == EmitKind::spirv && args.output.empty()) {
    return "--emit=spirv writes binary SPIR-V; name the file with -o (or '-o -' for standard output)";
  }
  if (raw.all_variants && !raw.keywords.empty()) return "--keywords selects one variant; --all-variants every one";
  if ((!raw.depfile.empty() || !raw.dep_target.empty()) && !raw.write_depfile && !raw.depfile_only) {
    return "-MF and -MT need -M or -MD";
  }
  if (raw.write_depfile && args.mode != Mode::package && args.mode != Mode::emit && args.mode != Mode::reflect &&
      args.mode != Mode::preprocess && args.mode != Mode::program) {
    return "-MD goes with an output: a package, -E, -S or --reflect";
  }
  if (raw.write_depfile && raw.depfile.empty() && (args.output.empty() || args.output == "-") &&
      args.mode != Mode::package) {
    return "-MD writes <output>.d; name the output with -o or the depfile with -MF";
  }
  if (!raw.depfile.empty() && args.inputs.size() > 1) return "-MF names one depfile; give one input";
  if (args.mode == Mode::merge && (args.output.empty() || args.output == "-")) return "--merge writes the file -o names";
  if (args.shard_count > 1 && args.mode != Mode::package) return "--shard applies to package builds";
  if ((args.mode == Mode::emit_jobs || args.mode == Mode::program) && args.cache_dir.empty() &&
      args.cache_url.empty()) {
    return "farm jobs hand their results over through the cache: give --cache-dir or --remote-cache";
  }
  if ((args.mode == Mode::emit_jobs || args.mode == Mode::program) && args.inputs.size() != 1) {
    return "--emit-jobs and --program take one shader";
  }
  return std::nullopt;
}

Result<FacetcArgs> build(const RawArgs& raw, std::string& error) {
  FacetcArgs args;
  args.inputs = raw.inputs;
  args.output = raw.output;
  args.out_dir = raw.out_dir;
  args.passes = raw.passes;
  args.all_variants = raw.all_variants;
  args.strict_variants = raw.strict_variants;
  args.build_unreachable = raw.build_unreachable;
  args.max_variants = raw.max_variants;
  args.stats = raw.stats;
  args.material_files = raw.material_files;
  args.strip_files = raw.strip_files;
  args.variant_files = raw.variant_files;
  args.scene = raw.scene;
  args.emit_strip_file = raw.emit_strip;
  args.jobs_format = raw.emit_jobs == "json" ? JobsFormat::json : JobsFormat::ninja;
  args.program = raw.program;
  args.compile_flags = compile_flags(raw);
  args.jobs = raw.jobs;
  args.junit_file = raw.junit;
  args.sarif_file = raw.sarif;
  if (!raw.no_cache) {
    const char* env = std::getenv("FACET_CACHE_DIR");
    args.cache_dir = !raw.cache_dir.empty() ? raw.cache_dir : env ? env : "";
    const char* remote = std::getenv("FACET_REMOTE_CACHE");
    args.cache_url = !raw.cache_url.empty() ? raw.cache_url : remote ? remote : "";
  }
  if (!raw.keywords.empty()) args.keywords = split_keywords(raw.keywords);
  if (!raw.shard.empty()) {
    unsigned i = 0, n = 0;
    char slash = 0;
    std::istringstream in(raw.shard);
    if (!(in >> i >> slash >> n) || slash != '/' || n == 0 || i >= n || !in.eof()) {
      error = "--shard takes i/N with 0 <= i < N, e.g. 0/4";
    }
    args.shard_index = i;
    args.shard_count = n == 0 ? 1 : n;
  }
  if (!raw.stage.empty()) {
    args.stage = parse_stage(raw.stage);
    if (!args.stage) error = fmt::format("unknown stage '{}'; use vertex, fragment, geometry, hull or domain", raw.stage);
  }
  static const std::map<std::string, backend::OptLevel> opts = {{"performance", backend::OptLevel::performance},
      {"size", backend::OptLevel::size}, {"none", backend::OptLevel::none}};
  static const std::map<std::string, backend::TargetEnv> envs = {{"vulkan1.1", backend::TargetEnv::vulkan1_1},
      {"vulkan1.2", backend::TargetEnv::vulkan1_2}, {"opengl4.5", backend::TargetEnv::opengl4_5}};
  args.backend.opt = opts.at(raw.opt);
  args.backend.target = envs.at(raw.target_env);
  args.backend.debug_info = raw.debug_info;
  args.backend.include_dirs = raw.include_dirs;
  args.backend.stdlib_dir = raw.stdlib_dir;
  args.warnings = {.suppress_all = raw.no_warnings, .warnings_as_errors = raw.werror,
                   .disabled_groups = raw.disabled_groups};
  args.diagnostics_format = raw.diagnostics_format == "json" ? DiagnosticsFormat::json : DiagnosticsFormat::text;
  if (raw.color != "auto") args.color = raw.color == "always";
  args.write_depfile = raw.write_depfile;
  args.depfile = raw.depfile;
  args.dep_target = raw.dep_target;
  if (error.empty()) {
    if (auto e = apply_defines(raw, args.backend)) error = *e;
  }
  if (error.empty()) {
    if (auto e = apply_unity_version(raw.unity_version, args.backend)) error = *e;
  }
  if (error.empty()) {
    if (auto e = apply_limits(raw, args.backend.limits)) error = *e;
  }
  if (error.empty()) {
    if (auto e = choose_mode(raw, args)) error = *e;
  }
  if (error.empty()) {
    if (auto e = check_consistency(raw, args)) error = *e;
  }
  if (!error.empty()) return failure(error);
  return args;
}

}  // namespace

std::vector<std::string> normalize_args(const std::vector<std::string>& argv) {
  static const std::map<std::string, std::string> spelled = {
      {"-O", "--opt=performance"}, {"-Os", "--opt=size"}, {"-O0", "--opt=none"}, {"-O1", "--opt=performance"},
      {"-O2", "--opt=performance"}, {"-O3", "--opt=performance"}, {"-Werror", "--Werror"},
      {"-MD", "--MD"}, {"-MF", "--MF"}, {"-MT", "--MT"}, {"--dump", "--dump=package"},
      {"--report", "--report=text"}};
  std::vector<std::string> out;
  bool after_double_dash = false;
  for (const std::string& a : argv) {
    if (after_double_dash) {
      out.push_back(a);
    } else if (a == "--") {
      after_double_dash = true;
      out.push_back(a);
    } else if (auto it = spelled.find(a); it != spelled.end()) {
      out.push_back(it->second);
    } else if (a.starts_with("-Wno-") && a.size() > 5) {
      out.push_back("--Wno=" + a.substr(5));
    } else {
      out.push_back(a);
    }
  }
  return out;
}

namespace {

// --help names the options glslc spells with one dash as glslc prints them
// (-MD, -MF FILE, -Werror, -Wno-<group>); both spellings are accepted.
std::string with_glslc_spellings(const std::string& help) {
  static const std::pair<std::string_view, std::string_view> spellings[] = {
      {"--Werror", "-Werror"}, {"--Wno TEXT ...", "-Wno-<group>"}, {"--MD", "-MD"},
      {"--MF TEXT", "-MF FILE"}, {"--MT TEXT", "-MT TARGET"}};
  std::string out;
  size_t pos = 0;
  while (pos < help.size()) {
    size_t eol = help.find('\n', pos);
    std::string line = help.substr(pos, eol == std::string::npos ? std::string::npos : eol - pos + 1);
    pos = eol == std::string::npos ? help.size() : eol + 1;
    for (auto [cli11, glslc] : spellings) {
      std::string name = "  " + std::string(cli11);
      if (!line.starts_with(name) || (line.size() > name.size() && line[name.size()] != ' ')) continue;
      size_t description = line.find_first_not_of(' ', name.size());
      if (description == std::string::npos || description < glslc.size() + 3) break;
      line = "  " + std::string(glslc) + std::string(description - 2 - glslc.size(), ' ') + line.substr(description);
      break;
    }
    out += line;
  }
  return out;
}

}  // namespace

ParsedArgs parse_args(const std::vector<std::string>& argv) {
  CLI::App app{"facetc: compiles ShaderLab .shader files to SPIR-V packages (see docs/cli.md)", "facetc"};
  app.get_formatter()->column_width(28);
  RawArgs raw;
  add_options(app, raw);
  std::vector<std::string> reversed = normalize_args(argv);
  std::reverse(reversed.begin(), reversed.end());
  try {
    app.parse(reversed);
  } catch (const CLI::CallForHelp&) {
    return {.text = with_glslc_spellings(app.help()), .exit_code = 0};
  } catch (const CLI::ParseError& e) {
    return {.text = fmt::format("facetc: error: {}\n(run 'facetc --help' for the options)\n", e.what()),
            .exit_code = 2};
  }
  if (raw.version) return {.text = version_string() + "\n", .exit_code = 0};
  std::string error;
  Result<FacetcArgs> args = build(raw, error);
  if (!args) {
    return {.text = fmt::format("facetc: error: {}\n(run 'facetc --help' for the options)\n", args.error().reason),
            .exit_code = 2};
  }
  return {.args = std::move(*args)};
}

}  // namespace facet::tools
