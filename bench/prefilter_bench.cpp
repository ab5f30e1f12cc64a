// What the reflection cube's accuracy costs (docs/performance.md): the GGX
// prefiltering of a 64-texel cube of an analytic environment (a bright lobe
// on a dim floor, the one tests/unit/render/environment_test.cpp measures)
// at 32 to 1024 samples a texel: its time (the best of three runs) and its
// worst difference from ggx_lobe_reference over the texels the test checks,
// where the lobe's light arrives (relative) and in the dim tails (of the
// peak). Times are of this machine: compare them as ratios.
//
//   facet_prefilter_bench
#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>

#include "facet/runtime/environment.h"
#include "facet/runtime/sky_sh.h"

namespace {

using namespace facet::runtime;

glm::vec3 blob(const glm::vec3& d) {
  const glm::vec3 toward = glm::normalize(glm::vec3(1, 1, 0.3f));
  return glm::vec3(0.05f) + glm::vec3(4, 2, 1) * std::exp(10 * (glm::dot(glm::normalize(d), toward) - 1));
}

struct Errors {
  double lit = 0, tail = 0;
};

Errors errors(const CubeMips& probe) {
  const float peak = 4.05f;
  Errors e;
  for (int m = 1; m <= kSpecCubeLodSteps; ++m) {
    const uint32_t size = probe.size >> m;
    const float roughness = unity_mip_roughness(float(m));
    for (int face : {0, 2, 5}) {
      for (uint32_t y : {0u, size / 2}) {
        const uint32_t x = size / 2;
        glm::vec3 n = cube_direction(face, (float(x) + 0.5f) / float(size), (float(y) + 0.5f) / float(size));
        glm::vec3 want = ggx_lobe_reference(blob, n, roughness, 1024);
        const float* got = &probe.mips[size_t(m)][((size_t(face) * size + y) * size + x) * 4];
        for (int c = 0; c < 3; ++c) {
          double d = std::abs(got[c] - want[c]);
          if (want[c] >= 0.2f) e.lit = std::max(e.lit, d / want[c]);
          else e.tail = std::max(e.tail, d / peak);
        }
      }
    }
  }
  return e;
}

}  // namespace

int main() {
  const CubeMips source = cube_from_radiance(blob, 64);
  fmt::print("{:>8} {:>12} {:>10} {:>16} {:>16}\n", "samples", "time (ms)", "x 256's", "worst lit (%)", "worst tail (%)");
  double base = 0;
  struct Row {
    uint32_t samples;
    double ms;
    Errors e;
  };
  std::vector<Row> rows;
  for (uint32_t samples : {32u, 64u, 128u, 256u, 512u, 1024u}) {
    double best = 1e30;
    CubeMips probe;
    for (int run = 0; run < 3; ++run) {
      auto start = std::chrono::steady_clock::now();
      probe = prefilter_ggx(source, {.samples = samples});
      best = std::min(best, std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
    }
    rows.push_back({samples, best, errors(probe)});
    if (samples == 256) base = best;
  }
  for (const Row& r : rows) {
    fmt::print("{:>8} {:>12.1f} {:>10.2f} {:>16.2f} {:>16.2f}\n", r.samples, r.ms, r.ms / base, 100 * r.e.lit,
               100 * r.e.tail);
  }
  return 0;
}
