// T11: every lighting model of the table at 20 angles against stored fp64
// values, so that a refactor that changes a result by more than 1e-6
// (relative) fails. The light is fixed at (1, 0, 1)/sqrt(2); the view turns
// in the same plane from the normal to grazing on the other side,
// theta_i = i/19 * pi/2, at two roughness and f0 points. FACET_UPDATE_GOLDENS=1
// rewrites tests/stability/golden/model_values.json instead of comparing
// (only for an intentional change, reviewed with the diff).
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "facet/reference/hlsl_math.h"
#include "models.h"

namespace facet::stability {
namespace {

constexpr int kAngles = 20;
constexpr double kTolerance = 1e-6;

struct Setting {
  double roughness, f0;
};
constexpr Setting kSettings[] = {{0.3, 0.04}, {0.8, 0.9}};

std::string golden_path() { return std::string(FACET_SOURCE_DIR) + "/tests/stability/golden/model_values.json"; }

// The model's values: for each setting, for each angle, the RGB result.
std::vector<double> values_of(const Model& m, double roughness_scale = 1.0) {
  std::vector<double> out;
  for (const Setting& s : kSettings) {
    for (int i = 0; i < kAngles; ++i) {
      double theta = double(i) / (kAngles - 1) * reference::kPi / 2;
      Inputs in;
      in.l = glm::normalize(glm::dvec3(1, 0, 1));
      in.v = glm::dvec3(-std::sin(theta), 0, std::cos(theta));
      in.roughness = s.roughness * roughness_scale;
      in.f0 = s.f0;
      glm::dvec3 c = m.cpu(in);
      out.insert(out.end(), {c.x, c.y, c.z});
    }
  }
  return out;
}

// Indices where `values` differ from `golden` by more than the tolerance
// (relative, with an absolute floor of 1e-300 for exact zeros).
std::vector<size_t> mismatches(const std::vector<double>& values, const std::vector<double>& golden) {
  std::vector<size_t> out;
  if (values.size() != golden.size()) return {0};
  for (size_t i = 0; i < values.size(); ++i) {
    double allowed = std::max(kTolerance * std::abs(golden[i]), 1e-300);
    if (!(std::abs(values[i] - golden[i]) <= allowed)) out.push_back(i);
  }
  return out;
}

nlohmann::json read_golden() {
  std::ifstream in(golden_path());
  if (!in) return nullptr;
  std::stringstream text;
  text << in.rdbuf();
  return nlohmann::json::parse(text.str());
}

TEST(GoldenValuesTest, EveryModelMatchesItsStoredValues) {
  if (std::getenv("FACET_UPDATE_GOLDENS")) {
    nlohmann::ordered_json doc;
    for (const Model& m : models()) doc[m.id] = values_of(m);
    std::ofstream(golden_path()) << doc.dump(1) << "\n";
    GTEST_SKIP() << "rewrote " << golden_path();
  }
  nlohmann::json golden = read_golden();
  ASSERT_TRUE(golden.is_object()) << "missing " << golden_path() << "; run with FACET_UPDATE_GOLDENS=1";
  EXPECT_EQ(golden.size(), models().size()) << "a model was added or removed: regenerate and review";
  for (const Model& m : models()) {
    ASSERT_TRUE(golden.contains(m.id)) << m.id;
    std::vector<double> expected = golden[m.id].get<std::vector<double>>();
    std::vector<double> got = values_of(m);
    std::vector<size_t> bad = mismatches(got, expected);
    EXPECT_TRUE(bad.empty()) << m.name << ": " << bad.size() << " values differ; first at " << bad.front() << ": "
                             << fmt::format("{:.17g} stored {:.17g}", got[bad.front()], expected[bad.front()]);
  }
}

// A roughness 1e-4 (relative) off the one a model should be evaluated at (a plausible
// refactoring slip, such as a clamp moved) is caught for every model with a
// roughness-dependent term.
TEST(GoldenValuesPlantedBugTest, ARoughnessOffByOneInTenThousandIsCaught) {
  nlohmann::json golden = read_golden();
  ASSERT_TRUE(golden.is_object());
  for (const char* id : {"ggx", "burley", "oren-nayar", "beckmann", "disney"}) {
    const Model* m = nullptr;
    for (const Model& candidate : models()) {
      if (candidate.id == id) m = &candidate;
    }
    ASSERT_NE(m, nullptr) << id;
    EXPECT_FALSE(mismatches(values_of(*m, 1.0 + 1e-4), golden[m->id].get<std::vector<double>>()).empty()) << id;
  }
}

}  // namespace
}  // namespace facet::stability
