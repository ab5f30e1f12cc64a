// facet's compiler library for engines: load a .shader (from disk or memory),
// pick passes and variants, compile them to SPIR-V with reflection, and get a
// Package plus diagnostics as data.
//
//   facet::Compiler compiler;
//   facet::SourceMap sources;
//   facet::Diagnostics diags;
//   auto shader = compiler.load("Lit.shader", sources, diags);
//   if (!shader) { std::cerr << facet::render_text(diags, sources); return 1; }
//   auto out = compiler.compile(*shader, {.keywords = {{"FOG_LINEAR"}}}, sources, diags);
//   // out->package.passes[i].variants[j].stages[k] -> SPIR-V + reflection
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "facet/backend.h"
#include "facet/cache.h"
#include "facet/diagnostics.h"
#include "facet/ir.h"
#include "facet/package.h"
#include "facet/package_file.h"
#include "facet/result.h"
#include "facet/source.h"
#include "facet/support/read_file.h"
#include "facet/variants.h"

namespace facet {

// The compiler's version string, e.g. "facet 0.1.0 (glslang 12, SPIRV-Cross ...)".
std::string version_string();
// Where the stdlib includes are: $FACET_STDLIB_DIR, else the source tree's
// stdlib/ for a build-tree binary, else the installed share/facet/stdlib.
std::string default_stdlib_dir();

// What a variant filter callback sees of one variant.
struct VariantInfo {
  const ir::Pass& pass;
  size_t pass_index = 0;                     // in the SubShader
  const std::vector<std::string>& keywords;  // enabled keywords, set order
};

struct CompileOptions {
  backend::BackendOptions backend;
  // Pass names (case-insensitive) or 0-based indices into the chosen
  // SubShader's passes; empty: every pass.
  std::vector<std::string> passes;
  // nullopt: every variant of each pass. Otherwise the one variant that
  // Unity's selection rule picks for these enabled keywords.
  std::optional<std::vector<std::string>> keywords;
  // With `keywords`: a keyword set that has no exact variant is an error.
  bool strict_selection = false;
  // Refuse to compile more variants than this for one pass (0: no limit).
  uint64_t max_variants_per_pass = 65536;
  // Also build the variants of Unity's shortcut keywords that facet's
  // renderer never enables (lightmaps, shadowmask, vertex lights); they are
  // counted and reported either way (facetc --build-unreachable).
  bool build_unreachable = false;
  // Worker threads (0: one per core; more than the cores: one per core). The package bytes do not depend on it.
  unsigned jobs = 0;
  // The compile cache folder (facet/cache.h); empty: no cache.
  std::string cache_dir;
  // A shared cache server (bazel-remote layout, facet/cache.h), e.g.
  // "http://cache:8080"; empty: none. With cache_dir too, the folder is
  // tried first and remote hits are copied into it.
  std::string cache_url;
  // Stripping (docs/stripping.md), applied after skip_variants and the
  // shader's keyword_rule pragmas: the keyword lists of the materials that
  // use the shader (the shader_feature rule made explicit; nullopt: every
  // combination), a declarative filter, and a callback in the manner of
  // Unity's IPreprocessShaders that returns false to strip a variant.
  std::optional<std::vector<variants::KeywordList>> materials;
  variants::StripFilter strip;
  std::function<bool(const VariantInfo&)> variant_filter;
  // Build only shard `shard_index` of `shard_count` (facetc --shard i/N):
  // every N-th variant over the passes in order, so that the shards' packages
  // merge (package::merge_packages) into the unsharded package.
  uint32_t shard_index = 0;
  uint32_t shard_count = 1;
  // Called as programs finish (done, total), from worker threads but never
  // two at once; for progress bars.
  std::function<void(uint64_t done, uint64_t total)> progress;
};

// What a compile did, rung by rung of the dedupe ladder.
struct CompileStats {
  uint64_t passes = 0;
  uint64_t variants = 0;            // variants in the package
  uint64_t variants_stripped = 0;   // by keyword_rule pragmas, the strip filter and the callback
  uint64_t stage_programs = 0;      // (pass, stage, keywords the stage sees) programs needed
  uint64_t unique_preprocessed = 0; // distinct preprocessed texts among them: compiled once each
  uint64_t unique_spirv = 0;        // distinct SPIR-V blobs stored
  uint64_t cache_hits = 0;          // unique programs served by the cache
  uint64_t cache_remote_hits = 0;   // of cache_hits, served by the cache server
  uint64_t cache_corrupt = 0;       // cache entries that failed their checks (recompiled)
  uint64_t preprocess_skipped = 0;  // programs whose include manifest was current (direct mode)
  uint64_t compiled = 0;            // unique programs glslang compiled
  unsigned jobs = 0;                // worker threads used
  double seconds = 0;
  // Where `seconds` went: choosing passes and variants, preprocessing (or
  // checking include manifests), compiling (or loading from the cache),
  // and assembling, deduplicating and checking the package.
  struct Phases {
    double select = 0, preprocess = 0, compile = 0, assemble = 0;
  } phases;
};

// One stage program the variants needed (a pass, a stage and the keywords
// that stage sees), and what became of it. For reports and tools.
struct ProgramRecord {
  uint32_t pass = 0;  // index into Package::passes
  Stage stage = Stage::vertex;
  std::vector<std::string> keywords;  // the keywords the stage sees, set order
  uint64_t token_hash = 0;            // of its relevant preprocessed tokens; 0 when preprocessing failed
  bool compiled = false;              // first of its tokens: glslang (or the cache) produced it
  bool cache_hit = false;
  double seconds = 0;                 // compile (or cache lookup) time, when `compiled`
  uint32_t blob = UINT32_MAX;         // its SPIR-V in Package::spirv_blobs
};

// What a build would cost, known before it runs: every program is
// preprocessed (cheap), and an evenly spread sample of the distinct ones is
// compiled and timed.
struct BuildEstimate {
  uint64_t variants = 0;
  uint64_t programs = 0;          // stage programs the variants need
  uint64_t unique = 0;            // distinct after preprocessing: what a build compiles
  uint64_t sampled = 0;           // how many of those were compiled to measure
  double preprocess_seconds = 0;  // wall time of preprocessing everything
  double seconds_per_program = 0; // mean compile time of the sample, one thread
  double estimated_seconds = 0;   // preprocess + unique x mean / threads
  unsigned jobs = 0;
};

// Programs an estimate compiles and times.
inline constexpr size_t kEstimateSample = 16;

struct CompiledShader {
  package::Package package;
  std::vector<std::string> dependencies;  // the .shader and every included file, sorted
  CompileStats stats;
  std::vector<ProgramRecord> programs;    // in pass, then first-use order
  // What estimate_build would have said before this build, worked out
  // from the build's own preprocessing time and the compile times of the
  // same evenly spread sample (so a report shows the estimate beside the
  // result without preprocessing twice). nullopt: every program came from
  // the cache.
  std::optional<BuildEstimate> estimate;
};

// A pass chosen for compilation: where it is in the IR and its keyword space.
struct SelectedPass {
  size_t subshader = 0;
  size_t pass = 0;
  ir::Pass ir;  // the pass compiled: the selected pass, or the one its UsePass names
  variants::KeywordSpace keywords;
};

// A loaded shader with the messages of loading and the source map they point
// into: what Compiler::open_file/open_source return, so that nothing has to
// be threaded through the calls. `shader` is empty when loading failed.
struct OpenedShader {
  std::optional<ir::Shader> shader;
  SourceMap sources;
  Diagnostics diagnostics;

  bool ok() const { return shader.has_value(); }
  // The messages as facetc prints them (file:line:col, the line, a caret, notes).
  std::string messages(const RenderOptions& options = {}) const;
};

// The outcome of a whole build: the package when it succeeded, and always the
// messages of loading and compiling with their source map (warnings come
// with a success). Compare shaderc's CompilationResult.
struct BuildResult {
  std::optional<CompiledShader> compiled;
  SourceMap sources;
  Diagnostics diagnostics;

  bool ok() const { return compiled.has_value(); }
  std::string messages(const RenderOptions& options = {}) const;
  std::string messages_json() const;  // as facetc --diagnostics-format=json
};

class Compiler {
 public:
  Compiler() = default;

  // ---- one call each: the results own their messages ----
  // Loads a file (or an in-memory text that `path` names) with the include
  // paths and defines of `options.backend`.
  OpenedShader open_file(const std::string& path, const CompileOptions& options = {}) const;
  OpenedShader open_source(const std::string& path, std::string text, const CompileOptions& options = {}) const;
  // Compiles what open_* loaded; the load's messages come first.
  BuildResult build(OpenedShader loaded, const CompileOptions& options = {}) const;
  // open_file + build.
  BuildResult build_file(const std::string& path, const CompileOptions& options = {}) const;
  BuildResult build_source(const std::string& path, std::string text, const CompileOptions& options = {}) const;

  // ---- the steps, for tools that keep one SourceMap and Diagnostics across calls ----

  // Reads and parses a file. Refuses binary files and files over 64 MiB.
  // Surface shaders are lowered into their generated passes here (facet/surface.h);
  // `options.backend` gives the include paths and defines their code is read with.
  Result<ir::Shader> load(const std::string& path, SourceMap& sources, Diagnostics& diags,
                          const CompileOptions& options = {}) const;
  // Parses an in-memory text; `path` names it in diagnostics and anchors
  // relative #includes.
  Result<ir::Shader> load_source(const std::string& path, std::string text, SourceMap& sources, Diagnostics& diags,
                                 const CompileOptions& options = {}) const;

  // The passes `options.passes` names (all by default) of the SubShader in
  // use, with their keyword spaces.
  Result<std::vector<SelectedPass>> select_passes(const ir::Shader& shader, const CompileOptions& options,
                                                  Diagnostics& diags) const;

  // The variants of one pass that `options` asks for, after stripping (the
  // set says how many were stripped).
  Result<variants::VariantSet> select_variants(const SelectedPass& pass, const CompileOptions& options,
                                               Diagnostics& diags) const;

  // Compiles the selected passes and variants into a package. Identical
  // messages from many variants are merged ("in 12 of 48 variants").
  Result<CompiledShader> compile(const ir::Shader& shader, const CompileOptions& options, SourceMap& sources,
                                 Diagnostics& diags) const;


 private:
  friend struct CompilerInternals;  // the build-farm calls of facet/build_farm.h
  backend::Backend backend_;
  std::shared_ptr<cache::RemoteServers> remote_servers_ = std::make_shared<cache::RemoteServers>();
};

// The input size limit of a .shader and of each file it includes (a
// package's is kMaxPackageBytes, facet/package_file.h).
inline constexpr uint64_t kMaxShaderBytes = 64ull << 20;

// Writes `bytes` to `path` through a temporary file and a rename, so that a
// failure never leaves a partial file behind.
Result<void> write_file_atomically(const std::string& path, std::string_view bytes, Diagnostics& diags);

}  // namespace facet
