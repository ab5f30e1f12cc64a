// keywords_from_properties: Toggle, ToggleOff and KeywordEnum as Unity's
// material inspector derives keywords from property values.
#include <gtest/gtest.h>

#include "facet/variants.h"

namespace facet::variants {
namespace {

ir::Property property(std::string name, float default_value, std::string attribute, std::vector<std::string> args) {
  ir::Property p{.name = std::move(name)};
  p.default_value = {default_value, 0, 0, 0};
  p.attributes.push_back({.name = std::move(attribute), .args = std::move(args)});
  return p;
}

TEST(VariantsMaterialKeywordsTest, ToggleWithAndWithoutKeyword) {
  std::vector<ir::Property> props = {property("_EmissionOn", 0, "Toggle", {"_EMISSION"}),
                                     property("_Invert", 1, "Toggle", {})};
  EXPECT_EQ(keywords_from_properties(props), (KeywordList{"_INVERT_ON"}));
  EXPECT_EQ(keywords_from_properties(props, {{"_EmissionOn", 1}, {"_Invert", 0}}), (KeywordList{"_EMISSION"}));
}

TEST(VariantsMaterialKeywordsTest, ToggleOffEnablesWhenZero) {
  std::vector<ir::Property> props = {property("_SpecularHighlights", 1, "ToggleOff", {"_SPECULARHIGHLIGHTS_OFF"}),
                                     property("_Fog", 0, "toggleoff", {})};
  EXPECT_EQ(keywords_from_properties(props), (KeywordList{"_FOG_OFF"}));
  EXPECT_EQ(keywords_from_properties(props, {{"_SpecularHighlights", 0}, {"_Fog", 1}}),
            (KeywordList{"_SPECULARHIGHLIGHTS_OFF"}));
}

TEST(VariantsMaterialKeywordsTest, KeywordEnumPicksTheEntryByValue) {
  std::vector<ir::Property> props = {property("_Overlay", 0, "KeywordEnum", {"None", "Add Light", "Multiply"})};
  EXPECT_EQ(keywords_from_properties(props), (KeywordList{"_OVERLAY_NONE"}));
  EXPECT_EQ(keywords_from_properties(props, {{"_Overlay", 1}}), (KeywordList{"_OVERLAY_ADD_LIGHT"}));
  EXPECT_EQ(keywords_from_properties(props, {{"_Overlay", 2.7f}}), (KeywordList{"_OVERLAY_MULTIPLY"}));
  EXPECT_EQ(keywords_from_properties(props, {{"_Overlay", 99}}), (KeywordList{"_OVERLAY_MULTIPLY"}));
  EXPECT_EQ(keywords_from_properties(props, {{"_Overlay", -3}}), (KeywordList{"_OVERLAY_NONE"}));
}

TEST(VariantsMaterialKeywordsTest, OtherAttributesImplyNothing) {
  std::vector<ir::Property> props = {property("_Cull", 2, "Enum", {"UnityEngine.Rendering.CullMode"}),
                                     property("_Color", 1, "HDR", {})};
  EXPECT_TRUE(keywords_from_properties(props).empty());
}

}  // namespace
}  // namespace facet::variants
