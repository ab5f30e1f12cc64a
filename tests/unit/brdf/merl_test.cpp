// T16: MERL files written from analytic BRDFs (the twins), loaded back and
// looked up; and the files a loader must refuse.
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <random>

#include "facet/reference/hlsl_math.h"
#include "unit/brdf/brdf_test_util.h"

namespace facet::brdf {
namespace {

using glm::dvec3;
using reference::kPi;
using test::scratch;

// GGX at alpha = 0.3 (roughness sqrt(0.3)) with a coloured f0, so that each
// channel's scale factor matters.
const char* const kGgxSpec = "ggx:roughness=0.5477225575,f0=0.9/0.6/0.3";

struct Written {
  Model model;
  std::string path;
  MerlData data;
};
const Written& ggx_file() {
  static const Written w = [] {
    Written w;
    w.model = *parse_model(kGgxSpec);
    w.path = scratch("ggx.binary");
    EXPECT_TRUE(write_merl(w.path, w.model.f).has_value());
    Result<MerlData> d = load_merl(w.path);
    EXPECT_TRUE(d.has_value()) << (d ? "" : d.error().reason);
    if (d) w.data = std::move(*d);
    return w;
  }();
  return w;
}

dvec3 random_direction(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  double z = u(rng), phi = 2.0 * kPi * u(rng), s = std::sqrt(1.0 - z * z);
  return {s * std::cos(phi), s * std::sin(phi), z};
}

// Whether the bin holding (v, l) was written from directions above the
// surface: bins straddling the horizon hold "not measured" (0 once loaded).
bool bin_measured(const dvec3& v, const dvec3& l) {
  size_t i = merl_index(to_half_diff(v, l));
  dvec3 cv, cl;
  from_half_diff(merl_bin_centre(int(i / (kMerlPhiD * kMerlThetaD)), int(i / kMerlPhiD % kMerlThetaD),
                                 int(i % kMerlPhiD)),
                 cv, cl);
  return cv.z > 0.0 && cl.z > 0.0;
}

TEST(Merl, WrittenFileHasTheMerlSize) {
  EXPECT_EQ(std::filesystem::file_size(ggx_file().path), 34992012u);
  EXPECT_EQ(kMerlFileBytes, 34992012u);
}

TEST(Merl, HalfDifferenceAnglesRoundTrip) {
  for (double th : {0.01, 0.3, 0.8, 1.2})
    for (double td : {0.0, 0.2, 0.7, 1.3})
      for (double pd : {0.1, 1.0, 1.5, 3.0}) {
        dvec3 v, l;
        from_half_diff({th, td, pd}, v, l);
        EXPECT_NEAR(glm::length(v), 1.0, 1e-12);
        HalfDiff a = to_half_diff(v, l);
        EXPECT_NEAR(a.theta_h, th, 1e-9);
        EXPECT_NEAR(a.theta_d, td, 1e-9);
        if (td > 0.0) {
          EXPECT_NEAR(a.phi_d, pd, 1e-9);
        }
      }
}

TEST(Merl, ThetaHBinsAreSquareRootSpaced) {
  // Bin i covers theta_h in [(i/90)^2, ((i+1)/90)^2) * 90 degrees.
  const double d = kPi / 2.0;
  EXPECT_EQ(merl_index({0.0, 0, 0}), 0u);
  EXPECT_EQ(merl_index({std::pow(1.0 / 90.0, 2) * d * 0.99, 0, 0}), 0u);
  EXPECT_EQ(merl_index({std::pow(1.0 / 90.0, 2) * d * 1.01, 0, 0}), size_t(kMerlPhiD) * kMerlThetaD);
  EXPECT_EQ(merl_index({std::pow(45.5 / 90.0, 2) * d, 0, 0}), 45u * kMerlPhiD * kMerlThetaD);
  EXPECT_EQ(merl_index({d, d, kPi}), kMerlPlane - 1);  // the far edges clamp into the last bin
}

TEST(Merl, LookupAtBinCentresReproducesTheAnalyticBrdf) {
  const Written& w = ggx_file();
  int checked = 0;
  for (int ih = 0; ih < kMerlThetaH; ih += 7)
    for (int id = 0; id < kMerlThetaD; id += 5)
      for (int ip = 0; ip < kMerlPhiD; ip += 11) {
        dvec3 v, l;
        from_half_diff(merl_bin_centre(ih, id, ip), v, l);
        if (v.z <= 0.0 || l.z <= 0.0) continue;
        dvec3 expected = w.model.f(v, l), got = merl_lookup(w.data, v, l);
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(got[c], expected[c], 1e-12 * expected[c]) << ih << " " << id << " " << ip;
        ++checked;
      }
  EXPECT_GT(checked, 1000);
}

TEST(Merl, LookupAnywhereIsWithinTheBinQuantisationError) {
  // Nearest-bin lookup of 20,000 random direction pairs (cosines >= 0.05):
  // measured relative error for GGX alpha = 0.3: median 1.35 %, 90th
  // percentile 3.6 %, 99th 7.3 %, max 31 % (where the lobe is steep across
  // a bin). T16 expects about 5 % away from the theta_h bin edges.
  const Written& w = ggx_file();
  std::mt19937_64 rng(7);
  std::vector<double> errors;
  while (errors.size() < 20000) {
    dvec3 v = random_direction(rng), l = random_direction(rng);
    if (v.z < 0.05 || l.z < 0.05 || !bin_measured(v, l)) continue;
    double expected = w.model.f(v, l).g;
    errors.push_back(std::abs(merl_lookup(w.data, v, l).g - expected) / expected);
  }
  std::sort(errors.begin(), errors.end());
  EXPECT_LT(errors[errors.size() / 2], 0.02);
  EXPECT_LT(errors[errors.size() * 9 / 10], 0.05);
}

TEST(Merl, ConstantBrdfIsExactEverywhereWithEachChannelsScale) {
  const dvec3 albedo(0.5, 0.3, 0.2);
  std::string path = scratch("lambert.binary");
  ASSERT_TRUE(write_merl(path, [&](const dvec3&, const dvec3&) { return albedo / kPi; }).has_value());
  // Stored values are BRDF / scale: 1500 / 1.15 / 1.66 in each channel's units.
  std::string bytes = test::read_bytes(path);
  auto stored = [&](size_t channel, size_t i) {
    uint64_t x;
    std::memcpy(&x, bytes.data() + 12 + 8 * (channel * kMerlPlane + i), 8);
    return std::bit_cast<double>(x);
  };
  EXPECT_NEAR(stored(0, 0), 0.5 / kPi * 1500.0, 1e-9);
  EXPECT_NEAR(stored(1, 0), 0.3 / kPi * 1500.0 / 1.15, 1e-9);
  EXPECT_NEAR(stored(2, 0), 0.2 / kPi * 1500.0 / 1.66, 1e-9);
  Result<MerlData> d = load_merl(path);
  ASSERT_TRUE(d.has_value());
  std::mt19937_64 rng(3);
  for (int i = 0; i < 1000; ++i) {
    dvec3 v = random_direction(rng), l = random_direction(rng);
    if (!bin_measured(v, l)) continue;
    dvec3 got = merl_lookup(*d, v, l);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(got[c], albedo[c] / kPi, 1e-14);
  }
}

TEST(Merl, NegativeEntriesLoadAsZero) {
  // Bins whose directions fall below the surface are written as -1 ("not
  // measured", as in MERL's data) and must read back as 0.
  const Written& w = ggx_file();
  HalfDiff below = merl_bin_centre(80, 80, 0);  // theta_h + theta_d > 90 deg in the plane of incidence
  dvec3 v, l;
  from_half_diff(below, v, l);
  ASSERT_TRUE(v.z <= 0.0 || l.z <= 0.0);
  std::string bytes = test::read_bytes(w.path);
  uint64_t raw;
  std::memcpy(&raw, bytes.data() + 12 + 8 * merl_index(below), 8);
  EXPECT_LT(std::bit_cast<double>(raw), 0.0);
  for (int c = 0; c < 3; ++c) EXPECT_EQ(w.data.values[merl_index(below) + c * kMerlPlane], 0.0);
}

// ---- files to refuse ----
std::string load_error(const std::string& path) {
  Result<MerlData> d = load_merl(path);
  return d ? "" : d.error().reason;
}
std::string header(int a, int b, int c) {
  std::string h(12, '\0');
  int32_t dims[3] = {a, b, c};
  std::memcpy(h.data(), dims, 12);  // the tests run on little-endian hosts, as MERL's files are
  return h;
}

TEST(Merl, MissingFileIsAnError) {
  std::string e = load_error(scratch("does_not_exist.binary"));
  EXPECT_NE(e.find("does_not_exist.binary: cannot open"), std::string::npos) << e;
}

TEST(Merl, TruncatedHeaderIsAnError) {
  std::string path = scratch("short_header.binary");
  test::write_bytes(path, std::string(5, '\0'));
  std::string e = load_error(path);
  EXPECT_NE(e.find("short_header.binary: truncated: 5 bytes"), std::string::npos) << e;
}

TEST(Merl, WrongDimensionsAreAnError) {
  std::string path = scratch("bad_dims.binary");
  test::write_bytes(path, header(90, 90, 360) + std::string(64, '\0'));
  std::string e = load_error(path);
  EXPECT_NE(e.find("bad_dims.binary: dimensions 90 x 90 x 360, but a MERL file has 90 x 90 x 180"),
            std::string::npos) << e;
}

TEST(Merl, TruncatedDataIsAnError) {
  std::string path = scratch("truncated.binary");
  test::write_bytes(path, header(90, 90, 180) + std::string(8 * 1000, '\0'));
  std::string e = load_error(path);
  EXPECT_NE(e.find("truncated.binary: 8012 bytes, but a 90 x 90 x 180 MERL file has 34992012 (truncated)"),
            std::string::npos) << e;
}

TEST(Merl, TrailingDataIsAnError) {
  std::string path = scratch("trailing.binary");
  test::write_bytes(path, test::read_bytes(ggx_file().path) + "x");
  std::string e = load_error(path);
  EXPECT_NE(e.find("trailing.binary: 34992013 bytes"), std::string::npos) << e;
  EXPECT_NE(e.find("(trailing data)"), std::string::npos) << e;
}

TEST(Merl, NonFiniteEntryIsAnError) {
  std::string path = scratch("nan.binary");
  std::string bytes = test::read_bytes(ggx_file().path);
  double nan = std::nan("");
  std::memcpy(bytes.data() + 12 + 8 * (kMerlPlane + 5), &nan, 8);
  test::write_bytes(path, bytes);
  std::string e = load_error(path);
  EXPECT_NE(e.find("nan.binary: entry 5 of the green plane"), std::string::npos) << e;
}

TEST(Merl, MerlModelRendersThroughTheCommandAndBadFilesExitOne) {
  std::string out = scratch("merl_polar.svg");
  test::CommandResult ok = test::run_command({"merl:" + ggx_file().path, kGgxSpec, "--view", "polar", "-o", out});
  EXPECT_EQ(ok.code, 0) << ok.err;
  EXPECT_TRUE(std::filesystem::exists(out));

  std::string bad = scratch("truncated_for_command.binary");
  test::write_bytes(bad, header(90, 90, 180));
  std::string out2 = scratch("merl_bad.svg");
  test::CommandResult r = test::run_command({"merl:" + bad, "--view", "polar", "-o", out2});
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("truncated_for_command.binary: 12 bytes"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(out2));
}

}  // namespace
}  // namespace facet::brdf
