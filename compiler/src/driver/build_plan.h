// The driver's build, phase by phase: plan the stage programs, preprocess
// them (or read their include manifests), compile each distinct one once.
// Internal to compiler/src/driver.
#pragma once

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <map>
#include <string>
#include <tuple>
#include <vector>

#include "facet/cache.h"
#include "facet/compiler.h"

namespace facet::driver {

// The outcome of one stage program, shared by every variant that needs it:
// the compiled variant when `ok`, and how it was had.
struct StageEntry : CompiledVariant {
  bool ok = false;
  bool cache_hit = false;
  double seconds = 0;
  Diagnostics diags;
};

struct StageTask {
  size_t pass = 0;  // index into the selected passes
  Stage stage = Stage::vertex;
  std::vector<std::string> keywords;  // the keywords the stage sees
  uint64_t text_hash = 0;             // of the preprocessed tokens
  std::string cache_key;              // hex; set when preprocessing succeeded
  std::string manifest_key;           // hex, of its include manifest; set with a cache
  bool preprocessed = false;
  bool key_from_manifest = false;     // cache_key and text_hash came from the include manifest
  size_t compiled_by = SIZE_MAX;      // the task whose compile this one reuses (itself when first)
  StageEntry entry;
};

// The variants of each pass and, per (pass, stage, projected key), one task.
struct Plan {
  std::vector<variants::VariantSet> variant_sets;  // per selected pass
  std::vector<StageTask> tasks;
  // (pass, stage, projected key) -> task index
  std::map<std::tuple<size_t, Stage, variants::VariantKey>, size_t> task_of;
};

// What every phase reads.
struct BuildContext {
  const ir::Shader& shader;
  const CompileOptions& options;
  SourceMap& sources;
  const backend::Backend& backend;
  const std::vector<SelectedPass>& passes;
  const cache::CacheStores& stores;
  unsigned jobs = 1;
};

Plan plan_tasks(const std::vector<SelectedPass>& passes, std::vector<variants::VariantSet> variant_sets);

struct PreprocessCounters {
  uint64_t manifest_hits = 0;
  std::vector<std::string> cache_problems;  // include manifests that were found but not used, and why
};

// Preprocesses every task (or takes its key from a current include
// manifest) and sets its token hash and cache key.
PreprocessCounters preprocess_tasks(const BuildContext& ctx, Plan& plan);

// Preprocesses one task even though its include manifest was current: the
// manifest named another program's entry. Rewrites the manifest; false when
// preprocessing fails.
bool preprocess_again(const BuildContext& ctx, StageTask& t);

// Tasks whose preprocessed texts are equal compile to the same module: the
// first of them compiles, the others reuse it. Returns how many compile.
size_t assign_compilers(const std::vector<SelectedPass>& passes, std::vector<StageTask>& tasks);

// The tasks that compile (compiled_by == themselves), in plan order.
std::vector<size_t> compiling_tasks(const Plan& plan);

struct CompileCounters {
  uint64_t hits = 0, remote_hits = 0, corrupt = 0;
  std::vector<std::string> cache_problems;  // entries that were found but not used, and why; sorted
};

// Compiles the tasks `which` (or takes them from the cache) in parallel.
CompileCounters compile_tasks(const BuildContext& ctx, Plan& plan, const std::vector<size_t>& which);

unsigned worker_count(unsigned requested);

// Runs body(i) for i in [0, n) on `jobs` threads.
template <typename Body>
void parallel_for_each(size_t n, unsigned jobs, const Body& body) {
  if (jobs <= 1 || n <= 1) {
    for (size_t i = 0; i < n; ++i) body(i);
    return;
  }
  tbb::task_arena arena{int(jobs)};
  arena.execute([&] {
    tbb::parallel_for(tbb::blocked_range<size_t>(0, n, 1), [&](const tbb::blocked_range<size_t>& r) {
      for (size_t i = r.begin(); i != r.end(); ++i) body(i);
    }, tbb::simple_partitioner());
  });
}

}  // namespace facet::driver
