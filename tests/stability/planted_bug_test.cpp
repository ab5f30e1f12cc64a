// The suite catches what it is for: deliberately broken variants of the GGX
// lobe, written inline here, run on the GPU through the same evaluator, grid
// and checker as the real models, are reported; the correct lobe, compiled in
// the same shader, is clean.
#include <gtest/gtest.h>

#include "stability/checks.h"
#include "stability/gpu.h"

namespace facet::stability {
namespace {

// The Cook-Torrance GGX lobe written out, with a hook for each planted bug.
std::string ggx_lobe(const std::string& alpha, const std::string& NoV, const std::string& NoL) {
  return "FacetAngles a = FacetComputeAngles(n, v, l);\n"
         "float3 nn = FacetSafeNormalize(n), vn = FacetSafeNormalize(v), ln = FacetSafeNormalize(l);\n"
         "float NoV = " + NoV + ";\nfloat NoL = " + NoL + ";\nfloat alpha = " + alpha + ";\n"
         "float a2 = alpha * alpha;\n"
         "float d = (a.NoH * a2 - a.NoH) * a.NoH + 1.0;\n"
         "float D = a2 / (FACET_PI * d * d);\n"
         "float V = 0.5 / (NoL * sqrt((NoV - a2 * NoV) * NoV + a2) + NoV * sqrt((NoL - a2 * NoL) * NoL + a2));\n"
         "c = D * V * FacetF_Schlick(float3(f0, f0, f0), 1.0, a.LoH) * NoL;";
}

struct Variant {
  std::string name;
  std::string hlsl;
};

const Variant kCorrect{"correct", ggx_lobe("FacetClampAlpha(rough * rough)", "a.NoV", "a.NoL")};
// Roughness 0 at the mirror direction: d = 0 and D = 0/0.
const Variant kUnclampedAlpha{"unclamped alpha in D", ggx_lobe("rough * rough", "a.NoV", "a.NoL")};
// NoV = NoL = 0 makes V's denominator 0; a back-facing view makes it negative.
const Variant kUnclampedNoV{"unclamped NoV in V", ggx_lobe("FacetClampAlpha(rough * rough)", "dot(nn, vn)", "a.NoL")};
// A light behind the surface shines through: negative NoL is not saturated.
const Variant kUnsaturatedNoL{"unsaturated NoL", ggx_lobe("FacetClampAlpha(rough * rough)", "a.NoV", "dot(nn, ln)")};

class StabilityPlantedBugTest : public StabilityGpuTest {
 protected:
  static void SetUpTestSuite() {
    StabilityGpuTest::SetUpTestSuite();
    std::vector<runtime::EvalFunction> functions;
    for (const Variant* v : {&kCorrect, &kUnclampedAlpha, &kUnclampedNoV, &kUnsaturatedNoL}) {
      Model m{.name = v->name, .hlsl = v->hlsl};
      functions.push_back({.includes = "#include \"FacetBRDF.hlsl\"\n", .hlsl = evaluator_hlsl(m),
                           .input_count = kInputs, .output_count = 3});
    }
    evaluator_ = compile_functions(context(), functions);
  }
  static void TearDownTestSuite() {
    evaluator_.reset();
    StabilityGpuTest::TearDownTestSuite();
  }
  // Variant i (in SetUpTestSuite's order) on the hard-case grid, checked
  // with the Cook-Torrance GGX model's bound.
  static Findings run(size_t i) {
    std::vector<Point> grid = hard_case_grid();
    std::vector<float> flat;
    for (const Point& p : grid) flat.insert(flat.end(), p.begin(), p.end());
    std::vector<float> values = run_function(context(), *evaluator_, i, flat, uint32_t(grid.size()));
    return check_values(values, grid, {.bound = model("Cook-Torrance GGX").bound});
  }
  inline static std::unique_ptr<runtime::FunctionEvaluator> evaluator_;
};

TEST_F(StabilityPlantedBugTest, TheCorrectLobeIsClean) {
  ASSERT_NE(evaluator_, nullptr);
  Findings f = run(0);
  EXPECT_TRUE(f.clean()) << f.summary();
}

TEST_F(StabilityPlantedBugTest, AnUnclampedRoughnessInDIsReportedAsNaNOrInf) {
  ASSERT_NE(evaluator_, nullptr);
  Findings f = run(1);
  std::printf("[ planted ] %s: %s", kUnclampedAlpha.name.c_str(), f.summary().c_str());
  EXPECT_FALSE(f.clean());
  EXPECT_GT(f.nan + f.inf, 0u) << f.summary();
}

TEST_F(StabilityPlantedBugTest, AnUnclampedNoVInVIsReportedAsNaNInfOrNegative) {
  ASSERT_NE(evaluator_, nullptr);
  Findings f = run(2);
  std::printf("[ planted ] %s: %s", kUnclampedNoV.name.c_str(), f.summary().c_str());
  EXPECT_GT(f.nan + f.inf, 0u) << f.summary();
  EXPECT_GT(f.negative, 0u) << f.summary();
}

TEST_F(StabilityPlantedBugTest, AnUnsaturatedNoLIsReportedAsLightFromBehind) {
  ASSERT_NE(evaluator_, nullptr);
  Findings f = run(3);
  std::printf("[ planted ] %s: %s", kUnsaturatedNoL.name.c_str(), f.summary().c_str());
  EXPECT_GT(f.negative + f.lit_from_behind, 0u) << f.summary();
}

}  // namespace
}  // namespace facet::stability
