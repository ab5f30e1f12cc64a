// The styles of overlaid curves and their markers: outlines, SVG paths, and
// marker positions along a polyline.
#include <fmt/format.h>

#include <cmath>
#include <numbers>
#include <sstream>

#include "facet/runtime/chart.h"

namespace facet::chart {
namespace {

constexpr const char* kColours[] = {"#1f77b4", "#d62728", "#2ca02c", "#ff7f0e", "#9467bd", "#8c564b", "#e377c2", "#17becf"};
// Solid first: series 0 is drawn first, and every later (dashed) curve lets
// it show through its gaps. The periods differ, so the gaps of several
// coinciding dashed curves do not all line up.
constexpr const char* kDashes[] = {"", "9 4", "2 3", "12 3 3 3", "5 5", "14 3 2 3 2 3", "1 3", "7 2 2 2"};
constexpr MarkerShape kShapes[] = {MarkerShape::circle,        MarkerShape::square, MarkerShape::triangle_up,
                                   MarkerShape::diamond,       MarkerShape::triangle_down, MarkerShape::plus,
                                   MarkerShape::cross,         MarkerShape::star};

std::vector<Point2> polygon(double x, double y, double r, int corners, double start_degrees, double inner = 0) {
  std::vector<Point2> out;
  const int n = inner > 0 ? corners * 2 : corners;
  for (int i = 0; i < n; ++i) {
    double a = (start_degrees + 360.0 * i / n) * std::numbers::pi / 180.0;
    double radius = inner > 0 && i % 2 == 1 ? inner : r;
    out.push_back({x + radius * std::cos(a), y + radius * std::sin(a)});
  }
  return out;
}

}  // namespace

SeriesStyle series_style(size_t i) { return {kColours[i % 8], kDashes[i % 8], kShapes[(i + i / 8) % 8]}; }

std::string_view marker_name(MarkerShape shape) {
  switch (shape) {
    case MarkerShape::circle: return "circle";
    case MarkerShape::square: return "square";
    case MarkerShape::triangle_up: return "triangle-up";
    case MarkerShape::diamond: return "diamond";
    case MarkerShape::triangle_down: return "triangle-down";
    case MarkerShape::plus: return "plus";
    case MarkerShape::cross: return "cross";
    case MarkerShape::star: break;
  }
  return "star";
}

std::vector<double> dash_lengths(const std::string& dash) {
  std::vector<double> out;
  std::istringstream in(dash);
  for (double v; in >> v;) out.push_back(v);
  return out;
}

std::vector<Point2> marker_outline(MarkerShape shape, double x, double y, double r) {
  switch (shape) {
    case MarkerShape::circle: return polygon(x, y, r, 16, 0);
    case MarkerShape::square: return polygon(x, y, r * 1.2, 4, 45);
    case MarkerShape::triangle_up: return polygon(x, y, r * 1.25, 3, -90);
    case MarkerShape::diamond: return polygon(x, y, r * 1.2, 4, 0);
    case MarkerShape::triangle_down: return polygon(x, y, r * 1.25, 3, 90);
    case MarkerShape::plus: return {{x - r, y}, {x + r, y}, {x, y - r}, {x, y + r}};
    case MarkerShape::cross: return {{x - r, y - r}, {x + r, y + r}, {x - r, y + r}, {x + r, y - r}};
    case MarkerShape::star: break;
  }
  return polygon(x, y, r * 1.35, 5, -90, r * 0.6);
}

std::string marker_svg(MarkerShape shape, double x, double y, double r, const std::string& colour, bool filled,
                       const std::string& attributes) {
  std::vector<Point2> p = marker_outline(shape, x, y, r);
  std::string d;
  const bool strokes = shape == MarkerShape::plus || shape == MarkerShape::cross;
  for (size_t i = 0; i < p.size(); ++i) {
    d += fmt::format("{}{:.2f} {:.2f} ", i == 0 || (strokes && i == 2) ? "M" : "L", p[i].x, p[i].y);
  }
  if (strokes) {
    return fmt::format(R"(<path d="{}" fill="none" stroke="{}" stroke-width="2.2" {}/>)", d, colour, attributes);
  }
  return fmt::format(R"(<path d="{}Z" fill="{}" stroke="{}" stroke-width="1.3" {}/>)", d, filled ? colour : "#ffffff",
                     colour, attributes);
}

std::vector<Point2> points_along(const std::vector<Point2>& polyline, double spacing, double phase) {
  std::vector<Point2> out;
  double next = phase, walked = 0;
  for (size_t i = 1; i < polyline.size(); ++i) {
    const Point2 a = polyline[i - 1], b = polyline[i];
    const double len = std::hypot(b.x - a.x, b.y - a.y);
    while (len > 0 && next <= walked + len) {
      double t = (next - walked) / len;
      out.push_back({a.x + (b.x - a.x) * t, a.y + (b.y - a.y) * t});
      next += spacing;
    }
    walked += len;
  }
  return out;
}

}  // namespace facet::chart
