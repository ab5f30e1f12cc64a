// The reflection cube on the CPU (facet/runtime/environment.h): Unity's
// roughness -> mip curve inverted, a uniform environment kept exactly, the
// prefiltered mips against a brute-force GGX integral of an analytic
// environment, and the equirectangular mapping of Skybox/Panoramic.
#include "facet/runtime/environment.h"

#include <gtest/gtest.h>

#include <cmath>

#include "facet/runtime/sky_sh.h"

namespace facet::runtime {
namespace {


TEST(Environment, UnityMipRoughnessInvertsUnitysCurve) {
  for (int m = 0; m <= kSpecCubeLodSteps; ++m) {
    float r = unity_mip_roughness(float(m));
    EXPECT_NEAR(r * (1.7f - 0.7f * r) * kSpecCubeLodSteps, float(m), 1e-4f) << "mip " << m;
  }
  EXPECT_EQ(unity_mip_roughness(0), 0.0f);
  EXPECT_NEAR(unity_mip_roughness(6), 1.0f, 1e-6f);
}

TEST(Environment, AUniformEnvironmentStaysUniformInEveryPrefilteredMip) {
  const glm::vec3 c(1.0f, 0.5f, 2.0f);
  CubeMips probe = prefilter_ggx(cube_from_radiance([&](const glm::vec3&) { return c; }, 16), {.samples = 64});
  ASSERT_EQ(probe.mips.size(), 5u);  // 16, 8, 4, 2, 1
  for (size_t m = 0; m < probe.mips.size(); ++m) {
    const std::vector<float>& level = probe.mips[m];
    for (size_t i = 0; i < level.size(); i += 4) {
      ASSERT_NEAR(level[i], c.r, 1e-5f) << "mip " << m << " texel " << i / 4;
      ASSERT_NEAR(level[i + 1], c.g, 1e-5f);
      ASSERT_NEAR(level[i + 2], c.b, 2e-5f);
    }
  }
}

// A bright lobe around `toward` on a dim floor: sharp enough that the
// prefiltering's blur and sampling show, smooth enough for a 64-texel cube.
glm::vec3 blob(const glm::vec3& d) {
  const glm::vec3 toward = glm::normalize(glm::vec3(1, 1, 0.3f));
  return glm::vec3(0.05f) + glm::vec3(4, 2, 1) * std::exp(10 * (glm::dot(glm::normalize(d), toward) - 1));
}

// Where the lobe's light arrives (the integral above a fifth of the floor's
// 40-fold), within 5 % of it; in the dim tails, within 1 % of the brightest
// radiance (the blur of filtered importance sampling leaks a little light).
TEST(Environment, PrefilteredMipsMatchTheGgxLobeIntegralOfAnAnalyticEnvironment) {
  const uint32_t size = 64;
  const float peak = 4.05f;
  CubeMips probe = prefilter_ggx(cube_from_radiance(blob, size), {.samples = 256});
  double worst_lit = 0, worst_tail = 0;
  for (int m = 1; m <= kSpecCubeLodSteps; ++m) {
    const uint32_t mip_size = size >> m;
    const float roughness = unity_mip_roughness(float(m));
    // Texels of the +X, +Y and -Z faces: towards the lobe, beside it, away from it.
    for (int face : {0, 2, 5}) {
      for (uint32_t y : {0u, mip_size / 2}) {
        const uint32_t x = mip_size / 2;
        glm::vec3 n = cube_direction(face, (float(x) + 0.5f) / float(mip_size), (float(y) + 0.5f) / float(mip_size));
        glm::vec3 want = ggx_lobe_reference(blob, n, roughness, 1024);
        const float* got = &probe.mips[size_t(m)][((size_t(face) * mip_size + y) * mip_size + x) * 4];
        for (int c = 0; c < 3; ++c) {
          const double difference = std::abs(got[c] - want[c]);
          const bool lit = want[c] >= 0.2f;
          if (lit) worst_lit = std::max(worst_lit, difference / want[c]);
          else worst_tail = std::max(worst_tail, difference / peak);
          EXPECT_LT(difference, lit ? 0.05 * want[c] : 0.01 * peak)
              << "mip " << m << " face " << face << " texel (" << x << ", " << y << ") channel " << c << ": " << got[c]
              << " vs " << want[c];
        }
      }
    }
  }
  std::printf("[ prefilter ] worst difference from the GGX integral: %.4f of the value where lit, %.4f of the peak "
              "in the tails\n", worst_lit, worst_tail);
}

TEST(Environment, EquirectangularImagesMapAsSkyboxPanoramicDoes) {
  // 8 x 4 texels: the top rows red, the bottom rows blue; column 3 and 4 (the
  // middle, u = 0.5) green in the middle rows.
  Equirect image{8, 4, 3, std::vector<float>(8 * 4 * 3, 0.0f)};
  for (uint32_t y = 0; y < 4; ++y) {
    for (uint32_t x = 0; x < 8; ++x) {
      float* p = &image.pixels[(y * 8 + x) * 3];
      if (y == 0) p[0] = 1;
      if (y == 3) p[2] = 1;
      if ((y == 1 || y == 2) && (x == 3 || x == 4)) p[1] = 1;
    }
  }
  EXPECT_GT(sample_equirect(image, {0, 1, 0}).r, 0.99f);   // straight up: row 0
  EXPECT_GT(sample_equirect(image, {0, -1, 0}).b, 0.99f);  // straight down: the last row
  // u = 0.5 - atan2(z, x) / 2pi: +X is the middle column.
  EXPECT_GT(sample_equirect(image, {1, 0, 0}).g, 0.99f);
  EXPECT_LT(sample_equirect(image, {-1, 0, 0}).g, 0.01f);
  EXPECT_LT(sample_equirect(image, {0, 0, 1}).g, 0.01f);
}

TEST(Environment, SamplingACubeReadsTheFaceItsDirectionSelects) {
  const glm::vec3 axes[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  CubeMips cube = cube_from_radiance([](const glm::vec3& d) { return d * 0.5f + 0.5f; }, 8);
  for (const glm::vec3& axis : axes) {
    glm::vec3 got = sample_cube(cube, axis, 0);
    EXPECT_LT(glm::distance(got, axis * 0.5f + 0.5f), 0.06f) << axis.x << " " << axis.y << " " << axis.z;
  }
  // The last mip (one texel a face) is the face's mean.
  glm::vec3 mean = sample_cube(cube, {0, 1, 0}, 3);
  EXPECT_GT(mean.y, 0.8f);  // 0.5 + 0.5 x the mean of 1 / sqrt(1 + u^2 + v^2) over the face, 0.86
  EXPECT_LT(mean.y, 0.9f);
}

}  // namespace
}  // namespace facet::runtime
