// The figures of the views: the polar plot, the albedo curve and the image
// panels, laid out in pixels (y down) for to_svg / to_png.
#include <fmt/format.h>

#include "brdf_internal.h"
#include "facet/reference/hlsl_math.h"

namespace facet::brdf {
namespace {

using glm::dvec2;
using reference::kPi;
constexpr double kDeg = kPi / 180.0;
const std::string kGrid = "#cccccc", kAxis = "#222222", kGuide = "#888888";
constexpr size_t kLegendChars = 96;

constexpr const char* kGuideDash = "6 4";

Stroke segment(dvec2 a, dvec2 b, const std::string& colour, double width, const std::string& dash = "") {
  return {{a, b}, colour, width, dash};
}

// Model i's curve in its series style, with markers along it (drawn over
// every curve). The markers of n curves start at different arc lengths, so
// that curves that coincide still show each one's markers.
void add_curve(Figure& f, std::vector<dvec2> points, size_t i, size_t n) {
  const chart::SeriesStyle style = chart::series_style(i);
  const double spacing = std::max(60.0, 15.0 * double(n));
  std::vector<chart::Point2> line;
  for (const dvec2& p : points) line.push_back({p.x, p.y});
  for (const chart::Point2& m : chart::points_along(line, spacing, spacing * (double(i) + 0.5) / double(n))) {
    f.marks.push_back({style.marker, dvec2(m.x, m.y), 3.5, style.colour, "marker", int(i)});
  }
  f.strokes.push_back({std::move(points), style.colour, 2.0, style.dash, "curve", int(i)});
}

// The smallest 1, 2, 2.5 or 5 times a power of ten that is >= x.
double nice_ceiling(double x) {
  if (!(x > 0.0)) return 1.0;
  double p = std::pow(10.0, std::floor(std::log10(x)));
  for (double m : {1.0, 1.5, 2.0, 2.5, 3.0, 4.0, 5.0, 6.0, 8.0, 10.0})
    if (m * p >= x * (1.0 - 1e-12)) return m * p;
  return 10.0 * p;
}

}  // namespace

std::vector<std::string> wrap_label(const std::string& label, size_t max_chars) {
  std::vector<std::string> lines{""};
  size_t start = 0;
  while (start < label.size()) {
    size_t comma = label.find(',', start);
    std::string piece = label.substr(start, comma == std::string::npos ? std::string::npos : comma + 1 - start);
    if (!lines.back().empty() && lines.back().size() + piece.size() > max_chars) lines.push_back("    ");
    lines.back() += piece;
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  return lines;
}

namespace {

// Returns the height used.
double add_legend(Figure& f, const std::vector<std::string>& labels, double y0) {
  double y = y0;
  for (size_t i = 0; i < labels.size(); ++i) {
    const chart::SeriesStyle style = chart::series_style(i);
    f.strokes.push_back(segment({14, y - 4}, {52, y - 4}, style.colour, 2.0, style.dash));
    f.marks.push_back({style.marker, dvec2(33, y - 4), 3.5, style.colour, "legend-marker"});
    for (const std::string& line : wrap_label(labels[i], kLegendChars)) {
      f.labels.push_back({{58, y}, line, "start", 12});
      y += 18;
    }
    y += 2;
  }
  return y - y0;
}

}  // namespace

Figure polar_figure(const std::vector<std::string>& labels, const std::vector<std::vector<PolarPoint>>& curves,
                    double incidence_deg, const std::string& channel) {
  const double R = 300, cx = 360, cy = 360;
  Figure f;
  f.width = 720;
  double peak = 0;
  for (const auto& c : curves)
    for (const PolarPoint& p : c) peak = std::max(peak, p.radius);
  const double rmax = nice_ceiling(peak);
  auto at = [&](double x, double y) { return dvec2(cx + x / rmax * R, cy - y / rmax * R); };

  for (int k = 1; k <= 4; ++k) {
    Stroke ring{{}, kGrid, 1.0};
    for (int a = 0; a <= 180; a += 2) ring.points.push_back(at(k / 4.0 * rmax * std::cos(a * kDeg), k / 4.0 * rmax * std::sin(a * kDeg)));
    f.strokes.push_back(ring);
    f.labels.push_back({at(k / 4.0 * rmax, 0) + dvec2(0, 14), fmt::format("{:.3g}", k / 4.0 * rmax), "middle", 10});
  }
  for (int a = -90; a <= 90; a += 30) {
    dvec2 dir(std::sin(a * kDeg), std::cos(a * kDeg));
    f.strokes.push_back(segment({cx, cy}, {cx + dir.x * R, cy - dir.y * R}, kGrid, 1.0));
    double lift = std::abs(a) == 90 ? -8 : 4;  // keeps the horizon labels off the radius labels
    f.labels.push_back({{cx + dir.x * (R + 18), cy - dir.y * (R + 16) + lift}, fmt::format("{}°", a), "middle", 10});
  }
  f.strokes.push_back(segment({cx - R, cy}, {cx + R, cy}, kAxis, 1.5));
  dvec2 light(-std::sin(incidence_deg * kDeg), std::cos(incidence_deg * kDeg));
  f.strokes.push_back(segment({cx, cy}, {cx + light.x * R, cy - light.y * R}, kGuide, 1.5, kGuideDash));
  f.labels.push_back({{cx + light.x * R * 0.9 - 8, cy - light.y * R * 0.9}, "light", "end", 11, kGuide});
  for (size_t i = 0; i < curves.size(); ++i) {
    std::vector<dvec2> points;
    for (const PolarPoint& p : curves[i]) points.push_back(at(p.x, p.y));
    add_curve(f, std::move(points), i, curves.size());
  }
  f.labels.push_back({{20, 24},
                      fmt::format("polar plot: f(l, v) cos θv in the plane of incidence, light at {}°, {}",
                                  incidence_deg, channel),
                      "start", 13});
  f.height = int(cy + 40 + add_legend(f, labels, cy + 40) + 10);
  return f;
}

Figure albedo_figure(const std::vector<std::string>& labels, const std::vector<std::vector<AlbedoPoint>>& curves,
                     Channel c, const std::string& channel) {
  const double x0 = 70, x1 = 690, y0 = 40, y1 = 400;
  Figure f;
  f.width = 720;
  double peak = 0;
  for (const auto& curve : curves)
    for (const AlbedoPoint& p : curve) peak = std::max(peak, channel_value(p.albedo, c));
  const double ymax = std::max(1.1, std::ceil(peak * 10.0) / 10.0 + 0.1);
  const double step = ymax <= 1.6 ? 0.1 : ymax <= 3.2 ? 0.2 : nice_ceiling(ymax / 10.0);
  auto at = [&](double theta, double e) { return dvec2(x0 + theta / 90.0 * (x1 - x0), y1 - e / ymax * (y1 - y0)); };

  for (int k = 0; k * step <= ymax + 1e-9; ++k) {
    double e = k * step;
    f.strokes.push_back(segment(at(0, e), at(90, e), kGrid, 1.0));
    f.labels.push_back({at(0, e) + dvec2(-6, 4), fmt::format("{:.2g}", e), "end", 10});
  }
  for (int t = 0; t <= 90; t += 15) {
    f.strokes.push_back(segment(at(t, 0), at(t, ymax), kGrid, 1.0));
    f.labels.push_back({at(t, 0) + dvec2(0, 16), fmt::format("{}°", t), "middle", 10});
  }
  f.strokes.push_back(segment(at(0, 1), at(90, 1), kGuide, 1.5, kGuideDash));
  f.strokes.push_back(segment(at(0, 0), at(90, 0), kAxis, 1.5));
  f.strokes.push_back(segment(at(0, 0), at(0, ymax), kAxis, 1.5));
  for (size_t i = 0; i < curves.size(); ++i) {
    std::vector<dvec2> points;
    for (const AlbedoPoint& p : curves[i]) points.push_back(at(p.theta_deg, channel_value(p.albedo, c)));
    add_curve(f, std::move(points), i, curves.size());
  }
  f.labels.push_back({{20, 24}, fmt::format("directional albedo E(θv) = ∫ f(v, l) cos θl dl, {}", channel), "start", 13});
  f.labels.push_back({{(x0 + x1) / 2, y1 + 34}, "view angle θv", "middle", 12});
  f.height = int(y1 + 56 + add_legend(f, labels, y1 + 56) + 10);
  return f;
}

Figure image_figure(const std::vector<Image8>& panels, const std::vector<std::string>& labels,
                    const std::string& caption) {
  const std::string text = "#e0e0e0";
  int size = panels.empty() ? 0 : panels[0].width;
  Figure f;
  f.background = "#202020";
  f.width = std::max(int(panels.size()) * (size + 8) + 8, 560);
  for (size_t i = 0; i < panels.size(); ++i) {
    double x = 8.0 + double(i) * (size + 8);
    f.images.push_back({dvec2(x, 32), panels[i]});
    f.labels.push_back({{x + size / 2.0, 32.0 + size + 16}, fmt::format("{}", i + 1), "middle", 12, text});
  }
  f.labels.push_back({{8, 22}, caption, "start", 13, text});
  double y = 32.0 + size + 24 + 12;
  for (size_t i = 0; i < labels.size(); ++i) {
    for (const std::string& line : wrap_label(fmt::format("{}: {}", i + 1, labels[i]), kLegendChars)) {
      f.labels.push_back({{8, y}, line, "start", 11, text});
      y += 16;
    }
  }
  f.height = int(y + 4);
  return f;
}

}  // namespace facet::brdf
