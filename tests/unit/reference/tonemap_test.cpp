// T15: sRGB transfer and tone mappers.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <string>

#include "facet/reference/color.h"
#include "facet/reference/tonemap.h"

namespace facet::reference {
namespace {

TEST(ReferenceColorTest, SRGBRoundTripIsExactOnEvery8BitCode) {
  for (int code = 0; code < 256; ++code) {
    double e = code / 255.0;
    double back = FacetLinearToSRGB(FacetSRGBToLinear(e));
    EXPECT_EQ(int(std::lround(back * 255.0)), code);
    EXPECT_NEAR(back, e, 1e-12);
  }
}

TEST(ReferenceColorTest, SRGBRoundTripHoldsOnAMillionLinearValues) {
  double worst = 0.0;
  for (int i = 0; i < 1000000; ++i) {
    double c = i / 999999.0;
    worst = std::max(worst, std::abs(FacetSRGBToLinear(FacetLinearToSRGB(c)) - c));
  }
  EXPECT_LE(worst, 1e-12);
}

TEST(ReferenceColorTest, SRGBIsMonotonicAndContinuousAtTheBreakpoints) {
  double prevEnc = -1, prevDec = -1;
  for (int i = 0; i <= 100000; ++i) {
    double x = i / 100000.0;
    double enc = FacetLinearToSRGB(x), dec = FacetSRGBToLinear(x);
    EXPECT_GT(enc, prevEnc);
    EXPECT_GT(dec, prevDec);
    prevEnc = enc, prevDec = dec;
  }
  // The IEC constants meet to within ~1e-8 (not exactly) at both breakpoints.
  const double c = 0.0031308, e = 0.04045;
  EXPECT_NEAR(12.92 * c, 1.055 * std::pow(c, 1 / 2.4) - 0.055, 1e-7);
  EXPECT_NEAR(e / 12.92, std::pow((e + 0.055) / 1.055, 2.4), 1e-7);
  EXPECT_NEAR(FacetLinearToSRGB(std::nextafter(c, 1.0)), FacetLinearToSRGB(c), 1e-7);
  EXPECT_NEAR(FacetSRGBToLinear(std::nextafter(e, 1.0)), FacetSRGBToLinear(e), 1e-7);
}

using Tonemapper = std::function<glm::dvec3(const glm::dvec3&)>;
std::vector<std::pair<std::string, Tonemapper>> tonemappers() {
  return {{"Reinhard", [](auto& c) { return FacetTonemapReinhard(c); }},
          {"Reinhard extended", [](auto& c) { return FacetTonemapReinhardExtended(c, 4.0); }},
          {"Hable", [](auto& c) { return FacetTonemapHable(c); }},
          {"ACES Narkowicz", [](auto& c) { return FacetTonemapACESNarkowicz(c); }},
          {"ACES Hill", [](auto& c) { return FacetTonemapACESHill(c); }},
          {"PBR Neutral", [](auto& c) { return FacetTonemapPBRNeutral(c); }},
          {"AgX", [](auto& c) { return FacetTonemapAgX(c); }}};
}

// Grey, primary and orange ramps from 1e-6 to 1e4, log spaced: the output's
// Rec.709 luminance never falls (the channels themselves may: AgX and Hill
// desaturate bright colours towards white). AgX is the exception, by a little:
// its contrast polynomial has a negative linear term (-0.1718 x), which makes
// it dip by up to 2.3e-6 below an input of about 5e-4, and its path to white
// dips by up to 3.3e-4 near saturation for mixed hues (under 1/10 of an 8-bit
// code); it is held to a 5e-4 dip.
TEST(ReferenceTonemapTest, TonemappersAreMonotonicInLuminanceAndStayInZeroOne) {
  const glm::dvec3 hues[] = {{1, 1, 1}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0.5, 0.2}};
  const glm::dvec3 rec709(0.2126, 0.7152, 0.0722);
  for (const auto& [name, tm] : tonemappers()) {
    double allowed = name == "AgX" ? 5e-4 : 1e-12;
    for (glm::dvec3 hue : hues) {
      double running_max = 0.0, dip = 0.0;
      for (int i = 0; i <= 20000; ++i) {
        double x = std::pow(10.0, -6.0 + 10.0 * i / 20000.0);
        glm::dvec3 y = tm(x * hue);
        for (int c = 0; c < 3; ++c) ASSERT_TRUE(y[c] >= 0.0 && y[c] <= 1.0) << name << " at " << x;
        double lum = glm::dot(y, rec709);
        dip = std::max(dip, running_max - lum);
        running_max = std::max(running_max, lum);
      }
      EXPECT_LE(dip, allowed) << name << " hue " << hue.x << "," << hue.y << "," << hue.z;
    }
  }
}

TEST(ReferenceTonemapTest, TonemappersMapBlackToBlackAndSurviveHugeInputs) {
  for (const auto& [name, tm] : tonemappers()) {
    glm::dvec3 black = tm(glm::dvec3(0.0));
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(black[c], 0.0, 1e-3) << name;
    glm::dvec3 huge = tm(glm::dvec3(1e30));
    glm::dvec3 neg = tm(glm::dvec3(-5.0));
    for (int c = 0; c < 3; ++c) {
      EXPECT_TRUE(std::isfinite(huge[c]) && huge[c] <= 1.0) << name;
      EXPECT_NEAR(neg[c], black[c], 1e-15) << name << ": negative input is taken as 0";
    }
  }
}

TEST(ReferenceTonemapTest, HillFitIsNegativeNearZeroUnlessClamped) {
  EXPECT_NEAR(FacetACESHillRRTODTFit(glm::dvec3(0.0)).x, -0.000090537 / 0.238081, 1e-9);
  EXPECT_LT(FacetACESHillRRTODTFit(glm::dvec3(0.003)).x, 0.0);
  EXPECT_EQ(FacetTonemapACESHill(glm::dvec3(0.0)), glm::dvec3(0.0));
}

TEST(ReferenceTonemapTest, WhitePointsMapToOne) {
  EXPECT_NEAR(FacetTonemapReinhardExtended(glm::dvec3(4.0), 4.0).x, 1.0, 1e-12);
  EXPECT_NEAR(FacetTonemapHable(glm::dvec3(5.6)).x, 1.0, 1e-12);  // 2 x = W = 11.2
}

TEST(ReferenceTonemapTest, AgXOutsetMatrixInvertsTheInset) {
  glm::dmat3 product = FacetAgXOutsetMatrix() * FacetAgXInsetMatrix();
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) EXPECT_NEAR(product[i][j], i == j ? 1.0 : 0.0, 1e-6);
}

TEST(ReferenceTonemapTest, PBRNeutralIsTheIdentityBelowTheCompressionStart) {
  glm::dvec3 c(0.5, 0.3, 0.2);  // min >= 0.08: the offset is the constant 0.04
  glm::dvec3 y = FacetTonemapPBRNeutral(c);
  EXPECT_NEAR(glm::length(y - (c - 0.04)), 0.0, 1e-12);
}

}  // namespace
}  // namespace facet::reference
