// Property values are 32-bit floats: a number that does not fit one (it
// would become an infinity), NaN and infinities are located errors at the
// number, in defaults, Range bounds and vectors alike.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <memory>

#include "facet/shaderlab.h"

namespace facet::shaderlab {
namespace {

using ::testing::HasSubstr;

struct Parsed {
  SourceMap sources;
  Diagnostics diags;
  FileId file = kNoFile;
  bool ok = false;
};

// A shader whose Properties block is `properties`.
std::unique_ptr<Parsed> parse_properties(const std::string& properties) {
  auto p = std::make_unique<Parsed>();
  p->file = p->sources.add_file("p.shader", "Shader \"T/P\" {\nProperties {\n" + properties +
                                                "\n}\nSubShader { Pass { } }\n}\n");
  p->ok = parse(p->file, p->sources, {}, p->diags).has_value();
  return p;
}

// The one error, as "line:col: message".
std::string only_error(const Parsed& p) {
  std::vector<std::string> errors;
  for (const Diagnostic& d : p.diags.all()) {
    if (d.severity != Severity::error) continue;
    LineColumn lc = p.sources.line_column(d.span.file, d.span.begin);
    errors.push_back(std::to_string(lc.line) + ":" + std::to_string(lc.column) + ": " + d.message);
  }
  return errors.size() == 1 ? errors[0] : "errors: " + std::to_string(errors.size());
}

TEST(PropertyFloatRangeTest, ADefaultPastTheFloatRangeIsAnErrorAtTheNumber) {
  auto p = parse_properties("_A (\"A\", Float) = 3.5e38");
  EXPECT_FALSE(p->ok);
  EXPECT_EQ(only_error(*p), "3:19: number '3.5e38' does not fit a 32-bit float in the default of '_A' "
                            "(the largest is about 3.4e38)");
  EXPECT_FALSE(parse_properties("_A (\"A\", Float) = -3.5e38")->ok);
}

TEST(PropertyFloatRangeTest, RangeBoundsPastTheFloatRangeAreErrors) {
  auto p = parse_properties("_R (\"R\", Range(-1e39, 1)) = 0");
  EXPECT_FALSE(p->ok);
  EXPECT_EQ(only_error(*p), "3:16: number '-1e39' does not fit a 32-bit float in 'Range(...)' "
                            "(the largest is about 3.4e38)");
  auto upper = parse_properties("_R (\"R\", Range(0, 1e39)) = 0");
  EXPECT_THAT(only_error(*upper), HasSubstr("3:19: number '1e39' does not fit a 32-bit float"));
}

TEST(PropertyFloatRangeTest, VectorAndColorComponentsPastTheFloatRangeAreErrors) {
  auto p = parse_properties("_V (\"V\", Vector) = (1, 2e39, 3, 4)");
  EXPECT_THAT(only_error(*p), HasSubstr("3:24: number '2e39' does not fit a 32-bit float in the default of '_V'"));
  auto c = parse_properties("_C (\"C\", Color) = (1, 1, 1, 1e300)");
  EXPECT_THAT(only_error(*c), HasSubstr("3:29: number '1e300' does not fit a 32-bit float"));
}

TEST(PropertyFloatRangeTest, NanAndInfinityAreErrorsAtTheWord) {
  EXPECT_EQ(only_error(*parse_properties("_A (\"A\", Float) = nan")),
            "3:19: 'nan' is not a number a property can hold in the default of '_A'; write a finite number");
  EXPECT_THAT(only_error(*parse_properties("_V (\"V\", Vector) = (0, inf, 0, 0)")),
              HasSubstr("3:24: 'inf' is not a number a property can hold"));
  EXPECT_THAT(only_error(*parse_properties("_R (\"R\", Range(0, NaN)) = 0")),
              HasSubstr("3:19: 'NaN' is not a number a property can hold in 'Range(...)'"));
}

TEST(PropertyFloatRangeTest, TheLargestFloatsStillParse) {
  auto p = parse_properties("_A (\"A\", Float) = 3.4028234e38\n_R (\"R\", Range(-3.4e38, 3.4e38)) = 1e-50");
  EXPECT_TRUE(p->ok) << only_error(*p);
}

TEST(PropertyFloatRangeTest, AHugeNumberIsEchoedShortened) {
  auto p = parse_properties("_A (\"A\", Float) = " + std::string(100000, '9'));
  EXPECT_FALSE(p->ok);
  std::string error = only_error(*p);
  EXPECT_LT(error.size(), 200u) << error.substr(0, 300);
  EXPECT_THAT(error, HasSubstr("3:19: number '" + std::string(64, '9') + "...' is out of range"));
}

}  // namespace
}  // namespace facet::shaderlab
