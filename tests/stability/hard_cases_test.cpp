// T1/T2: every model on the hard-case grid and the full input set, on the CPU
// twins (double, which must also fit fp32) and on the GPU (fp32 compute on
// lavapipe): finite, >= 0, nothing from a light behind the surface, and the
// GPU never above the twin's largest value on the grid (+5 %).
#include <gtest/gtest.h>

#include <cstdio>

#include "facet/reference/brdf.h"
#include "stability/checks.h"
#include "stability/gpu.h"

namespace facet::stability {
namespace {

std::vector<double> cpu_values(const Model& m, const std::vector<Point>& points) {
  std::vector<double> out;
  out.reserve(points.size() * 3);
  for (const Point& p : points) {
    Inputs in = unpack(p.data());
    glm::dvec3 c = m.cpu(in) * in.intensity;
    out.insert(out.end(), {c.x, c.y, c.z});
  }
  return out;
}

CheckOptions options_for(const Model& m) { return {.bound = m.bound, .behind_gives_zero = m.name != "Translucency"}; }

// The grid without the model's known-issue points (or only those).
std::vector<Point> grid_for(const Model& m, bool known_issue_points = false) {
  std::vector<Point> out;
  for (const Point& p : hard_case_grid())
    if (bool(m.known_issue && m.known_issue(unpack(p.data()))) == known_issue_points) out.push_back(p);
  return out;
}

TEST(StabilityCpuTest, EveryModelIsFiniteNonNegativeAndBoundedOnTheHardCaseGrid) {
  for (const Model& m : models()) {
    std::vector<Point> grid = grid_for(m);
    Findings f = check_values(cpu_values(m, grid), grid, options_for(m));
    std::printf("[ hard grid cpu ] %-28s largest %.5g (bound %.3g per unit intensity)\n", m.name.c_str(), f.largest,
                m.bound);
    EXPECT_TRUE(f.clean()) << m.name << ": " << f.summary();
  }
}

TEST(StabilityCpuTest, EveryModelIsFiniteNonNegativeAndBoundedOnTheFullInputSet) {
  std::vector<Point> set = full_input_set();
  for (const Model& m : models()) {
    Findings f = check_values(cpu_values(m, set), set, options_for(m));
    EXPECT_TRUE(f.clean()) << m.name << ": " << f.summary();
  }
}

class StabilityGpuHardCasesTest : public StabilityGpuTest {};

TEST_F(StabilityGpuHardCasesTest, EveryModelIsFiniteNonNegativeAndBoundedOnTheHardCaseGrid) {
  size_t evaluations = 0;
  for (const Model& m : models()) {
    std::vector<Point> grid = grid_for(m);
    Findings f = check_values(evaluate_model(m, grid), grid, options_for(m));
    evaluations += f.checked;
    std::printf("[ hard grid gpu ] %-28s largest %.5g (bound %.3g per unit intensity)\n", m.name.c_str(), f.largest,
                m.bound);
    EXPECT_TRUE(f.clean()) << m.name << ": " << f.summary();
  }
  EXPECT_GT(evaluations, 1000000u);
}

TEST_F(StabilityGpuHardCasesTest, EveryModelIsFiniteAndNonNegativeOnTheFullInputSet) {
  std::vector<Point> set = full_input_set();
  for (const Model& m : models()) {
    Findings f = check_values(evaluate_model(m, set), set, options_for(m));
    EXPECT_TRUE(f.clean()) << m.name << ": " << f.summary();
  }
}

// The stdlib problems this suite found (docs/stability.md, reported, not
// fixed here): still there on both sides. When one is fixed this fails; then
// drop the model's known_issue and the hard-case tests cover those points.
TEST_F(StabilityGpuHardCasesTest, KnownIssuesStillMisbehaveExactlyWhereDocumented) {
  int issues = 0;
  for (const Model& m : models()) {
    if (!m.known_issue) continue;
    ++issues;
    std::vector<Point> points = grid_for(m, true);
    ASSERT_FALSE(points.empty()) << m.name;
    Findings cpu = check_values(cpu_values(m, points), points, options_for(m));
    Findings gpu = check_values(evaluate_model(m, points), points, options_for(m));
    std::printf("[ known issue ] %s\n  %zu points; cpu: %s  gpu: %s", m.known_issue_text.c_str(), points.size(),
                cpu.summary().c_str(), gpu.summary().c_str());
    EXPECT_FALSE(gpu.clean()) << m.name << " is fixed on the GPU: " << m.known_issue_text;
    if (m.name == "Disney") {
      EXPECT_GT(cpu.over_bound, 0u) << "the twin shares the short half vector";
    }
  }
  EXPECT_EQ(issues, 2);
}

// The clamps of FacetComputeAngles hold in fp32 on the whole grid, and the
// roughness clamp maps 0 to FACET_MIN_ALPHA.
TEST_F(StabilityGpuHardCasesTest, ComputeAnglesAppliesItsClampsOnTheHardCaseGrid) {
  auto evaluator = compile_functions(
      context(), {{.includes = "#include \"FacetBRDF.hlsl\"\n",
                   .hlsl = "FacetAngles a = FacetComputeAngles(float3(x[0], x[1], x[2]), float3(x[3], x[4], x[5]),"
                           " float3(x[6], x[7], x[8]));\n"
                           "r = float4(a.NoV, min(min(a.NoL, a.NoH), a.LoH), max(max(a.NoL, a.NoH), a.LoH),"
                           " a.LoV + FacetClampAlpha(x[9] * x[9]));",
                   .input_count = kInputs, .output_count = 4}});
  ASSERT_NE(evaluator, nullptr);
  std::vector<Point> grid = hard_case_grid();
  std::vector<float> flat;
  for (const Point& p : grid) flat.insert(flat.end(), p.begin(), p.end());
  std::vector<float> r = run_function(context(), *evaluator, 0, flat, uint32_t(grid.size()));
  ASSERT_EQ(r.size(), grid.size() * 4);
  for (size_t i = 0; i < grid.size(); ++i) {
    SCOPED_TRACE(point_text(grid[i]));
    ASSERT_GE(r[i * 4], float(reference::FACET_MIN_NOV));
    ASSERT_GE(r[i * 4 + 1], 0.0f);
    ASSERT_LE(r[i * 4 + 2], 1.0f);
    ASSERT_TRUE(std::isfinite(r[i * 4 + 3]));
  }
}

}  // namespace
}  // namespace facet::stability
