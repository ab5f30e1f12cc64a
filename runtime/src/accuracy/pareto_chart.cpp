// The Pareto chart of the study as SVG: a header (device, caveat, family
// colours), a panel of image errors (every row with one, on one axis) and
// one panel per error kind, on a shared log time axis, point labels
// placed by chart::place_labels, and a numbered legend for the labels that
// did not fit.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>

#include "accuracy/pareto_chart.h"
#include "facet/markup.h"
#include "facet/runtime/accuracy.h"
#include "facet/runtime/chart.h"

namespace facet::runtime::accuracy {
namespace {

constexpr double kWidth = 960, kLeft = 84, kRight = 24, kPanelHeight = 190, kMarker = 4.5, kLabelSize = 10;
const std::string kText = "#222222", kMuted = "#666666", kLeader = "#999999";

struct Family {
  const char* group;
  const char* colour;
};
// A fixed colour per model family (the catalogue's groups), in legend order.
constexpr Family kFamilies[] = {{"D", "#8c564b"},        {"V", "#1f77b4"},      {"F", "#ff7f0e"},
                                {"diffuse", "#2ca02c"},  {"specular", "#d62728"}, {"Standard", "#9467bd"},
                                {"IBL", "#17becf"},      {"tonemap", "#e377c2"}, {"sRGB", "#bcbd22"},
                                {"translucency", "#7f7f7f"}};
constexpr const char* kOtherFamily = "#444444";

std::string family_colour(const std::string& group) {
  for (const Family& f : kFamilies) {
    if (group == f.group) return f.colour;
  }
  return kOtherFamily;
}

double headline_error(const StudyRow& r) { return r.error; }
double image_rmse(const StudyRow& r) {
  const ImageError* worst = worst_image_error(r);
  return worst ? worst->rmse : 0.0;
}

// A panel: which rows it draws and what its error axis reads.
struct PanelKind {
  std::optional<ErrorKind> kind;  // none: the image panel (rows with image errors)
  const char* title;
  const char* axis;
  double (*error)(const StudyRow&);
  bool member(const StudyRow& r) const { return kind ? error_kind(r) == *kind : !r.image.empty(); }
};
constexpr PanelKind kPanels[] = {
    {std::nullopt, "Image error: RMSE in the worst test scene against the Monte Carlo reference", "image RMSE", image_rmse},
    {ErrorKind::lobe, "Lobe error: max relL1 = ∫|f − f_ref|·cos / ∫f_ref·cos over the hemisphere", "relL1", headline_error},
    {ErrorKind::energy, "Energy error: directional albedo above 1, or energy lost", "energy error", headline_error},
    {ErrorKind::pointwise, "Pointwise error: largest absolute difference over the input range", "max abs error", headline_error},
    {ErrorKind::fp16, "Half precision: largest relative error against fp64", "rel. error", headline_error},
};

bool timed(const StudyRow& r) { return r.ns_per_eval && *r.ns_per_eval > 0; }
bool drawable(const StudyRow& r, const PanelKind& k) {
  double e = k.error(r);
  return timed(r) && e > 0 && std::isfinite(e);
}

// Pareto-optimal within its family and panel: no other such row is both
// cheaper and more accurate.
bool pareto(const StudyRow& r, const std::vector<const StudyRow*>& panel, const PanelKind& k) {
  for (const StudyRow* o : panel) {
    if (o == &r || o->group != r.group) continue;
    double oe = k.error(*o), re = k.error(r);
    if (*o->ns_per_eval <= *r.ns_per_eval && oe <= re && (*o->ns_per_eval < *r.ns_per_eval || oe < re)) return false;
  }
  return true;
}

// A log axis over [lo, hi] widened by a margin (to a decade around a single
// value), with ticks at 1-2-5 steps inside it.
struct LogAxis {
  double lo = 1, hi = 10;
  double p0 = 0, p1 = 1;  // pixels of lo and hi
  double at(double v) const { return p0 + (std::log10(v) - std::log10(lo)) / (std::log10(hi) - std::log10(lo)) * (p1 - p0); }
};
LogAxis log_axis(double lo, double hi, double p0, double p1) {
  const double span = std::log10(hi / lo);
  const double margin = span < 0.5 ? (1.0 - span) / 2 : 0.06 * span;
  return {lo / std::pow(10.0, margin), hi * std::pow(10.0, margin), p0, p1};
}
// The 1-2-5 value after v.
double step_up(double v) {
  double p = std::pow(10.0, std::floor(std::log10(v) + 1e-9));
  double m = v / p;
  return m < 1.5 ? 2 * p : m < 3.5 ? 5 * p : 10 * p;
}
// Tick values: 1-2-5 steps, or decades where those would be closer than min_gap pixels.
std::vector<double> ticks(const LogAxis& a, double min_gap) {
  std::vector<double> out;
  const bool decades = std::abs(a.at(2 * a.lo) - a.at(a.lo)) < min_gap;
  for (double v = std::pow(10.0, std::floor(std::log10(a.lo))); v <= a.hi; v = step_up(v)) {
    double mantissa = v / std::pow(10.0, std::floor(std::log10(v) + 1e-9));
    if (v >= a.lo && (!decades || std::abs(mantissa - 1) < 1e-6)) out.push_back(v);
  }
  return out;
}
std::string tick_text(double v) {
  if (v >= 1e-3 && v < 1e5) return fmt::format("{:g}", v);
  int e = int(std::floor(std::log10(v) + 1e-9));
  return fmt::format("{:g}e{}", std::round(v / std::pow(10.0, e)), e);
}

std::string text(double x, double y, double size, const std::string& s, const std::string& attrs = "",
                 const std::string& colour = kText) {
  return fmt::format(R"(<text x="{:.1f}" y="{:.1f}" font-size="{}" fill="{}"{}{}>{}</text>)", x, y, size, colour,
                     attrs.empty() ? "" : " ", attrs, xml_escape(s));
}

struct Header {
  std::string svg;
  double height = 0;
};

// Title, device, caveat, family colours and marker meaning.
std::string default_subtitle(const Study& study) {
  return fmt::format("Device: {}. Timed pass: {}x{} invocations, {} evaluations each, median of {} dispatches, "
                     "minus a null pass.",
                     study.device, study.options.width, study.options.height, study.options.evaluations,
                     study.options.frames);
}

Header header(const Study& study, const std::vector<std::string>& families, const ChartTitles& titles) {
  Header h;
  double y = 22;
  h.svg += text(12, y, 15, titles.title);
  y += 20;
  h.svg += text(12, y, 11, titles.subtitle.empty() ? default_subtitle(study) : titles.subtitle, "", kMuted);
  if (timed_on_cpu(study)) {
    y += 18;
    const std::string name = study.device.find("llvmpipe") != std::string::npos ? "lavapipe" : study.device;
    h.svg += text(12, y, 12,
                  fmt::format("Caveat: times measured on {}, a CPU implementation of Vulkan: relative only, not GPU costs.",
                              name),
                  R"(class="caveat" font-weight="bold")", "#b22222");
  }
  y += 22;
  double x = 12;
  for (const std::string& f : families) {
    double w = chart::text_width(f, 11) + 28;
    if (x + w > kWidth - kRight) x = 12, y += 18;
    h.svg += chart::marker_svg(chart::MarkerShape::circle, x + 5, y - 4, kMarker, family_colour(f), true, R"(class="swatch")");
    h.svg += text(x + 14, y, 11, f);
    x += w;
  }
  y += 18;
  h.svg += chart::marker_svg(chart::MarkerShape::circle, 17, y - 4, kMarker, kText, true, R"(class="swatch")");
  h.svg += text(26, y, 11, "Pareto-optimal within its family (nothing in the family is both cheaper and more accurate)");
  double x2 = 26 + chart::text_width("Pareto-optimal within its family (nothing in the family is both cheaper and more accurate)", 11) + 24;
  h.svg += chart::marker_svg(chart::MarkerShape::circle, x2 + 5, y - 4, kMarker, kText, false, R"(class="swatch")");
  h.svg += text(x2 + 14, y, 11, "dominated");
  h.height = y + 14;
  return h;
}

struct Panel {
  std::string svg;
  std::vector<std::string> legend;  // numbered entries: "3: id"
  double height = 0;
};

std::string axes(const LogAxis& x, const LogAxis& y, const chart::Box& area, const std::string& y_title) {
  std::string s = fmt::format(R"(<rect x="{}" y="{}" width="{}" height="{}" fill="#fafafa" stroke="#999999"/>)", area.x0,
                              area.y0, area.width(), area.height());
  for (double v : ticks(x, 40)) {
    s += fmt::format(R"(<line x1="{0:.1f}" x2="{0:.1f}" y1="{1}" y2="{2}" stroke="#dddddd"/>)", x.at(v), area.y0, area.y1);
    s += text(x.at(v), area.y1 + 18, 11, tick_text(v * 1000), R"(text-anchor="middle")");
  }
  for (double v : ticks(y, 15)) {
    s += fmt::format(R"(<line x1="{0}" x2="{1}" y1="{2:.1f}" y2="{2:.1f}" stroke="#dddddd"/>)", area.x0, area.x1, y.at(v));
    s += text(area.x0 - 6, y.at(v) + 4, 11, tick_text(v), R"(text-anchor="end")");
  }
  double mid = (area.y0 + area.y1) / 2;
  s += text(18, mid, 12, y_title, fmt::format(R"x(text-anchor="middle" transform="rotate(-90 18 {:.1f})")x", mid));
  return s;
}

// Where a marker goes: its own place, or, when that would hide part of a
// marker already placed (two rows of nearly the same cost and error), the
// nearest free place on growing rings around it, so that every point stays
// visible; deterministic, and at most a few pixels off for a pair.
std::pair<double, double> dodge(double x, double y, const std::vector<std::pair<double, double>>& placed) {
  const double min_distance = 2 * kMarker + 1.5;
  auto free_at = [&](double cx, double cy) {
    return std::none_of(placed.begin(), placed.end(),
                        [&](const auto& p) { return std::hypot(p.first - cx, p.second - cy) < min_distance; });
  };
  if (free_at(x, y)) return {x, y};
  for (double radius = 1; radius <= 8 * min_distance; radius += 1) {
    for (int k = 0; k < 16; ++k) {
      double angle = k * M_PI / 8;
      double cx = x + radius * std::cos(angle), cy = y - radius * std::sin(angle);
      if (free_at(cx, cy)) return {cx, cy};
    }
  }
  return {x, y};
}

// One panel: its title, axes, points and labels; `top` is where it starts.
Panel panel(const PanelKind& kind, const std::vector<const StudyRow*>& rows, const LogAxis& x_axis, double top,
            int first_number) {
  Panel p;
  std::vector<const StudyRow*> points;
  std::string off_chart;
  for (const StudyRow* r : rows) {
    if (drawable(*r, kind)) points.push_back(r);
    else if (timed(*r) && !std::isfinite(kind.error(*r))) off_chart += (off_chart.empty() ? "" : ", ") + r->id + " (inf: overflow)";
  }
  p.svg += text(12, top + 14, 12, kind.title, R"(class="panel-title" font-weight="bold")");
  double y = top + 14;
  if (!off_chart.empty()) {
    y += 16;
    p.svg += text(12, y, 11, "not drawn: " + off_chart, "", kMuted);
  }
  const double height = points.size() <= 2 ? kPanelHeight * 0.6 : kPanelHeight;
  const chart::Box area{kLeft, y + 14, kWidth - kRight, y + 14 + height};
  double lo = 1e300, hi = 0;
  for (const StudyRow* r : points) lo = std::min(lo, kind.error(*r)), hi = std::max(hi, kind.error(*r));
  LogAxis y_axis = log_axis(lo, hi, area.y1, area.y0);
  LogAxis x = x_axis;
  p.svg += axes(x, y_axis, area, kind.axis);

  std::vector<chart::LabelRequest> requests;
  chart::LayoutOptions options{.area = {area.x0 + 2, area.y0 + 2, area.x1 - 2, area.y1 - 2},
                               .font_size = kLabelSize,
                               .first_number = first_number};
  std::vector<std::pair<double, double>> placed;
  for (const StudyRow* r : points) {
    auto [px, py] = dodge(x.at(*r->ns_per_eval), y_axis.at(kind.error(*r)), placed);
    placed.push_back({px, py});
    requests.push_back({px, py, kMarker, r->id});
    options.obstacles.push_back(chart::square_around(px, py, kMarker + 1));
  }
  chart::LabelLayout layout = chart::place_labels(requests, options);
  std::string marks, labels, leaders;
  for (size_t i = 0; i < points.size(); ++i) {
    const StudyRow& r = *points[i];
    const chart::PlacedLabel& l = layout.labels[i];
    marks += fmt::format(R"(<g><title>{}: error {:.3g}, {:.3g} ps</title>{}</g>)", xml_escape(r.id), kind.error(r),
                         *r.ns_per_eval * 1000,
                         chart::marker_svg(chart::MarkerShape::circle, requests[i].x, requests[i].y, kMarker,
                                           family_colour(r.group), pareto(r, points, kind),
                                           fmt::format(R"(class="point" data-id="{}")", xml_escape(r.id))));
    if (l.has_leader) {
      leaders += fmt::format(R"(<line class="leader" x1="{:.1f}" y1="{:.1f}" x2="{:.1f}" y2="{:.1f}" stroke="{}"/>)",
                             l.leader_x0, l.leader_y0, l.leader_x1, l.leader_y1, kLeader);
    }
    if (l.placement != chart::Placement::legend_only) {
      labels += text(l.baseline_x, l.baseline_y, kLabelSize, l.text, R"(class="label")");
    }
    if (l.number > 0) p.legend.push_back(fmt::format("{}: {}", l.number, r.id));
  }
  // Leaders under the markers, markers under nothing: every point stays visible.
  p.svg += leaders + marks + labels;
  p.height = area.y1 + 24 - top;
  return p;
}

}  // namespace

std::string study_chart_svg(const Study& study) {
  return pareto_chart_svg(study, {.title = "Accuracy against cost: error of each approximation against GPU time per evaluation",
                                  .subtitle = "",
                                  .time_axis = "GPU time per evaluation, ps (minus the null pass; log scale, the same in every panel)"});
}

std::string pareto_chart_svg(const Study& study, const ChartTitles& titles) {
  std::vector<std::vector<const StudyRow*>> panel_rows(std::size(kPanels));
  std::vector<std::string> families;
  double lo = 1e300, hi = 0;
  for (const StudyRow& r : study.rows) {
    if (!timed(r)) continue;
    for (size_t k = 0; k < std::size(kPanels); ++k) {
      if (!kPanels[k].member(r)) continue;
      panel_rows[k].push_back(&r);
      if (std::find(families.begin(), families.end(), r.group) == families.end()) families.push_back(r.group);
      if (drawable(r, kPanels[k])) lo = std::min(lo, *r.ns_per_eval), hi = std::max(hi, *r.ns_per_eval);
    }
  }
  if (hi == 0) {
    return R"(<svg xmlns="http://www.w3.org/2000/svg" width="560" height="24" font-family="DejaVu Sans, sans-serif">)"
           R"(<text x="4" y="16" font-size="12">No row has both an error and a GPU time (run with a GPU to draw the chart).</text></svg>)"
           "\n";
  }
  std::sort(families.begin(), families.end(), [](const std::string& a, const std::string& b) {
    auto rank = [](const std::string& g) {
      for (size_t i = 0; i < std::size(kFamilies); ++i)
        if (g == kFamilies[i].group) return i;
      return std::size(kFamilies);
    };
    return rank(a) != rank(b) ? rank(a) < rank(b) : a < b;
  });
  const LogAxis x_axis = log_axis(lo, hi, kLeft, kWidth - kRight);
  Header h = header(study, families, titles);
  std::string body = h.svg;
  std::vector<std::string> legend;
  double y = h.height;
  for (size_t i = 0; i < std::size(kPanels); ++i) {
    const PanelKind& k = kPanels[i];
    const std::vector<const StudyRow*>& rows = panel_rows[i];
    if (std::none_of(rows.begin(), rows.end(), [&](const StudyRow* r) { return drawable(*r, k); })) continue;
    Panel p = panel(k, rows, x_axis, y, int(legend.size()) + 1);
    body += p.svg;
    legend.insert(legend.end(), p.legend.begin(), p.legend.end());
    y += p.height;
  }
  y += 16;
  body += text((kLeft + kWidth - kRight) / 2, y, 12, titles.time_axis, R"(text-anchor="middle")");
  for (const std::string& entry : legend) {
    y += 16;
    body += text(12, y, 11, entry, R"(class="legend")");
  }
  return fmt::format(R"(<svg xmlns="http://www.w3.org/2000/svg" width="{0}" height="{1}" viewBox="0 0 {0} {1}" )"
                     R"(font-family="DejaVu Sans, sans-serif" class="pareto">)"
                     "\n<rect width=\"{0}\" height=\"{1}\" fill=\"#ffffff\"/>\n{2}\n</svg>\n",
                     kWidth, int(y + 12), body);
}

}  // namespace facet::runtime::accuracy
