// Parsing glslang's info log, without glslang.
#include "info_log.h"

#include <gtest/gtest.h>

namespace facet::backend {
namespace {

TEST(InfoLogParseTest, LocatedErrorsAndWarnings) {
  auto messages = parse_info_log(
      "ERROR: /a/b.shader:12: 'foo' : undeclared identifier \n"
      "WARNING: /a/inc.cginc:3: 'bar' : something odd\n");
  ASSERT_EQ(messages.size(), 2u);
  EXPECT_EQ(messages[0].severity, Severity::error);
  EXPECT_EQ(messages[0].file, "/a/b.shader");
  EXPECT_EQ(messages[0].line, 12u);
  EXPECT_EQ(messages[0].token, "foo");
  EXPECT_EQ(messages[0].text, "undeclared identifier");
  EXPECT_EQ(messages[1].severity, Severity::warning);
  EXPECT_EQ(messages[1].file, "/a/inc.cginc");
  EXPECT_EQ(messages[1].token, "bar");
}

TEST(InfoLogParseTest, NoiseIsDroppedAndUnlocatedMessagesKept) {
  auto messages = parse_info_log(
      "ERROR: Linking vertex stage: Missing entry point: Each stage requires one entry point\n"
      "ERROR: 1 compilation errors.  No code generated.\n"
      "ERROR: 2 compilation errors.  No code generated.\n"
      "\n");
  ASSERT_EQ(messages.size(), 1u);
  EXPECT_EQ(messages[0].file, "");
  EXPECT_EQ(messages[0].line, 0u);
  EXPECT_EQ(messages[0].text, "Linking vertex stage: Missing entry point: Each stage requires one entry point");
}

TEST(InfoLogParseTest, ParseFailedLineCarriesAColumn) {
  auto messages = parse_info_log(
      "ERROR: x.shader:7: ')' : Expected \n"
      "x.shader(7): error at column 67, HLSL parsing failed.\n");
  ASSERT_EQ(messages.size(), 2u);
  EXPECT_EQ(messages[0].token, ")");
  EXPECT_EQ(messages[0].text, "Expected");
  EXPECT_TRUE(messages[1].parse_failed_marker);
  EXPECT_EQ(messages[1].file, "x.shader");
  EXPECT_EQ(messages[1].line, 7u);
  EXPECT_EQ(messages[1].column, 67u);
}

TEST(InfoLogParseTest, FileNamesMayContainColonsAndEmptyTokens) {
  auto messages = parse_info_log("ERROR: C:/shaders/x.shader:4: '' : compilation terminated \n");
  ASSERT_EQ(messages.size(), 1u);
  EXPECT_EQ(messages[0].file, "C:/shaders/x.shader");
  EXPECT_EQ(messages[0].line, 4u);
  EXPECT_EQ(messages[0].token, "");
  EXPECT_EQ(messages[0].text, "compilation terminated");
}

TEST(InfoLogParseTest, ContinuationLinesJoinTheirMessage) {
  auto messages = parse_info_log("ERROR: a.shader:1: 'x' : first part\n  second part\n");
  ASSERT_EQ(messages.size(), 1u);
  EXPECT_EQ(messages[0].text, "first part second part");
}

// Mapping with a hand-made context: the .shader is in the SourceMap, the
// prelude is added when a message points into it.
class InfoLogReportTest : public ::testing::Test {
 protected:
  InfoLogReportTest() : includer_(options_, "/stdlib") {
    file_ = sources_.add_file("/s/a.shader", "Shader \"A\" {\n  float x = y + 1;\n}\n");
    program_.body.span = {file_, 0, 40};
    source_.root_name = "/s/a.shader";
    source_.prelude = "#line 2 \"<prelude>\"\n#define A 1\n#define B(\n";
  }
  void report(const std::string& log) {
    LogContext context{program_, Stage::fragment, file_, source_, includer_, sources_, DiagId::hlsl_error};
    report_info_log(log, context, diags_);
  }

  BackendOptions options_;
  FileIncluder includer_;
  SourceMap sources_;
  FileId file_ = kNoFile;
  ir::Program program_;
  AssembledSource source_;
  Diagnostics diags_;
};

TEST_F(InfoLogReportTest, TokenGivesTheColumn) {
  report("ERROR: /s/a.shader:2: 'y' : undeclared identifier\n");
  ASSERT_EQ(diags_.size(), 1u);
  const Diagnostic& d = diags_.all()[0];
  EXPECT_EQ(d.message, "'y': undeclared identifier");
  LineColumn lc = sources_.line_column(d.span.file, d.span.begin);
  EXPECT_EQ(lc.line, 2u);
  EXPECT_EQ(lc.column, 13u);
  EXPECT_EQ(d.span.end - d.span.begin, 1u);
}

TEST_F(InfoLogReportTest, IdentifierTokensMatchWholeWordsOnly) {
  report("ERROR: /s/a.shader:2: 'x' : redefinition\n");
  ASSERT_EQ(diags_.size(), 1u);
  // "x" first occurs as a whole word in "x =", not inside another name.
  EXPECT_EQ(sources_.line_column(file_, diags_.all()[0].span.begin).column, 9u);
}

TEST_F(InfoLogReportTest, PreludeMessagesPointIntoThePrelude) {
  report("ERROR: <prelude>:3: '(' : bad macro\n");
  ASSERT_EQ(diags_.size(), 1u);
  const Diagnostic& d = diags_.all()[0];
  EXPECT_EQ(sources_.path(d.span.file), "<prelude>");
  EXPECT_EQ(sources_.line_text(d.span.file, sources_.line_column(d.span.file, d.span.begin).line), "#define B(");
}

TEST_F(InfoLogReportTest, UnknownFilesKeepTheirNameInTheMessage) {
  report("ERROR: /elsewhere.h:9: 'q' : oops\n");
  ASSERT_EQ(diags_.size(), 1u);
  EXPECT_FALSE(diags_.all()[0].span.has_location());
  EXPECT_EQ(diags_.all()[0].message, "/elsewhere.h:9: 'q': oops");
}

TEST_F(InfoLogReportTest, WarningsUseTheWarningId) {
  report("WARNING: /s/a.shader:2: '' : something\n");
  ASSERT_EQ(diags_.size(), 1u);
  EXPECT_EQ(diags_.all()[0].id, DiagId::shader_compiler_warning);
  EXPECT_EQ(diags_.all()[0].severity, Severity::warning);
}

TEST_F(InfoLogReportTest, TemporaryTypeNoiseIsRemovedAndCaseLowered) {
  report("ERROR: /s/a.shader:2: '=' :  cannot convert from ' temp 2-component vector of float' to ' temp float'\n");
  ASSERT_EQ(diags_.size(), 1u);
  EXPECT_EQ(diags_.all()[0].message, "'=': cannot convert from '2-component vector of float' to 'float'");
}

}  // namespace
}  // namespace facet::backend
