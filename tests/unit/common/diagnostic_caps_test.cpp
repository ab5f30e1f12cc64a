// Diagnostic floods: the printers show a repeated diagnostic once, at most
// kMaxShownDiagnostics in all, and shorten input text echoed whole; the list
// itself keeps every error.
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "facet/diagnostics.h"

namespace facet {
namespace {

using ::testing::HasSubstr;
using ::testing::Not;

size_t count_of(const std::string& text, const std::string& what) {
  size_t n = 0;
  for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

struct Flood {
  SourceMap sources;
  FileId file = sources.add_file("f.shader", std::string(20000, '\n'));
  Diagnostics diags;
};

TEST(DiagnosticCapsTest, TheSameDiagnosticOnManyLinesIsShownAFewTimes) {
  Flood f;
  for (uint32_t line = 0; line < 3000; ++line) {
    f.diags.add(DiagId::pragma_unused_skip_variant, Severity::warning, {f.file, line, line + 1},
                "'NOPE' in skip_variants is no keyword of this pass");
  }
  std::string text = render_text(f.diags, f.sources);
  EXPECT_EQ(count_of(text, "'NOPE' in skip_variants"), kMaxRepeats) << text.substr(0, 2000);
  EXPECT_EQ(count_of(text, "(and 2997 more like it)"), 1u);
  EXPECT_LT(text.size(), 1000u);
  auto json = nlohmann::json::parse(render_json(f.diags, f.sources));
  ASSERT_EQ(json.size(), kMaxRepeats);
  EXPECT_THAT(json[2]["message"].get<std::string>(), HasSubstr("(and 2997 more like it)"));
  EXPECT_EQ(f.diags.size(), 3000u) << "the list keeps them all";
}

TEST(DiagnosticCapsTest, AtMostAHundredAreShownThenOneLineSaysHowManyMore) {
  Flood f;
  for (uint32_t i = 0; i < 5000; ++i) {
    f.diags.add(DiagId::pragma_unused_skip_variant, Severity::warning, {f.file, i, i + 1},
                "'KW" + std::to_string(i) + "' in skip_variants is no keyword of this pass");
  }
  std::string text = render_text(f.diags, f.sources);
  EXPECT_EQ(count_of(text, "warning: "), kMaxShownDiagnostics);
  EXPECT_THAT(text, HasSubstr("facet: note: and 4900 more diagnostics (0 errors, 4900 warnings)\n"));
  EXPECT_THAT(text, HasSubstr("'KW99'"));
  EXPECT_THAT(text, Not(HasSubstr("'KW100'")));
  auto json = nlohmann::json::parse(render_json(f.diags, f.sources));
  ASSERT_EQ(json.size(), kMaxShownDiagnostics + 1);
  EXPECT_EQ(json.back()["id"], "diagnostics_hidden");
  EXPECT_EQ(json.back()["hidden"], 4900);
  EXPECT_EQ(json.back()["hidden_warnings"], 4900);
}

TEST(DiagnosticCapsTest, ErrorsAreShownBeforeAFloodOfWarningsHidesThem) {
  Flood f;
  for (uint32_t i = 0; i < 500; ++i) {
    f.diags.add(DiagId::pragma_unused_skip_variant, Severity::warning, {f.file, i, i + 1},
                "warning number " + std::to_string(i));
  }
  f.diags.add(DiagId::parse_bad_number, Severity::error, {f.file, 600, 601}, "the error that matters");
  std::string text = render_text(f.diags, f.sources);
  EXPECT_THAT(text, HasSubstr("error: the error that matters"));
  EXPECT_THAT(text, HasSubstr("and 401 more diagnostics (0 errors, 401 warnings)"));
  EXPECT_EQ(f.diags.error_count(), 1u);
}

TEST(DiagnosticCapsTest, HiddenErrorsAreCountedInTheSummary) {
  Flood f;
  for (uint32_t i = 0; i < 150; ++i) {
    f.diags.add(DiagId::parse_bad_number, Severity::error, {f.file, i, i + 1}, "error " + std::to_string(i));
  }
  std::string text = render_text(f.diags, f.sources);
  EXPECT_THAT(text, HasSubstr("and 50 more diagnostics (50 errors, 0 warnings)"));
  EXPECT_EQ(f.diags.error_count(), 150u);
}

TEST(DiagnosticCapsTest, InputTextEchoedWholeIsShortened) {
  Flood f;
  std::string huge(100000, '1');
  f.diags.add(DiagId::parse_bad_number, Severity::error, {f.file, 0, 1}, "number '" + huge + "' is out of range");
  std::string text = render_text(f.diags, f.sources);
  EXPECT_LT(text.size(), 1000u);
  // The word is "'111...": its first kMaxEchoedText characters include the quote.
  EXPECT_THAT(text, HasSubstr("number '" + std::string(kMaxEchoedText - 1, '1') + "... is out of range"));
  auto json = nlohmann::json::parse(render_json(f.diags, f.sources));
  EXPECT_LT(json[0]["message"].get<std::string>().size(), 200u);
  EXPECT_EQ(shorten_echo("short"), "short");
  EXPECT_EQ(shorten_echo(std::string(70, 'x')), std::string(64, 'x') + "...");
}

TEST(DiagnosticCapsTest, OrdinaryListsAreUnchanged) {
  Flood f;
  f.diags.add(DiagId::parse_bad_number, Severity::error, {f.file, 0, 1}, "first");
  f.diags.add(DiagId::parse_bad_number, Severity::error, {f.file, 1, 2}, "second");
  std::string text = render_text(f.diags, f.sources);
  EXPECT_THAT(text, HasSubstr("error: first\n"));
  EXPECT_THAT(text, HasSubstr("error: second\n"));
  EXPECT_THAT(text, Not(HasSubstr("more")));
}

}  // namespace
}  // namespace facet
