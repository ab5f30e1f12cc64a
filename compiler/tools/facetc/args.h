// facetc's command line: glslc's conventions where they apply (docs/cli.md).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "facet/backend.h"
#include "facet/diagnostics.h"
#include "facet/stage.h"

namespace facet::tools {

// What one run produces. Exactly one per run.
enum class Mode {
  package,        // default: every selected pass and variant -> .facetpkg
  preprocess,     // -E: preprocessed source of the selected variant(s)
  emit,           // -S / --emit=...: SPIR-V assembly, SPIR-V, GLSL, ESSL or MSL
  reflect,        // --reflect: reflection JSON
  list_variants,  // --list-variants: keyword sets, counts and every variant
  dump,           // --dump[=package|ast|ir|variants]
  depfile_only,   // -M: the make rule of every file the build reads, nothing else
  report,         // --report[=text|json|html]: the variant report of every input (docs/reports.md)
  merge,          // --merge: join the packages of --shard builds into one
  estimate,       // --estimate: what a build would take, from a timed sample
  emit_jobs,      // --emit-jobs=ninja|json: one build-farm job per distinct program, and the package job
  program,        // --program PASS:STAGE:KEYWORDS: one farm job, compiled into the cache
  check,          // --check: compile every shader of files and folders, a line each; no package (a CI linter)
};

enum class JobsFormat { ninja, json };

enum class ReportFormat { text, json, html };

// `source`: the text handed to glslang (prelude, keyword #defines, #line-mapped
// program), before its preprocessor runs.
enum class EmitKind { spirv_asm, spirv, glsl, essl, msl, source };
enum class DumpKind { package, ast, ir, variants };
enum class DiagnosticsFormat { text, json };

struct FacetcArgs {
  Mode mode = Mode::package;
  EmitKind emit = EmitKind::spirv_asm;
  DumpKind dump = DumpKind::package;
  ReportFormat report = ReportFormat::text;
  std::vector<std::string> material_files;  // --materials: material manifests (docs/reports.md)
  std::vector<std::string> strip_files;     // --strip: strip filters (docs/stripping.md)
  std::vector<std::string> variant_files;   // --variants: variant collections (docs/stripping.md)
  std::string scene;                        // --scene: build what this scene draws (scene_mode.h)
  std::string emit_strip_file;              // --report --emit-strip FILE: the summary's what-ifs as a strip filter
  std::vector<std::string> inputs;
  std::string output;      // -o; "-" is standard output; "" = the mode's default
  std::string out_dir;     // --out-dir
  std::vector<std::string> passes;   // --pass (repeatable)
  std::optional<Stage> stage;        // --stage
  std::optional<std::vector<std::string>> keywords;  // --keywords "A B"
  bool all_variants = false;
  bool strict_variants = false;
  bool build_unreachable = false;  // --build-unreachable
  uint64_t max_variants = 65536;
  backend::BackendOptions backend;   // -D -I -O -g --target-env --stdlib-dir
  WarningOptions warnings;           // -w -Werror -Wno-<group>
  DiagnosticsFormat diagnostics_format = DiagnosticsFormat::text;
  std::optional<bool> color;  // --color=always|never; nullopt (auto): when stderr is a terminal
  // Depfiles: -MD (beside the output), -MF FILE, -MT TARGET.
  bool write_depfile = false;
  std::string depfile;
  std::string dep_target;
  bool stats = false;
  unsigned jobs = 0;  // -j N; 0: one per core
  uint32_t shard_index = 0, shard_count = 1;  // --shard i/N
  JobsFormat jobs_format = JobsFormat::ninja;  // --emit-jobs
  std::string program;                         // --program PASS:STAGE:KW1,KW2
  std::vector<std::string> compile_flags;      // the options that shape compiled code, to pass on to jobs
  std::string facetc_path = "facetc";          // how jobs call facetc: this program's own path
  std::string cache_dir;  // --cache-dir, else $FACET_CACHE_DIR; "" (or --no-cache): none
  std::string cache_url;  // --remote-cache, else $FACET_REMOTE_CACHE; "" (or --no-cache): none
  std::string junit_file;  // --check --junit FILE: JUnit XML of the check
  std::string sarif_file;  // --check --sarif FILE: SARIF 2.1.0 of every diagnostic
};

// What parse_args decided: run with these arguments, or print `text` and
// exit with `exit_code` (--help and --version: 0 on stdout; usage errors: 2
// on stderr).
struct ParsedArgs {
  std::optional<FacetcArgs> args;
  std::string text;
  int exit_code = 0;
};

// glslc spells some options with one dash and several letters (-O0, -Os,
// -Werror, -Wno-x, -MD, -MF, -MT), which CLI11 reads as bundled short flags;
// this rewrites those spellings to their long forms first.
std::vector<std::string> normalize_args(const std::vector<std::string>& argv);

// argv without the program name.
ParsedArgs parse_args(const std::vector<std::string>& argv);

}  // namespace facet::tools
