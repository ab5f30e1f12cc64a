// The report for a terminal.
#include <fmt/format.h>

#include <algorithm>

#include "facet/report.h"
#include "ladder_columns.h"
#include "facet/support/text.h"

namespace facet::report {
namespace {

std::string set_words(const KeywordSetRow& s) {
  std::string out;
  for (const std::string& k : s.keywords) out += (out.empty() ? "" : " ") + (k.empty() ? std::string("_") : k);
  return out;
}

void ladder_table(const PassReport& p, std::string& out) {
  std::vector<LadderColumn> columns = ladder_columns(p);
  out += fmt::format("  {:<10}", "");
  for (const LadderColumn& c : columns) out += fmt::format(" {:>12}", c.short_header);
  out += "\n";
  for (const Ladder& l : p.ladders) {
    out += fmt::format("  {:<10}", l.scope);
    for (const LadderColumn& c : columns) out += fmt::format(" {:>12}", c.value(l));
    out += "\n";
  }
  if (!p.enumerated) {
    out += fmt::format("  not enumerated: {} variants are more than --max-variants allows; the counts are exact, "
                       "only the default variant was compiled, and the what-ifs count stage programs before "
                       "deduplication\n",
                       p.ladders.empty() ? std::string("its") : p.ladders.front().reachable.to_string());
  }
  if (!p.unreachable_keywords.empty()) {
    out += fmt::format("  unreachable: {} (facet's renderer never enables them: counted in full and materials, "
                       "not built unless --build-unreachable)\n",
                       fmt::join(p.unreachable_keywords, " "));
  }
}

void pass_text(const PassReport& p, std::string& out) {
  out += fmt::format("pass #{}{}{}: {:.3f} s compiling, {} bytes of SPIR-V\n", p.index,
                     p.name.empty() ? "" : " '" + p.name + "'", p.light_mode.empty() ? "" : " (" + p.light_mode + ")",
                     p.compile_seconds, p.spirv_bytes);
  ladder_table(p, out);
  for (const KeywordSetRow& s : p.sets) {
    out += fmt::format("  x{:<4} {} {}  [{}]\n", s.factor, s.pragma, set_words(s), fmt::join(s.stages, " "));
  }
  for (const Finding& f : p.findings) {
    out += fmt::format("  {}: '{}'{}: {}\n", finding_name(f.kind), f.keyword,
                       f.stage.empty() ? "" : " in " + f.stage, f.detail);
  }
  for (const WhatIf& w : p.what_ifs) {
    out += fmt::format("  what if: {} -> {} programs fewer, ~{:.3f} s\n", w.change, w.programs_saved.to_string(),
                       w.seconds_saved);
  }
  std::vector<const VariantRow*> slowest;
  for (const VariantRow& v : p.variants) {
    if (v.seconds > 0) slowest.push_back(&v);
  }
  std::stable_sort(slowest.begin(), slowest.end(), [](auto* a, auto* b) { return a->seconds > b->seconds; });
  if (slowest.size() > 5) slowest.resize(5);
  for (const VariantRow* v : slowest) {
    out += fmt::format("  slow: {{{}}} {:.4f} s, {} bytes\n", fmt::join(v->keywords, " "), v->seconds, v->spirv_bytes);
  }
}

std::string pass_label(const PlannedStep& s) {
  return fmt::format("pass #{}{}", s.pass, s.pass_name.empty() ? "" : " '" + s.pass_name + "'");
}

void summary_text(const StripPlan& plan, std::string& out) {
  if (plan.steps.empty()) {
    out += fmt::format("summary: {} now; no keyword set a strip file could hold at its default saves a program\n",
                       count_of(plan.programs_now, "program", "programs"));
  } else {
    std::string which = plan.steps.size() == 1 ? "the best what-if"
                                               : fmt::format("the {} best what-ifs", plan.steps.size());
    out += fmt::format("summary: {} now, {} after {} a strip file applies ({} fewer, ~{:.3f} s saved; "
                       "--emit-strip FILE writes {}):\n",
                       count_of(plan.programs_now, "program", "programs"), plan.programs_after, which,
                       plan.programs_now - plan.programs_after, plan.seconds_saved,
                       plan.steps.size() == 1 ? "it" : "them");
    for (size_t i = 0; i < plan.steps.size(); ++i) {
      const PlannedStep& s = plan.steps[i];
      out += fmt::format("  {}. {}: {} -> {} fewer, ~{:.3f} s\n", i + 1, pass_label(s), s.step.change,
                         s.step.programs_saved, s.step.seconds_saved);
    }
  }
  if (plan.passes_not_enumerated > 0) {
    out += fmt::format("  ({} too large to enumerate {} not in these figures; see {} what-ifs)\n",
                       count_of(plan.passes_not_enumerated, "pass", "passes"),
                       plan.passes_not_enumerated == 1 ? "is" : "are",
                       plan.passes_not_enumerated == 1 ? "its" : "their");
  }
}

}  // namespace

std::string to_text(const std::vector<ShaderReport>& reports) {
  std::string out;
  for (const ShaderReport& r : reports) {
    out += fmt::format("shader '{}' ({}): {}, {} compiled, {:.3f} s\n", r.name, r.path,
                       count_of(r.programs, "program", "programs"), r.compiled, r.compile_seconds);
    if (r.estimate) {
      out += fmt::format("estimate (as --estimate gives it before a build): ~{:.2f} s on {} threads ({} programs to compile at {:.1f} ms, "
                         "from {} sampled; preprocessing {:.2f} s)\n",
                         r.estimate->estimated_seconds, r.estimate->jobs, r.estimate->unique,
                         1000 * r.estimate->seconds_per_program, r.estimate->sampled,
                         r.estimate->preprocess_seconds);
    }
    summary_text(strip_plan(r), out);
    for (const PassReport& p : r.passes) pass_text(p, out);
    out += "\n";
  }
  return out;
}

}  // namespace facet::report
