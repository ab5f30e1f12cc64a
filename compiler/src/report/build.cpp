// build_report: counts, sets and per-variant rows from a compile.
#include <fmt/format.h>

#include <algorithm>
#include <map>
#include <set>

#include "facet/report.h"
#include "findings.h"

namespace facet::report {
namespace {

std::vector<Stage> program_stages(const ir::Program& program) {
  std::vector<Stage> stages;
  for (int s = 0; s < kStageCount; ++s) {
    if (program.has_stage(Stage(s))) stages.push_back(Stage(s));
  }
  return stages;
}

Ladder count_ladder(const SelectedPass& pass, std::optional<Stage> stage, const ReportOptions& options,
                    const std::vector<ProgramRecord>& records, uint32_t pass_index, const package::PackagePass& pp) {
  variants::VariantCounts counts = variants::count_variants(pass.keywords, {.stage = stage, .materials = options.materials});
  Ladder ladder{.scope = stage ? std::string(stage_name(*stage)) : "pass", .full = counts.full,
                .after_skip = counts.after_skip, .after_materials = counts.after_materials,
                .reachable = counts.reachable, .has_materials = options.materials.has_value()};
  std::set<std::pair<int, uint64_t>> tokens;
  std::set<uint32_t> blobs;
  for (const ProgramRecord& r : records) {
    if (r.pass != pass_index || (stage && r.stage != *stage)) continue;
    ++ladder.programs;
    tokens.insert({int(r.stage), r.token_hash});
    if (r.blob != UINT32_MAX) blobs.insert(r.blob);
  }
  std::set<variants::VariantKey> views;
  for (const package::PackageVariant& v : pp.variants) {
    views.insert(stage ? variants::project(pass.keywords, v.key, *stage) : v.key);
  }
  ladder.after_strip = views.size();
  ladder.unique_tokens = tokens.size();
  ladder.unique_spirv = blobs.size();
  return ladder;
}

std::vector<KeywordSetRow> set_rows(const variants::KeywordSpace& space, const ir::Program& program) {
  std::vector<KeywordSetRow> rows;
  for (const variants::KeywordSet& set : space.sets) {
    KeywordSetRow row{.pragma = set.pragma, .keywords = set.keywords};
    for (Stage s : program_stages(program)) {
      if (set.applies_to(s)) row.stages.emplace_back(stage_name(s));
    }
    uint64_t states = 0;
    for (const std::string& k : set.keywords) {
      bool skipped = !k.empty() && std::find(space.skip_variants.begin(), space.skip_variants.end(), k) !=
                                       space.skip_variants.end();
      states += !skipped;
    }
    row.factor = std::max<uint64_t>(1, states);
    rows.push_back(std::move(row));
  }
  return rows;
}

// Each variant's time is that of the programs it was the first to need, so
// the rows add up to the pass's compile time.
std::vector<VariantRow> variant_rows(const SelectedPass& pass, const package::PackagePass& pp,
                                     const package::Package& pkg, const std::vector<ProgramRecord>& records,
                                     uint32_t pass_index) {
  std::map<std::pair<Stage, std::vector<std::string>>, const ProgramRecord*> by_program;
  for (const ProgramRecord& r : records) {
    if (r.pass == pass_index) by_program.emplace(std::make_pair(r.stage, r.keywords), &r);
  }
  std::set<const ProgramRecord*> counted;
  std::vector<VariantRow> rows;
  for (const package::PackageVariant& v : pp.variants) {
    VariantRow row{.keywords = v.keywords};
    for (const package::PackageStage& st : v.stages) {
      row.spirv_bytes += pkg.spirv_blobs[st.blob].size() * 4;
      auto it = by_program.find({st.stage, variants::stage_keywords(pass.keywords, v.key, st.stage)});
      if (it != by_program.end() && counted.insert(it->second).second) row.seconds += it->second->seconds;
    }
    rows.push_back(std::move(row));
  }
  return rows;
}

// Most programs saved first; a change that saves no program is no advice.
void sort_by_saving(std::vector<WhatIf>& what_ifs) {
  std::erase_if(what_ifs, [](const WhatIf& w) { return w.programs_saved.is_zero(); });
  std::stable_sort(what_ifs.begin(), what_ifs.end(), [](const WhatIf& a, const WhatIf& b) {
    if (a.programs_saved != b.programs_saved) return a.programs_saved > b.programs_saved;
    return a.seconds_saved > b.seconds_saved;
  });
}

}  // namespace

ShaderReport build_report(const ir::Shader& shader, const std::vector<SelectedPass>& passes,
                          const CompiledShader& compiled, const SourceMap& sources, const ReportOptions& options) {
  ShaderReport report{.path = sources.path(shader.file), .name = shader.name};
  const package::Package& pkg = compiled.package;
  for (uint32_t p = 0; p < passes.size() && p < pkg.passes.size(); ++p) {
    const SelectedPass& sel = passes[p];
    PassReport pr{.index = uint32_t(sel.pass), .name = sel.ir.name, .light_mode = sel.ir.tag("LightMode")};
    pr.ladders.push_back(count_ladder(sel, std::nullopt, options, compiled.programs, p, pkg.passes[p]));
    for (Stage s : program_stages(*sel.ir.program)) {
      pr.ladders.push_back(count_ladder(sel, s, options, compiled.programs, p, pkg.passes[p]));
    }
    pr.sets = set_rows(sel.keywords, *sel.ir.program);
    pr.unreachable_keywords = sel.keywords.unreachable_keywords;
    pr.variants = variant_rows(sel, pkg.passes[p], pkg, compiled.programs, p);
    std::set<uint32_t> blobs;
    for (const ProgramRecord& r : compiled.programs) {
      if (r.pass != p) continue;
      pr.compile_seconds += r.seconds;
      if (r.blob != UINT32_MAX && blobs.insert(r.blob).second) pr.spirv_bytes += pkg.spirv_blobs[r.blob].size() * 4;
      ++report.programs;
      report.compiled += r.compiled;
    }
    pr.findings = keyword_findings(shader, sel, compiled, sources, p);
    if (options.counted_only) {
      pr.enumerated = false;
      for (Ladder& l : pr.ladders) l.after_strip = l.programs = l.unique_tokens = l.unique_spirv = 0;
      uint64_t compiles = 0;
      for (const ProgramRecord& r : compiled.programs) compiles += r.pass == p && r.compiled;
      pr.what_ifs = counted_what_ifs(sel, options, compiles ? pr.compile_seconds / double(compiles) : 0);
    } else {
      pr.what_ifs = what_ifs(sel, compiled.programs, p, pr.compile_seconds, options);
      pr.strip_steps = strip_steps(sel, pkg.passes[p], compiled.programs, p, options);
    }
    sort_by_saving(pr.what_ifs);
    report.compile_seconds += pr.compile_seconds;
    report.passes.push_back(std::move(pr));
  }
  return report;
}

}  // namespace facet::report
