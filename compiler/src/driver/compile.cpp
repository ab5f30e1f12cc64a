// Compiler::compile: selected passes x variants x stages -> Package.
#include <fmt/format.h>

#include <chrono>
#include <map>
#include <set>

#include "facet/compiler.h"

namespace facet {
namespace {

// One compiled (stage, projected key): shared by every variant that differs
// only in keywords the stage does not see.
struct StageEntry {
  bool ok = false;
  uint32_t blob = 0;
  StageReflection reflection;
  Diagnostics diags;
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

}  // namespace

Result<CompiledShader> Compiler::compile(const ir::Shader& shader, const CompileOptions& options, SourceMap& sources,
                                         Diagnostics& diags) const {
  auto started = std::chrono::steady_clock::now();
  auto passes = select_passes(shader, options, diags);
  FACET_TRY(passes);

  CompiledShader out;
  package::Package& pkg = out.package;
  fill_shader_level(shader, passes->empty() ? nullptr : &passes->front(), pkg);
  std::set<std::string> dependencies{sources.path(shader.file)};
  bool failed = false;

  for (const SelectedPass& sel : *passes) {
    auto keys = select_variants(sel, options, diags);
    if (!keys) {
      failed = true;
      continue;
    }
    const ir::Program& program = *sel.ir->program;
    const ir::Pass& written = shader.subshaders[sel.subshader].passes[sel.pass];
    std::string label = pass_label(*sel.ir, sel.pass);
    package::PackagePass pp{.name = sel.ir->name, .tags = sel.ir->tags, .state = written.state,
                            .keywords = sel.keywords};
    if (written.kind == ir::PassKind::use_pass) pp.state = sel.ir->state;

    std::map<std::pair<Stage, variants::VariantKey>, StageEntry> cache;
    std::vector<Diagnostics> per_variant;
    for (const variants::VariantKey& key : *keys) {
      Diagnostics variant_diags;
      package::PackageVariant pv{.key = key, .keywords = variants::all_keywords(sel.keywords, key)};
      bool variant_ok = true;
      for (int s = 0; s < kStageCount; ++s) {
        Stage stage = Stage(s);
        if (!program.has_stage(stage)) continue;
        auto cache_key = std::make_pair(stage, variants::project(sel.keywords, key, stage));
        auto [it, inserted] = cache.try_emplace(cache_key);
        StageEntry& entry = it->second;
        if (inserted) {
          auto stage_keywords = variants::stage_keywords(sel.keywords, key, stage);
          auto compiled = backend_.compile(shader, program, stage, stage_keywords, options.backend, sources,
                                           entry.diags);
          add_variant_context(entry.diags, label, stage, stage_keywords);
          ++out.stats.stage_programs;
          if (compiled) {
            entry.ok = true;
            entry.blob = uint32_t(pkg.spirv_blobs.size());
            pkg.spirv_blobs.push_back(std::move(compiled->spirv));
            entry.reflection = std::move(compiled->reflection);
            dependencies.insert(compiled->included_files.begin(), compiled->included_files.end());
          }
        }
        variant_diags.append(entry.diags);
        if (!entry.ok) {
          variant_ok = false;
          continue;
        }
        pv.stages.push_back({.stage = stage, .blob = entry.blob, .reflection = entry.reflection});
      }
      if (variant_ok) pp.variants.push_back(std::move(pv));
      per_variant.push_back(std::move(variant_diags));
    }
    Diagnostics merged = merge_variant_duplicates(per_variant);
    if (merged.has_errors()) failed = true;
    diags.append(merged);
    out.stats.variants += pp.variants.size();
    ++out.stats.passes;
    std::sort(pp.variants.begin(), pp.variants.end(),
              [](const auto& a, const auto& b) { return a.key < b.key; });
    pkg.passes.push_back(std::move(pp));
  }
  if (failed) return failure("compile errors");

  package::deduplicate_blobs(pkg);
  Diagnostics invariant;
  if (!package::validate_package(pkg, invariant)) FACET_ICE("the driver built an invalid package");
  out.stats.unique_spirv = pkg.spirv_blobs.size();
  out.dependencies.assign(dependencies.begin(), dependencies.end());
  out.stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  return out;
}

}  // namespace facet
