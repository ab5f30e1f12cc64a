// The one checker every stability test (and the planted-bug test) runs on
// reflected-light values: NaN, Inf, negative, above a bound, or lit by a
// light behind the surface.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "stability/inputs.h"

namespace facet::stability {

struct CheckOptions {
  // Largest allowed value per unit intensity (value <= bound * intensity,
  // with 1e-6 relative slack for the fp32 product).
  double bound = 3.4e38;
  // A light with dot(n, l) < 0 (n at least half unit length) must give 0.
  bool behind_gives_zero = true;
};

struct Findings {
  size_t checked = 0;  // values looked at
  size_t nan = 0, inf = 0, negative = 0, over_bound = 0, lit_from_behind = 0;
  double largest = 0;  // the largest finite value seen
  std::string first;   // the first few offending points, with their inputs
  bool clean() const { return nan + inf + negative + over_bound + lit_from_behind == 0; }
  std::string summary() const;
};

// values: 3 per point (r.xyz), point-major.
Findings check_values(const std::vector<float>& values, const std::vector<Point>& points, const CheckOptions& options);

// The same for double values from a CPU twin, which must also fit in fp32.
Findings check_values(const std::vector<double>& values, const std::vector<Point>& points, const CheckOptions& options);

std::string point_text(const Point& p);

}  // namespace facet::stability
