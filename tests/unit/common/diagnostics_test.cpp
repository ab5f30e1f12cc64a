#include "facet/diagnostics.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

namespace facet {
namespace {

TEST(SourceMapTest, LineColumnIsOneBasedAndCountsBytes) {
  SourceMap sources;
  FileId f = sources.add_file("a.shader", "ab\ncde\n\nf");
  EXPECT_EQ(sources.line_column(f, 0).line, 1u);
  EXPECT_EQ(sources.line_column(f, 0).column, 1u);
  EXPECT_EQ(sources.line_column(f, 4).line, 2u);
  EXPECT_EQ(sources.line_column(f, 4).column, 2u);
  EXPECT_EQ(sources.line_column(f, 8).line, 4u);
  EXPECT_EQ(sources.line_text(f, 2), "cde");
  EXPECT_EQ(sources.line_text(f, 3), "");
  EXPECT_EQ(sources.line_count(f), 4u);
  EXPECT_EQ(sources.offset_of(f, 2, 3), 5u);
  // Out-of-range offsets clamp instead of reading past the text.
  EXPECT_EQ(sources.line_column(f, 1000).line, 4u);
  EXPECT_EQ(sources.line_text(f, 99), "");
}

TEST(SourceMapTest, CarriageReturnsAreNotPartOfTheLine) {
  SourceMap sources;
  FileId f = sources.add_file("crlf.shader", "x\r\ny\r\n");
  EXPECT_EQ(sources.line_text(f, 1), "x");
}

TEST(DiagnosticsRenderTest, TextHasLocationSourceLineAndCaret) {
  SourceMap sources;
  FileId f = sources.add_file("s.shader", "Shader \"A\" {\n  Cull Sideways\n}\n");
  Diagnostics diags;
  diags.add(DiagId::parse_unexpected_token, {f, 20, 28}, "unknown cull mode 'Sideways'")
      .note({f, 0, 6}, "in this shader");
  std::string text = render_text(diags, sources);
  EXPECT_NE(text.find("s.shader:2:8: error: unknown cull mode 'Sideways'\n"), std::string::npos) << text;
  EXPECT_NE(text.find("    2 |   Cull Sideways\n"), std::string::npos) << text;
  EXPECT_NE(text.find("      |        ^~~~~~~~\n"), std::string::npos) << text;
  EXPECT_NE(text.find("s.shader:1:1: note: in this shader"), std::string::npos) << text;
  EXPECT_EQ(diags.error_count(), 1u);
}

TEST(DiagnosticsRenderTest, UnlocatedDiagnosticsSayFacet) {
  SourceMap sources;
  Diagnostics diags;
  diags.add(DiagId::io_cannot_read, {}, "cannot open 'x.shader'");
  EXPECT_EQ(render_text(diags, sources), "facet: error: cannot open 'x.shader'\n");
}

TEST(DiagnosticsRenderTest, JsonCarriesIdSeverityAndPosition) {
  SourceMap sources;
  FileId f = sources.add_file("s.shader", "abc\ndef\n");
  Diagnostics diags;
  diags.add(DiagId::parse_unexpected_token, {f, 5, 6}, "bad");
  auto j = nlohmann::json::parse(render_json(diags, sources));
  ASSERT_EQ(j.size(), 1u);
  EXPECT_EQ(j[0]["id"], "parse_unexpected_token");
  EXPECT_EQ(j[0]["severity"], "error");
  EXPECT_EQ(j[0]["line"], 2);
  EXPECT_EQ(j[0]["column"], 2);
}

TEST(DiagnosticsMergeTest, IdenticalMessagesFromVariantsMergeWithCounts) {
  std::vector<Diagnostics> per_variant(4);
  for (size_t i = 0; i < per_variant.size(); ++i) {
    if (i != 2) per_variant[i].add(DiagId::parse_unexpected_token, {0, 1, 2}, "same");
    if (i == 3) per_variant[i].add(DiagId::parse_unexpected_token, {0, 1, 2}, "other");
  }
  Diagnostics merged = merge_variant_duplicates(per_variant);
  ASSERT_EQ(merged.size(), 2u);
  EXPECT_EQ(merged.all()[0].variant_hits, 3u);
  EXPECT_EQ(merged.all()[0].variant_total, 4u);
  EXPECT_EQ(merged.all()[1].variant_hits, 1u);
  SourceMap sources;
  sources.add_file("f", "abc");
  EXPECT_NE(render_text(merged, sources).find("[in 3 of 4 variants]"), std::string::npos);
}

TEST(DiagnosticsWarningOptionsTest, WerrorPromotesAndWSuppresses) {
  Diagnostics diags;
  diags.add(DiagId::parse_unexpected_token, Severity::warning, {}, "w");
  WarningOptions werror{.warnings_as_errors = true};
  EXPECT_EQ(apply_warning_options(diags, werror).error_count(), 1u);
  WarningOptions quiet{.suppress_all = true};
  EXPECT_EQ(apply_warning_options(diags, quiet).size(), 0u);
}

TEST(DiagnosticsTest, DisablingAGroupSilencesItsNotesAndKeepsOtherGroupsNotes) {
  Diagnostics diags;
  diags.add(DiagId::parse_legacy_command, Severity::note, {}, "'Lighting' is a legacy fixed-function command");
  diags.add(DiagId::parse_unexpected_token, Severity::warning, {}, "w");
  ASSERT_EQ(diag_group(DiagId::parse_legacy_command), "legacy");
  Diagnostics kept = apply_warning_options(diags, {.disabled_groups = {"legacy"}});
  ASSERT_EQ(kept.size(), 1u);
  EXPECT_EQ(kept.all()[0].id, DiagId::parse_unexpected_token);
  EXPECT_EQ(apply_warning_options(diags, {.disabled_groups = {"usepass"}}).size(), 2u);
}

TEST(DiagnosticsRebaseTest, SpansNotesAndIncludeStacksPointIntoTheNewMapAtTheSameText) {
  SourceMap from;
  FileId unused = from.add_file("unused.h", "nothing");
  FileId shader = from.add_file("a.shader", "line one\nline two\n");
  FileId include = from.add_file("b.cginc", "#include\n");
  Diagnostics diags;
  diags.add(DiagId::parse_unexpected_token, {shader, 14, 17}, "here").note({include, 1, 8}, "from there");
  diags.mutable_all()[0].include_stack.push_back({include, 0, 1});
  diags.add(DiagId::render_invalid, {}, "no place");

  SourceMap to;
  FileId already = to.add_file("b.cginc", "#include\n");
  Diagnostics moved = rebase_diagnostics(diags, from, to);
  ASSERT_EQ(moved.size(), 2u);
  const Diagnostic& d = moved.all()[0];
  EXPECT_EQ(to.path(d.span.file), "a.shader");
  EXPECT_EQ(to.line_column(d.span.file, d.span.begin).line, 2u);
  EXPECT_EQ(d.notes[0].span.file, already);  // a file the map has under that path is used as it is
  EXPECT_EQ(d.include_stack[0].file, already);
  EXPECT_FALSE(moved.all()[1].span.has_location());
  EXPECT_EQ(to.file_count(), 2u);  // unused.h is not copied
  EXPECT_EQ(render_text(moved, to), render_text(diags, from));
  (void)unused;
}

TEST(DiagnosticsRebaseTest, AFileEditedSinceTheNewMapGotItIsAddedAgain) {
  SourceMap from, to;
  FileId old_text = to.add_file("a.shader", "one\n");
  FileId edited = from.add_file("a.shader", "one\ntwo\nthree\n");
  Diagnostics diags;
  diags.add(DiagId::render_invalid, {edited, 8, 13}, "on line 3");
  Diagnostics moved = rebase_diagnostics(diags, from, to);
  EXPECT_NE(moved.all()[0].span.file, old_text);
  EXPECT_EQ(to.line_column(moved.all()[0].span.file, moved.all()[0].span.begin).line, 3u);
  EXPECT_EQ(rebase_diagnostics(diags, from, to).all()[0].span.file, moved.all()[0].span.file);  // added once
}

TEST(DiagnosticsRebaseTest, ASpanPastTheOldMapLosesItsPlaceRatherThanPointingElsewhere) {
  SourceMap from, to;
  Diagnostics diags;
  diags.add(DiagId::render_invalid, {7, 0, 1}, "stale");
  Diagnostics moved = rebase_diagnostics(diags, from, to);
  EXPECT_FALSE(moved.all()[0].span.has_location());
  EXPECT_EQ(to.file_count(), 0u);
}

}  // namespace
}  // namespace facet
