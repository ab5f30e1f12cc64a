// What facet's charts share (the accuracy study's Pareto panels, `facet brdf`'s
// plots): label placement that never lets two labels overlap, a conservative
// estimate of a text's size, and the line styles that keep overlaid curves
// apart. Pure functions of their inputs: the same input gives the same
// output, byte for byte.
//
// Placing the labels of a scatter plot:
//
//   chart::LayoutOptions options{.area = {70, 20, 940, 220}, .font_size = 10};
//   for (const Point& p : points) options.obstacles.push_back(chart::square_around(p.x, p.y, 5));
//   chart::LabelLayout layout = chart::place_labels(requests, options);
//   for (const chart::PlacedLabel& l : layout.labels) { ... draw l.text at l.baseline_x, l.baseline_y ... }
//   for (size_t i : layout.legend) { ... "<number>: <requests[i].text>" under the chart ... }
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace facet::chart {

// An axis-aligned box in pixels, y down. Invariant: x0 <= x1, y0 <= y1.
struct Box {
  double x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  double width() const { return x1 - x0; }
  double height() const { return y1 - y0; }
};

// True when the interiors overlap (boxes that only touch do not).
bool intersects(const Box& a, const Box& b);
// True when the segment from (ax, ay) to (bx, by) passes through the interior of b.
bool segment_crosses(double ax, double ay, double bx, double by, const Box& b);
Box square_around(double x, double y, double half_side);

// An upper bound of the advance width of `text` (UTF-8) at `font_size`
// pixels in DejaVu Sans, the font facet's SVG asks for, and in the narrower
// sans-serif fonts a browser falls back to: per-character classes, each at
// least its widest DejaVu Sans glyph.
double text_width(std::string_view text, double font_size);
// The box that holds `text` drawn with its baseline at y and its start
// (text-anchor "start") at x: the font's ascent above, descent below.
Box text_box(std::string_view text, double font_size, double x, double baseline_y);

// A label wanted next to a marker at (x, y) of radius marker_radius.
struct LabelRequest {
  double x = 0, y = 0;
  double marker_radius = 4;
  std::string text;
};

struct LayoutOptions {
  Box area;                  // every placed label lies inside it
  double font_size = 10;
  double gap = 2;            // between a marker and the label beside it, and around every box
  std::vector<Box> obstacles;  // markers and whatever else no label may cover
  double max_distance = 120;   // how far a leader line may take a label from its marker
  int first_number = 1;        // the number of the first numbered label (charts of several panels count on)
};

enum class Placement {
  beside,       // next to its marker, no leader line
  leader,       // further away, joined to its marker by a leader line
  numbered,     // only its number is drawn (as a beside or leader label); the text is in the legend
  legend_only,  // nothing is drawn at the marker; the number and text are in the legend
};

struct PlacedLabel {
  Placement placement = Placement::beside;
  std::string text;  // what is drawn at the marker: the request's text, or its number
  int number = 0;    // number in the legend (numbered, legend_only; from first_number on), 0 otherwise
  Box box;           // the text's box (text_box of text at the baseline), empty for legend_only
  double baseline_x = 0, baseline_y = 0;  // where the text starts (text-anchor "start")
  bool has_leader = false;
  double leader_x0 = 0, leader_y0 = 0, leader_x1 = 0, leader_y1 = 0;  // from the marker's edge to the box
};

// Invariants: labels[i] belongs to requests[i]; no two drawn boxes
// intersect; no drawn box intersects an obstacle or leaves the area; no
// leader line crosses a drawn box or another leader; legend lists the
// requests that are numbered or legend_only in number order.
struct LabelLayout {
  std::vector<PlacedLabel> labels;
  std::vector<std::size_t> legend;
};

// Greedy placement, three passes in request order: every label that fits
// beside its marker; then the others further away (growing distances up to
// max_distance) on a leader line; then, for the rest, their numbers (beside
// or on a leader line), with the texts in the legend. Each candidate is one
// of 16 directions around the marker, tried in a fixed order (right, the
// right diagonals, left, ...); the first that collides with nothing placed
// so far wins. A number that finds no place either is legend_only.
LabelLayout place_labels(const std::vector<LabelRequest>& requests, const LayoutOptions& options);

// Pairs (i, j), i < j, of drawn labels whose boxes intersect: empty for any
// place_labels result (the test of the invariant, usable on any layout).
std::vector<std::pair<std::size_t, std::size_t>> overlapping_labels(const std::vector<PlacedLabel>& labels);

// How overlaid curve i is drawn: colour, SVG stroke-dasharray ("" solid) and
// marker shape. Distinct for i < 64, so that a curve under another still
// shows through the dashes' gaps and by its markers.
enum class MarkerShape { circle, square, triangle_up, diamond, triangle_down, plus, cross, star };
struct SeriesStyle {
  std::string colour;  // #rrggbb
  std::string dash;    // SVG stroke-dasharray in pixels, "" for a solid line
  MarkerShape marker = MarkerShape::circle;
};
SeriesStyle series_style(std::size_t i);
std::string_view marker_name(MarkerShape shape);  // "circle", "square", ...
// The dash pattern as lengths (on, off, on, off, ...); empty for solid.
std::vector<double> dash_lengths(const std::string& dash);

// The outline of a marker of half-size r centred at (x, y), as a closed
// polygon (circle: 16 points) or, for plus and cross, as two segments
// (4 points: a0 a1 b0 b1).
struct Point2 {
  double x = 0, y = 0;
};
std::vector<Point2> marker_outline(MarkerShape shape, double x, double y, double r);
// The SVG element of that marker (a <path>): filled in `colour`, or (filled
// false) white inside a `colour` outline; plus and cross are strokes.
// `attributes` are appended inside the tag (e.g. `class="marker"`).
std::string marker_svg(MarkerShape shape, double x, double y, double r, const std::string& colour, bool filled,
                       const std::string& attributes);

// Points spaced `spacing` pixels apart along the polyline, the first at
// arc length `phase`: where a series puts its markers (phase differs per
// series, so coinciding curves put their markers at different places).
std::vector<Point2> points_along(const std::vector<Point2>& polyline, double spacing, double phase);

}  // namespace facet::chart
