// The GPU side of the stability suite: the models of models.h compiled into
// compute evaluators (one shader per include set, compiled on first use, so a
// test process compiles only what it runs) on lavapipe with validation on.
#pragma once

#include <map>
#include <memory>
#include <string>
#include <vector>

#include "facet/runtime/evaluator.h"
#include "stability/inputs.h"
#include "stability/models.h"
#include "unit/runtime/context_fixture.h"

namespace facet::stability {

// Compiles `functions` into one evaluator; on failure the test fails with
// glslang's messages and the result is null.
std::unique_ptr<runtime::FunctionEvaluator> compile_functions(const runtime::Context& context,
                                                              const std::vector<runtime::EvalFunction>& functions,
                                                              const runtime::EvaluatorOptions& options = {});

// Runs function `function` on `points` (count * input_count floats);
// empty (and a test failure) when the dispatch fails.
std::vector<float> run_function(const runtime::Context& context, const runtime::FunctionEvaluator& evaluator,
                                size_t function, const std::vector<float>& points, uint32_t count);

class StabilityGpuTest : public runtime::test_support::LavapipeTest {
 protected:
  static void TearDownTestSuite() {
    groups_.clear();
    LavapipeTest::TearDownTestSuite();
  }

  // r.xyz of the model at every point (3 floats per point); empty on failure.
  static std::vector<float> evaluate_model(const Model& m, const std::vector<Point>& points);

 private:
  struct Group {
    std::unique_ptr<runtime::FunctionEvaluator> evaluator;
    std::vector<std::string> names;  // function i = model names[i]
  };
  static Group& group_for(const Model& m);
  inline static std::map<std::string, Group> groups_;
};

}  // namespace facet::stability
