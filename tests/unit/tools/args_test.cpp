// facetc's argument parsing, in process: glslc spellings, modes, conflicts.
#include <gtest/gtest.h>

#include "facetc/args.h"

namespace facet::tools {
namespace {

FacetcArgs parse_ok(std::vector<std::string> argv) {
  ParsedArgs parsed = parse_args(argv);
  EXPECT_TRUE(parsed.args) << parsed.text;
  return parsed.args ? *parsed.args : FacetcArgs{};
}

TEST(FacetcArgsTest, GlslcSpellingsBecomeLongOptions) {
  EXPECT_EQ(normalize_args({"-O0", "-Os", "-O", "-Werror", "-Wno-usepass", "-MD", "-MF", "x.d", "-MT", "t"}),
            (std::vector<std::string>{"--opt=none", "--opt=size", "--opt=performance", "--Werror", "--Wno=usepass",
                                      "--MD", "--MF", "x.d", "--MT", "t"}));
  // After "--" everything is an input, even names that look like options.
  EXPECT_EQ(normalize_args({"--", "-O0"}), (std::vector<std::string>{"--", "-O0"}));
}

TEST(FacetcArgsTest, OptimisationTargetAndDebug) {
  FacetcArgs a = parse_ok({"-O0", "-g", "--target-env", "opengl4.5", "x.shader"});
  EXPECT_EQ(a.backend.opt, backend::OptLevel::none);
  EXPECT_TRUE(a.backend.debug_info);
  EXPECT_EQ(a.backend.target, backend::TargetEnv::opengl4_5);
  EXPECT_EQ(parse_ok({"-Os", "x.shader"}).backend.opt, backend::OptLevel::size);
  EXPECT_EQ(parse_ok({"x.shader"}).backend.opt, backend::OptLevel::performance);
}

TEST(FacetcArgsTest, DefinesIncludesAndKeywords) {
  FacetcArgs a = parse_ok({"-DA", "-D", "B=2", "-Iinc", "-I", "more", "--keywords", "K1 K2,K3", "x.shader"});
  EXPECT_EQ(a.backend.defines,
            (std::vector<std::pair<std::string, std::string>>{{"A", "1"}, {"B", "2"}}));
  EXPECT_EQ(a.backend.include_dirs, (std::vector<std::string>{"inc", "more"}));
  ASSERT_TRUE(a.keywords);
  EXPECT_EQ(*a.keywords, (std::vector<std::string>{"K1", "K2", "K3"}));
}

TEST(FacetcArgsTest, ModesAndTheirKinds) {
  EXPECT_EQ(parse_ok({"x.shader"}).mode, Mode::package);
  EXPECT_EQ(parse_ok({"-E", "x.shader"}).mode, Mode::preprocess);
  FacetcArgs s = parse_ok({"-S", "x.shader"});
  EXPECT_EQ(s.mode, Mode::emit);
  EXPECT_EQ(s.emit, EmitKind::spirv_asm);
  EXPECT_EQ(parse_ok({"--emit=msl", "x.shader"}).emit, EmitKind::msl);
  FacetcArgs d = parse_ok({"--dump", "x.facetpkg"});
  EXPECT_EQ(d.mode, Mode::dump);
  EXPECT_EQ(d.dump, DumpKind::package);
  EXPECT_EQ(d.inputs, std::vector<std::string>{"x.facetpkg"});
  EXPECT_EQ(parse_ok({"--dump=ir", "x.shader"}).dump, DumpKind::ir);
  EXPECT_EQ(parse_ok({"-M", "x.shader"}).mode, Mode::depfile_only);
  FacetcArgs w = parse_ok({"-Werror", "-Wno-usepass", "-w", "x.shader"});
  EXPECT_TRUE(w.warnings.warnings_as_errors);
  EXPECT_TRUE(w.warnings.suppress_all);
  EXPECT_EQ(w.warnings.disabled_groups, std::vector<std::string>{"usepass"});
}

TEST(FacetcArgsTest, UsageErrorsSayWhatIsWrong) {
  const std::vector<std::pair<std::vector<std::string>, std::string>> cases = {
      {{}, "no input files"},
      {{"-E", "--reflect", "x.shader"}, "exclude each other"},
      {{"--emit=spirv", "x.shader"}, "-o"},
      {{"--stage", "tessellation", "x.shader"}, "unknown stage 'tessellation'"},
      {{"-MT", "t", "x.shader"}, "-MF and -MT need -M or -MD"},
      {{"--out-dir", "d", "-E", "x.shader"}, "--out-dir is for packages"},
      {{"-o", "a", "--out-dir", "d", "x.shader"}, "exclude each other"},
  };
  for (const auto& [argv, message] : cases) {
    ParsedArgs parsed = parse_args(argv);
    EXPECT_FALSE(parsed.args) << message;
    EXPECT_EQ(parsed.exit_code, 2) << message;
    EXPECT_NE(parsed.text.find(message), std::string::npos) << parsed.text;
  }
}

}  // namespace
}  // namespace facet::tools
