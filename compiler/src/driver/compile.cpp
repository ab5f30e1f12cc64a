// Compiler::compile: selected passes x variants x stages -> Package.
//
// The recipe: list the stage programs every variant needs (a program is a
// pass, a stage and the keywords that stage sees), preprocess them all in
// parallel, compile each distinct preprocessed text once in parallel, then
// assemble the package sequentially in key order, so the bytes do not depend
// on the thread count or on which thread finished first.
#include <fmt/format.h>
#include <xxhash.h>

#include <algorithm>
#include <chrono>
#include <map>
#include <set>

#include "build_plan.h"
#include "facet/build_farm.h"

namespace facet {

using driver::BuildContext;
using driver::CompileCounters;
using driver::Plan;
using driver::StageEntry;
using driver::StageTask;

namespace {

void fill_shader_level(const ir::Shader& shader, const SelectedPass* first, package::Package& pkg) {
  pkg.shader_name = shader.name;
  pkg.properties = shader.properties;
  pkg.fallback = shader.fallback.value_or("");
  pkg.custom_editor = shader.custom_editor;
  size_t sub = first ? first->subshader : 0;
  if (sub < shader.subshaders.size()) {
    pkg.subshader_tags = shader.subshaders[sub].tags;
    pkg.lod = shader.subshaders[sub].lod;
  }
}

// The plan's tasks as the caller sees them, with blobs of the final package.
std::vector<ProgramRecord> program_records(const std::vector<StageTask>& tasks, const package::Package& pkg) {
  std::map<uint64_t, std::vector<uint32_t>> blobs_by_hash;
  for (uint32_t b = 0; b < pkg.spirv_blobs.size(); ++b) {
    const auto& words = pkg.spirv_blobs[b];
    blobs_by_hash[XXH3_64bits(words.data(), words.size() * 4)].push_back(b);
  }
  std::vector<ProgramRecord> out;
  for (size_t i = 0; i < tasks.size(); ++i) {
    const StageTask& t = tasks[i];
    const StageEntry& e = tasks[t.compiled_by].entry;
    ProgramRecord r{.pass = uint32_t(t.pass), .stage = t.stage, .keywords = t.keywords,
                    .token_hash = t.preprocessed ? t.text_hash : 0, .compiled = t.compiled_by == i,
                    .cache_hit = t.compiled_by == i && e.cache_hit, .seconds = t.compiled_by == i ? e.seconds : 0};
    if (e.ok) {
      for (uint32_t b : blobs_by_hash[XXH3_64bits(e.spirv.data(), e.spirv.size() * 4)]) {
        if (pkg.spirv_blobs[b] == e.spirv) r.blob = b;
      }
    }
    out.push_back(std::move(r));
  }
  return out;
}

}  // namespace

namespace {

// The variants of every selected pass, stripped and sharded.
Result<std::vector<variants::VariantSet>> select_variant_sets(const Compiler& compiler,
                                                              const std::vector<SelectedPass>& passes,
                                                              const CompileOptions& options, Diagnostics& diags) {
  bool failed = false;
  std::vector<variants::VariantSet> sets;
  uint64_t variant_index = 0;
  for (const SelectedPass& sel : passes) {
    auto set = compiler.select_variants(sel, options, diags);
    if (!set) failed = true;
    sets.push_back(set ? std::move(*set) : variants::VariantSet{.space = sel.keywords});
    if (options.shard_count > 1) {
      std::erase_if(sets.back().keys, [&](const variants::VariantKey&) {
        return variant_index++ % options.shard_count != options.shard_index;
      });
    }
  }
  if (failed) return failure("variant selection failed");
  return sets;
}

uint64_t stripped_in(const std::vector<variants::VariantSet>& sets) {
  uint64_t n = 0;
  for (const variants::VariantSet& set : sets) n += set.stripped;
  return n;
}

cache::CacheStores cache_stores(const CompileOptions& options, cache::RemoteServers& servers) {
  cache::CacheStores stores;
  if (!options.cache_dir.empty()) stores.local.emplace(options.cache_dir);
  if (!options.cache_url.empty()) stores.remote.emplace(options.cache_url, 10000, servers.down_flag(options.cache_url));
  return stores;
}

// Warnings for the cache entries and include manifests that were found but
// not used; a cache never fails a build, so they are warnings, a handful
// each, then a count.
void report_cache_problems(const std::vector<std::string>& manifests, const std::vector<std::string>& entries,
                           Diagnostics& diags) {
  constexpr size_t kShown = 20;
  std::vector<std::string> all = manifests;
  std::sort(all.begin(), all.end());
  all.erase(std::unique(all.begin(), all.end()), all.end());
  all.insert(all.end(), entries.begin(), entries.end());
  for (size_t i = 0; i < all.size() && i < kShown; ++i) diags.add(DiagId::io_cannot_read, Severity::warning, {}, all[i]);
  if (all.size() > kShown) {
    diags.add(DiagId::io_cannot_read, Severity::warning, {},
              fmt::format("{} more corrupt cache entries or include manifests were not used", all.size() - kShown));
  }
}

// Phase 3: the package, sequentially in key order. false on compile errors.
// The task of each (pass, variant, stage) of the package, in assembly order.
std::vector<size_t> stage_tasks(const BuildContext& ctx, const Plan& plan) {
  std::vector<size_t> out;
  for (size_t p = 0; p < ctx.passes.size(); ++p) {
    const SelectedPass& sel = ctx.passes[p];
    for (const variants::VariantKey& key : plan.variant_sets[p].keys) {
      for (int s = 0; s < kStageCount; ++s) {
        Stage stage = Stage(s);
        if (!sel.ir.program->has_stage(stage)) continue;
        size_t task = plan.task_of.at(std::make_tuple(p, stage, variants::project(sel.keywords, key, stage)));
        out.push_back(plan.tasks[task].compiled_by);
      }
    }
  }
  return out;
}

bool assemble_package(const BuildContext& ctx, Plan& plan, CompiledShader& out, Diagnostics& diags) {
  package::Package& pkg = out.package;
  // A stage program's last user takes its reflection instead of copying it
  // (most fragment programs have exactly one user).
  const std::vector<size_t> by_of_stage = stage_tasks(ctx, plan);
  std::vector<uint32_t> users_left(plan.tasks.size(), 0);
  for (size_t by : by_of_stage) ++users_left[by];
  size_t next_stage = 0;
  fill_shader_level(ctx.shader, ctx.passes.empty() ? nullptr : &ctx.passes.front(), pkg);
  std::set<std::string> dependencies{ctx.sources.path(ctx.shader.file)};
  for (const SelectedPass& sel : ctx.passes) {  // passes taken from other shaders (UsePass, Fallback)
    if (sel.ir.program) dependencies.insert(ctx.sources.path(ir::program_file(ctx.shader, *sel.ir.program)));
  }
  std::map<size_t, uint32_t> blob_of;  // compiling task -> blob index
  bool failed = false;
  for (size_t p = 0; p < ctx.passes.size(); ++p) {
    const SelectedPass& sel = ctx.passes[p];
    const ir::Pass& written = ctx.shader.subshaders[sel.subshader].passes[sel.pass];
    package::PackagePass pp{.name = sel.ir.name, .tags = sel.ir.tags, .state = written.state,
                            .keywords = sel.keywords, .source_index = uint32_t(sel.pass)};
    // GrabPasses have no program: the pass after them records them.
    const size_t from = p == 0 || ctx.passes[p - 1].subshader != sel.subshader ? 0 : ctx.passes[p - 1].pass + 1;
    pp.grab_before = ir::grab_textures(ctx.shader.subshaders[sel.subshader], from, sel.pass);
    if (written.kind == ir::PassKind::use_pass) pp.state = sel.ir.state;
    std::vector<Diagnostics> per_variant;
    for (const variants::VariantKey& key : plan.variant_sets[p].keys) {
      Diagnostics variant_diags;
      package::PackageVariant pv{.key = key, .keywords = variants::all_keywords(sel.keywords, key)};
      bool variant_ok = true;
      for (int s = 0; s < kStageCount; ++s) {
        Stage stage = Stage(s);
        if (!sel.ir.program->has_stage(stage)) continue;
        size_t by = by_of_stage[next_stage++];
        StageEntry& e = plan.tasks[by].entry;
        variant_diags.append(e.diags);
        if (!e.ok) {
          variant_ok = false;
          continue;
        }
        auto [it, inserted] = blob_of.try_emplace(by, uint32_t(pkg.spirv_blobs.size()));
        if (inserted) {
          pkg.spirv_blobs.push_back(e.spirv);
          dependencies.insert(e.included_files.begin(), e.included_files.end());
        }
        if (--users_left[by] == 0) {
          pv.stages.push_back({.stage = stage, .blob = it->second, .reflection = std::move(e.reflection)});
        } else {
          pv.stages.push_back({.stage = stage, .blob = it->second, .reflection = e.reflection});
        }
      }
      if (variant_ok) pp.variants.push_back(std::move(pv));
      per_variant.push_back(std::move(variant_diags));
    }
    Diagnostics merged = merge_variant_duplicates(per_variant);
    failed = failed || merged.has_errors();
    diags.append(merged);
    out.stats.variants += pp.variants.size();
    ++out.stats.passes;
    std::sort(pp.variants.begin(), pp.variants.end(), [](const auto& a, const auto& b) { return a.key < b.key; });
    pkg.passes.push_back(std::move(pp));
  }
  out.dependencies.assign(dependencies.begin(), dependencies.end());
  return !failed;
}

}  // namespace

// What the build-farm calls need of a Compiler beyond its public calls.
struct CompilerInternals {
  static const backend::Backend& backend(const Compiler& compiler) { return compiler.backend_; }
  static cache::RemoteServers& remote_servers(const Compiler& compiler) { return *compiler.remote_servers_; }
};

Result<std::vector<ProgramJob>> program_jobs(const Compiler& compiler, const ir::Shader& shader,
                                             const CompileOptions& options, SourceMap& sources, Diagnostics& diags) {
  auto passes = compiler.select_passes(shader, options, diags);
  FACET_TRY(passes);
  auto sets = select_variant_sets(compiler, *passes, options, diags);
  FACET_TRY(sets);
  const cache::CacheStores no_cache;
  const BuildContext ctx{shader, options, sources, CompilerInternals::backend(compiler), *passes, no_cache,
                         driver::worker_count(options.jobs)};
  Plan plan = driver::plan_tasks(*passes, std::move(*sets));
  driver::preprocess_tasks(ctx, plan);
  driver::assign_compilers(*passes, plan.tasks);
  std::vector<ProgramJob> jobs;
  for (size_t i : driver::compiling_tasks(plan)) {
    const StageTask& t = plan.tasks[i];
    jobs.push_back({(*passes)[t.pass].pass, t.stage, t.keywords});
  }
  return jobs;
}

Result<bool> compile_program(const Compiler& compiler, const ir::Shader& shader, const CompileOptions& options,
                             const ProgramJob& job, SourceMap& sources, Diagnostics& diags) {
  const cache::CacheStores stores = cache_stores(options, CompilerInternals::remote_servers(compiler));
  if (!stores.any()) {
    diags.add(DiagId::driver_bad_option, {}, "a program job compiles into the cache: give --cache-dir or --remote-cache");
    return failure("no cache");
  }
  auto passes = compiler.select_passes(shader, options, diags);
  FACET_TRY(passes);
  auto pass = std::find_if(passes->begin(), passes->end(), [&](const SelectedPass& p) { return p.pass == job.pass; });
  if (pass == passes->end() || !pass->ir.program->has_stage(job.stage)) {
    diags.add(DiagId::driver_no_such_pass, {},
              fmt::format("the job names pass {} and the {} stage, which this shader does not have", job.pass,
                          stage_name(job.stage)));
    return failure("no such program");
  }
  std::vector<SelectedPass> one{*pass};
  const BuildContext ctx{shader, options, sources, CompilerInternals::backend(compiler), one, stores, 1};
  Plan plan;
  plan.variant_sets.resize(1);
  plan.tasks.push_back({.pass = 0, .stage = job.stage, .keywords = job.keywords});
  driver::PreprocessCounters preprocessed = driver::preprocess_tasks(ctx, plan);
  driver::assign_compilers(one, plan.tasks);
  CompileCounters counters = driver::compile_tasks(ctx, plan, {0});
  report_cache_problems(preprocessed.cache_problems, counters.cache_problems, diags);
  diags.append(plan.tasks[0].entry.diags);
  if (!plan.tasks[0].entry.ok) return failure("compile errors");
  return counters.hits == 0;
}

namespace {

// The evenly spread sample of `unique` (the tasks a build compiles) that an
// estimate times.
std::vector<size_t> estimate_sample(const std::vector<size_t>& unique, size_t sample) {
  std::vector<size_t> picked;
  const size_t n = std::min(std::max<size_t>(sample, 1), unique.size());
  for (size_t i = 0; i < n; ++i) picked.push_back(unique[i * unique.size() / n]);
  return picked;
}

// Fills in the sample's mean and the estimate from it.
void finish_estimate(BuildEstimate& e, const Plan& plan, const std::vector<size_t>& picked) {
  double total = 0;
  for (size_t i : picked) total += plan.tasks[i].entry.seconds;
  e.sampled = picked.size();
  e.seconds_per_program = picked.empty() ? 0 : total / double(picked.size());
  e.estimated_seconds = e.preprocess_seconds + double(e.unique) * e.seconds_per_program / double(e.jobs);
}

// What estimate_build would have said of this build, from the build's
// own numbers: its preprocessing time and the same sample's compile times
// (programs the cache served are no sample of a cold build; with every
// program from the cache there is no estimate).
std::optional<BuildEstimate> estimate_of_build(const Plan& plan, const std::vector<size_t>& to_compile,
                                               double preprocess_seconds, unsigned jobs, size_t sample) {
  std::vector<size_t> compiled;
  for (size_t i : to_compile) {
    if (!plan.tasks[i].entry.cache_hit) compiled.push_back(i);
  }
  if (compiled.empty()) return std::nullopt;
  BuildEstimate e{.programs = plan.tasks.size(), .unique = to_compile.size(),
                  .preprocess_seconds = preprocess_seconds, .jobs = jobs};
  for (const variants::VariantSet& set : plan.variant_sets) e.variants += set.keys.size();
  finish_estimate(e, plan, estimate_sample(compiled, sample));
  return e;
}

}  // namespace

Result<BuildEstimate> estimate_build(const Compiler& compiler, const ir::Shader& shader, const CompileOptions& options,
                                     SourceMap& sources, Diagnostics& diags, size_t sample) {
  auto passes = compiler.select_passes(shader, options, diags);
  FACET_TRY(passes);
  auto sets = select_variant_sets(compiler, *passes, options, diags);
  FACET_TRY(sets);
  const cache::CacheStores no_cache;
  const BuildContext ctx{shader, options, sources, CompilerInternals::backend(compiler), *passes, no_cache,
                         driver::worker_count(options.jobs)};
  BuildEstimate e{.jobs = ctx.jobs};
  for (const variants::VariantSet& set : *sets) e.variants += set.keys.size();
  auto started = std::chrono::steady_clock::now();
  Plan plan = driver::plan_tasks(*passes, std::move(*sets));
  driver::preprocess_tasks(ctx, plan);
  e.unique = driver::assign_compilers(*passes, plan.tasks);
  e.programs = plan.tasks.size();
  e.preprocess_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  std::vector<size_t> picked = estimate_sample(driver::compiling_tasks(plan), sample);
  driver::compile_tasks(ctx, plan, picked);
  finish_estimate(e, plan, picked);
  return e;
}

Result<CompiledShader> Compiler::compile(const ir::Shader& shader, const CompileOptions& options, SourceMap& sources,
                                         Diagnostics& diags) const {
  auto started = std::chrono::steady_clock::now();
  auto lap = started;
  auto seconds_since_lap = [&lap] {
    auto now = std::chrono::steady_clock::now();
    double s = std::chrono::duration<double>(now - lap).count();
    lap = now;
    return s;
  };
  CompileStats::Phases phases;
  auto passes = select_passes(shader, options, diags);
  FACET_TRY(passes);
  auto sets = select_variant_sets(*this, *passes, options, diags);
  FACET_TRY(sets);

  const cache::CacheStores stores = cache_stores(options, *remote_servers_);
  const BuildContext ctx{shader, options, sources, backend_, *passes, stores, driver::worker_count(options.jobs)};
  Plan plan = driver::plan_tasks(*passes, std::move(*sets));
  phases.select = seconds_since_lap();
  driver::PreprocessCounters preprocessed = driver::preprocess_tasks(ctx, plan);
  size_t compiling = driver::assign_compilers(*passes, plan.tasks);
  std::vector<size_t> to_compile = driver::compiling_tasks(plan);
  phases.preprocess = seconds_since_lap();
  CompileCounters counters = driver::compile_tasks(ctx, plan, to_compile);
  phases.compile = seconds_since_lap();
  report_cache_problems(preprocessed.cache_problems, counters.cache_problems, diags);

  CompiledShader out;
  if (!assemble_package(ctx, plan, out, diags)) return failure("compile errors");
  package::Package& pkg = out.package;
  package::deduplicate_blobs(pkg);
  Diagnostics invariant;
  if (!package::validate_package(pkg, invariant)) FACET_ICE("the driver built an invalid package");
  out.stats.stage_programs = plan.tasks.size();
  out.stats.variants_stripped = stripped_in(plan.variant_sets);
  out.stats.unique_preprocessed = compiling;
  out.stats.cache_hits = counters.hits;
  out.stats.cache_remote_hits = counters.remote_hits;
  out.stats.preprocess_skipped = preprocessed.manifest_hits;
  out.stats.cache_corrupt = counters.corrupt;
  out.stats.compiled = to_compile.size() - counters.hits;
  out.stats.unique_spirv = pkg.spirv_blobs.size();
  out.stats.jobs = ctx.jobs;
  out.programs = program_records(plan.tasks, pkg);
  out.estimate = estimate_of_build(plan, to_compile, phases.preprocess, ctx.jobs, kEstimateSample);
  phases.assemble = seconds_since_lap();
  out.stats.phases = phases;
  out.stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  return out;
}

}  // namespace facet
