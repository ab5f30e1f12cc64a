// What the views share inside facet_brdf: a small vector figure (strokes,
// labels, embedded images) written as SVG or rasterised to PNG, the display
// transfer, and whole-or-nothing file writes.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "facet/runtime/brdf.h"
#include "facet/runtime/chart.h"

namespace facet::brdf {

// 8-bit sRGB pixels, row-major, top row first.
struct Image8 {
  int width = 0, height = 0;
  std::vector<uint8_t> rgb;
};
// clamp(x * exposure, 0, 1), then the exact sRGB transfer (FacetLinearToSRGB).
Image8 to_display(const Image& im, double exposure);
// Panels side by side, each as tall as the tallest.
Image8 side_by_side(const std::vector<Image8>& panels);
Result<std::string> encode_png(const Image8& im);

struct Stroke {
  std::vector<glm::dvec2> points;  // pixels, y down
  std::string colour = "#000000";  // #rrggbb
  double width = 1.5;
  std::string dash;       // SVG stroke-dasharray in pixels ("" solid); the PNG dashes the same lengths
  std::string css_class;  // the SVG class ("curve" for a model's curve), "" for none
  int series = -1;        // the model's index for a curve, -1 for none (SVG data-series)
};
// A marker drawn over every stroke (markers of overlaid curves, legend samples).
struct Mark {
  chart::MarkerShape shape = chart::MarkerShape::circle;
  glm::dvec2 at{0.0};
  double radius = 3.5;
  std::string colour = "#000000";
  std::string css_class;  // "marker" on a curve (with its series), "legend-marker" in the legend
  int series = -1;        // the curve's index, -1 for none (SVG data-series)
};
struct Label {
  glm::dvec2 at{0.0};
  std::string text;
  std::string anchor = "start";  // SVG text-anchor: start, middle, end
  double size = 12;
  std::string colour = "#222222";
};
struct Embedded {
  glm::dvec2 at{0.0};
  Image8 image;
};
struct Figure {
  int width = 0, height = 0;
  std::string background = "#ffffff";
  std::vector<Embedded> images;
  std::vector<Stroke> strokes;
  std::vector<Mark> marks;  // drawn after the strokes, before the labels
  std::vector<Label> labels;
};
Result<std::string> to_svg(const Figure& f);
// Lines through OIIO's render_line; text through render_text where a font
// is found (a PNG without a font still has every curve).
Result<std::string> to_png(const Figure& f);

// Writes to a sibling temporary file, then renames: a failed write leaves
// nothing at `path`.
Result<void> write_file_whole(const std::string& path, const std::string& bytes);

}  // namespace facet::brdf

namespace facet::brdf {

// The figures of the views (plots.cpp). `channel` names what is plotted.
Figure polar_figure(const std::vector<std::string>& labels, const std::vector<std::vector<PolarPoint>>& curves,
                    double incidence_deg, const std::string& channel);
Figure albedo_figure(const std::vector<std::string>& labels, const std::vector<std::vector<AlbedoPoint>>& curves,
                     Channel c, const std::string& channel);
// Breaks a label after commas into lines of at most max_chars (where it can).
std::vector<std::string> wrap_label(const std::string& label, std::size_t max_chars);
// One panel per model with a caption above and the full labels below.
Figure image_figure(const std::vector<Image8>& panels, const std::vector<std::string>& labels,
                    const std::string& caption);

}  // namespace facet::brdf
