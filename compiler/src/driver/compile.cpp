// Compiler::compile: selected passes x variants x stages -> Package.
//
// The recipe: list the stage programs every variant needs (a program is a
// pass, a stage and the keywords that stage sees), preprocess them all in
// parallel, compile each distinct preprocessed text once in parallel, then
// assemble the package sequentially in key order, so the bytes do not depend
// on the thread count or on which thread finished first.
#include <fmt/format.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>
#include <xxhash.h>

#include <atomic>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <map>
#include <set>
#include <thread>
#include <tuple>

#include "driver/reachable.h"
#include "facet/cache.h"
#include "facet/compiler.h"

namespace facet {
namespace {

// The outcome of one stage program, shared by every variant that needs it.
struct StageEntry {
  bool ok = false;
  bool cache_hit = false;
  double seconds = 0;
  std::vector<uint32_t> spirv;
  StageReflection reflection;
  std::vector<std::string> included_files;
  Diagnostics diags;
};

struct StageTask {
  size_t pass = 0;  // index into the selected passes
  Stage stage = Stage::vertex;
  std::vector<std::string> keywords;  // the keywords the stage sees
  uint64_t text_hash = 0;             // of the preprocessed tokens
  std::string cache_key;              // hex; set when preprocessing succeeded
  bool preprocessed = false;
  size_t compiled_by = SIZE_MAX;      // the task whose compile this one reuses (itself when first)
  StageEntry entry;
};

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

unsigned worker_count(unsigned requested) {
  if (requested > 0) return requested;
  return std::max(1u, std::thread::hardware_concurrency());
}

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

// `"file"` of a #line marker as an absolute path, so that the same program
// reached through another working folder or relative path hashes the same.
std::string absolute_name(std::string_view quoted) {
  if (quoted.size() < 2 || quoted[1] == '<' || quoted.back() != '"') return std::string(quoted);
  std::error_code ec;
  std::filesystem::path p(std::string(quoted.substr(1, quoted.size() - 2)));
  return "\"" + std::filesystem::absolute(p, ec).lexically_normal().string() + "\"";
}

// The tokens of a preprocessed text: layout dropped and the line numbers of
// `#line` markers too (a keyword's #define shifts the prelude's lines without
// changing the program), but not their file names. With debug info the lines
// reach the SPIR-V, so the text is kept whole.
std::string token_text(const std::string& text, bool keep_lines) {
  if (keep_lines) return text;
  std::string tokens;
  tokens.reserve(text.size());
  size_t pos = 0;
  while (pos < text.size()) {
    size_t eol = text.find('\n', pos);
    if (eol == std::string::npos) eol = text.size();
    std::string_view line(text.data() + pos, eol - pos);
    pos = eol + 1;
    size_t first = line.find_first_not_of(" \t\r");
    if (first == std::string_view::npos) continue;
    line.remove_prefix(first);
    if (line.starts_with("#line")) {
      size_t quote = line.find('"');
      tokens += "#line ";
      if (quote != std::string_view::npos) tokens += absolute_name(line.substr(quote));
      tokens += '\n';
      continue;
    }
    bool in_space = false;
    for (char c : line) {
      bool space = c == ' ' || c == '\t' || c == '\r';
      if (space && !in_space) tokens += ' ';
      if (!space) tokens += c;
      in_space = space;
    }
    tokens += '\n';
  }
  return tokens;
}

// What the compiled module depends on besides its tokens.
std::string key_context(const ir::Shader& shader, const ir::Program& program, Stage stage,
                        const backend::BackendOptions& options) {
  std::string context = fmt::format("{}|opt {}|target {}|g {}|stage {}|lang {}|entry {}|", cache::build_id(),
                                    int(options.opt), int(options.target), options.debug_info, int(stage),
                                    int(program.language), program.entry_points[size_t(stage)]);
  for (const ir::Property& p : shader.properties) {  // reflection binds properties to uniforms
    context += fmt::format("{}:{}:{};", p.name, int(p.type), p.default_texture);
  }
  return context;
}

// What else decides which files an #include finds: the search path and the
// including file's folder (absolute, so any working folder finds the entry).
std::string search_context(const ir::Shader& shader, const backend::BackendOptions& options,
                           const SourceMap& sources) {
  namespace fs = std::filesystem;
  std::error_code ec;
  std::string context = "|direct|" + fs::absolute(sources.path(shader.file), ec).lexically_normal().string();
  for (const std::string& dir : options.include_dirs) context += "|I" + fs::absolute(dir, ec).string();
  context += "|stdlib " + (options.stdlib_dir.empty() ? backend::default_stdlib_dir() : options.stdlib_dir);
  for (const auto& [name, value] : options.defines) context += "|D" + name + "=" + value;
  return context;
}

// Content hashes of files, each read once per build; safe across threads.
class FileHashes {
 public:
  std::optional<uint64_t> of(const std::string& path) {
    {
      std::lock_guard lock(mutex_);
      if (auto it = hashes_.find(path); it != hashes_.end()) return it->second;
    }
    std::optional<uint64_t> hash;
    std::ifstream in(path, std::ios::binary);
    if (in) {
      std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
      hash = XXH3_64bits(bytes.data(), bytes.size());
    }
    std::lock_guard lock(mutex_);
    return hashes_.emplace(path, hash).first->second;
  }
  bool unchanged(const std::vector<std::pair<std::string, uint64_t>>& files) {
    return std::all_of(files.begin(), files.end(), [&](const auto& f) { return of(f.first) == f.second; });
  }

 private:
  std::mutex mutex_;
  std::map<std::string, std::optional<uint64_t>> hashes_;
};

std::string hex_key(const std::string& context, const std::string& tokens) {
  XXH3_state_t* state = XXH3_createState();
  XXH3_128bits_reset(state);
  XXH3_128bits_update(state, context.data(), context.size());
  XXH3_128bits_update(state, tokens.data(), tokens.size());
  XXH128_hash_t h = XXH3_128bits_digest(state);
  XXH3_freeState(state);
  return fmt::format("{:016x}{:016x}", h.high64, h.low64);
}

// The variants of each pass and, per (pass, stage, projected key), one task.
struct Plan {
  std::vector<std::vector<variants::VariantKey>> keys;  // per selected pass
  std::vector<StageTask> tasks;
  // (pass, stage, projected key) -> task index
  std::map<std::tuple<size_t, Stage, variants::VariantKey>, size_t> task_of;
};

Plan plan_tasks(const std::vector<SelectedPass>& passes, std::vector<std::vector<variants::VariantKey>> keys) {
  Plan plan;
  for (size_t p = 0; p < passes.size(); ++p) {
    const ir::Program& program = *passes[p].ir->program;
    for (const variants::VariantKey& key : keys[p]) {
      for (int s = 0; s < kStageCount; ++s) {
        Stage stage = Stage(s);
        if (!program.has_stage(stage)) continue;
        auto id = std::make_tuple(p, stage, variants::project(passes[p].keywords, key, stage));
        if (plan.task_of.count(id)) continue;
        plan.task_of.emplace(id, plan.tasks.size());
        plan.tasks.push_back({.pass = p, .stage = stage,
                              .keywords = variants::stage_keywords(passes[p].keywords, key, stage)});
      }
    }
  }
  plan.keys = std::move(keys);
  return plan;
}

// Tasks whose preprocessed texts are equal compile to the same module: the
// first of them compiles, the others reuse it. Returns how many compile.
size_t assign_compilers(const std::vector<SelectedPass>& passes, std::vector<StageTask>& tasks) {
  std::map<std::tuple<Stage, ir::ProgramLanguage, std::string, uint64_t>, size_t> first;
  size_t compiling = 0;
  for (size_t i = 0; i < tasks.size(); ++i) {
    StageTask& t = tasks[i];
    const ir::Program& program = *passes[t.pass].ir->program;
    if (!t.preprocessed) {
      t.compiled_by = i;  // its preprocessing failed: compile it alone for the full diagnostics
      ++compiling;
      continue;
    }
    auto id = std::make_tuple(t.stage, program.language, program.entry_points[size_t(t.stage)], t.text_hash);
    auto [it, inserted] = first.try_emplace(id, i);
    t.compiled_by = it->second;
    compiling += inserted;
  }
  return compiling;
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

Result<CompiledShader> Compiler::compile(const ir::Shader& shader, const CompileOptions& options, SourceMap& sources,
                                         Diagnostics& diags) const {
  auto started = std::chrono::steady_clock::now();
  auto passes = select_passes(shader, options, diags);
  FACET_TRY(passes);

  bool failed = false;
  std::vector<std::vector<variants::VariantKey>> keys;
  uint64_t stripped = 0, variant_index = 0;
  for (const SelectedPass& sel : *passes) {
    auto k = select_variants(sel, options, diags, &stripped);
    if (!k) failed = true;
    keys.push_back(k ? std::move(*k) : std::vector<variants::VariantKey>{});
    if (options.shard_count > 1) {
      std::erase_if(keys.back(), [&](const variants::VariantKey&) {
        return variant_index++ % options.shard_count != options.shard_index;
      });
    }
  }
  Plan plan = plan_tasks(*passes, std::move(keys));
  const unsigned jobs = worker_count(options.jobs);

  cache::CacheStores stores;
  if (!options.cache_dir.empty()) stores.local.emplace(options.cache_dir);
  if (!options.cache_url.empty()) stores.remote.emplace(options.cache_url);
  const bool store = stores.any();
  FileHashes file_hashes;
  std::atomic<uint64_t> manifest_hits{0};
  parallel_for_each(plan.tasks.size(), jobs, [&](size_t i) {
    StageTask& t = plan.tasks[i];
    const ir::Program& program = *(*passes)[t.pass].ir->program;
    Diagnostics ignored;  // the compile reports the same problems with more context
    const std::string context = key_context(shader, program, t.stage, options.backend);
    std::string manifest_key;
    if (store) {
      // Direct mode: the text before preprocessing and the files it read last time.
      auto assembled = backend_.source_text(shader, program, t.stage, t.keywords, options.backend, false, sources,
                                            ignored);
      manifest_key = hex_key(context + search_context(shader, options.backend, sources), *assembled);
      if (auto bytes = stores.load_bytes(manifest_key)) {
        auto manifest = cache::decode_manifest(*bytes);
        if (manifest && file_hashes.unchanged(manifest->files)) {
          t.preprocessed = true;
          t.text_hash = manifest->token_hash;
          t.cache_key = manifest->entry_key;
          ++manifest_hits;
          return;
        }
      }
    }
    std::vector<std::string> included;
    auto text = backend_.source_text(shader, program, t.stage, t.keywords, options.backend, true, sources, ignored,
                                     &included);
    if (!text) return;
    t.preprocessed = true;
    std::string tokens = token_text(*text, options.backend.debug_info);
    // Stage relevance: only what this stage's entry point reaches counts
    // (GLSL programs are already split per stage by #ifdef VERTEX/FRAGMENT;
    // with -g the module embeds the whole source, so all of it counts).
    if (program.language != ir::ProgramLanguage::glsl && !options.backend.debug_info) {
      tokens = reachable_text(tokens, program.entry_points[size_t(t.stage)]);
    }
    t.text_hash = XXH3_64bits(tokens.data(), tokens.size());
    t.cache_key = hex_key(context, tokens);
    if (store) {
      cache::IncludeManifest manifest{.entry_key = t.cache_key, .token_hash = t.text_hash};
      for (const std::string& path : included) {
        if (auto h = file_hashes.of(path)) manifest.files.emplace_back(path, *h);
      }
      if (manifest.files.size() == included.size()) stores.store_bytes(manifest_key, cache::encode_manifest(manifest));
    }
  });
  size_t compiling = assign_compilers(*passes, plan.tasks);

  std::vector<size_t> to_compile;
  for (size_t i = 0; i < plan.tasks.size(); ++i) {
    if (plan.tasks[i].compiled_by == i) to_compile.push_back(i);
  }
  std::atomic<uint64_t> hits{0}, corrupt{0}, remote_hits{0};
  std::mutex progress_mutex;
  uint64_t finished = 0;
  auto report_progress = [&] {
    if (!options.progress) return;
    std::lock_guard lock(progress_mutex);
    options.progress(++finished, to_compile.size());
  };
  parallel_for_each(to_compile.size(), jobs, [&](size_t n) {
    struct Done {  // reports the program finished on every way out
      const std::function<void()>& report;
      ~Done() { report(); }
    };
    const std::function<void()> report = report_progress;
    Done done{report};
    StageTask& t = plan.tasks[to_compile[n]];
    const SelectedPass& sel = (*passes)[t.pass];
    StageEntry& e = t.entry;
    auto begin = std::chrono::steady_clock::now();
    auto elapsed = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count(); };
    if (store && !t.cache_key.empty()) {
      bool from_remote = false;
      std::optional<std::string> bytes = stores.load_bytes(t.cache_key, &from_remote);
      std::optional<cache::CacheEntry> cached_entry = bytes ? cache::decode_entry(*bytes) : std::nullopt;
      cache::LoadResult cached{std::move(cached_entry), bytes.has_value() && !cached_entry};
      corrupt += cached.corrupt;
      if (cached.entry) {
        ++hits;
        remote_hits += from_remote;
        e.ok = e.cache_hit = true;
        e.seconds = elapsed();
        e.spirv = std::move(cached.entry->spirv);
        e.reflection = std::move(cached.entry->reflection);
        e.included_files = std::move(cached.entry->included_files);
        return;
      }
    }
    auto compiled = backend_.compile(shader, *sel.ir->program, t.stage, t.keywords, options.backend, sources, e.diags);
    add_variant_context(e.diags, pass_label(*sel.ir, sel.pass), t.stage, t.keywords);
    e.seconds = elapsed();
    if (!compiled) return;
    e.ok = true;
    e.spirv = std::move(compiled->spirv);
    e.reflection = std::move(compiled->reflection);
    e.included_files = std::move(compiled->included_files);
    // Only clean compiles are stored: a hit replays no diagnostics.
    if (store && !t.cache_key.empty() && e.diags.size() == 0) {
      stores.store_bytes(t.cache_key, cache::encode_entry({e.spirv, e.reflection, e.included_files}));
    }
  });

  CompiledShader out;
  package::Package& pkg = out.package;
  fill_shader_level(shader, passes->empty() ? nullptr : &passes->front(), pkg);
  std::set<std::string> dependencies{sources.path(shader.file)};
  std::map<size_t, uint32_t> blob_of;  // compiling task -> blob index

  for (size_t p = 0; p < passes->size(); ++p) {
    const SelectedPass& sel = (*passes)[p];
    const ir::Pass& written = shader.subshaders[sel.subshader].passes[sel.pass];
    package::PackagePass pp{.name = sel.ir->name, .tags = sel.ir->tags, .state = written.state,
                            .keywords = sel.keywords};
    if (written.kind == ir::PassKind::use_pass) pp.state = sel.ir->state;
    std::vector<Diagnostics> per_variant;
    for (const variants::VariantKey& key : plan.keys[p]) {
      Diagnostics variant_diags;
      package::PackageVariant pv{.key = key, .keywords = variants::all_keywords(sel.keywords, key)};
      bool variant_ok = true;
      for (int s = 0; s < kStageCount; ++s) {
        Stage stage = Stage(s);
        if (!sel.ir->program->has_stage(stage)) continue;
        size_t task = plan.task_of.at(std::make_tuple(p, stage, variants::project(sel.keywords, key, stage)));
        size_t by = plan.tasks[task].compiled_by;
        const StageEntry& e = plan.tasks[by].entry;
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
        pv.stages.push_back({.stage = stage, .blob = it->second, .reflection = e.reflection});
      }
      if (variant_ok) pp.variants.push_back(std::move(pv));
      per_variant.push_back(std::move(variant_diags));
    }
    Diagnostics merged = merge_variant_duplicates(per_variant);
    if (merged.has_errors()) failed = true;
    diags.append(merged);
    out.stats.variants += pp.variants.size();
    ++out.stats.passes;
    std::sort(pp.variants.begin(), pp.variants.end(), [](const auto& a, const auto& b) { return a.key < b.key; });
    pkg.passes.push_back(std::move(pp));
  }
  if (failed) return failure("compile errors");

  package::deduplicate_blobs(pkg);
  Diagnostics invariant;
  if (!package::validate_package(pkg, invariant)) FACET_ICE("the driver built an invalid package");
  out.stats.stage_programs = plan.tasks.size();
  out.stats.variants_stripped = stripped;
  out.stats.unique_preprocessed = compiling;
  out.stats.cache_hits = hits;
  out.stats.cache_remote_hits = remote_hits;
  out.stats.preprocess_skipped = manifest_hits;
  out.stats.cache_corrupt = corrupt;
  out.stats.compiled = to_compile.size() - hits;
  out.stats.unique_spirv = pkg.spirv_blobs.size();
  out.stats.jobs = jobs;
  out.dependencies.assign(dependencies.begin(), dependencies.end());
  out.programs = program_records(plan.tasks, pkg);
  out.stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  return out;
}

}  // namespace facet
