// The case table itself: well formed, deterministic, finite on its own
// points, and covering every function of facet's lighting library.
#include "facet/reference/cases.h"
#include "facet/reference/models.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>

namespace facet::reference {
namespace {

constexpr uint32_t kPoints = 4096;

TEST(ReferenceCasesTest, LightingCasesHoldFacetUnityAndModelCases) {
  EXPECT_EQ(lighting_cases().size(),
            facet_model_cases().size() + unity_standard_cases().size() + lighting_model_cases().size());
}

// The model cases are read from the model table: one per row with HLSL.
TEST(ReferenceCasesTest, EveryModelTableRowWithHlslHasOneCase) {
  std::set<std::string> functions;
  for (const FunctionCase& c : lighting_model_cases()) EXPECT_TRUE(functions.insert(c.function).second) << c.function;
  size_t rows = 0;
  for (const LightingModel& m : lighting_models()) {
    if (m.hlsl.empty()) continue;
    ++rows;
    EXPECT_TRUE(functions.count("model " + m.id)) << m.id;
  }
  EXPECT_EQ(functions.size(), rows);
}

TEST(ReferenceCasesTest, FacetCasesAreWellFormedAndUniquelyNamed) {
  std::set<std::string> names;
  for (const FunctionCase& c : facet_model_cases()) {
    SCOPED_TRACE(c.function + " / " + c.setting);
    EXPECT_TRUE(names.insert(c.function + " / " + c.setting).second);
    EXPECT_TRUE(c.input_count >= 1 && c.input_count <= 16);
    EXPECT_TRUE(c.output_count >= 1 && c.output_count <= 4);
    EXPECT_NE(c.hlsl.find(c.function + "("), std::string::npos);
    EXPECT_NE(c.includes.find("#include"), std::string::npos);
    EXPECT_TRUE(c.reference && c.sample);
  }
}

TEST(ReferenceCasesTest, SamplersAreDeterministicAndTwinsFiniteOnEveryPoint) {
  std::vector<FunctionCase> checked = facet_model_cases();
  for (FunctionCase& c : lighting_model_cases()) checked.push_back(std::move(c));
  for (const FunctionCase& c : checked) {
    SCOPED_TRACE(c.function + " / " + c.setting);
    for (uint32_t i = 0; i < kPoints; ++i) {
      float a[16], b[16];
      c.sample(i, kPoints, a);
      c.sample(i, kPoints, b);
      ASSERT_EQ(0, std::memcmp(a, b, sizeof(float) * size_t(c.input_count)));
      double x[16], r[4] = {0, 0, 0, 0};
      for (int k = 0; k < c.input_count; ++k) {
        ASSERT_TRUE(std::isfinite(a[k]));
        x[k] = a[k];
      }
      c.reference(x, r);
      for (int k = 0; k < c.output_count; ++k) ASSERT_TRUE(std::isfinite(r[k])) << "point " << i;
    }
  }
}

// Every function defined in facet's lighting files has a case (by name).
TEST(ReferenceCasesTest, EveryLibraryFunctionHasACase) {
  std::set<std::string> covered;
  for (const FunctionCase& c : facet_model_cases()) covered.insert(c.function);
  const std::regex definition(R"(^(?:float[234]?|FacetAngles)\s+(Facet\w+)\s*\()");
  for (const char* file : {"FacetBRDF.hlsl", "FacetDisney.hlsl", "FacetIBL.hlsl", "FacetTonemap.hlsl", "FacetColor.hlsl"}) {
    std::ifstream in(std::string(FACET_SOURCE_DIR) + "/stdlib/" + file);
    ASSERT_TRUE(in) << file;
    std::string line;
    int found = 0;
    while (std::getline(in, line)) {
      std::smatch m;
      if (!std::regex_search(line, m, definition)) continue;
      ++found;
      EXPECT_TRUE(covered.count(m[1])) << m[1] << " in " << file << " has no case";
    }
    EXPECT_GT(found, 0) << file;
  }
}

}  // namespace
}  // namespace facet::reference
