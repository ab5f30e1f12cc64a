// The report as one self-contained HTML page: tables plus inline SVG bar
// charts (variants per keyword set, compile time per pass). No scripts, no
// external resources: it reads the same offline.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "facet/markup.h"
#include "facet/report.h"
#include "ladder_columns.h"
#include "facet/support/text.h"

namespace facet::report {
namespace {

// Colours the chart tests look for in a screenshot.
constexpr const char* kSetBarColor = "#2f6fdf";
constexpr const char* kTimeBarColor = "#e8930c";

struct Bar {
  std::string label, value_text;
  double value = 0;
};

// A horizontal bar chart; bar length is proportional to `value`.
std::string bar_chart(const std::string& css_class, const char* color, const std::vector<Bar>& bars) {
  // Labels are right-aligned before the bars; the column fits the longest
  // (about 8 px per character at 13 px), within limits.
  size_t longest = 0;
  double max = 0;
  for (const Bar& b : bars) {
    longest = std::max(longest, b.label.size());
    max = std::max(max, b.value);
  }
  const int label_width = std::clamp(int(longest) * 8 + 16, 120, 720), bar_width = 420, row = 26;
  std::string svg = fmt::format(R"(<svg class="{}" xmlns="http://www.w3.org/2000/svg" width="{}" height="{}" role="img">)",
                                css_class, label_width + bar_width + 120, int(bars.size()) * row + 8);
  for (size_t i = 0; i < bars.size(); ++i) {
    const Bar& b = bars[i];
    int y = int(i) * row + 4;
    double w = max > 0 ? std::max(2.0, b.value / max * bar_width) : 2.0;
    svg += fmt::format(R"(<text x="{}" y="{}" text-anchor="end" font-size="13">{}</text>)", label_width - 8, y + 16,
                       xml_escape(b.label));
    svg += fmt::format(R"(<rect class="bar" x="{}" y="{}" width="{:.1f}" height="{}" fill="{}"/>)", label_width, y, w,
                       row - 8, color);
    svg += fmt::format(R"(<text x="{:.1f}" y="{}" font-size="13">{}</text>)", label_width + w + 6, y + 16,
                       xml_escape(b.value_text));
  }
  return svg + "</svg>\n";
}

std::string set_label(const KeywordSetRow& s) {
  std::string words;
  for (const std::string& k : s.keywords) words += (words.empty() ? "" : " ") + (k.empty() ? std::string("_") : k);
  return words;
}

std::string ladder_table(const PassReport& p) {
  std::vector<LadderColumn> columns = ladder_columns(p);
  std::string t = "<table class=\"ladder\"><tr><th></th>";
  for (const LadderColumn& c : columns) t += fmt::format("<th>{}</th>", xml_escape(c.long_header));
  t += "</tr>\n";
  for (const Ladder& l : p.ladders) {
    t += fmt::format("<tr><th>{}</th>", xml_escape(l.scope));
    for (const LadderColumn& c : columns) t += fmt::format("<td>{}</td>", c.value(l));
    t += "</tr>\n";
  }
  t += "</table>\n";
  if (!p.enumerated) {
    t += "<p>Not enumerated: more variants than <code>--max-variants</code> allows. The counts are exact, only the "
         "default variant was compiled, and the what-ifs count stage programs before deduplication.</p>\n";
  }
  if (!p.unreachable_keywords.empty()) {
    t += fmt::format("<p>unreachable: {} (facet's renderer never enables them: counted, not built unless "
                     "<code>--build-unreachable</code>)</p>\n",
                     xml_escape(fmt::format("{}", fmt::join(p.unreachable_keywords, " "))));
  }
  return t;
}

// The slowest variants with their compile times (each that of the programs
// it was first to need).
std::string slowest_table(const PassReport& p) {
  constexpr size_t kShown = 10;
  std::vector<const VariantRow*> slowest;
  for (const VariantRow& v : p.variants) {
    if (v.seconds > 0) slowest.push_back(&v);
  }
  if (slowest.empty()) return "";
  std::stable_sort(slowest.begin(), slowest.end(), [](auto* a, auto* b) { return a->seconds > b->seconds; });
  std::string h = fmt::format("<p class=\"caption\">The {} slowest of {} ({} compiled)</p>\n",
                              std::min(kShown, slowest.size()), count_of(p.variants.size(), "variant", "variants"),
                              slowest.size());
  h += "<table class=\"slowest\"><tr><th>variant keywords</th><th>compile seconds</th><th>SPIR-V bytes</th></tr>\n";
  for (size_t i = 0; i < slowest.size() && i < kShown; ++i) {
    const VariantRow& v = *slowest[i];
    std::string words = v.keywords.empty() ? "(none)" : fmt::format("{}", fmt::join(v.keywords, " "));
    h += fmt::format("<tr><td><code>{}</code></td><td>{:.4f}</td><td>{}</td></tr>\n", xml_escape(words), v.seconds,
                     v.spirv_bytes);
  }
  return h + "</table>\n";
}

std::string pass_section(const PassReport& p) {
  std::string h = fmt::format("<h3>pass #{}{}{}</h3>\n", p.index, p.name.empty() ? "" : " '" + xml_escape(p.name) + "'",
                              p.light_mode.empty() ? "" : " (" + xml_escape(p.light_mode) + ")");
  h += ladder_table(p);
  std::vector<Bar> bars;
  for (const KeywordSetRow& s : p.sets) {
    bars.push_back({fmt::format("{} {}", s.pragma, set_label(s)), fmt::format("×{}", s.factor),
                    std::log2(double(std::max<uint64_t>(s.factor, 1))) + 0.15});
  }
  if (!bars.empty()) {
    h += "<p class=\"caption\">Variants per keyword set (each multiplies the pass; bars on a log scale)</p>\n";
    h += bar_chart("chart-sets", kSetBarColor, bars);
  }
  if (!p.findings.empty()) {
    h += "<ul class=\"findings\">\n";
    for (const Finding& f : p.findings) {
      h += fmt::format("<li><b>{}</b> <code>{}</code>{}: {}</li>\n", finding_name(f.kind), xml_escape(f.keyword),
                       f.stage.empty() ? "" : " in " + xml_escape(f.stage), xml_escape(f.detail));
    }
    h += "</ul>\n";
  }
  if (!p.what_ifs.empty()) {
    h += "<table class=\"whatif\"><tr><th>what if</th><th>programs fewer</th><th>seconds saved</th></tr>\n";
    for (const WhatIf& w : p.what_ifs) {
      h += fmt::format("<tr><td>{}</td><td>{}</td><td>{:.3f}</td></tr>\n", xml_escape(w.change), w.programs_saved.to_string(),
                       w.seconds_saved);
    }
    h += "</table>\n";
  }
  h += slowest_table(p);
  return h;
}

std::string summary_section(const StripPlan& plan) {
  std::string h = fmt::format("<p class=\"summary\"><b>{}</b> now", count_of(plan.programs_now, "program", "programs"));
  if (plan.steps.empty()) {
    h += "; no keyword set a strip file could hold at its default saves a program";
  } else {
    h += fmt::format(", <b>{}</b> after the {} a strip file applies ({} fewer, ~{:.3f} s saved; "
                     "<code>--emit-strip FILE</code> writes {}):",
                     plan.programs_after,
                     plan.steps.size() == 1 ? std::string("best what-if") : fmt::format("{} best what-ifs", plan.steps.size()),
                     plan.programs_now - plan.programs_after, plan.seconds_saved, plan.steps.size() == 1 ? "it" : "them");
  }
  if (plan.passes_not_enumerated > 0) {
    h += fmt::format(" ({} too large to enumerate not in these figures)",
                     count_of(plan.passes_not_enumerated, "pass", "passes"));
  }
  h += "</p>\n";
  if (plan.steps.empty()) return h;
  h += "<ol class=\"summary-steps\">\n";
  for (const PlannedStep& s : plan.steps) {
    h += fmt::format("<li>pass #{}{}: {} &rarr; {} fewer, ~{:.3f} s</li>\n", s.pass,
                     s.pass_name.empty() ? "" : " '" + xml_escape(s.pass_name) + "'", xml_escape(s.step.change),
                     s.step.programs_saved, s.step.seconds_saved);
  }
  return h + "</ol>\n";
}

}  // namespace

std::string to_html(const std::vector<ShaderReport>& reports) {
  std::string h = R"(<!DOCTYPE html>
<html lang="en"><head><meta charset="utf-8"><title>facet variant report</title>
<style>
body { font-family: sans-serif; margin: 2em; color: #1d2430; }
table { border-collapse: collapse; margin: 0.5em 0 1em; }
th, td { border: 1px solid #c9cfd8; padding: 3px 8px; text-align: right; }
th:first-child, td:first-child { text-align: left; }
code { background: #eef1f5; padding: 0 3px; }
.caption { color: #56607a; margin-bottom: 0; }
</style></head><body>
<h1>facet variant report</h1>
)";
  std::vector<Bar> pass_times;
  for (const ShaderReport& r : reports) {
    for (const PassReport& p : r.passes) {
      pass_times.push_back({fmt::format("{} #{}{}", r.name, p.index, p.name.empty() ? "" : " " + p.name),
                            fmt::format("{:.3f} s", p.compile_seconds), p.compile_seconds});
    }
  }
  if (!pass_times.empty()) {
    h += "<p class=\"caption\">Compile time per pass</p>\n" + bar_chart("chart-time", kTimeBarColor, pass_times);
  }
  for (const ShaderReport& r : reports) {
    h += fmt::format("<h2>{}</h2>\n<p><code>{}</code>: {} programs, {} compiled, {:.3f} s</p>\n", xml_escape(r.name),
                     xml_escape(r.path), r.programs, r.compiled, r.compile_seconds);
    if (r.estimate) {
      h += fmt::format("<p>Estimate (as <code>--estimate</code> gives it before a build): ~{:.2f} s on {} threads ({} programs to compile at {:.1f} ms, "
                       "from {} sampled).</p>\n",
                       r.estimate->estimated_seconds, r.estimate->jobs, r.estimate->unique,
                       1000 * r.estimate->seconds_per_program, r.estimate->sampled);
    }
    h += summary_section(strip_plan(r));
    for (const PassReport& p : r.passes) h += pass_section(p);
  }
  return h + "</body></html>\n";
}

}  // namespace facet::report
