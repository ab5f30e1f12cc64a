// Label placement: a crowded scatter gets labels whose boxes are pairwise
// disjoint, inside the area, off every marker, with leader lines that cross
// no label; the same input gives the same layout; and the overlap check
// finds the overlaps of the naive layout (a label to the right of each
// point), so that it can fail.
#include <gtest/gtest.h>

#include <set>

#include "facet/runtime/chart.h"

namespace facet::chart {
namespace {

constexpr double kMarker = 4.5, kFont = 10;

// 40 points, 24 of them in a 160 x 80 pixel cluster (as the study's rows
// crowd around 0.3 ps), ids of the study's lengths.
std::vector<LabelRequest> crowded() {
  std::vector<LabelRequest> out;
  const char* names[] = {"V_SmithGGXCorrelatedFast", "V_SchlickGGX", "F_Schlick", "Fd_Burley", "BRDF2_Unity_PBS",
                         "CookTorranceGGX_Compensated", "EnvBRDFApprox", "SRGBPow22"};
  uint32_t seed = 12345;
  auto next = [&seed] { return (seed = seed * 1664525u + 1013904223u) / 4294967296.0; };
  for (int i = 0; i < 40; ++i) {
    bool cluster = i < 24;
    double x = cluster ? 300 + 160 * next() : 90 + 780 * next();
    double y = cluster ? 90 + 80 * next() : 30 + 180 * next();
    out.push_back({x, y, kMarker, std::string(names[i % 8]) + (i >= 8 ? "_" + std::to_string(i) : "")});
  }
  return out;
}

LayoutOptions options_for(const std::vector<LabelRequest>& requests) {
  LayoutOptions o{.area = {80, 20, 940, 220}, .font_size = kFont};
  for (const LabelRequest& r : requests) o.obstacles.push_back(square_around(r.x, r.y, kMarker + 1));
  return o;
}

bool inside(const Box& in, const Box& out) { return in.x0 >= out.x0 && in.y0 >= out.y0 && in.x1 <= out.x1 && in.y1 <= out.y1; }

TEST(ChartLabelLayoutTest, CrowdedPointsGetPairwiseDisjointLabels) {
  const std::vector<LabelRequest> requests = crowded();
  const LayoutOptions options = options_for(requests);
  const LabelLayout layout = place_labels(requests, options);
  ASSERT_EQ(layout.labels.size(), requests.size());
  EXPECT_TRUE(overlapping_labels(layout.labels).empty());
  size_t drawn = 0, leaders = 0;
  for (size_t i = 0; i < layout.labels.size(); ++i) {
    const PlacedLabel& l = layout.labels[i];
    SCOPED_TRACE(requests[i].text);
    if (l.placement == Placement::legend_only) continue;
    ++drawn;
    leaders += l.has_leader;
    EXPECT_TRUE(inside(l.box, options.area));
    // The box is the text's own box at its baseline.
    Box expected = text_box(l.text, kFont, l.baseline_x, l.baseline_y);
    EXPECT_DOUBLE_EQ(expected.x1, l.box.x1);
    EXPECT_DOUBLE_EQ(expected.y0, l.box.y0);
    for (const Box& o : options.obstacles) EXPECT_FALSE(intersects(l.box, o));
    for (const PlacedLabel& other : layout.labels) {
      if (&other == &l || !other.has_leader) continue;
      EXPECT_FALSE(segment_crosses(other.leader_x0, other.leader_y0, other.leader_x1, other.leader_y1, l.box));
    }
    if (l.placement == Placement::leader) {
      EXPECT_TRUE(l.has_leader);
    }
    if (l.placement == Placement::beside) {
      EXPECT_FALSE(l.has_leader);
    }
  }
  // The crowd needs leader lines and numbers; at most a tenth of the points
  // (3 here, whose numbers found no free place) are named by the legend alone.
  EXPECT_GT(leaders, 5u);
  EXPECT_FALSE(layout.legend.empty());
  EXPECT_GE(drawn, 36u);
  std::set<size_t> numbered;
  for (size_t i = 0; i < layout.labels.size(); ++i) {
    if (layout.labels[i].number > 0) numbered.insert(i);
  }
  EXPECT_EQ(numbered, std::set<size_t>(layout.legend.begin(), layout.legend.end()));
  for (size_t k = 0; k < layout.legend.size(); ++k) EXPECT_EQ(layout.labels[layout.legend[k]].number, int(k) + 1);
}

TEST(ChartLabelLayoutTest, TheSameInputGivesTheSameLayout) {
  const std::vector<LabelRequest> requests = crowded();
  const LabelLayout a = place_labels(requests, options_for(requests)), b = place_labels(requests, options_for(requests));
  ASSERT_EQ(a.labels.size(), b.labels.size());
  EXPECT_EQ(a.legend, b.legend);
  for (size_t i = 0; i < a.labels.size(); ++i) {
    EXPECT_EQ(a.labels[i].text, b.labels[i].text);
    EXPECT_EQ(a.labels[i].placement, b.labels[i].placement);
    EXPECT_EQ(a.labels[i].baseline_x, b.labels[i].baseline_x);
    EXPECT_EQ(a.labels[i].baseline_y, b.labels[i].baseline_y);
    EXPECT_EQ(a.labels[i].leader_x0, b.labels[i].leader_x0);
  }
}

// The negative control: the old chart's layout (each label 6 px right of and
// 4 px above its point) overlaps on the same points, and the check says so.
TEST(ChartLabelLayoutTest, TheOverlapCheckFindsTheNaiveLayoutsOverlaps) {
  std::vector<PlacedLabel> naive;
  for (const LabelRequest& r : crowded()) {
    naive.push_back({.text = r.text, .box = text_box(r.text, kFont, r.x + 6, r.y - 4), .baseline_x = r.x + 6, .baseline_y = r.y - 4});
  }
  EXPECT_GT(overlapping_labels(naive).size(), 10u);
}

TEST(ChartLabelLayoutTest, SparsePointsAreLabelledBesideTheirMarkers) {
  std::vector<LabelRequest> requests{{100, 50, kMarker, "A"}, {400, 100, kMarker, "F_Schlick"}, {700, 180, kMarker, "Fd_Lambert"}};
  LabelLayout layout = place_labels(requests, options_for(requests));
  EXPECT_TRUE(layout.legend.empty());
  for (size_t i = 0; i < requests.size(); ++i) {
    EXPECT_EQ(layout.labels[i].placement, Placement::beside) << requests[i].text;
    EXPECT_EQ(layout.labels[i].text, requests[i].text);
    EXPECT_FALSE(layout.labels[i].has_leader);
    // Right of the marker, vertically centred on it (the first direction).
    EXPECT_DOUBLE_EQ(layout.labels[i].box.x0, requests[i].x + kMarker + 2);
    EXPECT_NEAR((layout.labels[i].box.y0 + layout.labels[i].box.y1) / 2, requests[i].y, 1e-9);
  }
}

// A label wider than the area becomes its number; where not even the number
// fits, only the legend names the point.
TEST(ChartLabelLayoutTest, LabelsThatDoNotFitGoToTheNumberedLegend) {
  std::vector<LabelRequest> requests{{50, 20, kMarker, "a label far wider than the area it has to fit in"},
                                     {50, 20, kMarker, "another label that cannot fit"}};
  LayoutOptions options{.area = {30, 5, 90, 35}, .font_size = kFont, .first_number = 7};
  LabelLayout layout = place_labels(requests, options);
  ASSERT_EQ(layout.legend, (std::vector<size_t>{0, 1}));
  EXPECT_EQ(layout.labels[0].placement, Placement::numbered);
  EXPECT_EQ(layout.labels[0].text, "7");
  EXPECT_EQ(layout.labels[0].number, 7);
  EXPECT_EQ(layout.labels[1].number, 8);
  EXPECT_TRUE(overlapping_labels(layout.labels).empty());
  // A box too small for any text leaves only the legend.
  LabelLayout none = place_labels({{10, 10, kMarker, "x"}}, {.area = {0, 0, 20, 20}, .font_size = kFont,
                                                              .obstacles = {square_around(10, 10, 9)}});
  EXPECT_EQ(none.labels[0].placement, Placement::legend_only);
  EXPECT_EQ(none.legend, std::vector<size_t>{0});
}

TEST(ChartGeometryTest, BoxesThatTouchDoNotIntersectAndSegmentsCrossInteriorsOnly) {
  EXPECT_FALSE(intersects({0, 0, 10, 10}, {10, 0, 20, 10}));
  EXPECT_TRUE(intersects({0, 0, 10, 10}, {9.5, 9.5, 20, 20}));
  EXPECT_TRUE(segment_crosses(-5, 5, 15, 5, {0, 0, 10, 10}));
  EXPECT_FALSE(segment_crosses(-5, 0, 15, 0, {0, 0, 10, 10}));  // along an edge
  EXPECT_FALSE(segment_crosses(-5, 5, -1, 5, {0, 0, 10, 10}));  // stops short
  EXPECT_TRUE(segment_crosses(5, 5, 5, 6, {0, 0, 10, 10}));     // inside
}

// Advance widths of DejaVu Sans (em, from its hmtx table): the estimate is at least these.
TEST(ChartGeometryTest, TextWidthIsAtLeastDejaVuSansAdvances) {
  struct Glyph {
    const char* text;
    double em;
  };
  for (Glyph g : {Glyph{"m", 0.974}, {"W", 0.989}, {"M", 0.863}, {"0", 0.636}, {"_", 0.5}, {"i", 0.278}, {"r", 0.411},
                  {"O", 0.787}, {" ", 0.318}, {"=", 0.838}, {"θ", 0.602}, {"°", 0.5}}) {
    EXPECT_GE(text_width(g.text, 10), g.em * 10) << g.text;
  }
  EXPECT_DOUBLE_EQ(text_width("θ", 10), text_width("°", 10));  // one code point each, not two bytes
  EXPECT_DOUBLE_EQ(text_width("ab", 12), text_width("a", 12) + text_width("b", 12));
  Box b = text_box("x", 10, 5, 20);
  EXPECT_LE(b.y0, 20 - 9.28);
  EXPECT_GE(b.y1, 20 + 2.36);
}

TEST(ChartSeriesStyleTest, The64FirstStylesAreDistinctAndTheFirstIsSolid) {
  std::set<std::tuple<std::string, std::string, std::string_view>> seen;
  for (size_t i = 0; i < 64; ++i) {
    SeriesStyle s = series_style(i);
    seen.insert({s.colour, s.dash, marker_name(s.marker)});
  }
  EXPECT_EQ(seen.size(), 64u);
  EXPECT_EQ(series_style(0).dash, "");
  // The first eight differ in every one of colour, dash and marker.
  std::set<std::string> colours, dashes;
  std::set<std::string_view> markers;
  for (size_t i = 0; i < 8; ++i) {
    colours.insert(series_style(i).colour), dashes.insert(series_style(i).dash), markers.insert(marker_name(series_style(i).marker));
  }
  EXPECT_EQ(colours.size(), 8u);
  EXPECT_EQ(dashes.size(), 8u);
  EXPECT_EQ(markers.size(), 8u);
  EXPECT_EQ(dash_lengths("12 3 2 3"), (std::vector<double>{12, 3, 2, 3}));
  EXPECT_TRUE(dash_lengths("").empty());
}

TEST(ChartSeriesStyleTest, MarkersAlongAPolylineStartAtThePhaseAndKeepTheSpacing) {
  std::vector<Point2> line{{0, 0}, {100, 0}, {100, 50}};
  std::vector<Point2> at = points_along(line, 40, 10);
  ASSERT_EQ(at.size(), 4u);  // arc lengths 10, 50, 90, 130
  EXPECT_DOUBLE_EQ(at[1].x, 50);
  EXPECT_DOUBLE_EQ(at[3].x, 100);
  EXPECT_DOUBLE_EQ(at[3].y, 30);
  EXPECT_NE(marker_svg(MarkerShape::plus, 1, 2, 3, "#000000", true, "").find("fill=\"none\""), std::string::npos);
  EXPECT_NE(marker_svg(MarkerShape::square, 1, 2, 3, "#123456", false, "class=\"m\"").find("fill=\"#ffffff\" stroke=\"#123456\""),
            std::string::npos);
}

}  // namespace
}  // namespace facet::chart
