// Label placement without overlaps: text sizes from character classes,
// candidate positions around each marker, collision checks against every
// placed label, leader line and obstacle.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>

#include "facet/runtime/chart.h"

namespace facet::chart {
namespace {

// DejaVu Sans: ascent 0.928 em, descent 0.236 em; rounded up for the
// fallback fonts' metrics.
constexpr double kAscent = 0.96, kDescent = 0.26;

// The widest advance (em) of a character's class, DejaVu Sans or narrower.
double char_width(char32_t c) {
  auto in = [c](std::u32string_view set) { return set.find(c) != std::u32string_view::npos; };
  if (c >= 0x80) return 1.0;
  if (in(U" .,:;ijl|!'I")) return 0.42;
  if (in(U"frtJ()[]{}-/\\`\"")) return 0.5;
  if (in(U"mw")) return 1.0;
  if (in(U"MW")) return 1.02;
  if ((c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || in(U"_*?$")) return 0.66;
  if (c >= 'A' && c <= 'Z') return 0.8;
  return 1.02;  // = + < > # % & @ ~ ^ and the rest
}

// UTF-8 to code points (a malformed byte counts as one wide character).
std::u32string decode(std::string_view s) {
  std::u32string out;
  for (size_t i = 0; i < s.size();) {
    unsigned char b = static_cast<unsigned char>(s[i]);
    size_t n = b < 0x80 ? 1 : (b >> 5) == 6 ? 2 : (b >> 4) == 14 ? 3 : (b >> 3) == 30 ? 4 : 1;
    out.push_back(b < 0x80 ? char32_t(b) : char32_t(0x80));  // only "ASCII or not" matters
    i += n;
  }
  return out;
}

Box inflate(const Box& b, double d) { return {b.x0 - d, b.y0 - d, b.x1 + d, b.y1 + d}; }
bool inside(const Box& inner, const Box& outer) {
  return inner.x0 >= outer.x0 && inner.y0 >= outer.y0 && inner.x1 <= outer.x1 && inner.y1 <= outer.y1;
}
bool contains(const Box& b, double x, double y) { return x > b.x0 && x < b.x1 && y > b.y0 && y < b.y1; }

double cross(double ax, double ay, double bx, double by, double cx, double cy) {
  return (bx - ax) * (cy - ay) - (by - ay) * (cx - ax);
}
// A proper crossing of two segments (touching end points do not count).
bool segments_cross(const PlacedLabel& a, const PlacedLabel& b) {
  double d1 = cross(a.leader_x0, a.leader_y0, a.leader_x1, a.leader_y1, b.leader_x0, b.leader_y0);
  double d2 = cross(a.leader_x0, a.leader_y0, a.leader_x1, a.leader_y1, b.leader_x1, b.leader_y1);
  double d3 = cross(b.leader_x0, b.leader_y0, b.leader_x1, b.leader_y1, a.leader_x0, a.leader_y0);
  double d4 = cross(b.leader_x0, b.leader_y0, b.leader_x1, b.leader_y1, a.leader_x1, a.leader_y1);
  return ((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0));
}

struct Direction {
  double x, y;
};
// The order in which directions are tried: right, the right diagonals,
// left, the left diagonals, above, below, then the directions between.
const std::vector<Direction>& directions() {
  static const std::vector<Direction> k = [] {
    const double degrees[] = {0, -45, 45, 180, -135, 135, -90, 90, -22.5, 22.5, -157.5, 157.5, -67.5, -112.5, 67.5, 112.5};
    std::vector<Direction> out;
    for (double d : degrees) out.push_back({std::cos(d * std::numbers::pi / 180.0), std::sin(d * std::numbers::pi / 180.0)});
    return out;
  }();
  return k;
}

// The box of size w x h attached at point (tx, ty) on the side facing away
// from the marker in direction d.
Box attach(double tx, double ty, double w, double h, const Direction& d) {
  double x0 = d.x > 0.3 ? tx : d.x < -0.3 ? tx - w : tx - w / 2;
  double y0 = d.y > 0.3 ? ty : d.y < -0.3 ? ty - h : ty - h / 2;
  return {x0, y0, x0 + w, y0 + h};
}

class Placer {
 public:
  explicit Placer(const LayoutOptions& options) : options_(options) {}

  // The first free candidate for `text` at the request's marker, or nothing:
  // beside it (with_leader false) or further away on a leader line.
  std::optional<PlacedLabel> place(const LabelRequest& r, const std::string& text, bool with_leader) {
    const Box shape = text_box(text, options_.font_size, 0, 0);
    std::vector<double> distances;
    if (!with_leader) distances.push_back(0);
    for (double d : {8.0, 16.0, 26.0, 38.0, 52.0, 68.0, 86.0, 106.0, 130.0, 160.0}) {
      if (with_leader && d <= options_.max_distance) distances.push_back(d);
    }
    for (double extra : distances) {
      for (const Direction& d : directions()) {
        // Square rings: a diagonal candidate's corner clears the marker as far as a straight one's side.
        double reach = (r.marker_radius + options_.gap + extra) / std::max(std::abs(d.x), std::abs(d.y));
        Box b = attach(r.x + d.x * reach, r.y + d.y * reach, shape.width(), shape.height(), d);
        PlacedLabel l{.text = text, .box = b, .baseline_x = b.x0, .baseline_y = b.y0 - shape.y0};
        if (extra > 0 && !add_leader(l, r)) continue;
        if (fits(l, r)) {
          placed_.push_back(l);
          return l;
        }
      }
    }
    return std::nullopt;
  }

 private:
  // From the marker's edge to the nearest point of the box; false when the
  // box comes within the marker (no line to draw).
  static bool add_leader(PlacedLabel& l, const LabelRequest& r) {
    double qx = std::clamp(r.x, l.box.x0, l.box.x1), qy = std::clamp(r.y, l.box.y0, l.box.y1);
    double len = std::hypot(qx - r.x, qy - r.y);
    if (!(len > r.marker_radius)) return false;
    l.has_leader = true;
    l.leader_x0 = r.x + (qx - r.x) / len * r.marker_radius, l.leader_y0 = r.y + (qy - r.y) / len * r.marker_radius;
    l.leader_x1 = qx, l.leader_y1 = qy;
    return true;
  }

  bool fits(const PlacedLabel& l, const LabelRequest& r) const {
    if (!inside(l.box, options_.area)) return false;
    const Box padded = inflate(l.box, options_.gap), near = inflate(l.box, options_.gap / 4);
    for (const Box& o : options_.obstacles) {
      if (intersects(near, o)) return false;
      if (l.has_leader && !contains(o, r.x, r.y) && segment_crosses(l.leader_x0, l.leader_y0, l.leader_x1, l.leader_y1, o)) {
        return false;
      }
    }
    for (const PlacedLabel& p : placed_) {
      if (intersects(padded, p.box)) return false;
      if (p.has_leader && segment_crosses(p.leader_x0, p.leader_y0, p.leader_x1, p.leader_y1, near)) return false;
      if (l.has_leader && segment_crosses(l.leader_x0, l.leader_y0, l.leader_x1, l.leader_y1, inflate(p.box, options_.gap / 4))) {
        return false;
      }
      if (l.has_leader && p.has_leader && segments_cross(l, p)) return false;
    }
    return true;
  }

  const LayoutOptions& options_;
  std::vector<PlacedLabel> placed_;
};

}  // namespace

bool intersects(const Box& a, const Box& b) { return a.x0 < b.x1 && b.x0 < a.x1 && a.y0 < b.y1 && b.y0 < a.y1; }

// Liang-Barsky clipping of the segment against the box's interior.
bool segment_crosses(double ax, double ay, double bx, double by, const Box& b) {
  double t0 = 0, t1 = 1;
  const double dx = bx - ax, dy = by - ay;
  const double p[4] = {-dx, dx, -dy, dy}, q[4] = {ax - b.x0, b.x1 - ax, ay - b.y0, b.y1 - ay};
  for (int i = 0; i < 4; ++i) {
    if (p[i] == 0) {
      if (q[i] <= 0) return false;  // parallel to this edge and outside (or on it)
      continue;
    }
    double t = q[i] / p[i];
    if (p[i] < 0) t0 = std::max(t0, t);
    else t1 = std::min(t1, t);
  }
  return t1 - t0 > 1e-9;
}

Box square_around(double x, double y, double half_side) { return {x - half_side, y - half_side, x + half_side, y + half_side}; }

double text_width(std::string_view text, double font_size) {
  double em = 0;
  for (char32_t c : decode(text)) em += char_width(c);
  return em * font_size;
}

Box text_box(std::string_view text, double font_size, double x, double baseline_y) {
  return {x, baseline_y - kAscent * font_size, x + text_width(text, font_size), baseline_y + kDescent * font_size};
}

LabelLayout place_labels(const std::vector<LabelRequest>& requests, const LayoutOptions& options) {
  LabelLayout out;
  out.labels.resize(requests.size());
  Placer placer(options);
  // Three passes in request order: every label that fits beside its marker,
  // then the others on leader lines, then numbers for the rest.
  std::vector<size_t> left;
  for (size_t i = 0; i < requests.size(); ++i) left.push_back(i);
  for (bool with_leader : {false, true}) {
    std::vector<size_t> still;
    for (size_t i : left) {
      std::optional<PlacedLabel> l = placer.place(requests[i], requests[i].text, with_leader);
      if (!l) {
        still.push_back(i);
        continue;
      }
      l->placement = with_leader ? Placement::leader : Placement::beside;
      out.labels[i] = *l;
    }
    left = std::move(still);
  }
  for (size_t i : left) {
    const int number = options.first_number + int(out.legend.size());
    out.legend.push_back(i);
    std::optional<PlacedLabel> n = placer.place(requests[i], std::to_string(number), false);
    if (!n) n = placer.place(requests[i], std::to_string(number), true);
    PlacedLabel l = n ? *n : PlacedLabel{.placement = Placement::legend_only, .text = ""};
    if (n) l.placement = Placement::numbered;
    l.number = number;
    out.labels[i] = l;
  }
  return out;
}

std::vector<std::pair<size_t, size_t>> overlapping_labels(const std::vector<PlacedLabel>& labels) {
  std::vector<std::pair<size_t, size_t>> out;
  for (size_t i = 0; i < labels.size(); ++i) {
    for (size_t j = i + 1; j < labels.size(); ++j) {
      if (labels[i].placement == Placement::legend_only || labels[j].placement == Placement::legend_only) continue;
      if (intersects(labels[i].box, labels[j].box)) out.emplace_back(i, j);
    }
  }
  return out;
}

}  // namespace facet::chart
