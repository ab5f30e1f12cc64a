#include "stability/gpu.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cstdio>

namespace facet::stability {

std::unique_ptr<runtime::FunctionEvaluator> compile_functions(const runtime::Context& context,
                                                              const std::vector<runtime::EvalFunction>& functions,
                                                              const runtime::EvaluatorOptions& options) {
  auto start = std::chrono::steady_clock::now();
  Diagnostics diags;
  runtime::VkResultOf<runtime::FunctionEvaluator> compiled = runtime::compile_evaluator(context, functions, options, diags);
  if (!compiled) {
    std::string text;
    for (const Diagnostic& d : diags.all()) {
      text += d.message + "\n";
      for (const DiagNote& n : d.notes) text += "  note: " + n.message + "\n";
    }
    ADD_FAILURE() << runtime::describe(compiled.error()) << "\n" << text;
    return nullptr;
  }
  double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf("[ stability ] %zu function(s) compiled in %.2f s\n", functions.size(), seconds);
  return std::make_unique<runtime::FunctionEvaluator>(std::move(*compiled));
}

std::vector<float> run_function(const runtime::Context& context, const runtime::FunctionEvaluator& evaluator,
                                size_t function, const std::vector<float>& points, uint32_t count) {
  runtime::VkResultOf<runtime::Evaluation> result = runtime::evaluate(context, evaluator, function, points, count);
  if (!result) {
    ADD_FAILURE() << runtime::describe(result.error());
    return {};
  }
  return std::move(result->values);
}

StabilityGpuTest::Group& StabilityGpuTest::group_for(const Model& m) {
  Group& g = groups_[m.includes];
  if (g.evaluator) return g;
  std::vector<runtime::EvalFunction> functions;
  for (const Model& other : models()) {
    if (other.includes != m.includes) continue;
    functions.push_back({.includes = other.includes, .hlsl = evaluator_hlsl(other), .input_count = kInputs,
                         .output_count = 3});
    g.names.push_back(other.name);
  }
  g.evaluator = compile_functions(context(), functions);
  return g;
}

std::vector<float> StabilityGpuTest::evaluate_model(const Model& m, const std::vector<Point>& points) {
  Group& g = group_for(m);
  if (!g.evaluator) return {};
  size_t index = size_t(std::find(g.names.begin(), g.names.end(), m.name) - g.names.begin());
  std::vector<float> flat;
  flat.reserve(points.size() * kInputs);
  for (const Point& p : points) flat.insert(flat.end(), p.begin(), p.end());
  return run_function(context(), *g.evaluator, index, flat, uint32_t(points.size()));
}

}  // namespace facet::stability
