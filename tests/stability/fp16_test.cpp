// The fp16 mode (T3/T4, docs/stability.md "fp16"): the GGX D, V and F forms in true
// half arithmetic, on the CPU (GCC _Float16, facet/reference/fp16/) and on the
// GPU: an emulation that rounds every operation to half with f32tof16, and the
// stdlib's own functions in real 16-bit arithmetic (float16_t, shaderFloat16);
// plus the stdlib compiled with min16float without 16-bit types
// (RelaxedPrecision), which lavapipe evaluates at fp32.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <tuple>

#include "facet/backend.h"
#include "facet/reference/brdf.h"
#include "facet/reference/fp16/brdf_fp16.h"
#include "stability/checks.h"
#include "stability/gpu.h"

namespace facet::stability {
namespace {

namespace h16 = reference::fp16;
using h16::half;

constexpr double kPi = 3.14159265358979323846;
double D_ref(double c, double alpha) { return reference::FacetD_GGX(c, alpha); }

struct DError {
  double worst = 0;  // relative, over the finite results
  int infinite = 0;  // inf or NaN results
};

// theta_h in [0, 30 degrees] where D > 1e-3 of its peak (T4). Each form gets
// h rounded to half; the reference is fp64 at the same theta (the safe
// forms' reference is clamped like them at k = 453.5).
template <class Form>
DError d_error(double alpha, Form form, bool clamped_reference) {
  DError e;
  double peak = 1.0 / (kPi * alpha * alpha);
  for (int i = 0; i <= 6000; ++i) {
    double t = (kPi / 6.0) * i / 6000.0;
    double ref = D_ref(std::cos(t), alpha);
    if (ref < 1e-3 * peak) continue;
    if (clamped_reference) ref = std::min(ref, 453.5 * 453.5 / kPi);
    double d = double(form(half(std::sin(t)), half(std::cos(t)), half(alpha)));
    if (!std::isfinite(d)) ++e.infinite;
    else e.worst = std::max(e.worst, std::abs(d / ref - 1.0));
  }
  return e;
}

auto naive = [](half, half c, half a) { return h16::D_GGX<half>(c, a); };
auto safe = [](half s, half c, half a) { return h16::D_GGX_FP16Safe<half>({0, 0, 1}, {s, 0, c}, a); };
auto unassociated = [](half s, half c, half a) {
  return h16::D_GGX_FP16SafeUnassociated<half>({0, 0, 1}, {s, 0, c}, a);
};

TEST(StabilityFp16Test, NaiveGgxFailsAndTheCrossProductFormHoldsOnePercent) {
  if (!h16::kHasHalf) GTEST_SKIP() << "no _Float16";
  // T4: alpha = 0.0079 (r = 0.089) ... 0.25.
  for (double alpha : {reference::FACET_MIN_ALPHA_FP16, 0.02, 0.0625, 0.25}) {
    DError n = d_error(alpha, naive, false), s = d_error(alpha, safe, true);
    std::printf("[ fp16 D ] alpha %.6f: naive max rel err %.4g (%d inf), cross form %.4g (%d inf)\n", alpha, n.worst,
                n.infinite, s.worst, s.infinite);
    EXPECT_EQ(s.infinite, 0) << alpha;
    EXPECT_LE(s.worst, 0.01) << alpha;
    EXPECT_TRUE(n.infinite > 0 || n.worst > 0.02) << "naive form at alpha " << alpha << " unexpectedly accurate";
  }
  // The documented orders of magnitude: beyond 100 % at alpha = 0.02, 26 % at 0.0625.
  EXPECT_GT(d_error(0.02, naive, false).worst, 1.0);
  EXPECT_NEAR(d_error(0.0625, naive, false).worst, 0.26, 0.03);
  EXPECT_GT(d_error(reference::FACET_MIN_ALPHA_FP16, naive, false).infinite, 0) << "1 - NoH^2 cancels to 0";
}

// T3: at the fp32 clamp alpha = 0.002025 the peak 1/(pi alpha^2) = 77 625 is
// beyond half (65 504): the naive form overflows. The safe form clamps k to
// 453.5; written k * k * (1/pi) it formed k^2 = 205 662 first and overflowed
// too for every alpha below 1/256 (k > 256), which this suite found; the
// stdlib now writes k * (k / pi), finite everywhere.
TEST(StabilityFp16Test, AtTheFp32ClampNaiveFormOverflowsHalfAndTheStdlibSafeFormDoesNot) {
  if (!h16::kHasHalf) GTEST_SKIP() << "no _Float16";
  half one(1), zero(0), a(reference::FACET_MIN_ALPHA);
  EXPECT_TRUE(std::isinf(float(h16::D_GGX<half>(one, a))));
  EXPECT_NEAR(double(h16::D_GGX<double>(1.0, reference::FACET_MIN_ALPHA)), 77625, 1);
  EXPECT_TRUE(std::isinf(float(h16::D_GGX_FP16SafeUnassociated<half>({0, 0, 1}, {zero, 0, one}, a))));
  for (double alpha : {reference::FACET_MIN_ALPHA, 0.0039}) {
    EXPECT_GT(d_error(alpha, unassociated, true).infinite, 0) << alpha;
    DError r = d_error(alpha, safe, true);
    EXPECT_EQ(r.infinite, 0) << alpha;
    EXPECT_LE(r.worst, 0.02) << alpha;
  }
  for (double alpha : {0.004, reference::FACET_MIN_ALPHA_FP16}) EXPECT_EQ(d_error(alpha, safe, true).infinite, 0) << alpha;
  EXPECT_LE(float(h16::D_GGX_FP16Safe<half>({0, 0, 1}, {zero, 0, one}, a)), 65504.0f);
}

// V and F in half: where they overflow or lose precision.
TEST(StabilityFp16Test, VisibilityOverflowsHalfOnlyAtGrazingAndSchlickStaysWithinFiveHalfUlps) {
  if (!h16::kHasHalf) GTEST_SKIP() << "no _Float16";
  const double cosines[] = {1e-4, 1e-3, 0.01, 0.1, 0.5, 1.0};
  for (double alpha : {reference::FACET_MIN_ALPHA_FP16, 0.25, 1.0}) {
    int inf_exact = 0, inf_fast = 0;
    double worst_exact = 0, worst_fast = 0;
    for (double nv : cosines)
      for (double nl : cosines) {
        double ref = reference::FacetV_SmithGGXCorrelated(nv, nl, alpha);
        double ref_fast = reference::FacetV_SmithGGXCorrelatedFast(nv, nl, alpha);
        double e = double(h16::V_SmithGGXCorrelated<half>(half(nv), half(nl), half(alpha)));
        double f = double(h16::V_SmithGGXCorrelatedFast<half>(half(nv), half(nl), half(alpha)));
        bool grazing = std::min(nv, nl) <= 1e-3;
        if (!std::isfinite(e)) {
          ++inf_exact;
          EXPECT_TRUE(grazing) << nv << " " << nl << " " << alpha;
        } else if (!grazing) {
          worst_exact = std::max(worst_exact, std::abs(e / ref - 1));
        }
        if (!std::isfinite(f)) {
          ++inf_fast;
          EXPECT_TRUE(grazing) << nv << " " << nl << " " << alpha;
        } else if (!grazing) {
          worst_fast = std::max(worst_fast, std::abs(f / ref_fast - 1));
        }
      }
    std::printf("[ fp16 V ] alpha %.4f: exact V %d inf, max rel err %.4g off-grazing; Hammon V %d inf, %.4g\n", alpha,
                inf_exact, worst_exact, inf_fast, worst_fast);
    EXPECT_LE(worst_exact, 0.01);
    EXPECT_LE(worst_fast, 0.01);
    if (alpha < 0.01) {
      EXPECT_GT(inf_exact + inf_fast, 0) << "0.5 / 1.6e-6 at NoV = NoL = 1e-4 is beyond half";
    }
  }
  double worst = 0;
  for (int i = 0; i <= 1000; ++i) {
    double c = i / 1000.0;
    worst = std::max(worst, std::abs(double(h16::F_Schlick<half>(half(0.04), half(1), half(c))) -
                                     reference::FacetF_Schlick(double(float(half(0.04))), 1.0, double(half(c)))));
  }
  std::printf("[ fp16 F ] Schlick max abs err %.3g\n", worst);
  EXPECT_LE(worst, 5 * 4.8828125e-4);  // 5 ulps of half at 1
}

// The GPU emulation: each operation rounded to half (f32tof16 / f16tof32);
// the same forms, the same points: the GPU reproduces the CPU _Float16
// outcome (overflow where it overflows, the same error elsewhere).
const char* kHalfEmulation = R"(
#ifndef FACET_HALF_EMULATION
#define FACET_HALF_EMULATION
float hr(float x) { return f16tof32(f32tof16(x)); }
float naive_d16(float NoH, float alpha) {
  NoH = hr(NoH); alpha = hr(alpha);
  float a2 = hr(alpha * alpha);
  float d = hr(hr(hr(hr(NoH * a2) - NoH) * NoH) + 1.0);
  return hr(a2 / hr(hr(hr(3.14159265 * d) * d)));
}
float safe_d16(float s, float c, float alpha) {
  s = hr(s); c = hr(c); alpha = hr(alpha);
  float oneMinusNoH2 = hr(s * s);
  float a = hr(c * alpha);
  float k = min(hr(alpha / hr(oneMinusNoH2 + hr(a * a))), 453.5);
  return hr(k * hr(k * hr(0.31830988618)));
}
#endif
)";

class StabilityFp16GpuTest : public StabilityGpuTest {};

TEST_F(StabilityFp16GpuTest, EmulatedHalfOnTheGpuReproducesTheCpuHalfOutcome) {
  if (!h16::kHasHalf) GTEST_SKIP() << "no _Float16";
  auto evaluator = compile_functions(
      context(), {{.includes = kHalfEmulation, .hlsl = "r.x = naive_d16(x[1], x[2]); r.y = safe_d16(x[0], x[1], x[2]);",
                   .input_count = 3, .output_count = 2}});
  ASSERT_NE(evaluator, nullptr);
  std::vector<float> points;
  const double alphas[] = {reference::FACET_MIN_ALPHA, reference::FACET_MIN_ALPHA_FP16, 0.02, 0.0625, 0.25};
  for (double alpha : alphas)
    for (int i = 0; i < 512; ++i) {
      double t = (kPi / 6.0) * i / 511.0;
      points.insert(points.end(), {float(std::sin(t)), float(std::cos(t)), float(alpha)});
    }
  uint32_t count = uint32_t(points.size() / 3);
  std::vector<float> gpu = run_function(context(), *evaluator, 0, points, count);
  ASSERT_EQ(gpu.size(), size_t(count) * 2);
  int mismatches = 0, gpu_inf_naive = 0, gpu_inf_safe = 0;
  for (uint32_t i = 0; i < count; ++i) {
    half s(points[i * 3]), c(points[i * 3 + 1]), a(points[i * 3 + 2]);
    float cpu_naive = float(naive(s, c, a)), cpu_safe = float(safe(s, c, a));
    for (auto [g, cpu] : {std::pair{gpu[i * 2], cpu_naive}, std::pair{gpu[i * 2 + 1], cpu_safe}}) {
      // Two ulps of a half denormal (2^-24) of slack: the GPU's f32tof16 rounds
      // some denormal intermediates differently.
      bool same = std::isinf(cpu) ? std::isinf(g) : std::abs(g - cpu) <= 2e-3f * std::abs(cpu) + 1.2e-7f;
      if (!same && ++mismatches <= 5) ADD_FAILURE() << "point " << i << ": gpu " << g << " cpu " << cpu;
    }
    gpu_inf_naive += std::isinf(gpu[i * 2]);
    gpu_inf_safe += std::isinf(gpu[i * 2 + 1]);
  }
  std::printf("[ fp16 gpu ] %u points: naive D %d inf, stdlib-order safe D %d inf, %d mismatches with _Float16\n",
              count, gpu_inf_naive, gpu_inf_safe, mismatches);
  EXPECT_EQ(mismatches, 0);
  EXPECT_GT(gpu_inf_naive, 0);
}

// Real half on the GPU: the stdlib's own FacetD_GGX and FacetD_GGX_FP16Safe
// rewritten for half (backend::to_half_precision, through
// half_precision_stdlib) and compiled with 16-bit types, run with
// shaderFloat16: float16_t arithmetic, not an emulation. The same points as
// the emulation above; the same bounds as the _Float16 tests.
runtime::EvaluatorOptions real_half_options() {
  runtime::EvaluatorOptions options;
  options.backend.stdlib_dir = backend::default_stdlib_dir();
  options.backend.hlsl_16bit_types = true;
  options.backend.resolver = backend::half_precision_stdlib(options.backend.stdlib_dir);
  return options;
}
const char* kRealHalfIncludes = "#include \"FacetHalf.hlsl\"\n#include \"FacetBRDF.hlsl\"\n";

TEST_F(StabilityFp16GpuTest, OnRealHalfTheNaiveGgxOverflowsAtSmallAlphaAndTheSafeFormStaysWithinItsBound) {
  if (!context().shader_float16()) GTEST_SKIP() << context().device_info().name << " has no shaderFloat16";
  auto evaluator = compile_functions(
      context(),
      {{.includes = kRealHalfIncludes,
        .hlsl = "half s = (half)x[0], c = (half)x[1], a = (half)x[2];\n"
                "r.x = (float)FacetD_GGX(c, a);\n"
                "r.y = (float)FacetD_GGX_FP16Safe(half3(0.0h, 0.0h, 1.0h), half3(s, 0.0h, c), a);",
        .input_count = 3, .output_count = 2}},
      real_half_options());
  ASSERT_NE(evaluator, nullptr);
  const double alphas[] = {reference::FACET_MIN_ALPHA, reference::FACET_MIN_ALPHA_FP16, 0.02, 0.0625, 0.25};
  constexpr int kSteps = 512;
  std::vector<float> points;
  for (double alpha : alphas)
    for (int i = 0; i < kSteps; ++i) {
      double t = (kPi / 6.0) * i / (kSteps - 1);
      points.insert(points.end(), {float(std::sin(t)), float(std::cos(t)), float(alpha)});
    }
  std::vector<float> gpu = run_function(context(), *evaluator, 0, points, uint32_t(points.size() / 3));
  ASSERT_EQ(gpu.size(), points.size() / 3 * 2);
  for (size_t k = 0; k < std::size(alphas); ++k) {
    const double alpha = alphas[k], peak = 1.0 / (kPi * alpha * alpha);
    DError naive_error, safe_error;
    for (int i = 0; i < kSteps; ++i) {
      size_t p = k * kSteps + i;
      double ref = D_ref(double(points[p * 3 + 1]), double(points[p * 3 + 2]));
      if (ref < 1e-3 * peak) continue;
      double clamped = std::min(ref, 453.5 * 453.5 / kPi);
      for (auto [value, reference, e] : {std::tuple{gpu[p * 2], ref, &naive_error}, std::tuple{gpu[p * 2 + 1], clamped, &safe_error}}) {
        if (!std::isfinite(value)) ++e->infinite;
        else e->worst = std::max(e->worst, std::abs(value / reference - 1.0));
      }
    }
    std::printf("[ fp16 real ] %s alpha %.6f: naive D max rel err %.4g (%d inf), safe D %.4g (%d inf)\n",
                context().device_info().name.c_str(), alpha, naive_error.worst, naive_error.infinite, safe_error.worst,
                safe_error.infinite);
    EXPECT_EQ(safe_error.infinite, 0) << alpha;
    EXPECT_LE(safe_error.worst, alpha < 0.005 ? 0.02 : 0.01) << alpha;
    EXPECT_TRUE(naive_error.infinite > 0 || naive_error.worst > 0.02) << "naive form at alpha " << alpha << " unexpectedly accurate";
  }
  // At the fp32 clamp the peak 77 625 is beyond half: inf, where the safe form gives 453.5^2/pi.
  EXPECT_TRUE(std::isinf(gpu[0])) << gpu[0];
  EXPECT_NEAR(gpu[1], 453.5 * 453.5 / kPi, 0.01 * 65464);
}

// The stdlib itself compiled with float = min16float: the SPIR-V carries
// RelaxedPrecision, every model still passes the hard-case checks, and
// lavapipe (which keeps RelaxedPrecision at fp32) returns the fp32 peak
// 77 625 for the naive D where real half hardware overflows.
const char* kMin16Includes =
    "#define float min16float\n#define float2 min16float2\n#define float3 min16float3\n#define float4 min16float4\n"
    "#include \"FacetBRDF.hlsl\"\n"
    "#undef float\n#undef float2\n#undef float3\n#undef float4\n";

TEST_F(StabilityFp16GpuTest, StdlibCompiledWithMin16FloatIsRelaxedPrecisionAndLavapipeEvaluatesItAtFp32) {
  runtime::EvalFunction d{.includes = kMin16Includes, .hlsl = "r.x = FacetD_GGX(x[0], x[1]);", .input_count = 2};
  runtime::EvalFunction lobe{.includes = kMin16Includes,
                             .hlsl = evaluator_hlsl(Model{.name = "min16 GGX",
                                                          .hlsl = "FacetAngles a = FacetComputeAngles(n, v, l);\n"
                                                                  "c = FacetBRDF_CookTorranceGGX(n, v, l, float3(f0, f0, f0),"
                                                                  " rough) * a.NoL;"}),
                             .input_count = kInputs, .output_count = 3};
  Diagnostics diags;
  backend::BackendOptions options;
  options.stdlib_dir = backend::default_stdlib_dir();
  auto spirv = backend::compile_hlsl_compute(runtime::evaluator_source({d, lobe}), runtime::kEvalEntry, options, diags);
  ASSERT_TRUE(spirv) << spirv.error().reason;
  std::string text = backend::disassemble(*spirv);
  size_t relaxed = 0;
  for (size_t at = text.find("RelaxedPrecision"); at != std::string::npos; at = text.find("RelaxedPrecision", at + 1))
    ++relaxed;
  std::printf("[ fp16 min16float ] %zu RelaxedPrecision decorations\n", relaxed);
  EXPECT_GT(relaxed, 20u);

  auto evaluator = compile_functions(context(), {d, lobe});
  ASSERT_NE(evaluator, nullptr);
  std::vector<float> peak = run_function(context(), *evaluator, 0, {1.0f, float(reference::FACET_MIN_ALPHA)}, 1);
  ASSERT_EQ(peak.size(), 1u);
  std::printf("[ fp16 min16float ] naive D peak at alpha 0.002025 on %s: %g\n", context().device_info().name.c_str(),
              peak[0]);
  if (context().device_info().name.find("llvmpipe") != std::string::npos) {
    // fp32's own cancellation makes it 77 169, not 77 625; in half it is inf.
    EXPECT_TRUE(std::isfinite(peak[0]) && peak[0] > 65504.0f) << "lavapipe runs RelaxedPrecision at fp32";
  }
  std::vector<Point> grid = hard_case_grid();
  std::vector<float> flat;
  for (const Point& p : grid) flat.insert(flat.end(), p.begin(), p.end());
  Findings f = check_values(run_function(context(), *evaluator, 1, flat, uint32_t(grid.size())), grid,
                            {.bound = model("Cook-Torrance GGX").bound});
  EXPECT_TRUE(f.clean()) << f.summary();
}

}  // namespace
}  // namespace facet::stability
