// The report for a terminal.
#include <fmt/format.h>

#include <algorithm>

#include "facet/report.h"
#include "facet/support/text.h"

namespace facet::report {
namespace {

std::string set_words(const KeywordSetRow& s) {
  std::string out;
  for (const std::string& k : s.keywords) out += (out.empty() ? "" : " ") + (k.empty() ? std::string("_") : k);
  return out;
}

// A rung that needs every program compiled: "-" for a pass counted only.
std::string compiled_rung(const PassReport& p, uint64_t value) { return p.enumerated ? std::to_string(value) : "-"; }

void ladder_table(const PassReport& p, std::string& out) {
  out += fmt::format("  {:<10} {:>12} {:>12} {:>12} {:>11} {:>12} {:>10} {:>10} {:>10}\n", "", "full", "after skip",
                     "materials", "reachable", "after strip", "programs", "unique pp", "unique spv");
  for (const Ladder& l : p.ladders) {
    out += fmt::format("  {:<10} {:>12} {:>12} {:>12} {:>11} {:>12} {:>10} {:>10} {:>10}\n", l.scope,
                       l.full.to_string(), l.after_skip.to_string(),
                       l.has_materials ? l.after_materials.to_string() : "-", l.reachable.to_string(),
                       compiled_rung(p, l.after_strip), compiled_rung(p, l.programs), compiled_rung(p, l.unique_tokens),
                       compiled_rung(p, l.unique_spirv));
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
    for (const PassReport& p : r.passes) pass_text(p, out);
    out += "\n";
  }
  return out;
}

}  // namespace facet::report
