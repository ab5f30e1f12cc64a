// Bad arguments and bad models: exit code 1, a message that names the
// problem, and no output file.
#include <gtest/gtest.h>

#include <filesystem>

#include "unit/brdf/brdf_test_util.h"

namespace facet::brdf {
namespace {

using test::run_command;
using test::scratch;

struct BadCase {
  std::vector<std::string> args;  // "OUT" is replaced by the output path
  std::string message;
};

void expect_refused(const BadCase& c, const std::string& name) {
  std::string out = scratch("refused_" + name);
  std::vector<std::string> args;
  for (const std::string& a : c.args) args.push_back(a == "OUT" ? out : a);
  test::CommandResult r = run_command(args);
  EXPECT_EQ(r.code, 1) << name;
  EXPECT_NE(r.err.find(c.message), std::string::npos) << name << ": " << r.err;
  EXPECT_TRUE(r.err.starts_with("facet brdf: error: ")) << r.err;
  EXPECT_FALSE(std::filesystem::exists(out)) << name;
}

TEST(BrdfCommand, BadModelsAreRefusedWithTheReason) {
  const std::pair<const char*, BadCase> cases[] = {
      {"unknown.svg", {{"fancy", "--view", "polar", "-o", "OUT"}, "unknown model 'fancy' (models: lambert, burley"}},
      {"param.svg",
       {{"ggx:rough=0.3", "--view", "polar", "-o", "OUT"},
        "model 'ggx': unknown parameter 'rough' (parameters: roughness, f0)"}},
      {"number.svg", {{"ggx:roughness=abc", "--view", "polar", "-o", "OUT"}, "model 'ggx': roughness: 'abc' is not a number"}},
      {"range.svg", {{"ggx:roughness=2", "--view", "polar", "-o", "OUT"}, "model 'ggx': roughness = 2 is outside [0, 1]"}},
      {"colour.svg",
       {{"ggx:roughness=0.1/0.2/0.3", "--view", "polar", "-o", "OUT"}, "model 'ggx': roughness takes one number"}},
      {"twice.svg",
       {{"ggx:roughness=0.1,roughness=0.2", "--view", "polar", "-o", "OUT"}, "model 'ggx': roughness is given twice"}},
      {"pair.svg", {{"ggx:roughness", "--view", "polar", "-o", "OUT"}, "model 'ggx': 'roughness' is not name=value"}},
      {"merl.svg", {{"merl:", "--view", "polar", "-o", "OUT"}, "model 'merl' needs a file: merl:PATH"}},
      // A later bad model stops the command before anything is drawn.
      {"second.svg", {{"lambert", "burley:sigma=1", "--view", "polar", "-o", "OUT"}, "unknown parameter 'sigma'"}},
  };
  for (const auto& [name, c] : cases) expect_refused(c, name);
}

TEST(BrdfCommand, BadOptionsAreRefusedWithTheReason) {
  const std::pair<const char*, BadCase> cases[] = {
      {"noview.svg", {{"ggx", "-o", "OUT"}, "--view is required"}},
      {"badview.svg", {{"ggx", "--view", "cube", "-o", "OUT"}, "--view"}},
      {"nomodel.svg", {{"--view", "polar", "-o", "OUT"}, "no model given"}},
      {"noout", {{"ggx", "--view", "polar"}, "-o is required"}},
      {"out.jpg", {{"ggx", "--view", "polar", "-o", "OUT"}, "the output must end in .png or .svg"}},
      {"size.png", {{"ggx", "--view", "slice", "--size", "3", "-o", "OUT"}, "--size"}},
      {"incidence.svg", {{"ggx", "--view", "polar", "--incidence", "95", "-o", "OUT"}, "--incidence"}},
      {"light.png", {{"ggx", "--view", "lit-sphere", "--light", "sun", "-o", "OUT"}, "--light"}},
      {"unknown.svg", {{"ggx", "--view", "polar", "--frobnicate", "-o", "OUT"}, "frobnicate"}},
      // Each within its range, together hours of work.
      {"furnace.png",
       {{"ggx", "--view", "lit-sphere", "--light", "furnace", "--size", "4096", "-o", "OUT"},
        "these options ask for 38654705664 evaluations of each model, more than 268435456"}},
      {"albedo.svg",
       {{"ggx", "--view", "albedo", "--quadrature", "2048", "--points", "1000", "-o", "OUT"},
        "these options ask for 4194304000 evaluations of each model, more than 268435456"}},
  };
  for (const auto& [name, c] : cases) expect_refused(c, name);
}

TEST(BrdfCommand, UnwritableOutputIsAnError) {
  test::CommandResult r = run_command({"lambert", "--view", "polar", "-o", "/nonexistent-dir/x.svg"});
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("/nonexistent-dir/x.svg: cannot write"), std::string::npos) << r.err;
}

TEST(BrdfCommand, ListModelsNamesEveryFamilyAndItsParameters) {
  test::CommandResult r = run_command({"--list-models"});
  EXPECT_EQ(r.code, 0);
  for (const FamilyInfo& f : model_families()) {
    EXPECT_NE(r.out.find(f.name + "  ("), std::string::npos) << f.name;
    for (const ParamInfo& p : f.params) EXPECT_NE(r.out.find("    " + p.name + " "), std::string::npos) << p.name;
  }
}

TEST(BrdfCommand, HelpExitsZero) {
  test::CommandResult r = run_command({"--help"});
  EXPECT_EQ(r.code, 0);
  EXPECT_NE(r.out.find("--view"), std::string::npos);
}

TEST(BrdfCommand, LabelsSpellOutEveryParameter) {
  Result<Model> m = parse_model("ggx:f0=1/0.5/0.25");
  ASSERT_TRUE(m.has_value());
  EXPECT_EQ(m->label, "ggx:roughness=0.5,f0=1/0.5/0.25");
}

}  // namespace
}  // namespace facet::brdf
