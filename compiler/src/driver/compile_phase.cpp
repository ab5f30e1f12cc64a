// Phase 2: compile each distinct stage program once, or take it from the cache.
#include <fmt/format.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <mutex>
#include <thread>

#include "build_plan.h"

namespace facet::driver {
namespace {

std::string pass_label(const ir::Pass& pass, size_t index) {
  std::string name = pass.name.empty() ? fmt::format("#{}", index) : fmt::format("'{}'", pass.name);
  std::string light_mode = pass.tag("LightMode");
  return light_mode.empty() ? name : fmt::format("{} ({})", name, light_mode);
}

void add_variant_context(Diagnostics& diags, const std::string& pass, Stage stage,
                         const std::vector<std::string>& keywords) {
  std::string kw = keywords.empty() ? "none" : fmt::format("{}", fmt::join(keywords, " "));
  for (Diagnostic& d : diags.mutable_all()) {
    if (d.severity == Severity::note) continue;
    d.note({}, fmt::format("while compiling pass {}, {} stage, keywords {{{}}}", pass, stage_name(stage), kw));
  }
}

}  // namespace

// More threads than cores would not run (TBB keeps its workers to the
// cores, and warns on stderr for an arena asked for more), and an arena of
// billions of threads crashes inside TBB: -j is at most the core count.
unsigned worker_count(unsigned requested) {
  const unsigned cores = std::max(1u, std::thread::hardware_concurrency());
  return requested > 0 ? std::min(requested, cores) : cores;
}

CompileCounters compile_tasks(const BuildContext& ctx, Plan& plan, const std::vector<size_t>& which) {
  const CompileOptions& options = ctx.options;
  const bool store = ctx.stores.any();
  std::atomic<uint64_t> hits{0}, corrupt{0}, remote_hits{0};
  std::mutex progress_mutex, problems_mutex;
  std::vector<std::string> problems;
  uint64_t finished = 0;
  auto report_progress = [&] {
    if (!options.progress) return;
    std::lock_guard lock(progress_mutex);
    options.progress(++finished, which.size());
  };
  parallel_for_each(which.size(), ctx.jobs, [&](size_t n) {
    struct Done {  // reports the program finished on every way out
      const std::function<void()>& report;
      ~Done() { report(); }
    };
    const std::function<void()> report = report_progress;
    Done done{report};
    StageTask& t = plan.tasks[which[n]];
    const SelectedPass& sel = ctx.passes[t.pass];
    StageEntry& e = t.entry;
    auto begin = std::chrono::steady_clock::now();
    auto elapsed = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count(); };
    if (store && !t.cache_key.empty()) {
      cache::EntryLookup found = ctx.stores.load_entry(t.cache_key, t.text_hash);
      if (found.other_program && t.key_from_manifest) {
        // The include manifest named another program's entry: the key is
        // wrong, so preprocess after all (which rewrites the manifest) and
        // look up the real key; a failed preprocess stores nothing.
        std::vector<std::string> problems = std::move(found.problems);
        found = preprocess_again(ctx, t) ? ctx.stores.load_entry(t.cache_key, t.text_hash) : cache::EntryLookup{};
        found.problems.insert(found.problems.begin(), problems.begin(), problems.end());
      }
      if (!found.problems.empty()) {
        ++corrupt;
        std::lock_guard lock(problems_mutex);
        problems.insert(problems.end(), found.problems.begin(), found.problems.end());
      }
      if (found.entry) {
        ++hits;
        remote_hits += found.remote;
        e.ok = e.cache_hit = true;
        e.seconds = elapsed();
        e.spirv = std::move(found.entry->spirv);
        e.reflection = std::move(found.entry->reflection);
        e.included_files = std::move(found.entry->included_files);
        return;
      }
    }
    auto compiled = ctx.backend.compile(ctx.shader, *sel.ir.program, t.stage, t.keywords, options.backend,
                                        ctx.sources, e.diags);
    add_variant_context(e.diags, pass_label(sel.ir, sel.pass), t.stage, t.keywords);
    e.seconds = elapsed();
    if (!compiled) return;
    e.ok = true;
    e.spirv = std::move(compiled->spirv);
    e.reflection = std::move(compiled->reflection);
    e.included_files = std::move(compiled->included_files);
    // Only clean compiles are stored: a hit replays no diagnostics.
    if (store && !t.cache_key.empty() && e.diags.size() == 0) {
      ctx.stores.store_entry(t.cache_key, {static_cast<const CompiledVariant&>(e), t.text_hash});
    }
  });
  std::sort(problems.begin(), problems.end());  // the same order whichever thread finished first
  return {hits, remote_hits, corrupt, std::move(problems)};
}

}  // namespace facet::driver
