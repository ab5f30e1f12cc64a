// Golden images: a rendered frame against a reviewed PNG in tests/golden/,
// compared through OpenImageIO with a tolerance for rasteriser noise
// (docs/rendering.md, "Golden images", says how the thresholds were chosen).
#pragma once

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>
#include <fmt/format.h>

#include <cstdlib>
#include <filesystem>
#include <string>

#include "facet/runtime/renderer.h"
#include "render_test_support.h"

namespace facet::runtime::test_support {

// Every golden is rendered at this size, whatever the scene's own size: small
// enough for the suite's time under ASan, large enough that a silhouette is
// mostly interior pixels.
constexpr int kGoldenWidth = 96, kGoldenHeight = 72;

// A pixel "fails" when one of its colour channels is off by more than this
// (in 0..1, about 13 of 255 levels): well above the level or two that other
// floating-point code generation or half-float rounding moves a pixel by.
constexpr float kPixelFailThreshold = 0.05f;
// At most this fraction of the pixels may fail (69 at 96 x 72): silhouettes
// covered differently by a tenth of a pixel fail at most 26 pixels in the
// example scenes; one object 10 % darker fails at least 167.
constexpr double kMaxFailingFraction = 0.01;
// The mean absolute error over every colour channel of every pixel (0..1,
// about 0.8 of a level): catches a change spread thinly over the whole image
// (a light 5 % dimmer moves each pixel by only a level or three) that no
// single pixel shows; the tenth-of-a-pixel shift stays below 0.0018.
constexpr double kMaxMeanError = 0.003;

inline std::filesystem::path golden_dir() { return std::filesystem::path(FACET_SOURCE_DIR) / "tests" / "golden"; }

inline bool updating_goldens() {
  const char* v = std::getenv("FACET_UPDATE_GOLDENS");
  return v && std::string(v) == "1";
}

struct GoldenComparison {
  bool ok = false;
  double mean_error = 0, max_error = 0;
  long failing_pixels = 0;
  std::string message;  // why it failed, or the numbers when it passed
};

// The frame's LDR pixels as an OpenImageIO buffer (RGB; alpha is always 255).
inline OIIO::ImageBuf frame_image(const RenderedFrame& frame) {
  OIIO::ImageSpec spec(frame.width, frame.height, 4, OIIO::TypeDesc::UINT8);
  OIIO::ImageBuf rgba(spec, const_cast<uint8_t*>(frame.ldr.data()));
  return OIIO::ImageBufAlgo::channels(rgba, 3, {});
}

// Compares `actual` with `golden` (both RGB, 0..1 after OIIO's conversion).
inline GoldenComparison compare_images(const OIIO::ImageBuf& actual, const OIIO::ImageBuf& golden) {
  GoldenComparison c;
  const OIIO::ImageSpec& a = actual.spec();
  const OIIO::ImageSpec& g = golden.spec();
  if (a.nchannels < 3 || g.nchannels < 3) {
    c.message = fmt::format("expected RGB images, got {} and {} channels", a.nchannels, g.nchannels);
    return c;
  }
  if (a.width != g.width || a.height != g.height) {
    c.message = fmt::format("size {}x{} differs from the golden's {}x{}", a.width, a.height, g.width, g.height);
    return c;
  }
  OIIO::ROI rgb = actual.roi();
  rgb.chbegin = 0;
  rgb.chend = 3;
  OIIO::ImageBufAlgo::CompareResults r =
      OIIO::ImageBufAlgo::compare(actual, golden, kPixelFailThreshold, kPixelFailThreshold, rgb);
  // r.error is not checked: OpenImageIO 2.4 also sets it when pixels exceed
  // failthresh, which is the outcome measured here, not a failure to compare.
  c.mean_error = r.meanerror;
  c.max_error = r.maxerror;
  c.failing_pixels = long(r.nfail);
  long allowed = long(kMaxFailingFraction * a.width * a.height);
  c.ok = c.failing_pixels <= allowed && c.mean_error <= kMaxMeanError;
  c.message = fmt::format("{} pixels off by more than {} (at most {} allowed), mean error {:.5f} (at most {}), "
                          "max error {:.3f} at ({}, {})",
                          c.failing_pixels, kPixelFailThreshold, allowed, c.mean_error, kMaxMeanError, c.max_error,
                          r.maxx, r.maxy);
  return c;
}

// Compares `frame` with tests/golden/<name>.png. A missing or unreadable
// golden fails with the command that creates it. On a mismatch the actual
// image and the absolute difference go to ./golden_failures/ for review.
inline GoldenComparison compare_with_golden(const RenderedFrame& frame, const std::string& name) {
  std::filesystem::path path = golden_dir() / (name + ".png");
  GoldenComparison c;
  if (!std::filesystem::exists(path)) {
    c.message = fmt::format("{} is missing; create it with FACET_UPDATE_GOLDENS=1 facet_render_tests "
                            "--gtest_filter='*Golden*' and review the image before committing it",
                            path.string());
    return c;
  }
  OIIO::ImageBuf golden(path.string());
  if (!golden.read(0, 0, true, OIIO::TypeDesc::FLOAT)) {
    c.message = fmt::format("{}: cannot read the golden: {}", path.string(), golden.geterror());
    return c;
  }
  OIIO::ImageBuf actual = frame_image(frame);
  c = compare_images(actual, OIIO::ImageBufAlgo::channels(golden, 3, {}));
  c.message = path.string() + ": " + c.message;
  if (c.ok) return c;
  std::filesystem::path out = std::filesystem::current_path() / "golden_failures";
  std::filesystem::create_directories(out);
  actual.write((out / (name + ".actual.png")).string());
  if (golden.spec().width == actual.spec().width && golden.spec().height == actual.spec().height) {
    OIIO::ImageBuf diff = OIIO::ImageBufAlgo::absdiff(actual, OIIO::ImageBufAlgo::channels(golden, 3, {}));
    OIIO::ImageBufAlgo::mul(diff, 4.0f).write((out / (name + ".diff4x.png")).string(), OIIO::TypeDesc::UINT8);
  }
  c.message += fmt::format("; the actual image and the difference ×4 are in {}", out.string());
  return c;
}

// Writes tests/golden/<name>.png from `frame` (only under FACET_UPDATE_GOLDENS=1).
inline Result<void, Printed> update_golden(const RenderedFrame& frame, const std::string& name) {
  std::filesystem::create_directories(golden_dir());
  Diagnostics diags;
  if (!write_png(frame, (golden_dir() / (name + ".png")).string(), diags)) return unexpected(printed(diags, {}));
  return {};
}

}  // namespace facet::runtime::test_support
