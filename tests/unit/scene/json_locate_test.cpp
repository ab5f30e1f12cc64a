// Where a scene's JSON path is in the file's text: the place a located
// scene error points at.
#include "scene/json_locate.h"

#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

namespace facet::runtime {
namespace {

std::string value_at(const std::string& text, const std::string& path) {
  std::optional<JsonExtent> extent = locate_json_value(text, path);
  if (!extent) return "<none>";
  return text.substr(extent->begin, extent->end - extent->begin);
}

const std::string kScene = R"({
  "width": 64,
  "camera": {"position": [0, 1, -3], "look_at": [0, 0, 0]},
  "objects": [
    {"mesh": "cube", "material": {"shader": "a.shader"}},
    {"mesh": "sphere", "material": {"shader": "b.shader", "properties": {"_Color": [1, 0], "_Name": "x \"q\" ]"}}}
  ]
})";

TEST(JsonLocate, FindsMembersAndElementsByTheReadersPath) {
  EXPECT_EQ(value_at(kScene, "width"), "64");
  EXPECT_EQ(value_at(kScene, "camera.position"), "[0, 1, -3]");
  EXPECT_EQ(value_at(kScene, "objects[0].mesh"), "\"cube\"");
  EXPECT_EQ(value_at(kScene, "objects[1].material.properties._Color"), "[1, 0]");
  EXPECT_EQ(value_at(kScene, "objects[1]").substr(0, 18), "{\"mesh\": \"sphere\",");
}

TEST(JsonLocate, StringsWithQuotesAndBracketsAreSkippedWhole) {
  EXPECT_EQ(value_at(kScene, "objects[1].material.properties._Name"), R"("x \"q\" ]")");
}

TEST(JsonLocate, OfAKeyGivenTwiceTheLastValueIsTheOneTheReaderKept) {
  EXPECT_EQ(value_at(R"({"time": 1, "time": "noon"})", "time"), "\"noon\"");
}

TEST(JsonLocate, AByteOrderMarkIsSkipped) {
  EXPECT_EQ(value_at("\xEF\xBB\xBF{\"width\": 7}", "width"), "7");
}

TEST(JsonLocate, TheEmptyPathIsTheDocument) {
  EXPECT_EQ(value_at("  [1, 2]  ", ""), "[1, 2]");
}

TEST(JsonLocate, AMissingValueOrBrokenTextHasNoPlace) {
  EXPECT_EQ(value_at(kScene, "objects[2]"), "<none>");
  EXPECT_EQ(value_at(kScene, "camera.fov"), "<none>");
  EXPECT_EQ(value_at(kScene, "width.x"), "<none>");
  EXPECT_EQ(value_at(kScene, "objects[x]"), "<none>");
  EXPECT_EQ(value_at(R"({"a": [1, )", "a[1]"), "<none>");
  EXPECT_EQ(value_at(R"({"a": )", "a"), "<none>");
}

TEST(JsonLocate, DeepNestingEndsWithoutAPlace) {
  std::string deep(100000, '[');
  EXPECT_EQ(value_at(deep, "[0]"), "<none>");
}

TEST(JsonLocate, ASceneValueSpanReadsTheFileOnceIntoTheSourceMap) {
  SourceMap sources;
  EXPECT_FALSE(scene_value_span(sources, "", "width").has_location());
  EXPECT_FALSE(scene_value_span(sources, "/no/such/scene.json", "width").has_location());
  FileId file = sources.add_file("given.json", kScene);
  SourceSpan span = scene_value_span(sources, "given.json", "objects[1].material.properties._Color");
  ASSERT_TRUE(span.has_location());
  EXPECT_EQ(span.file, file);
  EXPECT_EQ(sources.line_column(file, span.begin).line, 6u);
  EXPECT_EQ(sources.file_count(), 1u);
}

TEST(JsonLocate, AnEditedSceneFileIsLocatedInItsNewTextUnderANewFileId) {
  const std::string path = (std::filesystem::temp_directory_path() /
                            ("facet_json_locate." + std::to_string(::getpid()) + ".json")).string();
  std::ofstream(path) << kScene;
  SourceMap sources;
  SourceSpan before = scene_value_span(sources, path, "width");
  ASSERT_TRUE(before.has_location());
  EXPECT_EQ(scene_value_span(sources, path, "width").file, before.file);  // the same text: the same file
  std::ofstream(path, std::ios::trunc) << "{\n\n  \"width\": 128}";
  SourceSpan after = scene_value_span(sources, path, "width");
  ASSERT_TRUE(after.has_location());
  EXPECT_NE(after.file, before.file);
  EXPECT_EQ(sources.line_column(after.file, after.begin).line, 3u);
  EXPECT_EQ(sources.text(after.file).substr(after.begin, after.end - after.begin), "128");
  std::filesystem::remove(path);
}

}  // namespace
}  // namespace facet::runtime
