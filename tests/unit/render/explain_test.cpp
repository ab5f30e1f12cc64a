// facet render --explain: each pass of each object once, its draws under it
// in submission order, and a pass never drawn once with all its reasons.
#include <gtest/gtest.h>

#include "facet/runtime/renderer.h"

namespace facet::runtime {
namespace {

DrawRecord draw(const std::string& object, const std::string& pass, const std::string& light, const std::string& why) {
  return {.object = object, .shader = "S", .pass = pass, .light_mode = "ShadowCaster", .light = light,
          .keywords = {"SHADOWS_DEPTH"}, .state = "Cull Back", .why = why};
}

DrawRecord skipped(const std::string& object, const std::string& pass, const std::string& why) {
  DrawRecord d = draw(object, pass, "", why);
  d.drawn = false;
  return d;
}

size_t occurrences(const std::string& text, const std::string& what) {
  size_t n = 0;
  for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

TEST(ExplainTest, ListsEachPassOnceWithItsDrawsInSubmissionOrder) {
  RenderedFrame frame;
  frame.draws = {draw("objects[0] (floor)", "2 ShadowCaster", "lights[0] (directional)", "into map 0"),
                 draw("objects[1] (ball)", "2 ShadowCaster", "lights[0] (directional)", "into map 0"),
                 draw("objects[0] (floor)", "2 ShadowCaster", "lights[1] (spot)", "into map 1"),
                 // The main draw list skips the caster pass it drew into the maps.
                 skipped("objects[0] (floor)", "2 ShadowCaster", "drawn only into shadow maps"),
                 skipped("objects[2] (leaf)", "-", "not in the map of lights[0]"),
                 skipped("objects[2] (leaf)", "-", "not in the map of lights[1]"),
                 skipped("objects[2] (leaf)", "-", "not in the map of lights[1]")};
  std::string text = explain_text(frame);
  EXPECT_EQ(occurrences(text, "objects[0] (floor) 'S' pass 2 ShadowCaster"), 1u) << text;
  EXPECT_NE(text.find("objects[0] (floor) 'S' pass 2 ShadowCaster (ShadowCaster), queue 2000: 2 draws\n"
                      "   1 light lights[0] (directional)\n"),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("   3 light lights[1] (spot)\n"), std::string::npos) << text;
  EXPECT_NE(text.find("objects[1] (ball) 'S' pass 2 ShadowCaster (ShadowCaster), queue 2000: 1 draw\n"),
            std::string::npos)
      << text;
  EXPECT_EQ(text.find("drawn only into shadow maps"), std::string::npos) << "the pass was drawn: " << text;
  EXPECT_NE(text.find("not drawn:\n   - objects[2] (leaf) 'S' pass - (ShadowCaster): not in the map of lights[0]; "
                      "not in the map of lights[1]\n"),
            std::string::npos)
      << text;
  EXPECT_EQ(occurrences(text, "objects[2] (leaf)"), 1u) << text;
}

}  // namespace
}  // namespace facet::runtime
