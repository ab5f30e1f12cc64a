// The four views for every model of the registry: through the command (files
// exist with the expected sizes) and through the data functions (every value
// finite and non-negative; PNG's 8 bits cannot show a NaN).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "unit/brdf/brdf_test_util.h"

namespace facet::brdf {
namespace {

using test::png_size;
using test::run_command;
using test::scratch;

// Every family with its defaults; merl reads a synthetic file of a grey Lambert.
std::vector<std::string> every_model_spec() {
  static const std::string merl = [] {
    std::string path = scratch("views_lambert.binary");
    Result<void> ok = write_merl(path, [](const glm::dvec3&, const glm::dvec3&) { return glm::dvec3(0.5 / 3.14159); });
    EXPECT_TRUE(ok.has_value());
    return path;
  }();
  std::vector<std::string> specs;
  for (const FamilyInfo& f : model_families()) specs.push_back(f.name == "merl" ? "merl:" + merl : f.name);
  return specs;
}

// Every polyline's points are numbers: no "nan" or "inf" in them.
bool polylines_are_numbers(const std::string& svg) {
  for (size_t at = svg.find("points=\""); at != std::string::npos; at = svg.find("points=\"", at)) {
    at += 8;
    size_t end = svg.find('"', at);
    if (svg.substr(at, end - at).find_first_not_of("0123456789.-, ") != std::string::npos) return false;
  }
  return true;
}

bool all_finite_non_negative(const Image& im) {
  for (float x : im.rgb)
    if (!std::isfinite(x) || x < 0.0f) return false;
  return true;
}

TEST(BrdfViews, RegistryHoldsEveryStdlibModelFamily) {
  std::vector<std::string> names;
  for (const FamilyInfo& f : model_families()) names.push_back(f.name);
  for (const char* expected : {"lambert", "burley", "frostbite", "oren-nayar-qualitative", "oren-nayar", "phong",
                               "blinn-phong", "ward", "ashikhmin-shirley", "ggx", "ggx-ms", "ggx-fast",
                               "ggx-separable", "ggx-schlick", "ggx-karis", "beckmann", "cook-torrance-1982", "disney",
                               "unity-brdf1", "unity-brdf2", "unity-brdf3", "merl"}) {
    EXPECT_NE(std::find(names.begin(), names.end(), expected), names.end()) << expected;
  }
}

TEST(BrdfViews, EveryModelsDataIsFiniteAndNonNegative) {
  for (const std::string& spec : every_model_spec()) {
    SCOPED_TRACE(spec);
    Result<Model> m = parse_model(spec);
    ASSERT_TRUE(m.has_value()) << m.error().reason;
    EXPECT_TRUE(all_finite_non_negative(render_lit_sphere(*m, {.size = 24})));
    EXPECT_TRUE(all_finite_non_negative(render_lit_sphere(*m, {.size = 8, .furnace = true, .quadrature = 12})));
    EXPECT_TRUE(all_finite_non_negative(render_slice(*m, {.size = 24})));
    for (const PolarPoint& p : polar_curve(*m, 60.0, Channel::luminance, 91)) {
      EXPECT_TRUE(std::isfinite(p.x) && std::isfinite(p.y) && p.radius >= 0.0) << p.theta_deg;
    }
    for (const AlbedoPoint& p : albedo_curve(*m, 6, 89.0, 24)) {
      for (int c = 0; c < 3; ++c) EXPECT_TRUE(std::isfinite(p.albedo[c]) && p.albedo[c] >= 0.0) << p.theta_deg;
    }
  }
}

TEST(BrdfViews, EveryModelRendersTheFourViewsAsPngAndSvg) {
  const std::vector<std::string> specs = every_model_spec();
  for (size_t i = 0; i < specs.size(); ++i) {
    SCOPED_TRACE(specs[i]);
    for (const char* view : {"lit-sphere", "slice", "polar", "albedo"}) {
      for (const char* ext : {".png", ".svg"}) {
        std::string out = scratch(std::string("every_") + std::to_string(i) + "_" + view + ext);
        test::CommandResult r = run_command({specs[i], "--view", view, "-o", out, "--size", "20", "--points", "4",
                                             "--quadrature", "16"});
        ASSERT_EQ(r.code, 0) << view << ext << ": " << r.err;
        ASSERT_TRUE(std::filesystem::exists(out)) << out;
        std::string text = test::read_bytes(out);
        if (std::string(ext) == ".png") {
          auto [w, h] = png_size(out);
          if (std::string(view) == "lit-sphere" || std::string(view) == "slice") {
            EXPECT_EQ(w, 20);  // the PNG of an image view is the panels alone
            EXPECT_EQ(h, 20);
          } else {
            EXPECT_EQ(w, 720);
            EXPECT_GT(h, 400);
          }
        } else {
          EXPECT_TRUE(text.starts_with("<svg ")) << view;
          EXPECT_TRUE(polylines_are_numbers(text)) << view;
        }
      }
    }
  }
}

TEST(BrdfViews, ImageViewsPlaceOnePanelPerModelSideBySide) {
  std::string out = scratch("three_spheres.png");
  test::CommandResult r = run_command({"lambert", "ggx", "disney", "--view", "lit-sphere", "--size", "32", "-o", out});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(png_size(out), std::make_pair(96, 32));
}

TEST(BrdfViews, OverlaidPlotsDrawOnePolylinePerModelWithItsLegend) {
  for (const char* view : {"polar", "albedo"}) {
    std::string out = scratch(std::string("overlay_") + view + ".svg");
    test::CommandResult r = run_command({"ggx:roughness=0.3", "beckmann:roughness=0.3", "--view", view, "-o", out,
                                         "--points", "5", "--quadrature", "24"});
    ASSERT_EQ(r.code, 0) << r.err;
    std::string svg = test::read_bytes(out);
    // One curve per model, in its series style (the first solid, the
    // second dashed), each with markers of its own shape.
    EXPECT_NE(svg.find(R"(class="curve" data-series="0" fill="none" stroke="#1f77b4" stroke-width="2" points=)"),
              std::string::npos) << view;
    EXPECT_NE(svg.find(R"(class="curve" data-series="1" fill="none" stroke="#d62728" stroke-width="2" stroke-dasharray="9 4")"),
              std::string::npos) << view;
    EXPECT_EQ(svg.find(R"(data-series="2")"), std::string::npos) << view;
    EXPECT_NE(svg.find(R"(class="marker" data-shape="circle" data-series="0")"), std::string::npos) << view;
    EXPECT_NE(svg.find(R"(class="marker" data-shape="square" data-series="1")"), std::string::npos) << view;
    EXPECT_NE(svg.find(">ggx:roughness=0.3,f0=0.04<"), std::string::npos) << view;
    EXPECT_NE(svg.find(">beckmann:roughness=0.3,f0=0.04<"), std::string::npos) << view;
  }
}

TEST(BrdfViews, SliceColumnsFollowThetaHAndRowsThetaD) {
  // GGX at small roughness: bright only in the first columns (theta_h near 0).
  Result<Model> m = parse_model("ggx:roughness=0.2,f0=1");
  ASSERT_TRUE(m.has_value());
  Image im = render_slice(*m, {.size = 30});
  int bottom = im.height - 1;  // theta_d near 0
  EXPECT_GT(im.at(0, bottom).g, 10.0 * im.at(15, bottom).g);
  // A white Lambert is pi * f = 1 everywhere (phi_d = 90 keeps l and v above the surface).
  Result<Model> lambert = parse_model("lambert");
  Image flat = render_slice(*lambert, {.size = 10});
  for (float x : flat.rgb) EXPECT_NEAR(x, 1.0, 1e-6);
}

}  // namespace
}  // namespace facet::brdf
