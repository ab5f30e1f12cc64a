// Phase 1: which stage programs the variants need, and their tokens.
#include <fmt/format.h>
#include <xxhash.h>

#include <atomic>
#include <filesystem>
#include <mutex>

#include "build_plan.h"
#include "facet/reachability.h"

namespace facet::driver {
namespace {

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
std::string search_context(const ir::Shader& shader, const ir::Program& program,
                           const backend::BackendOptions& options, const SourceMap& sources) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const std::string home = sources.path(ir::program_file(shader, program));
  std::string context = "|direct|" + fs::absolute(home, ec).lexically_normal().string();
  for (const std::string& dir : options.include_dirs) context += "|I" + fs::absolute(dir, ec).string();
  context += "|stdlib " + (options.stdlib_dir.empty() ? backend::default_stdlib_dir() : options.stdlib_dir);
  for (const auto& [name, value] : options.defines) context += "|D" + name + "=" + value;
  context += "|U" + std::to_string(options.unity_version);
  return context;
}

// Content hashes of files, each read once per build; safe across threads.
// A listed file that is not a regular file, or is too large to hash, has no
// hash (its manifest is stale) and a problem naming it.
class FileHashes {
 public:
  cache::FileHash of(const std::string& path) {
    {
      std::lock_guard lock(mutex_);
      if (auto it = hashes_.find(path); it != hashes_.end()) return it->second;
    }
    cache::FileHash hash = cache::hash_file(path);
    std::lock_guard lock(mutex_);
    return hashes_.emplace(path, std::move(hash)).first->second;
  }
  // Whether every listed file still hashes the same; the first refused file's problem otherwise.
  bool unchanged(const std::vector<std::pair<std::string, uint64_t>>& files, std::string& problem) {
    for (const auto& [path, hash] : files) {
      cache::FileHash now = of(path);
      if (!now.problem.empty()) problem = fmt::format("it lists '{}': {}", path, now.problem);
      if (now.hash != hash) return false;
    }
    return true;
  }

 private:
  std::mutex mutex_;
  std::map<std::string, cache::FileHash> hashes_;
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

}  // namespace

Plan plan_tasks(const std::vector<SelectedPass>& passes, std::vector<variants::VariantSet> variant_sets) {
  Plan plan;
  for (size_t p = 0; p < passes.size(); ++p) {
    const ir::Program& program = *passes[p].ir.program;
    for (const variants::VariantKey& key : variant_sets[p].keys) {
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
  plan.variant_sets = std::move(variant_sets);
  return plan;
}

// Tasks whose preprocessed texts are equal compile to the same module: the
// first of them compiles, the others reuse it. Returns how many compile.
size_t assign_compilers(const std::vector<SelectedPass>& passes, std::vector<StageTask>& tasks) {
  std::map<std::tuple<Stage, ir::ProgramLanguage, std::string, uint64_t, std::string>, size_t> first;
  size_t compiling = 0;
  for (size_t i = 0; i < tasks.size(); ++i) {
    StageTask& t = tasks[i];
    const ir::Program& program = *passes[t.pass].ir.program;
    if (!t.preprocessed) {
      t.compiled_by = i;  // its preprocessing failed: compile it alone for the full diagnostics
      ++compiling;
      continue;
    }
    // The key too: tasks whose include manifests disagree about it are not
    // merged on the token hash alone (one of the manifests is wrong).
    auto id = std::make_tuple(t.stage, program.language, program.entry_points[size_t(t.stage)], t.text_hash,
                              t.cache_key);
    auto [it, inserted] = first.try_emplace(id, i);
    t.compiled_by = it->second;
    compiling += inserted;
  }
  return compiling;
}

std::vector<size_t> compiling_tasks(const Plan& plan) {
  std::vector<size_t> out;
  for (size_t i = 0; i < plan.tasks.size(); ++i) {
    if (plan.tasks[i].compiled_by == i) out.push_back(i);
  }
  return out;
}

namespace {

// Direct mode: the task's key from a current include manifest. false when
// there is none (or it is stale, or unusable: `problems` says why).
bool key_from_manifest(const BuildContext& ctx, StageTask& t, FileHashes& file_hashes,
                       std::vector<std::string>& problems) {
  cache::ManifestLookup found = ctx.stores.load_manifest(t.manifest_key);
  problems.insert(problems.end(), found.problems.begin(), found.problems.end());
  if (!found.manifest) return false;
  std::string refused;
  bool current = file_hashes.unchanged(found.manifest->files, refused);
  if (!refused.empty()) {
    problems.push_back(fmt::format("unusable include manifest '{}': {}; the program is preprocessed instead",
                                   found.location, refused));
  }
  if (!current) return false;
  t.preprocessed = true;
  t.key_from_manifest = true;
  t.text_hash = found.manifest->token_hash;
  t.cache_key = found.manifest->entry_key;
  return true;
}

// Preprocesses the task: its token hash and cache key, and with a cache its
// include manifest (under t.manifest_key).
void preprocess_task(const BuildContext& ctx, StageTask& t, FileHashes& file_hashes) {
  const CompileOptions& options = ctx.options;
  const ir::Program& program = *ctx.passes[t.pass].ir.program;
  Diagnostics ignored;  // the compile reports the same problems with more context
  auto source = ctx.backend.source_text(ctx.shader, program, {.stage = t.stage, .keywords = t.keywords},
                                        options.backend, ctx.sources, ignored);
  if (!source) return;
  const std::vector<std::string>& included = source->included_files;
  t.preprocessed = true;
  t.key_from_manifest = false;
  std::string tokens = token_text(source->text, options.backend.debug_info);
  // Stage relevance: only what this stage's entry point reaches counts
  // (GLSL programs are already split per stage by #ifdef VERTEX/FRAGMENT;
  // with -g the module embeds the whole source, so all of it counts).
  if (program.language != ir::ProgramLanguage::glsl && !options.backend.debug_info) {
    tokens = reachable_text(tokens, program.entry_points[size_t(t.stage)]);
  }
  t.text_hash = XXH3_64bits(tokens.data(), tokens.size());
  t.cache_key = hex_key(key_context(ctx.shader, program, t.stage, options.backend), tokens);
  if (t.manifest_key.empty()) return;
  cache::IncludeManifest manifest{.entry_key = t.cache_key, .token_hash = t.text_hash};
  for (const std::string& path : included) {
    if (auto h = file_hashes.of(path).hash) manifest.files.emplace_back(path, *h);
  }
  if (manifest.files.size() == included.size()) ctx.stores.store_manifest(t.manifest_key, manifest);
}

}  // namespace

PreprocessCounters preprocess_tasks(const BuildContext& ctx, Plan& plan) {
  const CompileOptions& options = ctx.options;
  const bool store = ctx.stores.any();
  FileHashes file_hashes;
  std::atomic<uint64_t> manifest_hits{0};
  std::mutex problems_mutex;
  std::vector<std::string> problems;
  parallel_for_each(plan.tasks.size(), ctx.jobs, [&](size_t i) {
    StageTask& t = plan.tasks[i];
    const ir::Program& program = *ctx.passes[t.pass].ir.program;
    if (store) {
      // Direct mode: the text before preprocessing and the files it read last time.
      Diagnostics ignored;
      auto assembled = ctx.backend.source_text(ctx.shader, program,
                                               {.stage = t.stage, .keywords = t.keywords, .preprocess = false},
                                               options.backend, ctx.sources, ignored);
      const std::string context = key_context(ctx.shader, program, t.stage, options.backend);
      if (assembled) {
        t.manifest_key = hex_key(context + search_context(ctx.shader, program, options.backend, ctx.sources), assembled->text);
      }
      std::vector<std::string> found;
      bool hit = assembled && key_from_manifest(ctx, t, file_hashes, found);
      if (!found.empty()) {
        std::lock_guard lock(problems_mutex);
        problems.insert(problems.end(), found.begin(), found.end());
      }
      if (hit) {
        ++manifest_hits;
        return;
      }
    }
    preprocess_task(ctx, t, file_hashes);
  });
  return {manifest_hits, std::move(problems)};
}

bool preprocess_again(const BuildContext& ctx, StageTask& t) {
  FileHashes file_hashes;
  t.preprocessed = false;
  t.cache_key.clear();  // the manifest's key is wrong: without a new one nothing is stored
  preprocess_task(ctx, t, file_hashes);
  return t.preprocessed;
}

}  // namespace facet::driver
