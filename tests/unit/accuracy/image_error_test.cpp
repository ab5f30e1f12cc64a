// The study's image-level errors against the Monte Carlo reference: every
// approximation has them, a form exact by construction measures only the
// reference's noise, the known failures show where they should, and the
// figures survive the study's JSON.
#include <gtest/gtest.h>

#include <cmath>

#include "facet/runtime/accuracy.h"

namespace facet::runtime::accuracy {
namespace {

// 64 samples per pixel: enough for the orders of magnitude these tests read.
const std::vector<StudyRow>& rows() {
  static const std::vector<StudyRow> all = [] {
    std::vector<StudyRow> r = compute_errors();
    compute_image_errors(r, 64);
    return r;
  }();
  return all;
}

const StudyRow& row(const std::string& id) {
  for (const StudyRow& r : rows()) {
    if (r.id == id) return r;
  }
  throw std::runtime_error("no row " + id);
}

const ImageError& in_scene(const StudyRow& r, const std::string& scene) {
  for (const ImageError& e : r.image) {
    if (e.scene == scene) return e;
  }
  throw std::runtime_error(r.id + " has no image error in " + scene);
}

TEST(AccuracyImageErrorTest, EveryApproximationHasImageErrorsAndNoReferenceRowHas) {
  for (const StudyRow& r : rows()) {
    bool reference = r.metric == "-";
    EXPECT_EQ(r.image.empty(), reference) << r.id;
    EXPECT_EQ(r.image_how.empty(), reference) << r.id;
    for (const ImageError& e : r.image) {
      EXPECT_GE(e.rmse, 0.0) << r.id;
      EXPECT_GE(e.max_error, e.rmse) << r.id << " in " << e.scene;
    }
  }
}

// Lambert in the white furnace is exact: what the study reports is the
// reference's noise, and the noise figure says so.
TEST(AccuracyImageErrorTest, AnExactFormMeasuresOnlyTheReferencesNoise) {
  const ImageError& e = in_scene(row("Fd_Lambert"), "uniform");
  EXPECT_GT(e.noise, 0.0);
  EXPECT_LT(e.rmse, 2.0 * e.noise);
}

TEST(AccuracyImageErrorTest, ApproximationsWithKnownErrorsStandOutOfTheNoise) {
  for (const char* id : {"V_SchlickGGXKaris", "F_Pow4", "BRDF2_Unity_PBS", "CookTorranceGGX"}) {
    const ImageError* worst = worst_image_error(row(id));
    ASSERT_NE(worst, nullptr) << id;
    EXPECT_GT(worst->rmse, 2.0 * worst->noise) << id << " in " << worst->scene;
  }
  // The single-scatter GGX loses energy in the furnace; compensated, far less.
  EXPECT_GT(in_scene(row("CookTorranceGGX"), "uniform").rmse,
            2.0 * in_scene(row("CookTorranceGGX_Compensated"), "uniform").rmse);
  // Karis' k is further from the exact V than Hammon's fast form, as on the lobes.
  EXPECT_GT(worst_image_error(row("V_SchlickGGXKaris"))->rmse, worst_image_error(row("V_SmithGGXCorrelatedFast"))->rmse);
}

// The naive half-precision D overflows on the smoothest sphere where a
// sampled half vector rounds to the normal; the safe form stays finite and close.
TEST(AccuracyImageErrorTest, TheNaiveHalfPrecisionDOverflowsInTheImageAndTheSafeFormDoesNot) {
  EXPECT_TRUE(std::isinf(in_scene(row("D_GGX_fp16"), "uniform").max_error));
  for (const ImageError& e : row("D_GGX_FP16Safe").image) {
    EXPECT_TRUE(std::isfinite(e.rmse)) << e.scene;
    EXPECT_LT(e.rmse, 0.05) << e.scene;
  }
}

TEST(AccuracyImageErrorTest, ImageErrorsRoundTripThroughJsonInfinityToo) {
  Study s;
  s.options.image_samples = 64;
  s.rows = rows();
  Result<Study> back = study_from_json(study_json(s));
  ASSERT_TRUE(back);
  EXPECT_EQ(back->options.image_samples, 64u);
  ASSERT_EQ(back->rows.size(), s.rows.size());
  for (size_t i = 0; i < s.rows.size(); ++i) {
    ASSERT_EQ(back->rows[i].image.size(), s.rows[i].image.size()) << s.rows[i].id;
    EXPECT_EQ(back->rows[i].image_how, s.rows[i].image_how);
    for (size_t k = 0; k < s.rows[i].image.size(); ++k) {
      EXPECT_EQ(back->rows[i].image[k].scene, s.rows[i].image[k].scene);
      EXPECT_DOUBLE_EQ(back->rows[i].image[k].rmse, s.rows[i].image[k].rmse) << s.rows[i].id;
      EXPECT_DOUBLE_EQ(back->rows[i].image[k].max_error, s.rows[i].image[k].max_error) << s.rows[i].id;
    }
  }
  std::string html = study_html(s);
  EXPECT_NE(html.find("<th>image RMSE</th>"), std::string::npos);
  EXPECT_NE(html.find("Monte Carlo reference, 64 samples per pixel"), std::string::npos);
}

}  // namespace
}  // namespace facet::runtime::accuracy
