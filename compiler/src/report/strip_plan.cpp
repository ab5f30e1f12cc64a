// The what-ifs a strip file can apply, and the shader's summary built from
// them: which keyword sets to hold in their default state, and what the
// build left by those strip rules compiles.
#include <fmt/format.h>

#include <algorithm>
#include <map>
#include <set>

#include "facet/report.h"
#include "findings.h"

namespace facet::report {
namespace {

using CompileId = std::pair<int, uint64_t>;  // (stage, relevant-token hash): one compile

// The pass as built: each variant's keywords and the stage programs it
// needs, and what compiling each program cost.
struct BuiltPass {
  std::vector<const std::vector<std::string>*> variant_keywords;
  std::vector<std::vector<uint32_t>> variant_programs;  // program ids
  std::vector<CompileId> program_compile;                // by program id
  std::map<CompileId, double> compile_seconds;
};

// A compile that another pass also needs is not saved by any step of this
// pass, so its seconds are left out.
BuiltPass built_pass(const SelectedPass& pass, const package::PackagePass& built,
                     const std::vector<ProgramRecord>& records, uint32_t pass_index) {
  BuiltPass out;
  std::map<std::pair<int, std::vector<std::string>>, const ProgramRecord*> record_of;
  std::set<CompileId> used_elsewhere;
  for (const ProgramRecord& r : records) {
    if (r.pass != pass_index) used_elsewhere.insert({int(r.stage), r.token_hash});
  }
  for (const ProgramRecord& r : records) {
    if (r.pass != pass_index) continue;
    record_of.emplace(std::make_pair(int(r.stage), r.keywords), &r);
    CompileId id{int(r.stage), r.token_hash};
    if (r.compiled && !used_elsewhere.count(id)) out.compile_seconds[id] += r.seconds;
  }
  // Programs as the build plans them: one per (stage, the key projected on it).
  std::map<std::pair<int, variants::VariantKey>, uint32_t> program_ids;
  for (const package::PackageVariant& v : built.variants) {
    out.variant_keywords.push_back(&v.keywords);
    std::vector<uint32_t>& programs = out.variant_programs.emplace_back();
    for (const package::PackageStage& st : v.stages) {
      auto key = std::make_pair(int(st.stage), variants::project(pass.keywords, v.key, st.stage));
      auto [it, added] = program_ids.emplace(key, uint32_t(program_ids.size()));
      if (added) {
        auto r = record_of.find({int(st.stage), variants::stage_keywords(pass.keywords, v.key, st.stage)});
        out.program_compile.push_back({int(st.stage), r == record_of.end() ? 0 : r->second->token_hash});
      }
      programs.push_back(it->second);
    }
  }
  return out;
}

struct Left {
  size_t variants = 0, programs = 0;
  double seconds = 0;  // of the compiles still needed
};

// What a build with every keyword of `off` always off keeps of the pass.
Left left_with(const BuiltPass& pass, const std::set<std::string>& off) {
  Left left;
  std::vector<char> alive(pass.program_compile.size(), 0);
  for (size_t v = 0; v < pass.variant_keywords.size(); ++v) {
    const std::vector<std::string>& keywords = *pass.variant_keywords[v];
    if (std::any_of(keywords.begin(), keywords.end(), [&](const std::string& k) { return off.count(k) > 0; })) continue;
    ++left.variants;
    for (uint32_t id : pass.variant_programs[v]) alive[id] = 1;
  }
  std::set<CompileId> compiles;
  for (size_t id = 0; id < alive.size(); ++id) {
    if (!alive[id]) continue;
    ++left.programs;
    compiles.insert(pass.program_compile[id]);
  }
  for (const CompileId& c : compiles) {
    auto it = pass.compile_seconds.find(c);
    if (it != pass.compile_seconds.end()) left.seconds += it->second;
  }
  return left;
}

// The keywords a set's non-default states enable: all of them when it has
// an off state "_", else all but the first.
std::vector<std::string> non_default_keywords(const variants::KeywordSet& set) {
  bool has_off = std::find(set.keywords.begin(), set.keywords.end(), "") != set.keywords.end();
  std::vector<std::string> out;
  for (size_t i = 0; i < set.keywords.size(); ++i) {
    if (set.keywords[i].empty() || (!has_off && i == 0)) continue;
    out.push_back(set.keywords[i]);
  }
  return out;
}

// A keyword a manifest's material enables is in use: a strip rule that
// turns it off would take that material's variants away.
bool used_by_materials(const std::vector<std::string>& keywords, const ReportOptions& options) {
  if (!options.materials) return false;
  for (const variants::KeywordList& material : *options.materials) {
    for (const std::string& k : keywords) {
      if (std::find(material.begin(), material.end(), k) != material.end()) return true;
    }
  }
  return false;
}

bool better(const StripStep& a, const StripStep& b) {
  if (a.programs_saved != b.programs_saved) return a.programs_saved > b.programs_saved;
  return a.seconds_saved > b.seconds_saved;
}

}  // namespace

std::vector<StripStep> strip_steps(const SelectedPass& pass, const package::PackagePass& built,
                                   const std::vector<ProgramRecord>& records, uint32_t pass_index,
                                   const ReportOptions& options, size_t max_steps) {
  BuiltPass programs = built_pass(pass, built, records, pass_index);
  std::vector<StripStep> candidates;
  std::set<std::vector<std::string>> seen;
  for (const variants::KeywordSet& set : pass.keywords.sets) {
    std::vector<std::string> off = non_default_keywords(set);
    if (off.empty() || !seen.insert(off).second || used_by_materials(off, options)) continue;
    bool has_off = std::find(set.keywords.begin(), set.keywords.end(), "") != set.keywords.end();
    std::string held = has_off ? "off" : "at " + set.keywords.front();
    candidates.push_back({.change = fmt::format("hold '{}' {} (always_off {})", set_spelling(set), held,
                                                fmt::join(off, " ")),
                          .always_off = off});
  }
  std::set<std::string> chosen_off;
  Left current = left_with(programs, chosen_off);
  std::vector<StripStep> steps;
  std::vector<bool> used(candidates.size(), false);
  while (steps.size() < max_steps) {
    std::optional<size_t> best;
    Left best_left;
    for (size_t c = 0; c < candidates.size(); ++c) {
      if (used[c]) continue;
      std::set<std::string> off = chosen_off;
      off.insert(candidates[c].always_off.begin(), candidates[c].always_off.end());
      Left left = left_with(programs, off);
      if (left.variants == 0 || left.programs >= current.programs) continue;
      candidates[c].programs_saved = current.programs - left.programs;
      candidates[c].seconds_saved = std::max(0.0, current.seconds - left.seconds);
      if (!best || better(candidates[c], candidates[*best])) {
        best = c;
        best_left = left;
      }
    }
    if (!best) break;
    used[*best] = true;
    chosen_off.insert(candidates[*best].always_off.begin(), candidates[*best].always_off.end());
    current = best_left;
    steps.push_back(candidates[*best]);
  }
  return steps;
}

StripPlan strip_plan(const ShaderReport& report, size_t max_steps) {
  StripPlan plan;
  std::vector<size_t> next(report.passes.size(), 0);
  for (const PassReport& p : report.passes) {
    if (!p.enumerated) {
      ++plan.passes_not_enumerated;
      continue;
    }
    if (!p.ladders.empty()) plan.programs_now += p.ladders.front().programs;
  }
  plan.programs_after = plan.programs_now;
  // Passes build independently, so the best next step of the shader is the
  // best of each pass's next step.
  while (plan.steps.size() < max_steps) {
    std::optional<size_t> best;
    for (size_t i = 0; i < report.passes.size(); ++i) {
      const std::vector<StripStep>& steps = report.passes[i].strip_steps;
      if (next[i] >= steps.size()) continue;
      if (!best || better(steps[next[i]], report.passes[*best].strip_steps[next[*best]])) best = i;
    }
    if (!best) break;
    const PassReport& p = report.passes[*best];
    const StripStep& step = p.strip_steps[next[*best]++];
    plan.steps.push_back({.pass = p.index, .pass_name = p.name, .step = step});
    plan.programs_after -= std::min(plan.programs_after, step.programs_saved);
    plan.seconds_saved += step.seconds_saved;
  }
  return plan;
}

}  // namespace facet::report
