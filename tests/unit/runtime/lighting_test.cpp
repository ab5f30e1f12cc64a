// Every stdlib lighting function against its CPU twin: each case of the
// reference table runs on kPoints input points as an fp32 compute shader on
// lavapipe (validation on) and in double on the CPU, on the same float inputs.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <optional>

#include "facet/reference/cases.h"
#include "facet/runtime/evaluator.h"
#include "unit/runtime/context_fixture.h"

namespace facet::runtime {
namespace {

using reference::FunctionCase;

constexpr uint32_t kPoints = 4096;
// Cases compiled into one shader (the includes parsed once per batch). Small
// batches because ctest runs every case in a process of its own, which
// compiles only its batch: measured under ASan, 223 cases took 40 s through
// ctest -j2 with 8 per batch and 53 s with 32; one process takes 4 s.
constexpr size_t kBatchSize = 8;

const std::vector<FunctionCase>& cases() {
  static const std::vector<FunctionCase> all = reference::lighting_cases();
  return all;
}

EvalFunction eval_function(const FunctionCase& c) {
  return {.includes = c.includes, .hlsl = c.hlsl, .input_count = c.input_count, .output_count = c.output_count};
}

std::string diagnostics_text(const Diagnostics& diags) {
  std::string text;
  for (const Diagnostic& d : diags.all()) {
    text += d.message + "\n";
    for (const DiagNote& n : d.notes) text += "  note: " + n.message + "\n";
  }
  return text;
}

// Where each case's compiled shader is: a batch, or its own shader when its
// batch failed (so that one broken case names itself), or the reason.
struct CompiledCase {
  const FunctionEvaluator* evaluator = nullptr;
  size_t function = 0;
  std::string error;
};

struct CompiledTable {
  std::vector<std::unique_ptr<FunctionEvaluator>> evaluators;
  std::vector<CompiledCase> cases;
  std::vector<bool> batch_done;
};

// Compiles [begin, end) as one shader; on failure, each case alone.
void compile_batch(const Context& context, size_t begin, size_t end, CompiledTable& table) {
  std::vector<EvalFunction> functions;
  for (size_t i = begin; i < end; ++i) functions.push_back(eval_function(cases()[i]));
  Diagnostics diags;
  if (VkResultOf<FunctionEvaluator> batch = compile_evaluator(context, functions, {}, diags)) {
    table.evaluators.push_back(std::make_unique<FunctionEvaluator>(std::move(*batch)));
    for (size_t i = begin; i < end; ++i) table.cases[i] = {table.evaluators.back().get(), i - begin, {}};
    return;
  }
  for (size_t i = begin; i < end; ++i) {
    Diagnostics alone;
    VkResultOf<FunctionEvaluator> single = compile_evaluator(context, {functions[i - begin]}, {}, alone);
    if (!single) {
      table.cases[i].error = describe(single.error()) + "\n" + diagnostics_text(alone);
      continue;
    }
    table.evaluators.push_back(std::make_unique<FunctionEvaluator>(std::move(*single)));
    table.cases[i] = {table.evaluators.back().get(), 0, {}};
  }
}

struct Comparison {
  uint32_t failures = 0;
  double max_relative_error = 0;  // over the points whose value is not tiny
  std::string first_failures;     // up to a few, with their inputs
};

bool within(const FunctionCase& c, double gpu, double cpu) {
  if (!std::isfinite(cpu)) return std::isnan(cpu) ? std::isnan(gpu) : gpu == cpu;
  return std::isfinite(gpu) && std::abs(gpu - cpu) <= c.relative_tolerance * std::abs(cpu) + c.absolute_floor;
}

std::string point_text(const float* x, int n) {
  std::string text;
  for (int k = 0; k < n; ++k) text += (k ? ", " : "") + std::to_string(x[k]);
  return text;
}

Comparison compare(const FunctionCase& c, const std::vector<float>& points, const std::vector<float>& gpu) {
  Comparison out;
  const double tiny = c.absolute_floor / c.relative_tolerance;
  for (uint32_t i = 0; i < kPoints; ++i) {
    const float* x = &points[size_t(i) * c.input_count];
    double xd[kMaxEvalInputs] = {};
    std::copy(x, x + c.input_count, xd);
    double cpu[kMaxEvalOutputs] = {};
    c.reference(xd, cpu);
    for (int k = 0; k < c.output_count; ++k) {
      double g = gpu[size_t(i) * c.output_count + k];
      if (std::isfinite(g) && std::abs(cpu[k]) >= tiny) {
        out.max_relative_error = std::max(out.max_relative_error, std::abs(g - cpu[k]) / std::abs(cpu[k]));
      }
      if (within(c, g, cpu[k])) continue;
      if (++out.failures <= 5) {
        out.first_failures += "  point " + std::to_string(i) + " (" + point_text(x, c.input_count) + ") r[" +
                              std::to_string(k) + "]: gpu " + std::to_string(g) + ", cpu " + std::to_string(cpu[k]) +
                              "\n";
      }
    }
  }
  return out;
}

// The case's points, point-major. Each point is drawn into a 16-float slot
// whose tail holds a marker, so that a sampler writing more floats than the
// case declares is caught here (an empty result) instead of overrunning.
std::vector<float> sample_points(const FunctionCase& c) {
  constexpr float kMarker = -123456.75f;
  std::vector<float> points;
  points.reserve(size_t(kPoints) * c.input_count);
  for (uint32_t i = 0; i < kPoints; ++i) {
    float slot[kMaxEvalInputs];
    std::fill(std::begin(slot), std::end(slot), kMarker);
    c.sample(i, kPoints, slot);
    if (std::any_of(slot + c.input_count, std::end(slot), [](float v) { return v != kMarker; })) return {};
    points.insert(points.end(), slot, slot + c.input_count);
  }
  return points;
}

class LightingGpuTest : public test_support::LavapipeTest, public ::testing::WithParamInterface<size_t> {
 protected:
  static void TearDownTestSuite() {
    table_.reset();
    LavapipeTest::TearDownTestSuite();
  }

  // Compiles the batch that holds case `index` on first use: ctest runs each
  // case in a process of its own, which then compiles one batch, not the table.
  static const CompiledCase& compiled_case(size_t index) {
    if (!table_) {
      table_ = std::make_unique<CompiledTable>();
      table_->cases.resize(cases().size());
      table_->batch_done.resize((cases().size() + kBatchSize - 1) / kBatchSize);
    }
    size_t batch = index / kBatchSize;
    if (!table_->batch_done[batch]) {
      auto start = std::chrono::steady_clock::now();
      size_t begin = batch * kBatchSize, end = std::min(cases().size(), begin + kBatchSize);
      compile_batch(context(), begin, end, *table_);
      table_->batch_done[batch] = true;
      double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      std::printf("[ lighting ] cases %zu..%zu compiled in %.2f s\n", begin, end - 1, seconds);
    }
    return table_->cases[index];
  }
  inline static std::unique_ptr<CompiledTable> table_;
};

TEST_P(LightingGpuTest, MatchesTheCpuTwin) {
  const FunctionCase& c = cases()[GetParam()];
  SCOPED_TRACE(c.function + " [" + c.setting + "]");
  ASSERT_TRUE(c.input_count >= 1 && c.input_count <= kMaxEvalInputs) << c.input_count << " inputs";
  ASSERT_TRUE(c.output_count >= 1 && c.output_count <= kMaxEvalOutputs) << c.output_count << " outputs";
  const CompiledCase& compiled = compiled_case(GetParam());
  ASSERT_NE(compiled.evaluator, nullptr) << "the case's HLSL did not compile:\n" << compiled.error;
  std::vector<float> points = sample_points(c);
  ASSERT_EQ(points.size(), size_t(kPoints) * c.input_count) << "sample() writes more than input_count floats";
  VkResultOf<Evaluation> gpu = evaluate(context(), *compiled.evaluator, compiled.function, points, kPoints);
  ASSERT_TRUE(gpu) << describe(gpu.error());
  Comparison result = compare(c, points, gpu->values);
  std::printf("[ lighting ] %-40s %-32s max rel err %.3g (tolerance %.3g + %.3g), %u failures\n", c.function.c_str(),
              c.setting.c_str(), result.max_relative_error, c.relative_tolerance, c.absolute_floor, result.failures);
  RecordProperty("max_relative_error", std::to_string(result.max_relative_error));
  EXPECT_EQ(result.failures, 0u) << "of " << kPoints << " points x " << c.output_count << " outputs (tolerance "
                                 << c.relative_tolerance << " relative + " << c.absolute_floor << " absolute):\n"
                                 << result.first_failures;
}

std::string case_name(const ::testing::TestParamInfo<size_t>& info) {
  const FunctionCase& c = cases()[info.param];
  std::string name = std::to_string(info.param) + "_" + c.function + "_" + c.setting;
  for (char& ch : name) {
    if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
  }
  return name;
}

std::vector<size_t> case_indices() {
  std::vector<size_t> indices(cases().size());
  for (size_t i = 0; i < indices.size(); ++i) indices[i] = i;
  return indices;
}

INSTANTIATE_TEST_SUITE_P(Table, LightingGpuTest, ::testing::ValuesIn(case_indices()), case_name);
// An empty table is reported by LightingTableTest below, not as a gtest error.
GTEST_ALLOW_UNINSTANTIATED_PARAMETERIZED_TEST(LightingGpuTest);

TEST(LightingTableTest, HasCasesForTheGpuComparison) { EXPECT_FALSE(cases().empty()); }

}  // namespace
}  // namespace facet::runtime
