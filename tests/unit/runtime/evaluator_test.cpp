#include "facet/runtime/evaluator.h"

#include <gtest/gtest.h>

#include <cstring>

#include "facet/runtime/vulkan_context.h"
#include "unit/runtime/context_fixture.h"

namespace facet::runtime {
namespace {

class EvaluatorTest : public test_support::LavapipeTest {
 protected:
  VkResultOf<FunctionEvaluator> compile(const std::vector<EvalFunction>& functions) {
    return compile_evaluator(context(), functions, {}, diags_);
  }
  Diagnostics diags_;
};

std::string messages(const Diagnostics& diags) {
  std::string text;
  for (const Diagnostic& d : diags.all()) {
    text += d.message + "\n";
    for (const DiagNote& n : d.notes) text += "  note: " + n.message + "\n";
  }
  return text;
}

TEST_F(EvaluatorTest, ComputesXSquaredPlusOneExactly) {
  VkResultOf<FunctionEvaluator> evaluator = compile({{.hlsl = "r.x = x[0] * x[0] + 1;", .input_count = 1}});
  ASSERT_TRUE(evaluator) << describe(evaluator.error()) << "\n" << messages(diags_);
  // 1000 points: not a multiple of the group size, so the bounds check matters.
  std::vector<float> points;
  for (int i = 0; i < 1000; ++i) points.push_back(float(i - 500) * 0.25f);
  VkResultOf<Evaluation> result = evaluate(context(), *evaluator, 0, points, uint32_t(points.size()));
  ASSERT_TRUE(result) << describe(result.error());
  ASSERT_EQ(result->values.size(), points.size());
  for (size_t i = 0; i < points.size(); ++i) {
    ASSERT_EQ(result->values[i], points[i] * points[i] + 1.0f) << "point " << i << " x=" << points[i];
  }
}

TEST_F(EvaluatorTest, PicksEachFunctionOfABatchAndStoresItsOutputs) {
  VkResultOf<FunctionEvaluator> evaluator = compile({
      {.hlsl = "r.x = x[0] + x[1];", .input_count = 2, .output_count = 1},
      {.hlsl = "r = float4(x[0], x[1], x[2], x[0] * 2);", .input_count = 3, .output_count = 4},
  });
  ASSERT_TRUE(evaluator) << describe(evaluator.error()) << "\n" << messages(diags_);
  VkResultOf<Evaluation> sum = evaluate(context(), *evaluator, 0, std::vector<float>{1, 2, 10, 20}, 2);
  ASSERT_TRUE(sum) << describe(sum.error());
  EXPECT_EQ(sum->values, (std::vector<float>{3, 30}));
  VkResultOf<Evaluation> copy = evaluate(context(), *evaluator, 1, std::vector<float>{1, 2, 3}, 1);
  ASSERT_TRUE(copy) << describe(copy.error());
  EXPECT_EQ(copy->values, (std::vector<float>{1, 2, 3, 2}));
}

TEST_F(EvaluatorTest, IncludesTheStdlib) {
  VkResultOf<FunctionEvaluator> evaluator = compile(
      {{.includes = "#include \"FacetCore.hlsl\"\n#include \"FacetCore.hlsl\"\n", .hlsl = "r.x = x[0];", .input_count = 1}});
  ASSERT_TRUE(evaluator) << describe(evaluator.error()) << "\n" << messages(diags_);
  EXPECT_EQ(evaluator_source(evaluator->functions).find("#include \"FacetCore.hlsl\""),
            evaluator_source(evaluator->functions).rfind("#include \"FacetCore.hlsl\""))
      << "a repeated include line is kept once";
}

TEST_F(EvaluatorTest, DispatchReportsItsGpuTime) {
  ASSERT_GT(context().device_info().timestamp_valid_bits, 0u) << "lavapipe has timestamps";
  VkResultOf<FunctionEvaluator> evaluator = compile({{.hlsl = "r.x = sin(x[0]);", .input_count = 1}});
  ASSERT_TRUE(evaluator) << describe(evaluator.error()) << "\n" << messages(diags_);
  std::vector<float> points(4096, 0.5f);
  VkResultOf<Evaluation> result = evaluate(context(), *evaluator, 0, points, uint32_t(points.size()));
  ASSERT_TRUE(result) << describe(result.error());
  ASSERT_TRUE(result->gpu_ns.has_value());
  EXPECT_GT(*result->gpu_ns, 0u);
}

TEST_F(EvaluatorTest, CompileErrorIsADiagnosticNamingTheToken) {
  VkResultOf<FunctionEvaluator> evaluator = compile({{.hlsl = "r.x = undefined_thing(x[0]);", .input_count = 1}});
  ASSERT_FALSE(evaluator);
  EXPECT_EQ(evaluator.error().code, VkErrorCode::compile_failed);
  ASSERT_TRUE(diags_.has_errors());
  std::string text = messages(diags_);
  EXPECT_NE(text.find("undefined_thing"), std::string::npos) << text;
  EXPECT_NE(text.find("<compute>:"), std::string::npos) << "the message names the line:\n" << text;
}

TEST_F(EvaluatorTest, MissingIncludeIsADiagnostic) {
  VkResultOf<FunctionEvaluator> evaluator =
      compile({{.includes = "#include \"NoSuchFile.hlsl\"\n", .hlsl = "r.x = x[0];", .input_count = 1}});
  ASSERT_FALSE(evaluator);
  EXPECT_NE(messages(diags_).find("NoSuchFile.hlsl"), std::string::npos) << messages(diags_);
}

TEST_F(EvaluatorTest, RejectsCountsOutOfRange) {
  VkResultOf<FunctionEvaluator> evaluator = compile({{.hlsl = "r.x = 0;", .input_count = 17}});
  ASSERT_FALSE(evaluator);
  EXPECT_EQ(evaluator.error().code, VkErrorCode::invalid_argument);
}

TEST_F(EvaluatorTest, RejectsPointsThatDoNotMatchTheInputCount) {
  VkResultOf<FunctionEvaluator> evaluator = compile({{.hlsl = "r.x = x[0];", .input_count = 2}});
  ASSERT_TRUE(evaluator) << describe(evaluator.error()) << "\n" << messages(diags_);
  VkResultOf<Evaluation> result = evaluate(context(), *evaluator, 0, std::vector<float>{1, 2, 3}, 2);
  ASSERT_FALSE(result);
  EXPECT_EQ(result.error().code, VkErrorCode::invalid_argument);
}

TEST_F(EvaluatorTest, DispatchWithTheWrongBufferCountIsInvalid) {
  VkResultOf<FunctionEvaluator> evaluator = compile({{.hlsl = "r.x = x[0];", .input_count = 1}});
  ASSERT_TRUE(evaluator) << describe(evaluator.error()) << "\n" << messages(diags_);
  VkResultOf<DispatchTiming> timing = dispatch(context(), evaluator->pipeline, {});
  ASSERT_FALSE(timing);
  EXPECT_EQ(timing.error().code, VkErrorCode::invalid_argument);
}

}  // namespace
}  // namespace facet::runtime
