#include "stability/checks.h"

#include <fmt/format.h>

#include <cfloat>
#include <cmath>

namespace facet::stability {
namespace {

bool behind(const Point& p) {
  double nl = double(p[0]) * p[6] + double(p[1]) * p[7] + double(p[2]) * p[8];
  double nn = double(p[0]) * p[0] + double(p[1]) * p[1] + double(p[2]) * p[2];
  return nn >= 0.25 && nl < 0.0;
}

template <class T>
Findings check(const std::vector<T>& values, const std::vector<Point>& points, const CheckOptions& options) {
  Findings f;
  if (values.size() != points.size() * 3) {
    f.nan = 1;
    f.first = fmt::format("  {} values for {} points\n", values.size(), points.size());
    return f;
  }
  int reported = 0;
  for (size_t i = 0; i < points.size(); ++i) {
    const Point& p = points[i];
    double intensity = p[11];
    for (int k = 0; k < 3; ++k) {
      double y = double(values[i * 3 + k]);
      ++f.checked;
      const char* what = nullptr;
      if (std::isnan(y)) ++f.nan, what = "NaN";
      else if (std::isinf(y) || std::abs(y) > double(FLT_MAX)) ++f.inf, what = "Inf (or beyond fp32)";
      else if (y < 0.0) ++f.negative, what = "negative";
      else if (y > options.bound * intensity * (1.0 + 1e-6)) ++f.over_bound, what = "over the bound";
      else if (options.behind_gives_zero && behind(p) && y != 0.0) ++f.lit_from_behind, what = "lit from behind";
      if (std::isfinite(y)) f.largest = std::max(f.largest, y);
      if (what && reported++ < 4) f.first += fmt::format("  {} {} at {}\n", what, y, point_text(p));
    }
  }
  return f;
}

}  // namespace

std::string Findings::summary() const {
  return fmt::format("{} values: {} NaN, {} Inf, {} negative, {} over the bound, {} lit from behind; largest {:.4g}\n{}",
                     checked, nan, inf, negative, over_bound, lit_from_behind, largest, first);
}

Findings check_values(const std::vector<float>& values, const std::vector<Point>& points, const CheckOptions& options) {
  return check(values, points, options);
}
Findings check_values(const std::vector<double>& values, const std::vector<Point>& points, const CheckOptions& options) {
  return check(values, points, options);
}

std::string point_text(const Point& p) {
  return fmt::format("n=({:g},{:g},{:g}) v=({:g},{:g},{:g}) l=({:g},{:g},{:g}) r={:g} f0={:g} I={:g}", p[0], p[1], p[2],
                     p[3], p[4], p[5], p[6], p[7], p[8], p[9], p[10], p[11]);
}

}  // namespace facet::stability
