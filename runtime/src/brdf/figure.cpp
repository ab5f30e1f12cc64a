// Figures as SVG (written directly) and PNG (OpenImageIO), the display
// transfer, and whole-or-nothing writes.
#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>
#include <OpenImageIO/imageio.h>
#include <fmt/format.h>

#include <cstdio>

#include "brdf_internal.h"
#include "facet/markup.h"
#include "facet/reference/color.h"
#include "facet/support/atomic_file.h"

namespace facet::brdf {
namespace {

std::string base64(const std::string& bytes) {
  static const char* k = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  for (size_t i = 0; i < bytes.size(); i += 3) {
    uint32_t n = uint32_t(uint8_t(bytes[i])) << 16;
    if (i + 1 < bytes.size()) n |= uint32_t(uint8_t(bytes[i + 1])) << 8;
    if (i + 2 < bytes.size()) n |= uint32_t(uint8_t(bytes[i + 2]));
    out += k[(n >> 18) & 63];
    out += k[(n >> 12) & 63];
    out += i + 1 < bytes.size() ? k[(n >> 6) & 63] : '=';
    out += i + 2 < bytes.size() ? k[n & 63] : '=';
  }
  return out;
}

std::vector<float> rgb_of(const std::string& hex) {
  unsigned r = 0, g = 0, b = 0;
  std::sscanf(hex.c_str(), "#%02x%02x%02x", &r, &g, &b);
  return {r / 255.0f, g / 255.0f, b / 255.0f};
}

void draw_line(OIIO::ImageBuf& buf, glm::dvec2 from, glm::dvec2 to, const std::vector<float>& c, int thickness) {
  glm::ivec2 a(glm::round(from)), b(glm::round(to));
  for (int t = 0; t < thickness; ++t) OIIO::ImageBufAlgo::render_line(buf, a.x, a.y + t, b.x, b.y + t, c, true);
}

// The polyline cut into the dash pattern's "on" pieces, by arc length (as SVG does).
std::vector<std::pair<glm::dvec2, glm::dvec2>> dash_pieces(const Stroke& s) {
  std::vector<std::pair<glm::dvec2, glm::dvec2>> out;
  std::vector<double> pattern = chart::dash_lengths(s.dash);
  double period = 0;
  for (double d : pattern) period += d;
  for (size_t i = 1; i < s.points.size(); ++i) out.emplace_back(s.points[i - 1], s.points[i]);
  if (period <= 0) return out;
  std::vector<std::pair<glm::dvec2, glm::dvec2>> dashed;
  size_t k = 0;
  double left = pattern[0];  // of the current dash or gap
  for (auto [a, b] : out) {
    double len = glm::length(b - a), at = 0;
    while (at < len) {
      double step = std::min(left, len - at);
      if (k % 2 == 0 && step > 0) dashed.emplace_back(a + (b - a) * (at / len), a + (b - a) * ((at + step) / len));
      at += step, left -= step;
      if (left <= 0) k = (k + 1) % pattern.size(), left = pattern[k];
    }
  }
  return dashed;
}

void draw_stroke(OIIO::ImageBuf& buf, const Stroke& s) {
  std::vector<float> c = rgb_of(s.colour);
  for (auto [a, b] : dash_pieces(s)) draw_line(buf, a, b, c, s.width >= 2.0 ? 2 : 1);
}

void draw_mark(OIIO::ImageBuf& buf, const Mark& m) {
  std::vector<float> c = rgb_of(m.colour);
  std::vector<chart::Point2> p = chart::marker_outline(m.shape, m.at.x, m.at.y, m.radius);
  auto at = [&](size_t i) { return glm::dvec2(p[i].x, p[i].y); };
  if (m.shape == chart::MarkerShape::plus || m.shape == chart::MarkerShape::cross) {
    draw_line(buf, at(0), at(1), c, 2);
    draw_line(buf, at(2), at(3), c, 2);
    return;
  }
  for (size_t i = 0; i < p.size(); ++i) draw_line(buf, at(i), at((i + 1) % p.size()), c, 2);
}

// OIIO's text rendering draws these symbols badly at small sizes.
std::string ascii(std::string s) {
  const std::pair<const char*, const char*> k[] = {{"θ", "theta_"}, {"φ", "phi_"}, {"°", " deg"}, {"π", "pi"},
                                                   {"∫", "int"}, {"–", "-"}, {"·", "*"}};
  for (auto [from, to] : k) {
    for (size_t at = s.find(from); at != std::string::npos; at = s.find(from, at + std::strlen(to))) {
      s.replace(at, std::strlen(from), to);
    }
  }
  return s;
}

void draw_label(OIIO::ImageBuf& buf, const Label& l) {
  auto align = l.anchor == "middle" ? OIIO::ImageBufAlgo::TextAlignX::Center
               : l.anchor == "end"  ? OIIO::ImageBufAlgo::TextAlignX::Right
                                    : OIIO::ImageBufAlgo::TextAlignX::Left;
  // No font on the machine: render_text fails and the PNG keeps its curves.
  OIIO::ImageBufAlgo::render_text(buf, int(l.at.x), int(l.at.y), ascii(l.text), int(l.size), "DejaVuSans", rgb_of(l.colour),
                                  align);
  (void)OIIO::geterror();
  (void)buf.geterror();
}

}  // namespace

Image8 to_display(const Image& im, double exposure) {
  Image8 out{im.width, im.height, std::vector<uint8_t>(im.rgb.size())};
  for (size_t i = 0; i < im.rgb.size(); ++i) {
    double x = std::clamp(double(im.rgb[i]) * exposure, 0.0, 1.0);
    out.rgb[i] = uint8_t(std::lround(reference::FacetLinearToSRGB(x) * 255.0));
  }
  return out;
}

Image8 side_by_side(const std::vector<Image8>& panels) {
  Image8 out;
  for (const Image8& p : panels) out.width += p.width, out.height = std::max(out.height, p.height);
  out.rgb.assign(size_t(out.width) * size_t(out.height) * 3, 0);
  int x0 = 0;
  for (const Image8& p : panels) {
    for (int y = 0; y < p.height; ++y) {
      std::copy_n(p.rgb.begin() + size_t(y) * p.width * 3, size_t(p.width) * 3,
                  out.rgb.begin() + (size_t(y) * out.width + x0) * 3);
    }
    x0 += p.width;
  }
  return out;
}

Result<std::string> encode_png(const Image8& im) {
  std::vector<unsigned char> bytes;
  OIIO::Filesystem::IOVecOutput proxy(bytes);
  auto out = OIIO::ImageOutput::create("figure.png", &proxy);
  if (!out) return failure("OpenImageIO has no PNG writer: " + OIIO::geterror());
  OIIO::ImageSpec spec(im.width, im.height, 3, OIIO::TypeDesc::UINT8);
  if (!out->open("figure.png", spec) || !out->write_image(OIIO::TypeDesc::UINT8, im.rgb.data()) || !out->close()) {
    return failure("PNG encoding failed: " + out->geterror());
  }
  return std::string(bytes.begin(), bytes.end());
}

Result<std::string> to_svg(const Figure& f) {
  std::string s = fmt::format(
      "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{0}\" height=\"{1}\" viewBox=\"0 0 {0} {1}\" "
      "font-family=\"DejaVu Sans, sans-serif\">\n<rect width=\"{0}\" height=\"{1}\" fill=\"{2}\"/>\n",
      f.width, f.height, f.background);
  for (const Embedded& e : f.images) {
    Result<std::string> png = encode_png(e.image);
    if (!png) return unexpected(png.error());
    s += fmt::format("<image x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\" href=\"data:image/png;base64,{}\"/>\n",
                     e.at.x, e.at.y, e.image.width, e.image.height, base64(*png));
  }
  for (const Stroke& st : f.strokes) {
    std::string pts;
    for (const glm::dvec2& p : st.points) pts += fmt::format("{:.2f},{:.2f} ", p.x, p.y);
    std::string attributes = st.css_class.empty() ? "" : " class=\"" + st.css_class + "\"";
    if (st.series >= 0) attributes += fmt::format(" data-series=\"{}\"", st.series);
    s += fmt::format("<polyline{} fill=\"none\" stroke=\"{}\" stroke-width=\"{}\"{} points=\"{}\"/>\n", attributes,
                     st.colour, st.width,
                     st.dash.empty() ? "" : " stroke-dasharray=\"" + st.dash + "\"", pts);
  }
  for (const Mark& m : f.marks) {
    std::string attributes = fmt::format("class=\"{}\" data-shape=\"{}\"", m.css_class, chart::marker_name(m.shape));
    if (m.series >= 0) attributes += fmt::format(" data-series=\"{}\"", m.series);
    s += chart::marker_svg(m.shape, m.at.x, m.at.y, m.radius, m.colour, true, attributes) + "\n";
  }
  for (const Label& l : f.labels) {
    s += fmt::format("<text class=\"label\" x=\"{:.1f}\" y=\"{:.1f}\" font-size=\"{}\" fill=\"{}\" text-anchor=\"{}\">{}</text>\n",
                     l.at.x, l.at.y, l.size, l.colour, l.anchor, xml_escape(l.text));
  }
  return s + "</svg>\n";
}

Result<std::string> to_png(const Figure& f) {
  OIIO::ImageBuf buf(OIIO::ImageSpec(f.width, f.height, 3, OIIO::TypeDesc::FLOAT));
  std::vector<float> bg = rgb_of(f.background);
  OIIO::ImageBufAlgo::fill(buf, bg);
  for (const Embedded& e : f.images) {
    for (int y = 0; y < e.image.height; ++y) {
      for (int x = 0; x < e.image.width; ++x) {
        const uint8_t* p = &e.image.rgb[(size_t(y) * e.image.width + x) * 3];
        float c[3] = {p[0] / 255.0f, p[1] / 255.0f, p[2] / 255.0f};
        buf.setpixel(int(e.at.x) + x, int(e.at.y) + y, c, 3);
      }
    }
  }
  for (const Stroke& s : f.strokes) draw_stroke(buf, s);
  for (const Mark& m : f.marks) draw_mark(buf, m);
  for (const Label& l : f.labels) draw_label(buf, l);
  Image8 im{f.width, f.height, std::vector<uint8_t>(size_t(f.width) * f.height * 3)};
  buf.get_pixels(OIIO::ROI(0, f.width, 0, f.height, 0, 1, 0, 3), OIIO::TypeDesc::UINT8, im.rgb.data());
  return encode_png(im);
}

Result<void> write_file_whole(const std::string& path, const std::string& bytes) {
  if (Result<void, std::string> written = support::write_file_atomically(path, bytes); !written) {
    return failure(fmt::format("{}: cannot write ({})", path, written.error()));
  }
  return {};
}

}  // namespace facet::brdf
