// First contact: `facet --version`, `facet help [subcommand]`, facetc's
// glslc-style spellings in --help, and '-' as standard input.
#include "facetc_test_util.h"

namespace facet::tools::testing {
namespace {

using ::testing::HasSubstr;
using ::testing::Not;

class FrontDoorTest : public FacetcTest {
 protected:
  // Runs `command` (a shell line) in the scratch folder.
  FacetcRun shell(const std::string& command) const {
    int status = std::system(("cd " + shell_quote(dir_.string()) + " && " + command + " >stdout.txt 2>stderr.txt").c_str());
    FacetcRun run;
    run.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    run.out = read_all(dir_ / "stdout.txt");
    run.err = read_all(dir_ / "stderr.txt");
    return run;
  }
  static std::string facet() { return shell_quote(FACET_PATH); }
  static std::string facetc_binary() { return shell_quote(FACETC_PATH); }
};

TEST_F(FrontDoorTest, FacetPrintsItsVersion) {
  FacetcRun run = shell(facet() + " --version");
  EXPECT_EQ(run.exit_code, 0) << run.err;
  EXPECT_THAT(run.out, ::testing::StartsWith("facet "));
  EXPECT_EQ(run.out, shell(facetc_binary() + " --version").out) << "one version for both tools";
}

TEST_F(FrontDoorTest, FacetHelpListsTheSubcommandsAndEachOnesOptions) {
  FacetcRun all = shell(facet() + " help");
  EXPECT_EQ(all.exit_code, 0);
  EXPECT_THAT(all.out, HasSubstr("  render  "));
  EXPECT_THAT(all.out, HasSubstr("  bench  "));
  FacetcRun render = shell(facet() + " help render");
  EXPECT_EQ(render.exit_code, 0) << render.err;
  EXPECT_EQ(render.out, shell(facet() + " render --help").out);
  EXPECT_THAT(render.out, HasSubstr("-o"));
  FacetcRun unknown = shell(facet() + " help paint");
  EXPECT_EQ(unknown.exit_code, 1);
  EXPECT_THAT(unknown.err, HasSubstr("facet: unknown subcommand 'paint'"));
}

TEST_F(FrontDoorTest, FacetcHelpSpellsTheOptionsAsGlslcDoes) {
  FacetcRun run = shell(facetc_binary() + " --help");
  EXPECT_EQ(run.exit_code, 0);
  for (const char* line : {"\n  -MD ", "\n  -MF FILE ", "\n  -MT TARGET ", "\n  -Werror ", "\n  -Wno-<group> "}) {
    EXPECT_THAT(run.out, HasSubstr(line)) << run.out;
  }
  EXPECT_THAT(run.out, Not(HasSubstr("\n  --MD ")));
  // Both spellings still work.
  fs::copy_file(example("Unlit.shader"), dir_ / "Unlit.shader");
  EXPECT_EQ(shell(facetc_binary() + " Unlit.shader -o a.facetpkg -MD -MF a.d -Werror -Wno-legacy").exit_code, 0);
  EXPECT_EQ(shell(facetc_binary() + " Unlit.shader -o b.facetpkg --MD --MF b.d --Werror --Wno legacy").exit_code, 0);
  EXPECT_EQ(read_all(dir_ / "a.facetpkg"), read_all(dir_ / "b.facetpkg"));
}

TEST_F(FrontDoorTest, DashReadsTheShaderFromStandardInput) {
  fs::copy_file(example("Unlit.shader"), dir_ / "Unlit.shader");
  FacetcRun piped = shell(facetc_binary() + " - -o piped.facetpkg < Unlit.shader");
  ASSERT_EQ(piped.exit_code, 0) << piped.err;
  ASSERT_EQ(shell(facetc_binary() + " Unlit.shader -o file.facetpkg").exit_code, 0);
  EXPECT_THAT(shell(facetc_binary() + " --dump piped.facetpkg").out, HasSubstr("\"name\": \"Examples/Unlit\""));
  // The same SPIR-V as from the file (the package's build id names its source).
  EXPECT_EQ(shell(facetc_binary() + " -S - < Unlit.shader").out, shell(facetc_binary() + " -S Unlit.shader").out);
  FacetcRun preprocessed = shell(facetc_binary() + " -E - < Unlit.shader");
  EXPECT_EQ(preprocessed.exit_code, 0) << preprocessed.err;
  EXPECT_THAT(preprocessed.out, HasSubstr("frag"));
  FacetcRun depfile = shell(facetc_binary() + " - -o d.facetpkg -MD < Unlit.shader");
  EXPECT_EQ(depfile.exit_code, 0) << depfile.err;
  EXPECT_THAT(read_all(dir_ / "d.facetpkg.d"), ::testing::StartsWith("d.facetpkg:"));
  EXPECT_THAT(read_all(dir_ / "d.facetpkg.d"), Not(HasSubstr(" - ")));
}

TEST_F(FrontDoorTest, StandardInputErrorsAreLocatedAndRefusedUses) {
  write_all(dir_ / "bad.shader", "Shader \"Test/Bad\" {\n  SubShader {\n    Pass { Cull Sideways }\n  }\n}\n");
  FacetcRun bad = shell(facetc_binary() + " - -o bad.facetpkg < bad.shader");
  EXPECT_EQ(bad.exit_code, 1);
  EXPECT_THAT(bad.err, HasSubstr("<stdin>:3:17: error: unknown value 'Sideways' for 'Cull'")) << bad.err;
  EXPECT_FALSE(fs::exists(dir_ / "bad.facetpkg"));
  FacetcRun unnamed = shell(facetc_binary() + " - < bad.shader");
  EXPECT_EQ(unnamed.exit_code, 2);
  EXPECT_THAT(unnamed.err, HasSubstr("a package of standard input ('-') needs a name: give -o"));
  FacetcRun twice = shell(facetc_binary() + " -E - - < bad.shader");
  EXPECT_EQ(twice.exit_code, 2);
  EXPECT_THAT(twice.err, HasSubstr("standard input ('-') can be an input once"));
  EXPECT_TRUE(shell("ls *.facetpkg").out.empty()) << "nothing half-written";
}

}  // namespace
}  // namespace facet::tools::testing
