// T14 on the GPU: the stdlib's HLSL split sum, c * FacetEnvBRDF_DFG(f0, 1,
// FacetDFG_Integrate(NoV, alpha, N)), evaluated in fp32 on lavapipe
// (validation on) at the CPU test's 18 points, against the same independent
// Monte Carlo estimate c * E(v) (split_sum.h).
//
// N is 64,512, not the CPU test's 2^18: lavapipe ends the loops of a shader
// function after 65,535 iterations in all (gallivm's
// LP_MAX_TGSI_LOOP_ITERATIONS), silently; with 2^18 samples the GPU summed a
// quarter of them. 64,512 leaves the evaluator's own loops 1,023. In double,
// the integral on 64,512 points is within 6e-4 of c of the Monte Carlo
// estimate at every point, as the 2^18-point one is.
//
// The tolerance: the CPU test's 1e-3 of c (the estimator's noise and the
// quadrature's error, which the GPU shares) plus 2e-4 of c for fp32. The
// fp32 part is dominated by the loop's running sum of N terms: each addition
// rounds to half an ulp of the sum, 2^-24 of it, so the result's rounding
// error is about 2^-24 * sqrt(N / 3) = 8.7e-6 (relative, rms, for errors that
// do not line up); 2e-4 is twenty times that. The per-sample terms (a few
// dozen roundings each, independent across samples) and the inputs' rounding
// to float add less than 1e-6. That assumes sin and cos far more accurate
// than Vulkan's minimum (2^-11 absolute), which would not do, so the test
// also checks the fp32 part directly: the GPU against the CPU twin in double
// at the same N points, within 2e-4.
//
// Two planted bugs in HLSL copies, run the same way: the DFG's two terms
// swapped (caught at every point) and f90 = 0 instead of 1 (caught wherever
// the Fresnel term carries weight: every point with NoV <= 0.5; at NoV 0.95
// the dropped term, dfg.x <= 1.3e-4, is below the tolerance).
#include <fmt/format.h>
#include <gtest/gtest.h>

#include "stability/gpu.h"
#include "stability/split_sum.h"

namespace facet::stability {
namespace {

constexpr uint32_t kGpuDfgSamples = 64512;  // lavapipe: at most 65,535 loop iterations per invocation
constexpr double kFp32Allowance = 2e-4;
constexpr double kGpuBound = kSplitSumBound + kFp32Allowance;
constexpr const char* kIbl = "#include \"FacetIBL.hlsl\"\n";

// The split sum of the stdlib from x = (NoV, perceptual roughness, f0), with
// `env_brdf` (a function of the stdlib's signature) and `f90`.
std::string split_sum_hlsl(const std::string& env_brdf, const std::string& f90) {
  return fmt::format(
      "float alpha = FacetClampAlpha(x[1] * x[1]);\n"
      "float2 dfg = FacetDFG_Integrate(x[0], alpha, {}u);\n"
      "r.xyz = {} * {}(float3(x[2], x[2], x[2]), {}, dfg);",
      kGpuDfgSamples, kSplitSumRadiance, env_brdf, f90);
}

// The planted copy: FacetEnvBRDF_DFG with dfg.x and dfg.y exchanged.
constexpr const char* kSwappedCopy =
    "float3 Planted_EnvBRDF_DFG_Swapped(float3 f0, float f90, float2 dfg)\n"
    "{\n    return f0 * (dfg.x - dfg.y) + f90 * dfg.y;\n}\n";

enum Function : size_t { kStdlib = 0, kSwapped = 1, kNoFresnelEdge = 2 };

class StabilitySplitSumGpuTest : public StabilityGpuTest {
 protected:
  static void SetUpTestSuite() {
    StabilityGpuTest::SetUpTestSuite();
    std::vector<runtime::EvalFunction> functions{
        {.includes = kIbl, .hlsl = split_sum_hlsl("FacetEnvBRDF_DFG", "1.0"), .input_count = 3, .output_count = 3},
        {.includes = std::string(kIbl) + kSwappedCopy, .hlsl = split_sum_hlsl("Planted_EnvBRDF_DFG_Swapped", "1.0"),
         .input_count = 3, .output_count = 3},
        {.includes = kIbl, .hlsl = split_sum_hlsl("FacetEnvBRDF_DFG", "0.0"), .input_count = 3, .output_count = 3},
    };
    evaluator_ = compile_functions(context(), functions);
  }
  static void TearDownTestSuite() {
    evaluator_.reset();
    StabilityGpuTest::TearDownTestSuite();
  }
  // r.x of function `f` at every point. f0 is grey, so the three channels
  // must be equal; they are not when lavapipe's loop limit ended the
  // evaluator's output loop early.
  static std::vector<double> run(Function f) {
    std::vector<float> flat;
    for (const SplitSumPoint& p : split_sum_points()) flat.insert(flat.end(), {float(p.NoV), float(p.rough), float(p.f0)});
    std::vector<float> values = run_function(context(), *evaluator_, f, flat, uint32_t(split_sum_points().size()));
    std::vector<double> out;
    for (size_t i = 0; i + 2 < values.size(); i += 3) {
      EXPECT_TRUE(values[i] == values[i + 1] && values[i] == values[i + 2])
          << where(split_sum_points()[i / 3]) << ": r = " << values[i] << ", " << values[i + 1] << ", " << values[i + 2];
      out.push_back(values[i]);
    }
    return out;
  }
  static std::string where(const SplitSumPoint& p) {
    return fmt::format("NoV {} rough {} f0 {}", p.NoV, p.rough, p.f0);
  }
  inline static std::unique_ptr<runtime::FunctionEvaluator> evaluator_;
};

// The CPU twin at the inputs the GPU saw (rounded to float).
SplitSumPoint as_float(const SplitSumPoint& p) { return {double(float(p.NoV)), double(float(p.rough)), double(float(p.f0))}; }

TEST_F(StabilitySplitSumGpuTest, AConstantEnvironmentGivesItsRadianceTimesTheDirectionalAlbedo) {
  ASSERT_NE(evaluator_, nullptr);
  std::vector<double> gpu = run(kStdlib);
  ASSERT_EQ(gpu.size(), split_sum_points().size());
  double worst = 0, worst_fp32 = 0;
  for (size_t i = 0; i < gpu.size(); ++i) {
    const SplitSumPoint& p = split_sum_points()[i];
    double error = std::abs(gpu[i] - split_sum_direct_estimates()[i].x) / kSplitSumRadiance;
    double fp32 = std::abs(gpu[i] - split_sum_on_cpu(as_float(p), false, kGpuDfgSamples).x) / kSplitSumRadiance;
    worst = std::max(worst, error);
    worst_fp32 = std::max(worst_fp32, fp32);
    EXPECT_LE(error, kGpuBound) << where(p) << fmt::format(": GPU {:.6f}, direct {:.6f}", gpu[i],
                                                           split_sum_direct_estimates()[i].x);
    EXPECT_LE(fp32, kFp32Allowance) << where(p) << fmt::format(": GPU {:.6f}, CPU twin {:.6f}", gpu[i],
                                                               split_sum_on_cpu(as_float(p), false, kGpuDfgSamples).x);
  }
  std::printf("[ split sum gpu ] largest |GPU - c E(v)| %.3g of c (bound %.3g); largest |GPU - CPU twin| %.3g (bound %.3g)\n",
              worst, kGpuBound, worst_fp32, kFp32Allowance);
  RecordProperty("worst_error", fmt::format("{:.3g}", worst));
  RecordProperty("worst_fp32_error", fmt::format("{:.3g}", worst_fp32));
}

TEST_F(StabilitySplitSumGpuTest, PlantedSwappedDfgTermsAreCaughtAtEveryPoint) {
  ASSERT_NE(evaluator_, nullptr);
  std::vector<double> gpu = run(kSwapped);
  ASSERT_EQ(gpu.size(), split_sum_points().size());
  double smallest = 1e9;
  for (size_t i = 0; i < gpu.size(); ++i) {
    double gap = std::abs(gpu[i] - split_sum_direct_estimates()[i].x) / kSplitSumRadiance;
    smallest = std::min(smallest, gap);
    EXPECT_GT(gap, kGpuBound) << where(split_sum_points()[i]);
  }
  std::printf("[ split sum gpu ] planted swap: smallest gap %.3g of c\n", smallest);
}

TEST_F(StabilitySplitSumGpuTest, PlantedF90OfZeroIsCaughtWhereTheFresnelTermCarriesWeight) {
  ASSERT_NE(evaluator_, nullptr);
  std::vector<double> gpu = run(kNoFresnelEdge);
  ASSERT_EQ(gpu.size(), split_sum_points().size());
  size_t caught = 0;
  for (size_t i = 0; i < gpu.size(); ++i) {
    const SplitSumPoint& p = split_sum_points()[i];
    bool found = std::abs(gpu[i] - split_sum_direct_estimates()[i].x) / kSplitSumRadiance > kGpuBound;
    caught += found;
    if (p.NoV <= 0.5) {
      EXPECT_TRUE(found) << where(p);
    }
  }
  std::printf("[ split sum gpu ] planted f90 = 0: caught at %zu of %zu points\n", caught, gpu.size());
}

}  // namespace
}  // namespace facet::stability
