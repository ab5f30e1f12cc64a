// The polar plot shows radius = f(l, v) cos(theta_v) in the plane of
// incidence (brdf.h), so Lambert's cosine law makes Lambert a circle through
// the origin: centre (0, albedo/(2 pi)), radius albedo/(2 pi), at any incidence.
#include <gtest/gtest.h>

#include <cmath>

#include "facet/reference/hlsl_math.h"
#include "facet/runtime/brdf.h"

namespace facet::brdf {
namespace {

using reference::kPi;

// Largest |distance from (0, R) - R| over the points above the surface.
double circle_deviation(const std::vector<PolarPoint>& points, double R) {
  double worst = 0.0;
  for (const PolarPoint& p : points) {
    if (std::abs(p.theta_deg) >= 90.0) continue;
    worst = std::max(worst, std::abs(std::hypot(p.x, p.y - R) - R));
  }
  return worst;
}

TEST(BrdfPolar, LambertIsACircleTangentAtTheOriginForEveryIncidence) {
  Result<Model> m = parse_model("lambert:albedo=0.5");
  ASSERT_TRUE(m.has_value());
  const double R = 0.5 / (2.0 * kPi);
  for (double incidence : {0.0, 30.0, 60.0, 85.0}) {
    std::vector<PolarPoint> points = polar_curve(*m, incidence, Channel::luminance, 181);
    ASSERT_EQ(points.size(), 181u);
    EXPECT_LT(circle_deviation(points, R), 1e-12) << incidence;
    // The top of the circle: straight up at 2R (theta_v = 0 is the middle sample).
    EXPECT_NEAR(points[90].y, 2.0 * R, 1e-12);
    EXPECT_NEAR(points[90].x, 0.0, 1e-12);
  }
}

TEST(BrdfPolar, GlossyLobeIsNoCircleAndLeansToTheMirrorSide) {
  // The same check fails for a specular lobe, so it does discriminate.
  Result<Model> m = parse_model("ggx:roughness=0.3,f0=1");
  ASSERT_TRUE(m.has_value());
  std::vector<PolarPoint> points = polar_curve(*m, 45.0, Channel::luminance, 181);
  double peak_theta = 0, peak = 0;
  for (const PolarPoint& p : points)
    if (p.radius > peak) peak = p.radius, peak_theta = p.theta_deg;
  EXPECT_GT(circle_deviation(points, peak / 2.0), 0.1 * peak);
  EXPECT_GT(peak_theta, 30.0);  // light at -45 deg: the lobe peaks on the +x side
  EXPECT_LT(peak_theta, 50.0);
}

TEST(BrdfPolar, ChannelsPickTheirComponent) {
  Result<Model> m = parse_model("lambert:albedo=0.2/0.4/0.8");
  ASSERT_TRUE(m.has_value());
  double red = polar_curve(*m, 0.0, Channel::red, 3)[1].radius;
  double blue = polar_curve(*m, 0.0, Channel::blue, 3)[1].radius;
  double lum = polar_curve(*m, 0.0, Channel::luminance, 3)[1].radius;
  EXPECT_NEAR(red, 0.2 / kPi, 1e-12);
  EXPECT_NEAR(blue, 0.8 / kPi, 1e-12);
  EXPECT_NEAR(lum, (0.2126 * 0.2 + 0.7152 * 0.4 + 0.0722 * 0.8) / kPi, 1e-12);
}

}  // namespace
}  // namespace facet::brdf
