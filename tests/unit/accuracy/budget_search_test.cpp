// Choosing by budget: every combination of terms is rendered against the
// exact model, the exact combination itself measures zero, costs are the sums
// of the study's rows, and the answer is the cheapest combination within the
// budget.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "facet/runtime/accuracy.h"

namespace facet::runtime::accuracy {
namespace {

// The study's rows with made-up GPU times (row i: i + 1 fs), so that costs
// are known sums.
Study timed_study() {
  Study s;
  s.device = "test device";
  s.rows = compute_errors();
  for (size_t i = 0; i < s.rows.size(); ++i) s.rows[i].ns_per_eval = double(i + 1) * 1e-6;
  return s;
}

const BudgetSearch& search() {
  static const BudgetSearch result = search_term_combinations(timed_study(), 16);
  return result;
}

const TermCombination& named(const std::string& name) {
  for (const TermCombination& c : search().combinations) {
    if (c.name == name) return c;
  }
  throw std::runtime_error("no combination " + name);
}

TEST(AccuracyBudgetSearchTest, RendersEveryCombinationOfTheTermsAndTheExactOneMeasuresZero) {
  EXPECT_EQ(search().combinations.size(), 2u * 5u * 4u * 3u);
  const TermCombination& exact = named("D_GGX + V_SmithGGXCorrelated + F_exact + Fd_Lambert");
  EXPECT_EQ(exact.image_rmse, 0.0);
  for (const TermCombination& c : search().combinations) {
    if (&c != &exact) {
      EXPECT_GT(c.image_rmse, 0.0) << c.name;
    }
  }
  ASSERT_EQ(search().unity_tiers.size(), 3u);
  for (const TermCombination& t : search().unity_tiers) EXPECT_TRUE(std::isfinite(t.image_rmse) && t.image_rmse > 0) << t.name;
}

TEST(AccuracyBudgetSearchTest, ACombinationCostsTheSumOfItsRowsAndTheListIsCheapestFirst) {
  const Study study = timed_study();
  auto cost_of = [&](const std::string& id) {
    for (const StudyRow& r : study.rows) {
      if (r.id == id) return *r.ns_per_eval * 1000.0;
    }
    return -1.0;
  };
  const TermCombination& c = named("D_GGX + V_SchlickGGX + F_exact + Fd_Burley");
  EXPECT_DOUBLE_EQ(c.cost, cost_of("D_GGX") + cost_of("V_SchlickGGX") + cost_of("F_Dielectric") + cost_of("F_Conductor") +
                               cost_of("Fd_Burley"));
  EXPECT_EQ(search().cost_unit, "ps/eval");
  EXPECT_TRUE(std::is_sorted(search().combinations.begin(), search().combinations.end(),
                             [](const TermCombination& a, const TermCombination& b) { return a.cost < b.cost; }));
}

TEST(AccuracyBudgetSearchTest, TheAnswerIsTheCheapestCombinationWithinTheBudget) {
  for (double budget : {1e-9, 0.01, 0.05, 1e9}) {
    const TermCombination* answer = cheapest_within(search(), budget);
    ASSERT_NE(answer, nullptr) << budget;
    EXPECT_LE(answer->image_rmse, budget);
    for (const TermCombination& c : search().combinations) {
      if (c.image_rmse <= budget) {
        EXPECT_GE(c.cost, answer->cost) << c.name << " is cheaper within " << budget;
      }
    }
  }
  // Only the exact combination is within a budget of (almost) nothing.
  EXPECT_EQ(cheapest_within(search(), 1e-9)->name, "D_GGX + V_SmithGGXCorrelated + F_exact + Fd_Lambert");
  std::string answers = budget_answers(search(), {0.01, 1e-12});
  EXPECT_NE(answers.find("| 0.01 | "), std::string::npos);
  EXPECT_NE(answers.find("BRDF1_Unity_PBS"), std::string::npos);
}

TEST(AccuracyBudgetSearchTest, WithoutGpuTimesCostsAreInstructionCounts) {
  Study s = timed_study();
  s.rows[0].ns_per_eval.reset();
  BudgetSearch untimed = search_term_combinations(s, 2);
  EXPECT_EQ(untimed.cost_unit, "SPIR-V instr.");
  EXPECT_NE(budget_chart_svg(untimed, {0.1}).find("needs a study timed on a GPU"), std::string::npos);
}

TEST(AccuracyBudgetSearchTest, TheCommandAnswersEachBudgetAndRejectsANegativeOne) {
  namespace fs = std::filesystem;
  fs::path dir = fs::temp_directory_path() / ("facet_budget_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  std::string from = std::string(FACET_SOURCE_DIR) + "/docs/figures/accuracy-h200.json";
  std::ostringstream out, err;
  ASSERT_EQ(run_accuracy_command({"--from", from, "--budget", "0.02", "--budget", "0.2", "--image-samples", "8", "--out",
                                  (dir / "b.json").string()},
                                 out, err),
            0)
      << err.str();
  EXPECT_NE(out.str().find("| 0.02 | "), std::string::npos);
  std::ifstream in(dir / "b.json");
  nlohmann::json j = nlohmann::json::parse(in);
  EXPECT_EQ(j["answers"].size(), 2u);
  EXPECT_EQ(j["combinations"].size(), 120u);
  EXPECT_EQ(j["cost_unit"], "ps/eval");
  EXPECT_EQ(run_accuracy_command({"--from", from, "--budget", "-1", "--out", (dir / "c.json").string()}, out, err), 2);
  EXPECT_FALSE(fs::exists(dir / "c.json"));
  fs::remove_all(dir);
}

}  // namespace
}  // namespace facet::runtime::accuracy
