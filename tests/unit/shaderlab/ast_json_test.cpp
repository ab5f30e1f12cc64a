// AST dumps compared whole against goldens in tests/data/shaderlab/:
// <name>.shader -> <name>.ast.json. Set FACET_UPDATE_GOLDENS=1 to rewrite
// them; the reviewed diff is the test.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "facet/shaderlab.h"

namespace facet::shaderlab {
namespace {

namespace fs = std::filesystem;

std::string read_file(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

std::string dump(const std::string& text, Diagnostics& diags) {
  SourceMap sources;
  FileId file = sources.add_file("golden.shader", text);
  auto shader = parse(file, sources, {}, diags);
  if (!shader) return render_text(diags, sources);
  return ast_to_json(*shader, sources);
}

std::vector<std::string> golden_names() {
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(FACET_TESTDATA_DIR "/shaderlab")) {
    if (entry.path().extension() == ".shader") names.push_back(entry.path().stem().string());
  }
  std::sort(names.begin(), names.end());
  return names;
}

class ShaderlabAstJsonTest : public testing::TestWithParam<std::string> {};

TEST_P(ShaderlabAstJsonTest, MatchesGolden) {
  fs::path dir = FACET_TESTDATA_DIR "/shaderlab";
  Diagnostics diags;
  std::string actual = dump(read_file(dir / (GetParam() + ".shader")), diags);
  ASSERT_FALSE(diags.has_errors()) << actual;
  fs::path golden = dir / (GetParam() + ".ast.json");
  if (std::getenv("FACET_UPDATE_GOLDENS")) {
    std::ofstream(golden, std::ios::binary) << actual;
    GTEST_SKIP() << "rewrote " << golden;
  }
  ASSERT_TRUE(fs::exists(golden)) << "missing " << golden << "; run with FACET_UPDATE_GOLDENS=1";
  EXPECT_EQ(actual, read_file(golden));
}

TEST_P(ShaderlabAstJsonTest, IsStableAcrossRuns) {
  std::string text = read_file(fs::path(FACET_TESTDATA_DIR "/shaderlab") / (GetParam() + ".shader"));
  Diagnostics a, b;
  EXPECT_EQ(dump(text, a), dump(text, b));
}

INSTANTIATE_TEST_SUITE_P(Goldens, ShaderlabAstJsonTest, testing::ValuesIn(golden_names()),
                         [](const testing::TestParamInfo<std::string>& info) { return info.param; });

TEST(ShaderlabAstJsonTest, DumpIsValidJsonWithSpans) {
  SourceMap sources;
  FileId file = sources.add_file("t.shader", "Shader \"A\" {\n  Properties { _C (\"c\", Color) = (1,1,1) }\n}");
  Diagnostics diags;
  auto shader = parse(file, sources, {}, diags);
  ASSERT_TRUE(shader);
  std::string json = ast_to_json(*shader, sources);
  EXPECT_NE(json.find("\"span\": \"1:1-3:2\""), std::string::npos) << json;
  EXPECT_NE(json.find("\"numbers\": [1.0, 1.0, 1.0]"), std::string::npos) << json;
}

}  // namespace
}  // namespace facet::shaderlab
